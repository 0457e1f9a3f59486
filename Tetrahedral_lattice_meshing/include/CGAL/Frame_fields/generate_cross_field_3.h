// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// generate_cross_field_3(): a smooth cross field aligned with the boundary
// and the sharp edges of a tetrahedral mesh, for users who have no frame field.

#ifndef CGAL_FRAME_FIELDS_GENERATE_CROSS_FIELD_3_H
#define CGAL_FRAME_FIELDS_GENERATE_CROSS_FIELD_3_H

#include <CGAL/Frame_fields/Discrete_frame_field_3.h>
#include <CGAL/Frame_fields/Singular_curve.h>
#include <CGAL/Frame_fields/internal/Cross_field_solver.h>
#include <CGAL/Frame_fields/internal/Indexed_tetrahedral_mesh.h>
#include <CGAL/Frame_fields/parameters.h>
#include <CGAL/VVM/internal/Stopping.h>

#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Triangulation_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Frame_fields {

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// what `generate_cross_field_3()` tells its visitor after each smoothing round; `stage` is
/// `VVM::Stage::FRAME_FIELD`
struct Cross_field_round_report : VVM::Stage_report
{
  double energy = 0; ///< the smoothness energy after the round
};

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * The output of `generate_cross_field_3()`: the field, one frame per vertex, and
 * what it was aligned with and where it is singular. Indices refer to
 * `field.points()`.
 *
 * \tparam GeomTraits the kernel of the mesh's points (a model of `Kernel`)
 */
template <class GeomTraits>
struct Generated_cross_field_3
{
  /// the frames: rotations times `axis_length`, with the mesh's points and cells
  Discrete_frame_field_3<GeomTraits> field;
  /// the facets the frames were aligned with (the boundary; in a complex, all its facets)
  std::vector<std::array<std::size_t, 3>> boundary_facets;
  /// the sharp edges the frames were aligned with
  std::vector<std::array<std::size_t, 2>> feature_edges;
  /// per vertex, the unit direction its frame keeps as an axis: the boundary normal, the
  /// sharp edge's tangent, or at a corner the normal of its largest group of nearly
  /// parallel facets; zero for a free (interior) vertex
  std::vector<Eigen::Vector3d> constrained_axes;
  /// the interior edges around which the cell frames do not match (the holonomy of the
  /// cube-symmetry matchings of consecutive cells is not the identity)
  std::vector<std::array<std::size_t, 2>> singular_edges;
  /// the singular edges chained into curves, which end where other than two singular
  /// edges meet (an end on the boundary, or a branching), or close into loops
  std::vector<Singular_curve> singular_curves;
  /// the ends of singular curves at a vertex inside the domain that no other singular
  /// edge meets: a smooth field has none
  std::size_t number_of_dead_ends = 0;
  /// the edges whose ring of cells closes inside the domain
  std::size_t number_of_interior_edges = 0;
  /// all edges of the mesh's cells
  std::size_t number_of_edges = 0;
  /// \f$ \sum_{edges\ ij} |c_i - c_j|^2 \f$ over the unit SH vectors \f$ c \f$ of the frames
  double smoothness_energy = 0;
  /// the smoothness energy after the projection of the least-squares solution, then after
  /// each smoothing round (never increasing; its last value is `smoothness_energy`)
  std::vector<double> round_energies;
  /// the vertices on sharp edges where no axis could follow an edge (corners, ends of
  /// feature curves, turns of more than 45 degrees): one axis follows the normal of their
  /// largest group of nearly parallel boundary facets
  std::size_t number_of_corner_vertices = 0;
  /// the conjugate gradient iterations of the least-squares smoothness solve
  int solver_iterations = 0;
  /// the relative residual \f$ |Mx - b| / |b| \f$ of the accepted least-squares solution
  double solver_error = 0;
  /// `true` if the conjugate gradient did not converge and a sparse LDLT factorization
  /// solved the system instead
  bool direct_solver = false;
  /// `maximum_running_time` stopped the smoothing rounds
  bool time_limit_reached = false;
  /// the visitor returned `false`: the smoothing rounds stopped there
  bool stopped_by_visitor = false;
};

