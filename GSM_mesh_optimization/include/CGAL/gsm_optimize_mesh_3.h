// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::gsm_optimize_mesh_3(): Gradient-based Shape Matching optimization of
// a tetrahedral mesh, a final stage after CGAL::make_mesh_3().

#ifndef CGAL_GSM_OPTIMIZE_MESH_3_H
#define CGAL_GSM_OPTIMIZE_MESH_3_H

#include <CGAL/GSM_mesh_optimization/internal/GSM_optimizer.h>
#include <CGAL/GSM_mesh_optimization/internal/Input_mesh_sizing.h>
#include <CGAL/GSM_mesh_optimization/internal/Triangulation_complex.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_sizes.h>
#include <CGAL/GSM_mesh_optimization/parameters.h>
#include <CGAL/GSM_mesh_optimization/shape_matching_energy.h>
#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h>
#include <CGAL/VVM/internal/Thread_limit.h>

#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/Named_function_parameters.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_set>

namespace CGAL {

namespace GSM_mesh_optimization {

/// \ingroup PkgGSMMeshOptimizationRef
/// what `gsm_optimize_mesh_3()` did, for its `report` output
struct Optimization_report
{
  int number_of_rounds = 0;           ///< rounds of vertex smoothing and flips
  int number_of_polishing_rounds = 0; ///< polishing passes (the mean-angle moves included)
  double energy = 0;                  ///< the mean energy of the cells after the last round
  double min_dihedral_angle = 0;      ///< degrees, after the last round
  /// cells whose smallest dihedral angle, in the metric, is under the sliver bound (30 degrees
  /// if the bound is 0) after the last round
  std::size_t number_of_cells_under_bound = 0;
  std::size_t number_of_moves = 0;    ///< vertex moves, all rounds together
  std::size_t number_of_flips = 0;    ///< flips (in polishing: edge removals and boundary peels)
  std::size_t number_of_splits = 0;   ///< edges split (new vertices)
  std::size_t number_of_removals = 0; ///< vertices removed
  double time = 0;                    ///< seconds
  Mesh_optimization_return_code return_code = MAX_ITERATION_NUMBER_REACHED;
  bool time_limit_reached = false;    ///< `maximum_running_time` stopped it
  bool stopped_by_visitor = false;    ///< the visitor returned `false`
};

namespace internal {

template <class C3T3>
Eigen::Vector3d centroid_of(const C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c)
{
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  for(int i = 0; i < 4; ++i) s += to_eigen(c3t3.triangulation().point(c, i));
  return 0.25 * s;
}

// Rejects what GSM cannot start from, before anything is changed.
template <class C3T3>
void check_input_mesh(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  if(tr.dimension() != 3 || c3t3.number_of_cells_in_complex() == 0)
    throw std::invalid_argument("GSM: the complex has no cell");
  for(auto v : tr.finite_vertex_handles()) {
    if(!to_eigen(tr.point(v)).allFinite())
      throw std::invalid_argument("GSM: a vertex has a non-finite coordinate");
  }
  std::size_t inverted = 0;
  for(auto c : tr.finite_cell_handles()) {
    const auto cp = tr.geom_traits().construct_point_3_object();
    if(CGAL::orientation(cp(tr.point(c, 0)), cp(tr.point(c, 1)), cp(tr.point(c, 2)),
                         cp(tr.point(c, 3))) != CGAL::POSITIVE)
      ++inverted;
  }
  if(inverted > 0)
    throw std::invalid_argument("GSM: the triangulation has " + std::to_string(inverted) +
                                " inverted or flat cells");
}

// Template edge length of eq. 3.21, measured in the metric (or in the vertices' sizes,
// if given): the regular tet edge l of a BCC-like mesh with N vertices in a domain of
// volume V and boundary area A (both mapped by B): V = N l^3 / sqrt(2) - A l / sqrt(6).
// Evaluating B at every cell also rejects a bad field before anything changes.
template <class C3T3>
double estimated_edge_length(const C3T3& c3t3, const Metric_field& metric = Metric_field::uniform(1.),
                             const Vertex_sizes<typename C3T3::Triangulation>* sizing = nullptr)
{
  const auto& tr = c3t3.triangulation();
  double volume = 0, area = 0;
  std::unordered_set<const void*> vertices;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) {
      p[i] = to_eigen(tr.point(c, i));
      vertices.insert(&*c->vertex(i));
    }
    const double det = sizing ? std::pow(0.25 * sizing->sum(c), -3)
                              : metric(0.25 * (p[0] + p[1] + p[2] + p[3])).determinant();
    volume += std::abs(det * (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0]))) / 6.;
  }
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    std::array<Eigen::Vector3d, 3> p;
    double h = 0;
    for(int k = 0; k < 3; ++k) {
      p[k] = to_eigen(tr.point(f->first, (f->second + 1 + k) & 3));
      if(sizing) h += (*sizing)(f->first->vertex((f->second + 1 + k) & 3)) / 3.;
    }
    const Eigen::Matrix3d B = sizing ? Eigen::Matrix3d(Eigen::Matrix3d::Identity() / h) : metric((p[0] + p[1] + p[2]) / 3.);
    area += 0.5 * (B * (p[1] - p[0])).cross(B * (p[2] - p[0])).norm();
  }
  const double n = double(vertices.size());
  // f(l) = N l^3 / sqrt 2 - A l / sqrt 6 - V is increasing past its minimum: bisect there
  auto f = [&](double l) { return n * l * l * l / std::sqrt(2.) - area * l / std::sqrt(6.) - volume; };
  double lo = std::sqrt(area * std::sqrt(2.) / (3. * std::sqrt(6.) * n)), hi = (std::max)(2. * lo, 1e-12);
  while(f(hi) < 0 && hi < 1e300) hi *= 2;
  for(int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return hi;
}


