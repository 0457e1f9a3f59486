// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::make_lattice_mesh_3(): a tetrahedral mesh of a domain whose vertices
// form a BCC or FCC lattice aligned with a frame field (dissertation ch. 4.3).

#ifndef CGAL_MAKE_LATTICE_MESH_3_H
#define CGAL_MAKE_LATTICE_MESH_3_H

#include <CGAL/lattice_particles_3.h>
#include <CGAL/gsm_optimize_mesh_3.h>
#include <CGAL/Tetrahedral_lattice_meshing/alignment_error.h>
#include <CGAL/VVM/internal/Lattice_tetrahedralization.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the last stage of `make_lattice_mesh_3()`, in the frame field's metric \f$ B^T B \f$
enum class Lattice_mesh_optimization
{
  /// the particles' Delaunay triangulation as it is
  NONE,
  /// `gsm_optimize_mesh_3()` without vertex smoothing: energy-guided flips (the dissertation's
  /// connectivity optimization), then the polishing of the cells under 30 degrees; the vertices
  /// stay on the lattice except those of the cells the polishing lifts
  FLIPS,
  /// `gsm_optimize_mesh_3()` in full: vertex smoothing and flips, then the polishing
  GSM
};

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// what `make_lattice_mesh_3()` did, for its `Tetrahedral_lattice_meshing::parameters::report` output
struct Lattice_mesh_report
{
  std::size_t number_of_particles = 0;
  double edge_length = 0;             ///< \f$ l^* \f$
  double particle_time = 0;           ///< seconds: boundary sampling (but beside the generated cross field) and particle optimization
  double connection_time = 0;         ///< seconds: the complex made of the particles
  double gsm_time = 0;                ///< seconds: the last stage (`Lattice_mesh_optimization`)
  std::size_t number_of_feature_edges = 0;
  std::size_t number_of_surface_facets = 0;
  std::size_t number_of_projected_particles = 0; ///< free particles the complex left on its boundary, put onto the surface
  std::size_t number_of_metric_flips = 0; ///< flips that made the tets Delaunay in the field's space (anisotropic fields)
  bool metric_is_anisotropic = false; ///< the last stage ran in the metric \f$ B^T B \f$ (the frames are not all rotations)
  /// `maximum_running_time` stopped a stage: the particles' rounds or the last stage, or left
  /// no time for the last stage (the mesh is valid, its vertices those of the last round)
  bool time_limit_reached = false;
  /// the visitor returned `false`: the stage it was told about stopped there, and the stages after it did not run
  bool stopped_by_visitor = false;
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

/// what a vertex's position costs the mean-angle moves of the last stage: the sum of the
/// alignment errors (degrees) of its edges in the complex, so that a move must raise the
/// smallest angles of its star by more than it turns its edges off the lattice (on angles
/// alone, even with the aligned vertices kept in place, the moves raised the mean angle but
/// turned the edges further off the lattice; with the cost both improve). Called
/// sequentially: it keeps the neighbours of the last
/// vertex asked, which the moves do not change.
template <class C3T3, class FrameField>
class Vertex_alignment_cost
{
  typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
  typedef typename C3T3::Triangulation::Cell_handle Cell_handle;
  typedef typename FrameField::Point_3 Point_3;

public:
  Vertex_alignment_cost(const C3T3& c3t3, const FrameField& field, const Lattice& lattice)
    : c3t3_(c3t3), field_(field), lattice_(lattice)
  {}