namespace internal {

template <class Point_3, class NamedParameters>
Generated_cross_field_3<typename Kernel_traits<Point_3>::Kernel>
generate_cross_field(const Indexed_tetrahedral_mesh<Point_3>& mesh, const NamedParameters& np);

} // namespace internal

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * generates a smooth cross field on the cells in the complex of `c3t3`, one frame per
 * vertex, with one axis along the normal of every facet in the complex and along every
 * edge in the complex (sharp features), by the method of Ray et al. 2016: each frame
 * as 9 band-4 spherical-harmonic coefficients; the boundary vertices restricted to
 * frames with one axis on the (area-weighted) normal, and the vertices of sharp edges
 * to frames with one axis on the edge; a sparse least-squares solve for smoothness
 * (\f$ \sum_{ij} |c_i - c_j|^2 \f$ over the mesh edges); the projection of each vertex
 * onto its nearest valid frame; then the minimisation of the same energy over the frames
 * themselves (the octahedral variety), by L-BFGS on per-vertex rotations, the constrained
 * frames turning only about their axis, in rounds until a round lowers the energy by less
 * than `Frame_fields::parameters::smoothing_tolerance` times it. At corners
 * (the vertices of sharp edges where the edges end, meet, or turn by more than 45
 * degrees), where no single edge gives the axis, one axis follows the mean normal of
 * the largest group (by area) of nearly parallel facets around the vertex.
 *
 * The sharp edges are the edges in the complex; the named parameter
 * `Frame_fields::parameters::features_angle` of the `Triangulation_3` overload does
 * not apply here, and passing it is a compile-time error.
 *
 * \tparam Tr the triangulation of the complex (`Mesh_triangulation_3<...>::%type`)
 * \tparam CornerIndex the corner index type of the complex
 * \tparam CurveIndex the curve index type of the complex
 * \tparam NamedParameters a sequence of named parameters
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the largest number of smoothing rounds (of at most 25 L-BFGS iterations each)}
 *     \cgalParamType{`int`}
 *     \cgalParamDefault{100}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::smoothing_tolerance}
 *     \cgalParamDescription{the smoothing stops after the first round lowering the energy by less than this fraction}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{1e-4}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{called after each smoothing round with its
 *       `Frame_fields::Cross_field_round_report`, and once the field is made with a
 *       `VVM::Stage_report`; if it returns `false`, the smoothing stops there
 *       (`stopped_by_visitor`). A callable `(int round, double energy)` still works (deprecated)}
 *     \cgalParamType{a callable taking `const VVM::Stage_report&` or
 *       `const Frame_fields::Cross_field_round_report&`, returning `void` or `bool`}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_running_time}
 *     \cgalParamDescription{a time limit in seconds, from the call: the smoothing rounds stop once
 *       it is reached (`time_limit_reached`), the field that of the last round; the least-squares
 *       solve before them always runs (the field needs it); 0 for none}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::axis_length}
 *     \cgalParamDescription{the length of the three axes of every frame}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{1}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{progress on `std::cerr`}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{false}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws std::invalid_argument if the complex has no cell or no facet, a vertex is not
 *   finite, or a parameter is out of range
 * \throws std::runtime_error if the least-squares system cannot be solved (neither the
 *   conjugate gradient nor the sparse LDLT factorization succeeds)
 */