// The common part of gsm_optimize_mesh_3() and gsm_optimize_triangulation_3():
// named parameters, checks, the metric fitted to the vertex count, the run.
// `domain` is null for a bare triangulation (MeshDomain void).
template <class C3T3, class MeshDomain, class NamedParameters>
Mesh_optimization_return_code
gsm_optimize(C3T3& c3t3, const MeshDomain* domain, bool boundary_fixed, const NamedParameters& np)
{
  namespace GSM = GSM_mesh_optimization;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  GSM::internal::check_input_mesh(c3t3);

  GSM::internal::GSM_options options;
  options.number_of_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 50);
  options.maximum_running_time = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  options.do_flip = choose_parameter(get_parameter(np, CGAL::internal_np::do_flip), true);
  options.split_edges = choose_parameter(get_parameter(np, GSM::internal_np::split_edges), true);
  options.shortest_polishing_moves = choose_parameter(get_parameter(np, GSM::internal_np::shortest_polishing_moves), false);
  options.smooth_vertices = choose_parameter(get_parameter(np, GSM::internal_np::smooth_vertices), true);
  options.sliver_bound = choose_parameter(get_parameter(np, GSM::internal_np::sliver_bound), 30.);
  options.mean_angle_threshold = choose_parameter(get_parameter(np, GSM::internal_np::mean_angle_threshold), 0.);
  options.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  options.convergence_threshold =
      choose_parameter(get_parameter(np, GSM::internal_np::convergence_threshold), 1e-4);
  options.freeze_boundary =
      boundary_fixed || choose_parameter(get_parameter(np, GSM::internal_np::freeze_boundary), false);
  options.boundary_distance = choose_parameter(get_parameter(np, GSM::internal_np::boundary_distance), 0.);
  options.energy = choose_parameter(get_parameter(np, GSM::internal_np::energy),
                                    GSM::Shape_matching_energy::GSM);
  const int threads = choose_parameter(get_parameter(np, VVM::internal_np::number_of_threads), 0);
  auto refuse_unless = [](bool ok, const char* what) {
    if(!ok) throw std::invalid_argument(std::string("GSM: ") + what);
  };
  refuse_unless(options.number_of_iterations >= 0, "number_of_iterations must be non-negative");
  refuse_unless(options.maximum_running_time >= 0, "maximum_running_time must be non-negative (0: no limit)");
  refuse_unless(options.convergence_threshold >= 0, "convergence_threshold must be non-negative");
  refuse_unless(threads >= 0, "number_of_threads must be non-negative (0: TBB's choice)");
  refuse_unless(options.sliver_bound >= 0 && options.sliver_bound < 70.5,
                "sliver_bound must be in [0, 70.5) degrees (the sliver bound)");
  refuse_unless(options.mean_angle_threshold >= 0, "mean_angle_threshold must be non-negative");
  refuse_unless(options.boundary_distance >= 0 && options.boundary_distance < HUGE_VAL,
                "boundary_distance must be non-negative and finite");

  // the time limit counts from here: the metric's fitting is part of the run
  const VVM::internal::Time_limit time_limit(options.maximum_running_time);
  // the visitor and the report see the rounds (set only if asked: the rounds' figures cost a pass)
  auto visitor = get_parameter(np, CGAL::internal_np::visitor);
  VVM::internal::check_visitor<decltype(visitor), GSM::Round_report>();
  GSM::Optimization_report* report =
      choose_parameter(get_parameter(np, VVM::internal_np::report), static_cast<GSM::Optimization_report*>(nullptr));
  GSM::Optimization_report local_report;
  GSM::Optimization_report& r = report ? *report : local_report;
  r = GSM::Optimization_report();
  if(report || VVM::internal::is_given(visitor))
    options.visitor = [&visitor, &r](const GSM::Round_report& round) {
      bool go = true;
      if(round.is_polishing && r.number_of_polishing_rounds == 0) // the rounds are over
        go = VVM::internal::visit_stage_end(visitor, VVM::Stage::OPTIMIZATION, r.number_of_rounds, round.elapsed_time);
      ++(round.is_polishing ? r.number_of_polishing_rounds : r.number_of_rounds);
      r.energy = round.energy;
      r.min_dihedral_angle = round.min_dihedral_angle;
      r.number_of_cells_under_bound = round.number_of_cells_under_bound;
      r.number_of_moves += round.number_of_moves;
      r.number_of_flips += round.number_of_flips;
      r.number_of_splits += round.number_of_splits;
      r.number_of_removals += round.number_of_removals;
      go = VVM::internal::visit_report(visitor, round) && go;
      if(!go) r.stopped_by_visitor = true;
      return go;
    };

  auto sizing = get_parameter(np, GSM::internal_np::sizing_field);
  auto metric_field = get_parameter(np, GSM::internal_np::metric_field);
  constexpr bool has_sizing = !std::is_same<decltype(sizing), CGAL::internal_np::Param_not_found>::value;
  constexpr bool has_metric = !std::is_same<decltype(metric_field), CGAL::internal_np::Param_not_found>::value;
  static_assert(!(has_sizing && has_metric),
                "GSM: give a sizing field or a metric field, not both");
  const bool uniform = choose_parameter(get_parameter(np, GSM::internal_np::uniform_sizing), false);
  GSM::internal::Metric_field metric = GSM::internal::Metric_field::uniform(1.);
  // an isotropic size (given, or the input mesh's) is sampled at the vertices
  typedef GSM::internal::Vertex_sizes<typename C3T3::Triangulation> Vertex_sizes;
  std::shared_ptr<Vertex_sizes> vertex_sizes;
  if constexpr(has_sizing)
    vertex_sizes = std::make_shared<Vertex_sizes>(c3t3.triangulation(),
                                                  [sizing](const Eigen::Vector3d& x) { return double(sizing(x)); });
  else if constexpr(has_metric)
    metric = GSM::internal::Metric_field::anisotropic(
        [metric_field](const Eigen::Vector3d& x) { return Eigen::Matrix3d(metric_field(x)); });
  else if(!uniform) {
    // the input's own grading (facet_distance, sizing criteria, small features) is the target,
    // sampled at the vertices
    auto field = std::make_shared<const GSM::internal::Input_mesh_sizing>(c3t3);
    vertex_sizes = std::make_shared<Vertex_sizes>(c3t3.triangulation(),
                                                  [field](const Eigen::Vector3d& x) { return (*field)(x); });
  }
  // The field gives shape and relative size; the vertex count gives the absolute size.
  metric = metric.scaled(1. / GSM::internal::estimated_edge_length(c3t3, metric, vertex_sizes.get()));

  const auto thread_limit = VVM::internal::thread_limit(threads);
  options.maximum_running_time = time_limit.remaining();
  GSM::internal::GSM_optimizer<C3T3, MeshDomain> optimizer(c3t3, domain, metric, options, vertex_sizes);
  auto cost = get_parameter(np, GSM::internal_np::vertex_move_cost);
  if constexpr(!std::is_same<decltype(cost), CGAL::internal_np::Param_not_found>::value)
    optimizer.set_move_cost([cost](const typename C3T3::Triangulation::Vertex_handle& v, const Eigen::Vector3d& x) {
      return double(cost(v, x));
    });
  r.return_code = optimizer();
  r.time = time_limit.elapsed();
  r.time_limit_reached = r.return_code == TIME_LIMIT_REACHED;
  if(!r.stopped_by_visitor)
    VVM::internal::visit_stage_end(visitor, r.number_of_polishing_rounds ? VVM::Stage::POLISHING : VVM::Stage::OPTIMIZATION,
                                   r.number_of_polishing_rounds ? r.number_of_polishing_rounds : r.number_of_rounds, r.time);
  return r.return_code;
}

} // namespace internal
} // namespace GSM_mesh_optimization


