// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::make_lattice_mesh_3(): a tetrahedral mesh of a domain whose vertices
// form a BCC or FCC lattice aligned with a frame field (dissertation ch. 4.3).

#ifndef CGAL_MAKE_LATTICE_MESH_3_H
#define CGAL_MAKE_LATTICE_MESH_3_H

#include <CGAL/lattice_particles_3.h>
#include <CGAL/gsm_optimize_mesh_3.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_complex.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <type_traits>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// what `make_lattice_mesh_3()` did, for its `Tetrahedral_lattice_meshing::parameters::mesh_report` output
struct Lattice_mesh_report
{
  std::size_t number_of_particles = 0;
  double edge_length = 0;             ///< \f$ l^* \f$
  double particle_time = 0;           ///< seconds: boundary sampling and particle optimization
  double connection_time = 0;         ///< seconds: the complex made of the particles
  double gsm_time = 0;                ///< seconds: GSM
  std::size_t number_of_feature_edges = 0;
  std::size_t number_of_surface_facets = 0;
  bool metric_is_anisotropic = false; ///< GSM ran in the metric \f$ B^T B \f$ (the frames are not all rotations)
};

namespace internal {

/// true if \f$ B^T B \f$ is the same multiple of the identity at every point (rotations, uniform scale)
template <class FrameField, class Point_3>
bool is_conformal(const FrameField& field, const std::vector<Point_3>& points)
{
  double scale = -1;
  for(const Point_3& p : points) {
    const Eigen::Matrix3d M = field.B(p).transpose() * field.B(p);
    const double s = M.trace() / 3.;
    if(scale < 0) scale = s;
    if((M - s * Eigen::Matrix3d::Identity()).norm() > 1e-9 * s || std::abs(s - scale) > 1e-9 * scale) return false;
  }
  return true;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 *
 * makes a tetrahedral mesh of `domain` whose vertices form a lattice (BCC or FCC) aligned with
 * the frame field `field`: the particles of `lattice_particles_3()`, connected by their
 * Delaunay triangulation into a `Mesh_complex_3_in_triangulation_3` (cells labelled with the
 * domain's subdomain at their centroid, boundary facets with their surface patch, feature
 * edges along the sharp edges, corners, vertex dimensions and indices as `make_mesh_3()` sets
 * them), then optimized by `gsm_optimize_mesh_3()` in the field's metric
 * \f$ M = B^T B \f$ (isotropic when the frames are rotations), whose flips make the
 * connectivity follow the field and whose boundary sliding brings the boundary onto the
 * surface (dissertation 4.3.2, with CGAL's Delaunay triangulation and GSM in place of
 * GEOGRAM's restricted Voronoi diagram and TetGen).
 *
 * \tparam C3T3 a `Mesh_complex_3_in_triangulation_3` of a `Mesh_triangulation_3` of `MeshDomain`
 * \tparam MeshDomain a model of `MeshDomain_3` (or `MeshDomainWithFeatures_3`) with `bbox()`
 * \tparam FrameField a model of `FrameField_3`
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{all the named parameters of `lattice_particles_3()`}\cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::optimize_with_gsm}
 *     \cgalParamDescription{whether GSM ends the meshing}
 *     \cgalParamType{`bool`} \cgalParamDefault{`true`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::mesh_report}
 *     \cgalParamDescription{receives the counts and the time of each stage}
 *     \cgalParamType{`Tetrahedral_lattice_meshing::Lattice_mesh_report*`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * `maximum_running_time` bounds the particle optimization; GSM gets the time left (at least
 * one second) when a limit is given.
 *
 * \throw std::invalid_argument as `lattice_particles_3()`, before any work, on bad input;
 *   and if the particles give no cell inside the domain
 */
template <class C3T3, class MeshDomain, class FrameField, class NamedParameters = parameters::Default_named_parameters>
C3T3 make_lattice_mesh_3(const MeshDomain& domain, const FrameField& field,
                         const NamedParameters& np = parameters::default_values())
{
  namespace TLM = Tetrahedral_lattice_meshing;
  namespace GSM = GSM_mesh_optimization;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename MeshDomain::R::Point_3 Point_3;

  const TLM::Lattice_type type = choose_parameter(get_parameter(np, TLM::internal_np::lattice), TLM::Lattice_type::BCC);
  if(type == TLM::Lattice_type::CUBIC)
    throw std::invalid_argument("make_lattice_mesh_3: the cubic lattice makes hexahedra (Hex_dominant_meshing), "
                                "not tetrahedra: use BCC or FCC");
  const bool with_gsm = choose_parameter(get_parameter(np, TLM::internal_np::optimize_with_gsm), true);
  const double time_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  const int threads = choose_parameter(get_parameter(np, TLM::internal_np::number_of_threads), 0);
  TLM::Lattice_mesh_report* report = choose_parameter(get_parameter(np, TLM::internal_np::mesh_report),
                                                      static_cast<TLM::Lattice_mesh_report*>(nullptr));
  TLM::Lattice_mesh_report local;
  TLM::Lattice_mesh_report& r = report ? *report : local;

  auto pd = TLM::internal::lattice_particles(domain, field, np);
  r.number_of_particles = pd.particles.size();
  r.edge_length = pd.particles.edge_length;
  r.particle_time = pd.particles.time;

  CGAL::Real_timer timer;
  timer.start();
  C3T3 c3t3;
  const TLM::internal::Complex_report cr = TLM::internal::connect_particles(c3t3, domain, *pd.boundary, pd.particles);
  r.number_of_feature_edges = cr.number_of_feature_edges;
  r.number_of_surface_facets = cr.number_of_surface_facets;
  r.connection_time = timer.time();
  if(c3t3.number_of_cells_in_complex() == 0)
    throw std::invalid_argument("make_lattice_mesh_3: the particles make no cell inside the domain "
                                "(edge length too large for it?)");
  if(!with_gsm) return c3t3;

  timer.reset();
  const double left = time_limit > 0 ? (std::max)(1., time_limit - pd.particles.time - r.connection_time) : 0.;
  auto gsm_np = GSM::parameters::number_of_threads(threads, CGAL::parameters::maximum_running_time(left));
  r.metric_is_anisotropic = !TLM::internal::is_conformal(field, pd.particles.points);
  if(r.metric_is_anisotropic) {
    auto metric = [&field](const Eigen::Vector3d& x) {
      const Eigen::Matrix3d B = field.B(Point_3(x[0], x[1], x[2]));
      return Eigen::Matrix3d(B.transpose() * B);
    };
    CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::metric_field(metric, gsm_np));
  } else
    CGAL::gsm_optimize_mesh_3(c3t3, domain, gsm_np);
  r.gsm_time = timer.time();
  return c3t3;
}

} // namespace CGAL

#endif // CGAL_MAKE_LATTICE_MESH_3_H
