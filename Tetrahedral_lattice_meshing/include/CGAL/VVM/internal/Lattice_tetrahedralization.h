// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The lattice tetrahedralization shared by `make_lattice_mesh_3()` and
// `make_hex_dominant_mesh_3()` (dissertation 4.3.2 and 4.4): the particles of a
// lattice aligned with a frame field, connected by their Delaunay triangulation
// in the field's space into a complex, refined at the boundary if asked
// (section 4.4.2), then made Delaunay in the field's space by flips. The
// packages built on lattices reach the lattice package through this header.

#ifndef CGAL_VVM_INTERNAL_LATTICE_TETRAHEDRALIZATION_H
#define CGAL_VVM_INTERNAL_LATTICE_TETRAHEDRALIZATION_H

#include <CGAL/lattice_particles_3.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Boundary_refinement.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Lattice_connection.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Metric_Delaunay_flips.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_complex.h>
#include <CGAL/VVM/internal/Eigen_conversion.h>
#include <CGAL/VVM/internal/Stopping.h>

#include <CGAL/Real_timer.h>

#include <Eigen/Core>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace VVM {
namespace internal {

/// the named parameters of `lattice_particles_3()`, read and checked, and the frame field of
/// the overloads without a positional one
using Tetrahedral_lattice_meshing::internal::Lattice_request;
using Tetrahedral_lattice_meshing::internal::read_lattice_request;
using Tetrahedral_lattice_meshing::internal::with_frame_field;

/// the time the particles' connection into tets (and its metric flips) takes per particle, on
/// one core, rounded up from `benchmark/time_limits`: under a time limit, the particle rounds
/// keep it for the connection, which always runs
constexpr double connection_seconds_per_particle = 1e-4;

/// how the particles become tets
struct Lattice_tetrahedralization_options
{
  /// the entry point, named in the error messages
  std::string caller;
  /// the boundary refinement's distance (`refine_boundary()`); 0: none
  double boundary_distance = 0;
  /// tetrahedral lattices: no flip lays a flat cell of four surface vertices on a planar face,
  /// cospherical points in the field's space are connected by the better-shaped tets
  /// (`Metric_Delaunay_flips`), and the flips run unless the time limit is reached (a visitor's
  /// stop still gets a lattice mesh). The cubic lattice's tets are merged instead, whatever their
  /// shape, and a visitor's stop skips their flips.
  bool for_tetrahedral_lattice = true;
};

/// what the tetrahedralization did
struct Lattice_tetrahedralization_report
{
  std::size_t number_of_particles = 0;
  double edge_length = 0;                        ///< \f$ l^* \f$
  double particle_time = 0;                      ///< seconds: boundary sampling (but beside the generated cross field) and particle optimization
  int number_of_particle_rounds = 0;             ///< the particles' rounds, all levels together
  double connection_time = 0;                    ///< seconds: connection, boundary refinement and flips
  std::size_t number_of_projected_particles = 0; ///< free particles the complex left on its boundary, put onto it
  std::size_t number_of_boundary_points = 0;     ///< surface points added by the boundary refinement
  std::size_t number_of_metric_flips = 0;        ///< flips that made the tets Delaunay in the field's space
  std::size_t number_of_feature_edges = 0;      ///< edges of the complex on the domain's feature curves
  std::size_t number_of_surface_facets = 0;     ///< facets of the complex on the domain's surface
  bool time_limit_reached = false;              ///< a stage stopped or did not start at the time limit
  bool stopped_by_visitor = false;              ///< a visitor asked to stop
};

/// the fields of `t` that a package's own report has under the same names
template <class Report>
void copy_shared_fields(const Lattice_tetrahedralization_report& t, Report& r)
{
  r.number_of_particles = t.number_of_particles;
  r.edge_length = t.edge_length;
  r.particle_time = t.particle_time;
  r.number_of_projected_particles = t.number_of_projected_particles;
  r.number_of_metric_flips = t.number_of_metric_flips;
  r.time_limit_reached = t.time_limit_reached;
  r.stopped_by_visitor = t.stopped_by_visitor;
}

/// the particles and the report of a tetrahedralization
template <class MeshDomain>
struct Lattice_tetrahedralization
{
  Tetrahedral_lattice_meshing::internal::Particles_in_domain<MeshDomain> particles;
  Lattice_tetrahedralization_report report;
};

/// the particles of `request` in `domain` aligned with `field`, connected into the tets of
/// `c3t3` (empty; filled in place: a regular triangulation that flips made non-regular cannot be
/// moved while CGAL's assertions are on).
/// `particles_done(report)` is called once the particles are placed and returns `false` if a
/// visitor asks to stop. After a stop or once `time_limit` is reached, the boundary refinement
/// does not run; the flips neither, but for tetrahedral lattices, which skip them at the time
/// limit only (`Lattice_tetrahedralization_options::for_tetrahedral_lattice`).
template <class C3T3, class MeshDomain, class FrameField, class ParticlesDone>
Lattice_tetrahedralization<MeshDomain>
lattice_tetrahedralization(C3T3& c3t3, const MeshDomain& domain, const FrameField& field, Lattice_request request,
                           const Time_limit& time_limit, const Lattice_tetrahedralization_options& options,
                           const ParticlesDone& particles_done)
{
  namespace TLM_internal = Tetrahedral_lattice_meshing::internal;
  Lattice_tetrahedralization<MeshDomain> out;
  Lattice_tetrahedralization_report& r = out.report;
  request.seconds_kept_per_particle = connection_seconds_per_particle;
  out.particles = TLM_internal::lattice_particles(domain, field, request);
  auto& pd = out.particles;
  r.number_of_particles = pd.particles.size();
  r.edge_length = pd.particles.edge_length;
  r.particle_time = pd.particles.time;
  r.number_of_particle_rounds = pd.particles.number_of_rounds;
  r.time_limit_reached = pd.particles.time_limit_reached;
  r.stopped_by_visitor = pd.particles.stopped_by_visitor;
  if(!particles_done(r)) r.stopped_by_visitor = true;
  // the stages a valid mesh does not need do not start after a visitor's stop or the time limit
  auto skip_stage = [&]() {
    if(r.stopped_by_visitor) return true;
    if(time_limit.is_reached()) r.time_limit_reached = true;
    return r.time_limit_reached;
  };

  CGAL::Real_timer timer;
  timer.start();
  // the lattice is regular in the field's space: its tets are Delaunay there, not in Euclidean
  // space (where those of a stretched lattice are slivers in the field's metric)
  bool isotropic = true;
  const Eigen::Matrix3d delaunay_map = TLM_internal::mean_metric_root(field, pd.particles.points, isotropic);
  const Frame_inverse_function B = frame_inverse_function(field);
  TLM_internal::Complex_report cr =
      TLM_internal::connect_lattice_particles(c3t3, domain, pd, r.number_of_projected_particles, delaunay_map, B);
  if(options.boundary_distance > 0 && c3t3.number_of_cells_in_complex() > 0 && !skip_stage())
    r.number_of_boundary_points = TLM_internal::refine_boundary(c3t3, domain, pd, options.boundary_distance,
                                                                delaunay_map, B, r.number_of_projected_particles, cr);
  if(c3t3.number_of_cells_in_complex() == 0)
    throw std::invalid_argument(options.caller + ": the particles make no cell inside the domain "
                                "(edge length too large for it?)");
  if(!isotropic && (options.for_tetrahedral_lattice ? !time_limit.is_reached() : !skip_stage())) {
    typedef TLM_internal::Metric_Delaunay_flips<C3T3> Flips;
    // a field that jumps from vertex to vertex (one given on a mesh, scaled) can make the flips
    // cycle: the bound keeps their time to about that of connecting the particles
    const std::size_t max_flips = 2 * c3t3.number_of_cells_in_complex();
    Flips flips(c3t3, B, options.for_tetrahedral_lattice ? Flips::Flat_boundary_cells::FORBIDDEN
                                                         : Flips::Flat_boundary_cells::ALLOWED);
    r.number_of_metric_flips = flips.run(max_flips);
    if(options.for_tetrahedral_lattice) r.number_of_metric_flips += flips.break_ties_by_shape(max_flips);
  }
  r.number_of_feature_edges = cr.number_of_feature_edges;
  r.number_of_surface_facets = cr.number_of_surface_facets;
  r.connection_time = timer.time();
  if(options.for_tetrahedral_lattice && time_limit.is_reached()) r.time_limit_reached = true;
  return out;
}

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_LATTICE_TETRAHEDRALIZATION_H