/*!
 * \ingroup PkgGSMMeshOptimizationRef
 *
 * optimizes the cells in the complex of `c3t3` by Gradient-based Shape Matching: rounds of
 * Newton smoothing of the vertices (in parallel) and of flips, each kept only if it lowers the
 * mean GSM energy of the cells, which brings every tetrahedron close to the regular tetrahedron
 * of the target size; slivers, whose energy is huge, go first. A polishing stage then lifts the
 * cells whose smallest dihedral angle is still under `sliver_bound`, by vertex moves, edge
 * removals and, within a budget of 3% of the vertex count, edge splits paid for by vertex
 * removals.
 *
 * This is meant as the last stage after `make_mesh_3()`, in place of `perturb_mesh_3()` and
 * `exude_mesh_3()`. Surface vertices stay on their surface patch, feature-curve vertices on
 * their curve, corners do not move, and the boundary stays about as close to the domain's
 * surface as the input's; no cell is inverted, no flip crosses a surface, feature edge or
 * subdomain boundary, and subdomain and patch indices are kept.
 * The manual, \ref Chapter_GSM_mesh_optimization, describes the method, the stopping rules and
 * when to use which option.
 *
 * \pre `c3t3` was made from `domain` (by `make_mesh_3()`, or by
 *   `GSM_mesh_optimization::Complex_from_tetrahedra_3`).
 * \warning The triangulation is no longer regular (weighted Delaunay) afterwards: nothing that
 *   needs one (`refine_mesh_3()`, `perturb_mesh_3()`, `exude_mesh_3()`) may run after it.
 *
 * \tparam C3T3 a `Mesh_complex_3_in_triangulation_3`
 * \tparam MeshDomain a model of `MeshDomain_3` (or `MeshDomainWithFeatures_3`)
 * \tparam NamedParameters a sequence of named parameters
 *
 * \param c3t3 the mesh, modified in place
 * \param domain the domain `c3t3` was generated from
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the maximal number of rounds (smoothing then flips)}
 *     \cgalParamType{int}
 *     \cgalParamDefault{50}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_running_time}
 *     \cgalParamDescription{a time limit in seconds, from the call; the rounds and the polishing
 *       stop once it is reached, the mesh valid (`TIME_LIMIT_REACHED`); 0 for none}
 *     \cgalParamType{double}
 *     \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::convergence_threshold}
 *     \cgalParamDescription{the rounds stop when one lowers the mean energy by less than this
 *       fraction (or when the worst cells stop improving)}
 *     \cgalParamType{double}
 *     \cgalParamDefault{1e-4}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{do_flip}
 *     \cgalParamDescription{whether the connectivity is optimized by flips}
 *     \cgalParamType{bool}
 *     \cgalParamDefault{true}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::freeze_boundary}
 *     \cgalParamDescription{if `true`, surface, feature-curve and corner vertices stay where they
 *       are and no flat boundary cell is peeled: the boundary does not change}
 *     \cgalParamType{bool}
 *     \cgalParamDefault{false}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::boundary_distance}
 *     \cgalParamDescription{how far a boundary facet may stray from the domain's surface at
 *       least, along its normal; 0: as far as the input's facets did. A positive distance frees
 *       the boundary vertices of a mesh whose boundary lies on the surface}
 *     \cgalParamType{`double`, non-negative}
 *     \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::sliver_bound}
 *     \cgalParamDescription{the smallest dihedral angle, in degrees, sought by the final polishing
 *       (in the metric, if one is given); 0 skips the polishing}
 *     \cgalParamType{double, in [0, 70.5)}
 *     \cgalParamDefault{30}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::smooth_vertices}
 *     \cgalParamDescription{whether the rounds move vertices; `false` makes them flips only, which
 *       keeps the vertices where they are (e.g. on a lattice) until the polishing}
 *     \cgalParamType{bool}
 *     \cgalParamDefault{true}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::split_edges}
 *     \cgalParamDescription{whether the polishing may add and remove vertices (edge splits and
 *       collapses, at most 3% of the vertex count net); `false` keeps the vertex set}
 *     \cgalParamType{bool}
 *     \cgalParamDefault{true}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::shortest_polishing_moves}
 *     \cgalParamDescription{if `true`, the polishing moves a vertex by the shortest step that
 *       lifts its star to the bound: for meshes whose vertex positions matter, such as lattice
 *       meshes (`make_lattice_mesh_3()` sets it)}
 *     \cgalParamType{bool}
 *     \cgalParamDefault{false}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::mean_angle_threshold}
 *     \cgalParamDescription{if positive, after the polishing, the vertices of the cells under this
 *       many degrees move to raise the sum of their star's smallest angles (less
 *       `vertex_move_cost`); 0, or a `sliver_bound` of 0, skips these moves}
 *     \cgalParamType{double}
 *     \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::vertex_move_cost}
 *     \cgalParamDescription{what a vertex costs at a position, in degrees, for the moves of
 *       `mean_angle_threshold` only; called sequentially}
 *     \cgalParamType{a callable `double(C3T3::Triangulation::Vertex_handle, const Eigen::Vector3d&)`}
 *     \cgalParamDefault{no cost}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::sizing_field}
 *     \cgalParamDescription{the relative target edge length `h(p)`; only its variation matters
 *       (it is scaled to fit the vertex count). Called from several threads at once}
 *     \cgalParamType{a callable `double(const Eigen::Vector3d&)`, positive and finite}
 *     \cgalParamDefault{the input mesh's local edge length, so that a graded mesh keeps its grading}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::uniform_sizing}
 *     \cgalParamDescription{if `true` and no sizing or metric field is given, one target edge
 *       length for the whole mesh instead of the input mesh's local size}
 *     \cgalParamType{bool}
 *     \cgalParamDefault{false}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::metric_field}
 *     \cgalParamDescription{an anisotropic metric `M(p)`: the target tetrahedron is regular in
 *       the metric (scaled to fit the vertex count). Called from several threads at once}
 *     \cgalParamType{a callable `Eigen::Matrix3d(const Eigen::Vector3d&)`, symmetric positive definite}
 *     \cgalParamDefault{isotropic}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::energy}
 *     \cgalParamDescription{the energy minimized}
 *     \cgalParamType{`GSM_mesh_optimization::Shape_matching_energy`}
 *     \cgalParamDefault{`Shape_matching_energy::GSM`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::number_of_threads}
 *     \cgalParamDescription{the largest number of threads of the vertex sweeps; 0 lets TBB choose.
 *       The result does not depend on it.}
 *     \cgalParamType{int}
 *     \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{called after each round, and each polishing round, with its
 *       `GSM_mesh_optimization::Round_report`, and at the end of the rounds and of the
 *       polishing with a `VVM::Stage_report`; returning `false` stops the optimization
 *       (`MAX_ITERATION_NUMBER_REACHED`)}
 *     \cgalParamType{a callable taking `const VVM::Stage_report&` or
 *       `const GSM_mesh_optimization::Round_report&`, returning `void` or `bool`}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{GSM_mesh_optimization::parameters::report}
 *     \cgalParamDescription{receives what the optimization did}
 *     \cgalParamType{`GSM_mesh_optimization::Optimization_report*`}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{print one line per round to `std::cerr`}
 *     \cgalParamType{bool}
 *     \cgalParamDefault{false}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return `CONVERGENCE_REACHED`, `CANT_IMPROVE_ANYMORE` (a round changed nothing),
 *   `MAX_ITERATION_NUMBER_REACHED` or `TIME_LIMIT_REACHED`.
 *
 * \throw std::invalid_argument, before `c3t3` is changed, if the complex has no
 *   cell, a vertex has a non-finite coordinate, a cell is inverted or flat, both a
 *   sizing field and a metric field are given, or the field is not positive
 *   (definite) and finite at a cell of the mesh.
 *
 * \sa `gsm_optimize_triangulation_3()`, `GSM_mesh_optimization::mesh_quality_statistics()`
 */