  double operator()(const Vertex_handle& v, const Eigen::Vector3d& x)
  {
    using VVM::internal::to_eigen;
    if(v != vertex_) {
      vertex_ = v;
      neighbors_.clear();
      cells_.clear();
      c3t3_.triangulation().finite_incident_cells(v, std::back_inserter(cells_));
      for(const Cell_handle& c : cells_) {
        if(!c3t3_.is_in_complex(c)) continue;
        for(int i = 0; i < 4; ++i)
          if(c->vertex(i) != v && std::find(neighbors_.begin(), neighbors_.end(), c->vertex(i)) == neighbors_.end())
            neighbors_.push_back(c->vertex(i));
      }
    }
    double sum = 0;
    for(const Vertex_handle& w : neighbors_) {
      const Eigen::Vector3d q = to_eigen(c3t3_.triangulation().point(w)), m = 0.5 * (x + q);
      sum += edge_alignment_error(lattice_, field_.B(Point_3(m[0], m[1], m[2])), q - x);
    }
    return sum;
  }

private:
  const C3T3& c3t3_;
  const FrameField& field_;
  const Lattice& lattice_;
  Vertex_handle vertex_;
  std::vector<Vertex_handle> neighbors_;
  std::vector<Cell_handle> cells_;
};

/// the cells under this smallest angle (degrees, in the field's metric) have their vertices
/// moved by the last stage to raise their stars' mean angle: a lattice's own tets reach 60
/// (BCC) or more (FCC's regular tets), those of the boundary layer rarely do
constexpr double lattice_mean_angle_threshold = 60;

/// the last stage of `make_lattice_mesh_3()`: GSM in the field's metric \f$ B^T B \f$
/// (isotropic if the frames are conformal), with or without vertex smoothing, its polishing
/// aiming at `sliver_bound` degrees (0: none), then its mean-angle moves
/// under `mean_angle_threshold` degrees (0: none); `time_limit` 0 for none. A `visitor` given
/// sees GSM's rounds and stages (a stop sets `r.stopped_by_visitor`).
template <class C3T3, class MeshDomain, class FrameField, class Visitor = CGAL::internal_np::Param_not_found>
Mesh_optimization_return_code optimize_lattice_mesh(C3T3& c3t3, const MeshDomain& domain, const FrameField& field, const Lattice& lattice,
                           Lattice_mesh_optimization stage, double sliver_bound, int threads, double time_limit,
                           Lattice_mesh_report& r, double mean_angle_threshold = lattice_mean_angle_threshold,
                           const Visitor& visitor = Visitor())
{
  namespace GSM = GSM_mesh_optimization;
  typedef typename MeshDomain::R::Point_3 Point_3;
  if(stage == Lattice_mesh_optimization::NONE) return CONVERGENCE_REACHED;
  CGAL::Real_timer timer;
  timer.start();
  std::vector<Point_3> points;
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v)
    points.push_back(Point_3(v->point().x(), v->point().y(), v->point().z()));
  r.metric_is_anisotropic = !is_conformal(field, points);
  // the polishing's moves as short as will do: each takes vertices off the lattice
  // std::ref: the named parameter is copied, the cost keeps the last vertex's neighbours
  Vertex_alignment_cost<C3T3, FrameField> alignment_cost(c3t3, field, lattice);
  auto gsm_np = GSM::parameters::vertex_move_cost(std::ref(alignment_cost),
      GSM::parameters::mean_angle_threshold(mean_angle_threshold,
      GSM::parameters::shortest_polishing_moves(true, GSM::parameters::sliver_bound(sliver_bound,
      GSM::parameters::smooth_vertices(stage == Lattice_mesh_optimization::GSM,
      GSM::parameters::number_of_threads(threads, CGAL::parameters::maximum_running_time(time_limit)))))));
  auto optimize = [&](const auto& np) {
    if(r.metric_is_anisotropic) {
      auto metric = [&field](const Eigen::Vector3d& x) {
        const Eigen::Matrix3d B = field.B(Point_3(x[0], x[1], x[2]));
        return Eigen::Matrix3d(B.transpose() * B);
      };
      return CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::metric_field(metric, np));
    } // rotations of one scale: the lattice's edge length is the target everywhere
    return CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::uniform_sizing(true, np));
  };
  Mesh_optimization_return_code code;
  if constexpr(std::is_invocable<const Visitor&, const GSM::Round_report&>::value)
    code = optimize(gsm_np.visitor([&visitor, &r](const auto& report) { // GSM's rounds and stage ends
      const bool go = VVM::internal::visit_report(visitor, report);
      if(!go) r.stopped_by_visitor = true;
      return go;
    }));
  else
    code = optimize(gsm_np);
  r.gsm_time = timer.time();
  return code;
}

/// the polishing bound of the last stage (`GSM_mesh_optimization::parameters::sliver_bound`),
/// checked before any work
template <class NamedParameters>
double lattice_mesh_sliver_bound(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double bound = choose_parameter(get_parameter(np, GSM_mesh_optimization::internal_np::sliver_bound), 30.);
  if(!(bound >= 0 && bound < 70.5))
    throw std::invalid_argument("make_lattice_mesh_3: the sliver bound must be in [0, 70.5) degrees");
  return bound;
}