template <class Tr, class CornerIndex, class CurveIndex,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Generated_cross_field_3<typename Kernel_traits<typename Tr::Geom_traits::Point_3>::Kernel>
generate_cross_field_3(const Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>& c3t3,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  static_assert(std::is_same<std::decay_t<decltype(CGAL::parameters::get_parameter(np, internal_np::features_angle))>,
                             CGAL::internal_np::Param_not_found>::value,
                "generate_cross_field_3: features_angle applies to a Triangulation_3 only; the sharp "
                "edges of a Mesh_complex_3_in_triangulation_3 are its edges in the complex");
  return internal::generate_cross_field(internal::indexed_mesh(c3t3, 0.), np);
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * the same on the finite cells of a triangulation: the boundary is the convex hull, and
 * its edges whose facet normals differ by more than `Frame_fields::parameters::features_angle`
 * (degrees, default 60; 0 for none) are sharp.
 *
 * Any triangulation deriving from `Triangulation_3` (`Delaunay_triangulation_3`,
 * `Regular_triangulation_3`, the triangulation of a `Mesh_complex_3_in_triangulation_3`, ...)
 * is accepted through its base.
 *
 * \tparam GT the geometric traits of the triangulation
 * \tparam TDS its triangulation data structure
 * \tparam Lds its lock data structure
 * \tparam NamedParameters a sequence of named parameters
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the largest number of smoothing rounds (of at most 25 L-BFGS iterations each)}
 *     \cgalParamType{`int`}
 *     \cgalParamDefault{100}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::smoothing_tolerance}
 *     \cgalParamDescription{the smoothing stops after the first round lowering the energy by less than this fraction}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{1e-4}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{called after each smoothing round with its
 *       `Frame_fields::Cross_field_round_report`, and once the field is made with a
 *       `VVM::Stage_report`; if it returns `false`, the smoothing stops there
 *       (`stopped_by_visitor`). A callable `(int round, double energy)` still works (deprecated)}
 *     \cgalParamType{a callable taking `const VVM::Stage_report&` or
 *       `const Frame_fields::Cross_field_round_report&`, returning `void` or `bool`}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_running_time}
 *     \cgalParamDescription{a time limit in seconds, from the call: the smoothing rounds stop once
 *       it is reached (`time_limit_reached`), the field that of the last round; the least-squares
 *       solve before them always runs (the field needs it); 0 for none}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::axis_length}
 *     \cgalParamDescription{the length of the three axes of every frame}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{1}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::features_angle}
 *     \cgalParamDescription{hull edges whose facet normals differ by more than this (degrees) are sharp}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{60}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{progress on `std::cerr`}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{false}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws std::invalid_argument if the triangulation has dimension less than 3, a vertex is
 *   not finite, or a parameter is out of range
 * \throws std::runtime_error as above
 */
template <class GT, class TDS, class Lds,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Generated_cross_field_3<typename Kernel_traits<typename GT::Point_3>::Kernel>
generate_cross_field_3(const Triangulation_3<GT, TDS, Lds>& triangulation,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  const double angle = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::features_angle), 60.);
  if(!(angle >= 0 && angle <= 180))
    throw std::invalid_argument("generate_cross_field_3: features_angle must be in [0, 180] degrees");
  return internal::generate_cross_field(internal::indexed_mesh(triangulation, angle), np);
}

