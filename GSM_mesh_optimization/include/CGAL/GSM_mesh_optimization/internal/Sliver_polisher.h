// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The final stage of GSM: lifting the cells whose smallest dihedral angle is
// still under the sliver bound once the energy rounds have converged. The GSM
// energy of a cell mixes shape and size, and its minimum over a vertex's star
// is a compromise that can keep one poor cell, typically next to the surface,
// where vertices only slide. Here the objective is the cells' angles:
//
// - the critical cells, the worst 200th of the cells at most (all those
//   under the bound on most meshes), are lifted first: a vertex of one moves
//   up the smallest dihedral angle of its star (measured in the metric), along
//   the direction that raises all its cells within a degree of the worst
//   together (Least_norm_point_of_hull.h), within its degrees of freedom and
//   with the smoother's projections and validity checks, when that raises it
//   (max-min smoothing, Freitag and Ollivier-Gooch 1997); with `shortest_moves` (lattice
//   meshes, whose vertices should stay put) by the shortest step that takes
//   the star to the bound, else by the step that lifts it most, preferring
//   steps that put no more of the star's cells under the bound + 10 degrees;
// - a vertex of the other cells under the bound moves down the gradient of its
//   star's angle penalty (Angle_penalty.h), when that lowers it: on a steeply
//   graded or thin-walled mesh with thousands of cells under the bound, max-min
//   moves for all of them pushed more cells under 40 and 30 degrees than they lifted;
//   where the star's worst cell is within 10 degrees of the bound, only if it puts no
//   more of the star's cells under the bound + 10 than it lifts over the bound;
// - an interior edge of a cell under the bound is removed (edge removal, 3-2
//   flip included, Edge_removal.h) when the triangulation of its ring of least
//   penalty beats the cells around it (Shewchuk 2002): a sliver whose vertices
//   cannot move often goes with one of its edges;
// - a cell with two surface facets of one patch is peeled off the complex (the
//   boundary peel of Energy_guided_flips.h) when its two other facets stray from
//   the surface no further than the boundary may (Boundary_fidelity.h); so is a cap
//   with three, whose fourth facet becomes the surface;
// - a surface vertex of a cell under the bound is removed (Surface_vertex_collapse.h)
//   when its collapse into a neighbour on its patch beats its star's smallest angle, the
//   new facets as faithful to the surface as the boundary may be; each removal lets one
//   more split happen. In the first pass every surface vertex is tried, worst stars first:
//   stars just over the bound hold the wedges that later moves push under it. Where the
//   surface is much finer than the interior, the cells under the bound are wedges between
//   surface edges and the few interior vertices that neither moves nor splits lift;
// - a cell that no move lifts gets an interior edge split (Edge_split.h) when the
//   smallest angle of the new cells beats that of the old ones, and, unless the
//   cell is critical, the penalty of the new cells beats that of the old ones;
//   then a cell still under it gets a surface edge split (Surface_edge_split.h),
//   the new vertex on the surface, on the same terms; the interior splits come
//   first, for all the cells, so that the surface ones do not spend their budget;
//   at most 3% of the vertex count is added;
// - once that budget is spent, with cells still under the bound, interior
//   vertices whose removal (Vertex_collapse.h) leaves only cells 5 degrees over
//   the bound are removed, as many as there are such cells (at most 3% of the
//   vertex count in all), and the budget grows by as many: on thin organic
//   models the splits need ~5% more vertices, which the interior, far from the
//   thin parts, gives back;
// - on request (`mean_angle_threshold`, set by make_lattice_mesh_3), after those
//   passes, a vertex with a cell under a threshold in its star moves up the
//   gradient of the sum of its star's smallest angles less a cost of its
//   position (`vertex_move_cost`: a lattice mesh's alignment error), when that
//   raises it without lowering the star's worst cell under the bound or putting
//   more of its cells under the bound + 10 degrees: the mean angle of a lattice's
//   boundary layer, which the max-min moves do not aim at.
//
// All may raise the energy a little: this stage runs after the rounds whose
// energy never increases.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SLIVER_POLISHER_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SLIVER_POLISHER_H

