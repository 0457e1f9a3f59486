// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of GSM_mesh_optimization that CGAL's central list does not
// have. CGAL 5.5.1 offers no hook to add names to CGAL::parameters, so they
// live here; each has an overload that appends it to an existing pack:
//
//   namespace GSM = CGAL::GSM_mesh_optimization;
//   CGAL::gsm_optimize_mesh_3(c3t3, domain,
//       GSM::parameters::freeze_boundary(true,
//           CGAL::parameters::number_of_iterations(20).do_flip(false)));

#ifndef CGAL_GSM_MESH_OPTIMIZATION_PARAMETERS_H
#define CGAL_GSM_MESH_OPTIMIZATION_PARAMETERS_H

#include <CGAL/VVM/internal/add_named_parameter.h>
#include <CGAL/VVM/parameters.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal_np {

enum energy_t { energy };
enum freeze_boundary_t { freeze_boundary };
enum sizing_field_t { sizing_field };
enum metric_field_t { metric_field };
enum convergence_threshold_t { convergence_threshold };
enum split_edges_t { split_edges };
enum smooth_vertices_t { smooth_vertices };
enum sliver_bound_t { sliver_bound };
enum uniform_sizing_t { uniform_sizing };
enum shortest_polishing_moves_t { shortest_polishing_moves };
enum mean_angle_threshold_t { mean_angle_threshold };
enum vertex_move_cost_t { vertex_move_cost };
enum boundary_distance_t { boundary_distance };

} // namespace internal_np

namespace parameters {

/// `Shape_matching_energy::GSM` (default) or `Shape_matching_energy::ESM`
CGAL_VVM_ADD_NAMED_PARAMETER(energy)
/// `bool`: keep every surface, feature-curve and corner vertex where it is (default `false`)
CGAL_VVM_ADD_NAMED_PARAMETER(freeze_boundary)
/// `double`: how far the boundary facets may stray from the domain's surface at least (default 0:
/// as far as the input mesh's did; a mesh whose boundary lies on the surface keeps it there)
CGAL_VVM_ADD_NAMED_PARAMETER(boundary_distance)
/// a callable `double(const Point_3&)`: the target edge length at a point (adaptive meshing)
CGAL_VVM_ADD_NAMED_PARAMETER(sizing_field)
/// a callable `Eigen::Matrix3d(const Point_3&)`: the anisotropic metric M(x), symmetric positive definite
CGAL_VVM_ADD_NAMED_PARAMETER(metric_field)
/// `double`: stop when a round lowers the mean energy by less than this fraction (default 1e-4)
CGAL_VVM_ADD_NAMED_PARAMETER(convergence_threshold)
/// `int`: the number of threads of the vertex sweeps (default 0: TBB's choice)
using VVM::parameters::number_of_threads;
/// `Optimization_report*`: receives what `gsm_optimize_mesh_3()` did (default: none)
using VVM::parameters::report;
/// `double`: the smallest dihedral angle, in degrees, that the final polishing seeks (default 30; 0: no polishing)
CGAL_VVM_ADD_NAMED_PARAMETER(sliver_bound)
/// `bool`: whether the final polishing may split interior edges, adding vertices (default `true`)
CGAL_VVM_ADD_NAMED_PARAMETER(split_edges)
/// `bool`: whether the rounds move vertices (`false`: flips only, e.g. to keep a lattice; default `true`)
CGAL_VVM_ADD_NAMED_PARAMETER(smooth_vertices)
/// `bool`: one target edge length for the whole mesh instead of the input mesh's local size (default `false`)
CGAL_VVM_ADD_NAMED_PARAMETER(uniform_sizing)
/// `bool`: the polishing lifts a cell by the shortest vertex move that takes its star to the bound (default `false`)
CGAL_VVM_ADD_NAMED_PARAMETER(shortest_polishing_moves)
/// `double`: after the polishing, vertices with a cell under this many degrees in their star move to
/// raise the sum of their star's smallest angles (default 0: none)
CGAL_VVM_ADD_NAMED_PARAMETER(mean_angle_threshold)
/// the former name of `mean_angle_threshold`
template <class... Args>
[[deprecated("use mean_angle_threshold")]] auto mean_angle_moves(const Args&... args)
{
  return mean_angle_threshold(args...);
}
/// a callable `double(Vertex_handle, const Eigen::Vector3d&)`: what a vertex at a position costs, in
/// degrees of its star's smallest angles, for the moves of `mean_angle_threshold` (default: nothing)
CGAL_VVM_ADD_NAMED_PARAMETER(vertex_move_cost)

} // namespace parameters
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_PARAMETERS_H