template <class C3T3, class MeshDomain, class NamedParameters = parameters::Default_named_parameters>
Mesh_optimization_return_code
gsm_optimize_mesh_3(C3T3& c3t3, const MeshDomain& domain,
                    const NamedParameters& np = parameters::default_values())
{
  return GSM_mesh_optimization::internal::gsm_optimize(c3t3, &domain, false, np);
}

/*!
 * \ingroup PkgGSMMeshOptimizationRef
 *
 * optimizes the finite cells of a bare triangulation by Gradient-based Shape
 * Matching, as `gsm_optimize_mesh_3()` does for a complex: rounds of Newton
 * smoothing of the interior vertices and of energy-guided flips (2-3, 3-2, 4-4,
 * edge removal, multi-face removal). Its boundary, the convex hull, is fixed:
 * hull vertices do not move and no flip touches a hull facet. The triangulation
 * is no longer Delaunay (or regular) afterwards; cells are never inverted.
 *
 * \tparam Triangulation_3 a CGAL 3D triangulation (`Triangulation_3`,
 *   `Delaunay_triangulation_3` or `Regular_triangulation_3`) with an exact-predicates kernel
 * \tparam NamedParameters a sequence of named parameters
 *
 * \param tr the triangulation, modified in place
 * \param np the named parameters of `gsm_optimize_mesh_3()` (`freeze_boundary` is implied)
 *
 * \return as `gsm_optimize_mesh_3()`
 * \throw std::invalid_argument, before `tr` is changed, in the cases of `gsm_optimize_mesh_3()`
 *   (no cell, a non-finite coordinate, an inverted or flat cell, a bad field).
 */
template <class Triangulation_3, class NamedParameters = parameters::Default_named_parameters>
Mesh_optimization_return_code
gsm_optimize_triangulation_3(Triangulation_3& tr, const NamedParameters& np = parameters::default_values())
{
  if(tr.dimension() != 3)
    throw std::invalid_argument("gsm_optimize_triangulation_3: the triangulation has no cell");
  GSM_mesh_optimization::internal::Triangulation_complex<Triangulation_3> complex(tr);
  return GSM_mesh_optimization::internal::gsm_optimize(complex, static_cast<const void*>(nullptr), true, np);
}

} // namespace CGAL

#endif // CGAL_GSM_OPTIMIZE_MESH_3_H