#include <CGAL/GSM_mesh_optimization/internal/Angle_penalty.h>
#include <CGAL/GSM_mesh_optimization/internal/Central_differences.h>
#include <CGAL/GSM_mesh_optimization/internal/Edge_split.h>
#include <CGAL/GSM_mesh_optimization/internal/Energy_guided_flips.h>
#include <CGAL/GSM_mesh_optimization/internal/Least_norm_point_of_hull.h>
#include <CGAL/GSM_mesh_optimization/internal/Surface_edge_split.h>
#include <CGAL/GSM_mesh_optimization/internal/Surface_vertex_collapse.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_collapse.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_smoother.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <iterator>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class C3T3, class MeshDomain>
class Sliver_polisher
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef Vertex_smoother<C3T3, MeshDomain> Smoother;
  typedef typename Smoother::Ring Ring;
  typedef typename Smoother::Bare_point Bare_point;
  typedef Mesh_energy<C3T3> Energy;

public:
  struct Counts
  {
    std::size_t moves = 0, flips = 0, peels = 0, splits = 0, removals = 0;
  };

  /// `bound`: the smallest dihedral angle sought, in degrees
  Sliver_polisher(C3T3& c3t3, const Energy& energy, const Smoother& smoother, Energy_guided_flips<C3T3>& flips,
                  Edge_split<C3T3>& splits, Surface_edge_split<C3T3, MeshDomain>& surface_splits,
                  Vertex_collapse<C3T3>& collapses, Surface_vertex_collapse<C3T3, MeshDomain>& surface_collapses,
                  double bound, bool do_split,
                  bool boundary_fixed, bool shortest_moves)
    : c3t3_(c3t3), tr_(c3t3.triangulation()), energy_(energy), smoother_(smoother), flips_(flips), splits_(splits),
      surface_splits_(surface_splits), collapses_(collapses), surface_collapses_(surface_collapses),
      bound_(bound), penalty_(Angle_penalty::for_bound(bound)), do_split_(do_split), boundary_fixed_(boundary_fixed),
      shortest_moves_(shortest_moves),
      split_budget_(std::size_t(max_split_fraction * double(c3t3.triangulation().number_of_vertices()))),
      removal_budget_(split_budget_),
      fewest_vertices_(c3t3.triangulation().number_of_vertices() - split_budget_)
  {}

  /// one pass over the cells under the bound, worst first: their vertices' moves, then
  /// edge removals, peels, surface vertex removals (in the first pass, tried on all the
  /// surface vertices: `coarsen_surface()`) and splits of the cells still under it; it ends early when
  /// `stop()` says so
  template <class Stop>
  Counts polish_pass(const Stop& stop)
  {
    Counts done;
    auto bad = bad_cells();
    set_critical_angle(bad);
    std::vector<std::pair<double, Vertex_handle>> vertices;
    for(const auto& b : bad)
      for(const Vertex_handle& v : b.second) vertices.push_back({b.first, v});
    // stable, on the angle only: handles compare by address in some triangulations
    std::stable_sort(vertices.begin(), vertices.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    std::unordered_set<Vertex_handle> seen;
    Ring ring;
    for(const auto& w : vertices) {
      if(stop()) return done;
      const Vertex_handle v = w.second;
      if(!seen.insert(v).second) continue;
      if(!smoother_.is_movable(v)) continue;
      for(int k = 0; k < max_moves_per_vertex; ++k) {
        if(!smoother_.make_ring(v, ring) || !lift(ring)) break;
        ++done.moves;
      }
    }
    // the cells under the bound are scanned for again only after a change: in the last passes
    // at 100k vertices, with a few moves each, the scans were most of the time
    const auto rescan_if = [&](bool changed) {
      if(changed) bad = bad_cells();
    };
    rescan_if(done.moves > 0);
    if(!change_bad_cells(bad, [&](const Cell_handle&, const Cell_vertices& t) { return remove_an_edge(t); }, stop,
                         done.flips))
      return done;
    rescan_if(done.flips > 0);
    if(!boundary_fixed_ &&
       !change_bad_cells(bad, [&](const Cell_handle& c, const Cell_vertices&) { return peel(c); }, stop, done.peels))
      return done;
    rescan_if(done.peels > 0);
    if(!do_split_) return done;
    // surface vertices whose removal lifts a cell: each pays for a split
    if(!boundary_fixed_) {
      std::size_t n = 0;
      std::unordered_set<Vertex_handle> removed; // their handles are dangling
      const auto collapse = [&](const Cell_handle& c, const Cell_vertices&) {
        Vertex_handle v;
        if(!may_remove_surface_vertex() || !surface_collapses_.try_collapse_cell(c, v)) return false;
        removed.insert(v);
        return true;
      };
      bool finished;
      if(!surface_coarsened_ && !shortest_moves_ && !bad.empty()) {
        surface_coarsened_ = true;
        finished = coarsen_surface(stop, n);
      } else
        finished = change_bad_cells(bad, collapse, stop, n, &removed);
      done.removals += n;
      split_budget_ += n;
      if(!finished) return done;
      rescan_if(n > 0);
    }
    // the vertex budget is spent: vertices whose removal leaves good cells pay for more splits
    if(split_budget_ == 0 && removal_budget_ > 0) {
      const std::size_t n = collapses_.collapse_vertices((std::min)(bad.size(), removal_budget_), bound_ + removal_margin);
      done.removals += n;
      removal_budget_ -= n;
      split_budget_ += n;
      rescan_if(n > 0);
    }
    // interior splits first, for all the cells: surface splits in the same loop spent the
    // budget the interior splits and removals needed
    if(!change_bad_cells(bad, [&](const Cell_handle& c, const Cell_vertices&) { return split(splits_, c); }, stop,
                         done.splits))
      return done;
    rescan_if(done.splits > 0);
    if(!boundary_fixed_)
      change_bad_cells(bad, [&](const Cell_handle& c, const Cell_vertices&) { return split(surface_splits_, c); }, stop,
                       done.splits);
    return done;
  }

  /// one sweep of mean-angle moves over the movable vertices of the cells under `threshold`
  /// degrees, in the order of the cells: each moves up the gradient of the sum of its star's
  /// smallest angles less the smoother's `move_cost()`, when that raises it and neither lowers
  /// the star's smallest angle under the bound nor puts more of its cells under the bound + 10;
  /// returns the number of moves
  template <class Stop>
  std::size_t raise_mean_pass(double threshold, const Stop& stop)
  {
    std::vector<Vertex_handle> vertices;
    std::unordered_set<Vertex_handle> seen;
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c) {
      if(!(energy_.min_dihedral_angle(c) < threshold)) continue;
      for(int i = 0; i < 4; ++i)
        if(seen.insert(c->vertex(i)).second) vertices.push_back(c->vertex(i));
    }
    std::size_t moves = 0;
    Ring ring;
    for(const Vertex_handle& v : vertices) {
      if(stop()) break;
      if(!smoother_.is_movable(v) || !smoother_.make_ring(v, ring)) continue;
      if(raise_mean(ring)) ++moves;
    }
    return moves;
  }