/// the threshold of the last stage's mean-angle moves (`GSM_mesh_optimization::parameters::mean_angle_threshold`),
/// checked before any work
template <class NamedParameters>
double lattice_mesh_mean_angle_threshold(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double threshold =
      choose_parameter(get_parameter(np, GSM_mesh_optimization::internal_np::mean_angle_threshold), lattice_mean_angle_threshold);
  if(!(threshold >= 0))
    throw std::invalid_argument("make_lattice_mesh_3: the mean-angle threshold must not be negative");
  return threshold;
}

template <class C3T3, class MeshDomain, class FrameField, class NamedParameters>
C3T3 make_lattice_mesh(const MeshDomain& domain, const FrameField& field, const Lattice_request& request,
                       const NamedParameters& np)
{
  namespace TLM = Tetrahedral_lattice_meshing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(request.lattice.type == Lattice_type::CUBIC)
    throw std::invalid_argument("make_lattice_mesh_3: the cubic lattice makes hexahedra (Hex_dominant_meshing), "
                                "not tetrahedra: use BCC or FCC");
  const Lattice_mesh_optimization stage =
      choose_parameter(get_parameter(np, TLM::internal_np::mesh_optimization), Lattice_mesh_optimization::FLIPS);
  const double sliver_bound = lattice_mesh_sliver_bound(np);
  const double mean_angle_threshold = lattice_mesh_mean_angle_threshold(np);
  Lattice_mesh_report* report = choose_parameter(get_parameter(np, VVM::internal_np::report),
                                                 static_cast<Lattice_mesh_report*>(nullptr));
  Lattice_mesh_report local;
  Lattice_mesh_report& r = report ? *report : local;
  r = Lattice_mesh_report();
  const VVM::internal::Time_limit time_limit(request.options.maximum_running_time);
  auto visitor = get_parameter(np, CGAL::internal_np::visitor);
  VVM::internal::check_visitor<decltype(visitor), Lattice_round_report, GSM_mesh_optimization::Round_report>();

  VVM::internal::Lattice_tetrahedralization_options options;
  options.caller = "make_lattice_mesh_3";
  C3T3 c3t3;
  const VVM::internal::Lattice_tetrahedralization<MeshDomain> t = VVM::internal::lattice_tetrahedralization(
      c3t3, domain, field, request, time_limit, options,
      [&](const VVM::internal::Lattice_tetrahedralization_report& tr) {
        return tr.stopped_by_visitor ||
               VVM::internal::visit_stage_end(visitor, VVM::Stage::PARTICLES, tr.number_of_particle_rounds, tr.particle_time);
      });
  VVM::internal::copy_shared_fields(t.report, r);
  r.connection_time = t.report.connection_time;
  r.number_of_feature_edges = t.report.number_of_feature_edges;
  r.number_of_surface_facets = t.report.number_of_surface_facets;
  if(!r.stopped_by_visitor && !VVM::internal::visit_stage_end(visitor, VVM::Stage::TETRAHEDRA, 0, time_limit.elapsed()))
    r.stopped_by_visitor = true;
  if(r.time_limit_reached || r.stopped_by_visitor) return c3t3;
  if(optimize_lattice_mesh(c3t3, domain, field, request.lattice, stage, sliver_bound, request.threads,
                           time_limit.remaining(), r, mean_angle_threshold, visitor) == TIME_LIMIT_REACHED)
    r.time_limit_reached = true;
  return c3t3;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 *
 * makes a tetrahedral mesh of `domain` whose vertices form a lattice (BCC or FCC) aligned with
 * the frame field `field`: the particles of `lattice_particles_3()`, connected by their
 * Delaunay triangulation into a `Mesh_complex_3_in_triangulation_3` labelled as `make_mesh_3()`
 * labels its meshes, then optimized by `gsm_optimize_mesh_3()` in the field's metric: by
 * default flips and polishing only, so that the vertices stay on the lattice (dissertation
 * 4.3.2). The manual, \ref TLMMeshes, describes the stages and their trade-offs.
 *
 * \tparam C3T3 a `Mesh_complex_3_in_triangulation_3` of a `Mesh_triangulation_3` of `MeshDomain`
 * \tparam MeshDomain a model of `MeshDomain_3` (or `MeshDomainWithFeatures_3`) with `bbox()`
 * \tparam FrameField a model of `FrameField_3`
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{the named parameters of `lattice_particles_3()`}
 *     \cgalParamDescription{all of them, passed on to it}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::mesh_optimization}
 *     \cgalParamDescription{the last stage: `NONE` (the Delaunay triangulation of the particles),
 *       `FLIPS` (GSM's flips and polishing; the vertices stay on the lattice but for the
 *       polished cells) or `GSM` (GSM in full, vertices smoothed too)}
 *     \cgalParamType{`Tetrahedral_lattice_meshing::Lattice_mesh_optimization`}
 *     \cgalParamDefault{`FLIPS`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::sliver_bound}
 *     \cgalParamDescription{the smallest dihedral angle, in degrees (in the field's metric), that the
 *       polishing of the last stage seeks; 0 skips the polishing. A higher bound buys angles with
 *       alignment error and time}
 *     \cgalParamType{`double`, in [0, 70.5)}
 *     \cgalParamDefault{30}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::mean_angle_threshold}
 *     \cgalParamDescription{after the polishing, the vertices of the cells under this many degrees
 *       move where that raises their star's angles by more than it turns their edges off the
 *       lattice; the last stage takes several times longer. 0 skips these moves}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{60}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{called with the particles' rounds
 *       (`Tetrahedral_lattice_meshing::Lattice_round_report`), the last stage's rounds
 *       (`GSM_mesh_optimization::Round_report`) and each stage's end (`VVM::Stage_report`:
 *       `PARTICLES`, `TETRAHEDRA`, then GSM's); if it returns `false`, the call stops there
 *       (see below)}
 *     \cgalParamType{a callable taking `const VVM::Stage_report&` or one of the rounds' reports,
 *       returning `void` or `bool`}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::report}
 *     \cgalParamDescription{receives the counts and the time of each stage}
 *     \cgalParamType{`Tetrahedral_lattice_meshing::Lattice_mesh_report*`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * `maximum_running_time` (seconds from the call, 0: none) is shared by the stages: the
 * particles' rounds, then the last stage, stop once it is reached, and a stage that finds it
 * reached does not start; the result is a valid mesh of the particles of the last round
 * (`Lattice_mesh_report::time_limit_reached`). The stages without which there is no mesh
 * always run: the boundary's sampling, the first particles and their connection (and, in the
 * overload without a field, the cross field's mesh and least-squares solve). A visitor that
 * returns `false` stops the particles' rounds or the last stage there, and the stages after
 * it do not run (`Lattice_mesh_report::stopped_by_visitor`).
 *
 * \throw std::invalid_argument as `lattice_particles_3()`, before any work, on bad input
 *   (and on a sliver bound outside [0, 70.5) or a negative mean-angle threshold);
 *   and if the particles give no cell inside the domain
 */
template <class C3T3, class MeshDomain, class FrameField, class NamedParameters = parameters::Default_named_parameters>
C3T3 make_lattice_mesh_3(const MeshDomain& domain, const FrameField& field,
                         const NamedParameters& np = parameters::default_values())
{
  namespace TLM_internal = Tetrahedral_lattice_meshing::internal;
  return TLM_internal::make_lattice_mesh<C3T3>(domain, field, TLM_internal::read_lattice_request(np), np);
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 *
 * the same with the frame field of the named parameter `Tetrahedral_lattice_meshing::parameters::frame_field`
 * or, without it, the boundary-aligned cross field of `Frame_fields::generate_cross_field_3()`
 * (unit frames, one axis on the surface normal and along the feature curves), computed on a
 * `make_mesh_3()` mesh of `domain` whose edges are about \f$ l^* \f$ long.
 */
template <class C3T3, class MeshDomain, class T, class Tag, class Base>
C3T3 make_lattice_mesh_3(const MeshDomain& domain, const Named_function_parameters<T, Tag, Base>& np)
{
  namespace TLM_internal = Tetrahedral_lattice_meshing::internal;
  const TLM_internal::Lattice_request r = TLM_internal::read_lattice_request(np);
  TLM_internal::lattice_mesh_sliver_bound(np); // checked before the field is made
  TLM_internal::lattice_mesh_mean_angle_threshold(np);
  return TLM_internal::with_frame_field(domain, r, np, [&](const auto& field, const TLM_internal::Lattice_request& fr) {
    return TLM_internal::make_lattice_mesh<C3T3>(domain, field, fr, np);
  });
}

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the same with the default named parameters
template <class C3T3, class MeshDomain>
C3T3 make_lattice_mesh_3(const MeshDomain& domain)
{
  return make_lattice_mesh_3<C3T3>(domain, parameters::default_values());
}

} // namespace CGAL

#endif // CGAL_MAKE_LATTICE_MESH_3_H