namespace internal {

template <class Point_3, class NamedParameters>
Generated_cross_field_3<typename Kernel_traits<Point_3>::Kernel>
generate_cross_field(const Indexed_tetrahedral_mesh<Point_3>& mesh, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename Kernel_traits<Point_3>::Kernel K;
  const VVM::internal::Time_limit time_limit(
      choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.));
  const int rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 100);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::smoothing_tolerance), 1e-4);
  // the rounds' reports, or, for a visitor taking `(round, energy)` (deprecated), those two
  std::function<bool(int, double)> visitor;
  auto v = get_parameter(np, CGAL::internal_np::visitor);
  typedef decltype(v) Visitor;
  if constexpr(std::is_invocable<const Visitor&, const Cross_field_round_report&>::value)
    visitor = [v, &time_limit](int round, double energy) {
      Cross_field_round_report r;
      r.stage = VVM::Stage::FRAME_FIELD;
      r.round = round;
      r.elapsed_time = time_limit.elapsed();
      r.energy = energy;
      return VVM::internal::visit(v, r);
    };
  else if constexpr(std::is_invocable<const Visitor&, int, double>::value)
    visitor = [v](int round, double energy) { return VVM::internal::visit(v, round, energy); };
  else
    VVM::internal::check_visitor<Visitor, Cross_field_round_report>();
  const double axis_length = choose_parameter(get_parameter(np, internal_np::axis_length), 1.);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  if(rounds < 0) throw std::invalid_argument("generate_cross_field_3: number_of_iterations must be >= 0");
  if(!(choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.) >= 0))
    throw std::invalid_argument("generate_cross_field_3: maximum_running_time must be non-negative (0: no limit)");
  if(!(tolerance >= 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("generate_cross_field_3: smoothing_tolerance must be non-negative and finite");
  if(!(axis_length > 0) || !std::isfinite(axis_length))
    throw std::invalid_argument("generate_cross_field_3: axis_length must be positive and finite");
  mesh.check("generate_cross_field_3");
  if(mesh.boundary_facets.empty())
    throw std::invalid_argument("generate_cross_field_3: the mesh has no boundary facet to align with");

  Cross_field_solver solver(mesh.xyz, mesh.cells, mesh.boundary_facets, mesh.feature_edges);
  if(verbose)
    std::cerr << "generate_cross_field_3: " << mesh.points.size() << " vertices ("
              << solver.number_of_constrained_vertices() << " constrained, "
              << solver.number_of_corner_vertices() << " corners), " << mesh.cells.size()
              << " cells, " << mesh.boundary_facets.size() << " boundary facets, "
              << mesh.feature_edges.size() << " sharp edges\n";
  Generated_cross_field_3<K> out;
  Cross_field_solution s = solver.solve(rounds, tolerance, verbose, [&](int round, double energy) {
    if(round > 0 && visitor && !visitor(round, energy)) out.stopped_by_visitor = true;
    else if(time_limit.is_reached()) out.time_limit_reached = true;
    return !out.stopped_by_visitor && !out.time_limit_reached;
  }, [&time_limit]() { return time_limit.is_reached(); });

  std::vector<Eigen::Matrix3d> frames(s.vertex_frames.size());
  for(std::size_t v = 0; v < frames.size(); ++v) frames[v] = axis_length * s.vertex_frames[v];
  out.field = Discrete_frame_field_3<K>(mesh.points, mesh.cells, std::move(frames), Frame_location::VERTICES);
  out.boundary_facets = mesh.boundary_facets;
  out.feature_edges = mesh.feature_edges;
  out.constrained_axes = solver.constrained_axes();
  out.singular_edges = std::move(s.singularities.singular_edges);
  out.number_of_interior_edges = s.singularities.number_of_interior_edges;
  std::vector<char> on_boundary(mesh.points.size(), 0);
  for(const auto& f : mesh.boundary_facets)
    for(std::size_t v : f) on_boundary[v] = 1;
  Singular_curves_report curves = singular_curves(out.singular_edges, on_boundary, mesh.xyz);
  out.singular_curves = std::move(curves.curves);
  out.number_of_dead_ends = curves.number_of_dead_ends;
  out.number_of_edges = s.edges.size();
  out.smoothness_energy = s.smoothness_energy;
  out.round_energies = std::move(s.round_energies);
  out.number_of_corner_vertices = solver.number_of_corner_vertices();
  out.solver_iterations = s.solver_iterations;
  out.solver_error = s.solver_error;
  out.direct_solver = s.direct_solver;
  if(!out.stopped_by_visitor)
    VVM::internal::visit_stage_end(v, VVM::Stage::FRAME_FIELD,
                                   out.round_energies.empty() ? 0 : int(out.round_energies.size()) - 1,
                                   time_limit.elapsed());
  if(verbose)
    std::cerr << "generate_cross_field_3: " << out.singular_edges.size() << " singular edges of "
              << out.number_of_interior_edges << " interior edges in " << out.singular_curves.size()
              << " curves (" << out.number_of_dead_ends << " dead ends), smoothness energy "
              << out.smoothness_energy << "\n";
  return out;
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_GENERATE_CROSS_FIELD_3_H