private:
  typedef std::array<Vertex_handle, 4> Cell_vertices;

  // the first pass's surface collapses (on a mesh with cells under the bound, not on a
  // lattice's, whose vertices should stay on the lattice): tried on every surface vertex, not
  // only those of the cells under the bound, the vertices of the worst stars first, each
  // collapse still beating its star's smallest angle and penalty. Where the surface is finer
  // than the interior, many stars just over the bound hold the wedges that go under it at the
  // next move. Each removed vertex is checked against the facets that replace it, not
  // against later ones: not trying again the vertices whose star a collapse changed would
  // keep a chain of collapses from wearing a thin part away, but cost more angles than it
  // saved, and the boundaries stayed close to the surface without it;
  // counts the removals in `n`; false if `stop()` ended it
  template <class Stop>
  bool coarsen_surface(const Stop& stop, std::size_t& n)
  {
    const std::vector<Cell_handle> cells = energy_.cells_in_complex();
    const std::vector<double> angles = Energy::per_cell(cells, [this](const Cell_handle& c) { return energy_.min_dihedral_angle(c); });
    std::vector<std::pair<double, Vertex_handle>> vertices; // with the smallest angle of their star
    std::unordered_map<Vertex_handle, std::size_t> index;
    for(std::size_t i = 0; i < cells.size(); ++i)
      for(int k = 0; k < 4; ++k) {
        const Vertex_handle v = cells[i]->vertex(k);
        if(c3t3_.in_dimension(v) != 2) continue;
        const auto it = index.emplace(v, vertices.size());
        if(it.second)
          vertices.push_back({angles[i], v});
        else
          vertices[it.first->second].first = (std::min)(vertices[it.first->second].first, angles[i]);
      }
    // stable, on the angle only: the cells come in the triangulation's order
    std::stable_sort(vertices.begin(), vertices.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    typename Surface_vertex_collapse<C3T3, MeshDomain>::Plan p;
    for(const auto& x : vertices) {
      if(stop()) return false;
      if(!may_remove_surface_vertex()) break;
      if(!surface_collapses_.best_collapse(x.second, p)) continue;
      surface_collapses_.apply(p);
      ++n;
    }
    return true;
  }

  // on a mesh made elsewhere (its boundary not a convex hull: Complex_from_tetrahedra_3),
  // surface vertex removals stop where it would have 3% fewer vertices than at the start: its
  // flat patches, whose facets stay on the surface whatever goes, would lose many, and who
  // cleans up a mesh keeps its size. On make_mesh_3's meshes the removals of the first pass
  // are paid back by splits, and a cap costs angles (benchmark/tools/optimize_other_meshers.md)
  bool may_remove_surface_vertex() const
  {
    return smoother_.convex_hull() || tr_.number_of_vertices() > fewest_vertices_;
  }

  // calls `change(c, vertices)` on each cell of `bad` (the cells under the bound, worst first)
  // that is still there (none of its vertices `removed`), changes replacing cells, and counts
  // in `changed` those it says it changed; false if `stop()` ended it
  template <class Change, class Stop>
  bool change_bad_cells(const std::vector<std::pair<double, Cell_vertices>>& bad, const Change& change,
                        const Stop& stop, std::size_t& changed,
                        const std::unordered_set<Vertex_handle>* removed = nullptr)
  {
    for(const auto& b : bad) {
      if(stop()) return false;
      Cell_handle c;
      const Cell_vertices& t = b.second;
      if(removed != nullptr && std::any_of(t.begin(), t.end(), [&](const Vertex_handle& v) { return removed->count(v) != 0; }))
        continue;
      int i, j, k, l;
      if(tr_.is_cell(t[0], t[1], t[2], t[3], c, i, j, k, l) && change(c, t)) ++changed;
    }
    return true;
  }

  // a split of the cell `c` by `splits`, if the budget allows it
  template <class Splits>
  bool split(Splits& splits, const Cell_handle& c)
  {
    if(split_budget_ == 0 || !splits.try_split_cell(c)) return false;
    --split_budget_;
    return true;
  }

  // what the moves of the vertex of `r` weigh of its star's smallest angles at a position
  struct Star_angles
  {
    double worst = 180;   // the smallest
    double sum = 0;
    double penalty = 0;   // `penalty_` summed
    std::size_t under_bound = 0, under_guard = 0; // under the bound, under the bound + `guard_margin`
  };

  // the star's angles with the vertex of `r` placed at `x`, in one pass over its cells (a
  // backtracking step weighs several of these, and the angles are most of its cost)
  Star_angles star_angles(const Ring& r, const Eigen::Vector3d& x) const
  {
    Star_angles a;
    for(const Cell_handle& c : r.complex_cells) {
      const double q = energy_.min_dihedral_angle(c, r.v, x);
      a.worst = (std::min)(a.worst, q);
      a.sum += q;
      a.penalty += penalty_(q);
      if(q < bound_) ++a.under_bound;
      if(q < bound_ + guard_margin) ++a.under_guard;
    }
    return a;
  }

  // the unit direction `d` in which `score` of the vertex of `r` rises fastest from `x0`, within
  // the vertex's degrees of freedom, by central differences (the scores are only piecewise
  // smooth); false if there is none
  template <class Score>
  bool ascent_direction(const Ring& r, const Eigen::Vector3d& x0, const Score& score, Eigen::Vector3d& d) const
  {
    d = smoother_.tangential(r, central_differences(score, x0, 1e-4 * r.max_neighbor_distance));
    const double n = d.norm();
    if(!(n > 0) || !std::isfinite(n)) return false;
    d /= n;
    return true;
  }

  // the direction in which the smallest angle `q0` of the star of the vertex of `r` at `x0`
  // rises fastest, within the vertex's degrees of freedom (Freitag and Ollivier-Gooch 1997):
  // the point of least norm in the convex hull of the gradients of the cells within
  // `active_margin` of it. The central difference of the minimum itself sees one cell at a
  // time, and where two cells are balanced, a step up for one is a step down for the other.
  // False if no direction raises them all
  bool max_min_direction(const Ring& r, const Eigen::Vector3d& x0, double q0, Eigen::Vector3d& d) const
  {
    const double h = 1e-4 * r.max_neighbor_distance;
    std::vector<Eigen::Vector3d> gradients;
    for(const Cell_handle& c : r.complex_cells) {
      if(!(energy_.min_dihedral_angle(c, r.v, x0) < q0 + active_margin)) continue;
      const auto angle = [&](const Eigen::Vector3d& x) { return energy_.min_dihedral_angle(c, r.v, x); };
      gradients.push_back(smoother_.tangential(r, central_differences(angle, x0, h) / (2 * h)));
    }
    if(gradients.empty()) return false;
    const Eigen::Vector3d z = least_norm_point_of_hull(gradients);
    const double n = z.norm();
    // the rate of ascent, degrees per unit length, against that of one cell alone
    if(!(n > 1e-6 * gradients.front().norm()) || !std::isfinite(n)) return false;
    d = z / n;
    return true;
  }

  // the mean-angle move of the vertex of `r` (see `raise_mean_pass()`)
  bool raise_mean(const Ring& r) const
  {
    const Eigen::Vector3d x0 = energy_.position(r.v);
    const auto objective = [&](const Eigen::Vector3d& x, const Star_angles& a) { return a.sum - smoother_.move_cost(r.v, x); };
    const Star_angles a0 = star_angles(r, x0);
    const double s0 = objective(x0, a0);
    const double floor = (std::min)(a0.worst, bound_);
    Eigen::Vector3d d;
    if(!ascent_direction(r, x0, [&](const Eigen::Vector3d& x) { return objective(x, star_angles(r, x)); }, d))
      return false;
    double alpha = 0.2 * r.max_neighbor_distance;
    for(int k = 0; k < max_backtracking_steps; ++k, alpha *= 0.5) {
      Bare_point p;
      if(!smoother_.candidate(r, x0 + alpha * d, p) || !smoother_.is_valid_position(r, p)) continue;
      const Eigen::Vector3d x = Energy::to_eigen(p);
      const Star_angles a = star_angles(r, x);
      if(objective(x, a) > s0 + 1e-3 && a.worst >= floor && a.under_guard <= a0.under_guard &&
         smoother_.keeps_boundary_faithful(r, p)) {
        smoother_.move(r.v, p);
        return true;
      }
    }
    return false;
  }

  static constexpr int max_moves_per_vertex = 4;
  /// degrees: the cells of a star within it of its smallest angle set the max-min direction
  static constexpr double active_margin = 1;
  /// at most this fraction of the vertex count is added: a mesh far from the bound
  /// everywhere (such as an isotropic mesh under a strongly anisotropic metric) needs
  /// remeshing, not splits
  static constexpr double max_split_fraction = 0.03;
  /// degrees over the bound: a vertex is removed (Vertex_collapse.h) only if the cells its
  /// removal makes are all that far over it: a wider margin leaves too few removals to pay
  /// for the splits (the margins tried: benchmark/GSM_mesh_optimization/RESULTS.md)
  static constexpr double removal_margin = 5;
  static constexpr int max_backtracking_steps = 8;
  /// degrees over the bound: a max-min move may not put more of its star's cells under it
  static constexpr double guard_margin = 10;
  /// degrees under the bound: a penalty move of a star whose worst cell is nearer the bound may
  /// put no more of its cells under the bound + `guard_margin` than it lifts over the bound:
  /// where thousands of cells are near the bound, free trades pushed the bulk under 40 degrees,
  /// while the rule for every star kept the worst cells from being lifted
  static constexpr double free_trade_margin = 10;
  /// at most this share of the cells is lifted whatever it costs the others
  static constexpr double max_critical_share = 0.005;

  // the critical angle: the bound, or just over that of the k-th worst cell, k the
  // `max_critical_share` of the cells in the complex (at least 1), if more are under the
  // bound (ties with it are critical too)
  void set_critical_angle(const std::vector<std::pair<double, std::array<Vertex_handle, 4>>>& bad)
  {
    const std::size_t k =
        (std::max)(std::size_t(1), std::size_t(max_critical_share * double(c3t3_.number_of_cells_in_complex())));
    penalty_.critical = bad.size() > k ? std::nextafter(bad[k - 1].first, 180.) : bound_;
    splits_.set_penalty(penalty_);
    surface_splits_.set_penalty(penalty_);
    surface_collapses_.set_penalty(penalty_);
  }

  // the cells in the complex under the bound, worst first, with their vertices
  std::vector<std::pair<double, std::array<Vertex_handle, 4>>> bad_cells() const
  {
    std::vector<std::pair<double, std::array<Vertex_handle, 4>>> bad;
    const std::vector<Cell_handle> cells = energy_.cells_in_complex();
    const std::vector<double> angles = Energy::per_cell(cells, [this](const Cell_handle& c) { return energy_.min_dihedral_angle(c); });
    for(std::size_t i = 0; i < cells.size(); ++i) {
      const Cell_handle& c = cells[i];
      if(angles[i] < bound_) bad.push_back({angles[i], {{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}}});
    }
    std::stable_sort(bad.begin(), bad.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    return bad;
  }

  // removes the first edge of the cell on `t` whose removal lowers the penalty around it
  bool remove_an_edge(const std::array<Vertex_handle, 4>& t)
  {
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        Cell_handle c; // a removal replaces cells: find the edge again
        int ei, ej;
        if(tr_.is_edge(t[i], t[j], c, ei, ej) &&
           flips_.try_remove_edge_for_quality(typename Tr::Edge(c, ei, ej), penalty_))
          return true;
      }
    return false;
  }

  // peels `c` if it has two (three) surface facets of one patch and its others are faithful
  bool peel(const Cell_handle& c)
  {
    int surface = -1;
    for(int i = 0; i < 4; ++i)
      if(c3t3_.is_in_complex(c, i)) surface = i;
    if(surface < 0) return false;
    const auto patch = c3t3_.surface_patch_index(c, surface);
    return flips_.try_peel_boundary_cell(c, [&](const typename Tr::Facet& f, const typename Tr::Facet& g) {
      return smoother_.is_faithful(f, patch) && smoother_.is_faithful(g, patch) && smoother_.keeps_corners_near({f, g});
    });
  }

  // moves the vertex of `r`, whose star has a cell under the bound, up the gradient of
  // its star's smallest angle if that is critical, else down the gradient of its star's
  // penalty; true if that raised the one or lowered the other
  bool lift(const Ring& r) const
  {
    const Eigen::Vector3d x0 = energy_.position(r.v);
    const Star_angles a0 = star_angles(r, x0);
    const double q0 = a0.worst;
    if(!(q0 < bound_)) return false;
    const bool critical = penalty_.is_critical(q0);
    const auto score = [&](const Star_angles& a) { return critical ? a.worst : -a.penalty; };
    const double s0 = score(a0);
    const double least_gain = critical ? 1e-3 : -Angle_penalty::min_relative_gain * s0;
    Eigen::Vector3d d;
    if(critical ? !max_min_direction(r, x0, q0, d)
                : !ascent_direction(r, x0, [&](const Eigen::Vector3d& x) { return score(star_angles(r, x)); }, d))
      return false;
    double alpha = 0.2 * r.max_neighbor_distance;
    if(critical && shortest_moves_)
      return lift_critical(r, x0, q0 + least_gain, d, alpha, true) ||
             lift_critical(r, x0, q0 + least_gain, d, alpha, false);
    const bool fair_trade = !critical && !(q0 < bound_ - free_trade_margin);
    for(int k = 0; k < max_backtracking_steps; ++k, alpha *= 0.5) {
      Bare_point p;
      if(!smoother_.candidate(r, x0 + alpha * d, p) || !smoother_.is_valid_position(r, p)) continue;
      const Eigen::Vector3d x = Energy::to_eigen(p);
      const Star_angles a = star_angles(r, x);
      // a sum of penalties may trade several poor cells for one worse: never below the star's
      // worst, and near the bound, no more cells under the bound + 10 than it lifts over the bound
      if(score(a) > s0 + least_gain && (critical || a.worst >= q0) &&
         (!fair_trade || a.under_guard + a.under_bound <= a0.under_guard + a0.under_bound) &&
         smoother_.keeps_boundary_faithful(r, p)) {
        smoother_.move(r.v, p);
        return true;
      }
    }
    return false;
  }

  // the max-min move of the vertex of `r` along `d` (steps `alpha`, `alpha`/2, ...) with
  // `shortest_moves`: the shortest step that takes its star's smallest angle to the bound, else
  // the step that raises it most, to at least `least`; if `guarded`, never one that puts more
  // of the star's cells under the bound + `guard_margin`. The first step that raised it at all
  // moved the vertices of lattice meshes further off the lattice than needed, and pushed their
  // neighbours under 40 degrees
  bool lift_critical(const Ring& r, const Eigen::Vector3d& x0, double least, const Eigen::Vector3d& d,
                     double alpha, bool guarded) const
  {
    const std::size_t under = star_angles(r, x0).under_guard;
    double best = least;
    Bare_point best_p;
    bool found = false;
    for(int k = 0; k < max_backtracking_steps; ++k, alpha *= 0.5) {
      Bare_point p;
      if(!smoother_.candidate(r, x0 + alpha * d, p) || !smoother_.is_valid_position(r, p)) continue;
      const Star_angles a = star_angles(r, Energy::to_eigen(p));
      if(guarded && a.under_guard > under) continue;
      const double q = a.worst;
      // a step that reaches the bound replaces any longer one; a step that does not is taken
      // only while none has reached it, and if it lifts the star more
      if(q < bound_ && (q < best || (found && best >= bound_))) continue;
      if(!smoother_.keeps_boundary_faithful(r, p)) continue;
      best = q;
      best_p = p;
      found = true;
    }
    if(found) smoother_.move(r.v, best_p);
    return found;
  }

  C3T3& c3t3_;
  Tr& tr_;
  const Energy& energy_;
  const Smoother& smoother_;
  Energy_guided_flips<C3T3>& flips_;
  Edge_split<C3T3>& splits_;
  Surface_edge_split<C3T3, MeshDomain>& surface_splits_;
  Vertex_collapse<C3T3>& collapses_;
  Surface_vertex_collapse<C3T3, MeshDomain>& surface_collapses_;
  double bound_;
  Angle_penalty penalty_;
  bool do_split_;
  bool boundary_fixed_;
  bool shortest_moves_;
  bool surface_coarsened_ = false; // the first pass's surface collapses are done
  std::size_t split_budget_;
  std::size_t removal_budget_;
  std::size_t fewest_vertices_; // surface vertex removals stop there
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SLIVER_POLISHER_H
