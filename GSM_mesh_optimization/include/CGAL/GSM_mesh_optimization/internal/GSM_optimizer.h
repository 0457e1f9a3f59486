// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The GSM optimization loop (dissertation Alg. 1, after the initial mesh):
// rounds of vertex smoothing, worst vertices first, and energy-guided flips,
// until convergence, the round limit or the time limit; then the polishing of
// the cells still under the sliver bound (Sliver_polisher.h).

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_GSM_OPTIMIZER_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_GSM_OPTIMIZER_H

#include <CGAL/GSM_mesh_optimization/internal/Sliver_polisher.h>
#include <CGAL/GSM_mesh_optimization/internal/Energy_guided_flips.h>
#include <CGAL/GSM_mesh_optimization/internal/Mesh_energy.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_smoother.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/VVM/internal/Parallel_for.h>
#include <CGAL/VVM/internal/Stopping.h>

#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <boost/range/iterator_range.hpp>


#include <algorithm>
#include <array>
#include <functional>
#include <iostream>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {

/*!
 * \ingroup PkgGSMMeshOptimizationRef
 * What `gsm_optimize_mesh_3()` reports to its visitor after each round; `stage` is
 * `VVM::Stage::OPTIMIZATION` or, for the polishing passes, `VVM::Stage::POLISHING`.
 */
struct Round_report : VVM::Stage_report
{
  double energy = 0;          ///< mean energy of the cells in the complex (eq. 3.9)
  double min_dihedral_angle = 0; ///< degrees, over the cells in the complex
  /// cells in the complex whose smallest dihedral angle, in the metric, is under the
  /// sliver bound (30 degrees if the bound is 0)
  std::size_t number_of_cells_under_bound = 0;
  std::size_t number_of_moves = 0; ///< vertices moved in this round
  std::size_t number_of_flips = 0; ///< flips done in this round (in polishing: edge removals and boundary peels)
  std::size_t number_of_splits = 0; ///< edges split in this round (new vertices)
  std::size_t number_of_removals = 0; ///< vertices removed in this round
  /// a round of the final polishing, which lifts the worst cells and may raise the energy
  bool is_polishing = false;
};

namespace internal {

using VVM::internal::Index_range;
using VVM::internal::parallel_for_ranges;

/// the named parameters of `gsm_optimize_mesh_3()`, each field named as its parameter
struct GSM_options
{
  int number_of_iterations = 50;
  double maximum_running_time = 0; // seconds; 0: none
  double convergence_threshold = 1e-4;
  bool do_flip = true;
  bool smooth_vertices = true;
  double sliver_bound = 30; // degrees; 0: no polishing
  bool split_edges = true;
  bool shortest_polishing_moves = false; // the polishing's max-min moves: the shortest step to the bound
  double mean_angle_threshold = 0;  // degrees: after the polishing, the stars with a cell under it raise their sum
  bool freeze_boundary = false;
  double boundary_distance = 0; // the least bound of the boundary-fidelity guard
  bool verbose = false;
  Shape_matching_energy energy = Shape_matching_energy::GSM;
  std::function<bool(const Round_report&)> visitor; // false: stop
};

template <class C3T3, class MeshDomain>
class GSM_optimizer
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef Vertex_smoother<C3T3, MeshDomain> Smoother;
  typedef typename Smoother::Ring Ring;

public:
  /// cells measured by `metric`, or by `metric`'s scale over the mean size of their
  /// vertices if `sizing` is given
  GSM_optimizer(C3T3& c3t3, const MeshDomain* domain, const Metric_field& metric,
                const GSM_options& options, std::shared_ptr<Vertex_sizes<Tr>> sizing = nullptr)
    : c3t3_(c3t3), options_(options), energy_(c3t3, metric, options.energy, std::move(sizing)),
      smoother_(c3t3, domain, energy_, options.freeze_boundary, options.boundary_distance)
  {}

  /// what a vertex at a position costs the mean-angle moves, in degrees
  void set_move_cost(std::function<double(const Vertex_handle&, const Eigen::Vector3d&)> cost)
  {
    smoother_.set_move_cost(std::move(cost));
  }

  Mesh_optimization_return_code operator()()
  {
    CGAL::Real_timer timer;
    timer.start();
    std::pair<double, std::size_t> total = energy_.total();
    double sum = total.first;
    std::size_t count = total.second;
    Energy_guided_flips<C3T3> flips(c3t3_, energy_, sum, count);
    flips.set_boundary_fixed(options_.freeze_boundary);
    double previous_mean = sum / double(count);
    if(options_.verbose)
      std::cerr << "GSM: " << count << " cells, mean energy " << previous_mean << "\n";

    Mesh_optimization_return_code result = MAX_ITERATION_NUMBER_REACHED;
    // the rounds stop once the worst cells gain less than 0.05 degree and the cells under the
    // bound drop by less than a 20th, two rounds in a row: later rounds barely move them, and
    // the polishing lifts the last ones for a fraction of a round's time. With a polishing, a
    // round that raises the worst cells but leaves more cells under the bound than the best
    // earlier round did is no progress either: the polishing lifts the worst ones anyway
    Worst_cells_progress progress(energy_, bound(), round_angle_gain, round_count_share, options_.sliver_bound > 0);
    int round = 1;
    for(; round <= options_.number_of_iterations; ++round) {
      Round_report report;
      report.round = round;
      const double smoothing_start = timer.time();
      if(options_.smooth_vertices) report.number_of_moves = smoothing_pass(sum, timer);
      const double flips_start = timer.time();
      if(options_.do_flip && !time_is_up(timer)) {
        // after the first pass, only where the last one changed cells
        std::vector<Vertex_handle> changed, around;
        for(int pass = 0; pass < max_flip_passes; ++pass) {
          around.swap(changed);
          changed.clear();
          const std::size_t n = flips.flip_pass(pass == 0 ? nullptr : &around, &changed).total();
          report.number_of_flips += n;
          if(n == 0 || time_is_up(timer)) break;
        }
      }
      // recompute exactly: the running sum only guides the flips
      const auto summary = energy_.summary(bound());
      sum = summary.total.first;
      count = summary.total.second;
      report.energy = sum / double(count);
      report.elapsed_time = timer.time();
      notify(report, flips_start - smoothing_start, report.elapsed_time - flips_start);

      if(time_is_up(timer)) return stop_code();
      const double decrease = (previous_mean - report.energy) / previous_mean;
      previous_mean = report.energy;
      if(report.number_of_moves == 0 && report.number_of_flips == 0) {
        result = CANT_IMPROVE_ANYMORE;
        break;
      }
      // the mean energy can creep down for dozens of rounds while the worst cells stay as
      // they are or get worse (a graded or thin-walled mesh): those rounds buy nothing
      if(decrease < options_.convergence_threshold || progress.stalled(summary.worst_and_count_under)) {
        result = CONVERGENCE_REACHED;
        break;
      }
    }
    if(options_.sliver_bound > 0) polish((std::min)(round, options_.number_of_iterations), flips, sum, count, timer);
    return time_is_up(timer) ? stop_code() : result;
  }

private:
  static constexpr int max_flip_passes = 5;
  static constexpr int max_polishing_passes = 20;
  static constexpr int max_mean_passes = 10;
  static constexpr int max_stalled_passes = 2;
  // what counts as progress of the worst cells (see `Worst_cells_progress`) in the rounds
  // and in the polishing: the polishing's passes cost more and, on meshes that cannot
  // reach the bound, raise the smallest angle by a tenth of a degree a pass while pushing
  // more cells under the bound
  static constexpr double round_angle_gain = 0.05; // degrees
  static constexpr double round_count_share = 1. / 20;
  static constexpr double polishing_angle_gain = 0.5; // degrees
  static constexpr double polishing_count_share = 1. / 50;

  static constexpr double default_bound = 30; // degrees, for the stop rule when there is no polishing

  // Whether the worst cells have stopped improving: `stalled()` is true after
  // `max_stalled_passes` calls in a row that neither raise the smallest angle by
  // `angle_gain` degrees nor lower the number of cells under the bound by `count_share`
  // of the best count so far. With `count_must_not_rise`, a call that leaves more cells
  // under the bound than the best of the earlier calls does not count as progress, whatever
  // the angle (the first call is measured against the start only: a first round can put more
  // cells under the bound while it lifts the flattest).
  class Worst_cells_progress
  {
  public:
    Worst_cells_progress(const Mesh_energy<C3T3>& energy, double bound, double angle_gain, double count_share,
                         bool count_must_not_rise = false)
      : angle_gain_(angle_gain), count_share_(count_share), count_must_not_rise_(count_must_not_rise),
        best_(energy.worst_and_count_under(bound))
    {}

    /// `now`: the mesh's `worst_and_count_under(bound)`
    bool stalled(const std::pair<double, std::size_t>& now)
    {
      const bool rose = count_must_not_rise_ && calls_ > 0 && now.second > best_called_count_;
      const bool better = (now.first > best_.first + angle_gain_ && !rose) ||
                          double(best_.second - (std::min)(best_.second, now.second)) > count_share_ * double(best_.second);
      best_ = {(std::max)(best_.first, now.first), (std::min)(best_.second, now.second)};
      best_called_count_ = calls_++ > 0 ? (std::min)(best_called_count_, now.second) : now.second;
      stalled_ = better ? 0 : stalled_ + 1;
      return stalled_ >= max_stalled_passes;
    }

  private:
    double angle_gain_, count_share_;
    bool count_must_not_rise_;
    std::pair<double, std::size_t> best_;
    std::size_t best_called_count_ = 0; // the least count under the bound over the calls
    int calls_ = 0;
    int stalled_ = 0;
  };

  // rounds of the final stage, numbered on from the last round `round`, until one changes
  // nothing or the worst cells stop improving (on a mesh that cannot reach the bound, such
  // as a steeply graded one, passes go on moving vertices back and forth for nothing); then,
  // if asked for, passes of mean-angle moves until one moves nothing
  void polish(int round, Energy_guided_flips<C3T3>& flips, double& sum, std::size_t& count,
              const CGAL::Real_timer& timer)
  {
    Edge_split<C3T3> splits(c3t3_, energy_, sum, count, Angle_penalty::for_bound(options_.sliver_bound));
    Surface_edge_split<C3T3, MeshDomain> surface_splits(c3t3_, energy_, sum, count, smoother_,
                                                        Angle_penalty::for_bound(options_.sliver_bound));
    Vertex_collapse<C3T3> collapses(c3t3_, energy_, sum, count);
    Surface_vertex_collapse<C3T3, MeshDomain> surface_collapses(c3t3_, energy_, sum, count, smoother_,
                                                                Angle_penalty::for_bound(options_.sliver_bound));
    Sliver_polisher<C3T3, MeshDomain> polisher(c3t3_, energy_, smoother_, flips, splits, surface_splits, collapses,
                                               surface_collapses,
                                               options_.sliver_bound,
                                               options_.split_edges, options_.freeze_boundary,
                                               options_.shortest_polishing_moves);
    Worst_cells_progress progress(energy_, options_.sliver_bound, polishing_angle_gain, polishing_count_share);
    for(int pass = 0; pass < max_polishing_passes && !time_is_up(timer); ++pass) {
      const double start = timer.time();
      const auto done = polisher.polish_pass([&]() { return time_is_up(timer); });
      Round_report report;
      report.round = ++round;
      report.is_polishing = true;
      report.number_of_moves = done.moves;
      report.number_of_splits = done.splits;
      report.number_of_removals = done.removals;
      report.number_of_flips = done.flips + done.peels;
      const auto now = notify_polishing(report, start, sum, count, timer);
      if(done.moves == 0 && done.flips == 0 && done.peels == 0 && done.splits == 0 && done.removals == 0) break;
      if(progress.stalled(now)) break;
    }
    // then the mean-angle moves, if asked for (see `Sliver_polisher::raise_mean_pass()`)
    for(int pass = 0; options_.mean_angle_threshold > 0 && pass < max_mean_passes && !time_is_up(timer); ++pass) {
      const double start = timer.time();
      Round_report report;
      report.round = ++round;
      report.is_polishing = true;
      report.number_of_moves =
          polisher.raise_mean_pass(options_.mean_angle_threshold, [&]() { return time_is_up(timer); });
      notify_polishing(report, start, sum, count, timer);
      if(report.number_of_moves == 0) break;
    }
  }

  // a polishing pass begun at `start` is over: the energy sums recomputed, the visitor told
  // returns the mesh's `worst_and_count_under()` the sliver bound
  std::pair<double, std::size_t> notify_polishing(Round_report& report, double start, double& sum,
                                                  std::size_t& count, const CGAL::Real_timer& timer) const
  {
    const auto summary = energy_.summary(options_.sliver_bound);
    sum = summary.total.first;
    count = summary.total.second;
    report.energy = sum / double(count);
    report.elapsed_time = timer.time();
    notify(report, report.elapsed_time - start, 0);
    return summary.worst_and_count_under;
  }

  void notify(Round_report& report, double smoothing_time, double flip_time) const
  {
    report.stage = report.is_polishing ? VVM::Stage::POLISHING : VVM::Stage::OPTIMIZATION;
    if(options_.visitor || options_.verbose) {
      report.min_dihedral_angle = mesh_quality_statistics(c3t3_).min_dihedral_angle;
      report.number_of_cells_under_bound = energy_.worst_and_count_under(bound()).second;
    }
    if(options_.verbose)
      std::cerr << "GSM " << (report.is_polishing ? "polishing" : "round") << " " << report.round
                << ": mean energy " << report.energy << ", min dihedral " << report.min_dihedral_angle << ", "
                << report.number_of_cells_under_bound << " cells under " << bound() << ", "
                << report.number_of_moves << " moves, " << report.number_of_flips << " flips, "
                << report.number_of_splits << " splits, " << report.number_of_removals << " removals, " << report.elapsed_time << " s (smoothing "
                << smoothing_time << " s, flips " << flip_time << " s)\n";
    if(options_.visitor && !options_.visitor(report)) stop_requested_ = true;
  }

  // the sliver bound, or the default one for the stop rule when there is no polishing
  double bound() const { return options_.sliver_bound > 0 ? options_.sliver_bound : default_bound; }

  // the time limit is reached or the visitor asked to stop
  bool time_is_up(const CGAL::Real_timer& timer) const
  {
    return stop_requested_ || (options_.maximum_running_time > 0 && timer.time() >= options_.maximum_running_time);
  }

  // a visitor's stop is a round limit of the caller's
  Mesh_optimization_return_code stop_code() const
  {
    return stop_requested_ ? MAX_ITERATION_NUMBER_REACHED : TIME_LIMIT_REACHED;
  }

  // Every movable vertex once, those with the largest Newton step first. The
  // vertices go in batches that TBB smooths in parallel: a batch takes, in that
  // order, each vertex that no vertex already in it reads or writes (a move
  // reads the one-ring, plus the hull vertices across the vertex's hull edges).
  std::size_t smoothing_pass(double& sum, const CGAL::Real_timer& timer)
  {
    Stars stars(c3t3_.triangulation());
    const std::size_t n = stars.vertices.size();
    std::vector<double> step(n, 0.);
    parallel_for_ranges(n, 1, [&](const Index_range& range) {
      Ring ring;
      for(std::size_t r = range.begin(); r != range.end(); ++r) {
        const std::size_t i = stars.along_curve[r];
        const Vertex_handle v = stars.vertices[i];
        if(!smoother_.is_movable(v) || !smoother_.make_ring(v, stars.cells(i), ring)) continue;
        bool is_descent;
        const double norm = smoother_.newton_step(ring, is_descent).norm();
        if(norm > min_relative_step * ring.max_neighbor_distance) step[i] = norm;
      }
    });
    std::vector<std::size_t> pending;
    for(std::size_t i = 0; i < n; ++i)
      if(step[i] > 0) pending.push_back(i);
    std::stable_sort(pending.begin(), pending.end(),
                     [&](std::size_t a, std::size_t b) { return step[a] > step[b]; });

    // what each move reads, once: the batches below scan the deferred vertices again and again
    std::vector<std::vector<std::size_t>> reads(n);
    parallel_for_ranges(n, 1, [&](const Index_range& range) {
      for(std::size_t r = range.begin(); r != range.end(); ++r) {
        const std::size_t i = stars.along_curve[r];
        if(step[i] > 0) stars.reads(i, reads[i]);
      }
    });

    std::vector<unsigned> written(n, 0), read(n, 0);
    std::vector<std::size_t> batch, deferred, visit;
    std::vector<char> moved;
    std::vector<double> change;
    std::size_t moves = 0;
    for(unsigned stamp = 1; !pending.empty() && !time_is_up(timer); ++stamp) {
      batch.clear();
      deferred.clear();
      for(std::size_t i : pending) {
        bool independent = read[i] != stamp;
        for(std::size_t j : reads[i]) independent = independent && written[j] != stamp;
        if(!independent) {
          deferred.push_back(i);
          continue;
        }
        batch.push_back(i);
        written[i] = stamp;
        for(std::size_t j : reads[i]) read[j] = stamp;
      }
      moved.assign(batch.size(), 0);
      change.assign(batch.size(), 0.);
      // the batch's moves are independent: they go along the curve, and their changes are
      // summed in the batch's order below
      visit.resize(batch.size());
      std::iota(visit.begin(), visit.end(), std::size_t(0));
      std::sort(visit.begin(), visit.end(),
                [&](std::size_t a, std::size_t b) { return stars.rank[batch[a]] < stars.rank[batch[b]]; });
      parallel_for_ranges(batch.size(), 16,
                        [&](const Index_range& range) {
        Ring ring;
        for(std::size_t r = range.begin(); r != range.end(); ++r) {
          const std::size_t k = visit[r];
          const std::size_t i = batch[k];
          if(smoother_.make_ring(stars.vertices[i], stars.cells(i), ring))
            moved[k] = smoother_.smooth(ring, change[k]);
        }
      });
      for(std::size_t k = 0; k < batch.size(); ++k)
        if(moved[k]) {
          ++moves;
          sum += change[k];
        }
      pending.swap(deferred);
    }
    return moves;
  }

  // The cells around each finite vertex, gathered in two passes over the cells, each vertex's
  // in the cells' order: the triangulation's own incident_cells() marks cells and cannot run
  // in parallel. One array for all the stars: a vector per vertex, allocated one by one,
  // took time growing faster than the mesh
  struct Stars
  {
    typedef typename Tr::Cell_handle Cell_handle;
    typedef typename Tr::Geom_traits::Point_3 Bare_point;
    std::vector<Vertex_handle> vertices;
    // the vertices along a Hilbert curve, and the place of each on it: sweeps in this order
    // find the cells and neighbors of the last vertices still in cache (make_mesh_3 leaves
    // the vertices in memory in the order of its refinement, scattered in space)
    std::vector<std::size_t> along_curve, rank;
    // CGAL's map of handles: one probe in a flat table where std::unordered_map takes two or
    // three scattered ones
    CGAL::Unique_hash_map<Vertex_handle, std::size_t> index;
    const Tr& tr;

    explicit Stars(const Tr& t) : index(std::size_t(-1), t.number_of_vertices()), tr(t)
    {
      vertices.reserve(tr.number_of_vertices());
      for(Vertex_handle v : tr.finite_vertex_handles()) {
        index[v] = vertices.size();
        vertices.push_back(v);
      }
      std::vector<std::size_t> owners; // the vertex of each cell's finite corners, in order
      owners.reserve(4 * tr.number_of_cells());
      first_.assign(vertices.size() + 1, 0);
      for(auto c : tr.all_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(!tr.is_infinite(c->vertex(i))) {
            owners.push_back(std::as_const(index)[c->vertex(i)]);
            ++first_[owners.back() + 1];
          }
      std::partial_sum(first_.begin(), first_.end(), first_.begin());
      cells_.resize(owners.size());
      std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
      std::size_t k = 0;
      for(auto c : tr.all_cell_handles())
        for(int i = 0; i < 4; ++i)
          if(!tr.is_infinite(c->vertex(i))) cells_[next[owners[k++]]++] = c;

      std::vector<Bare_point> points;
      points.reserve(vertices.size());
      const auto point = tr.geom_traits().construct_point_3_object();
      for(const Vertex_handle& v : vertices) points.push_back(point(tr.point(v)));
      along_curve.resize(vertices.size());
      std::iota(along_curve.begin(), along_curve.end(), std::size_t(0));
      typedef CGAL::Spatial_sort_traits_adapter_3<typename Tr::Geom_traits,
                                                  typename CGAL::Pointer_property_map<Bare_point>::const_type>
          Sort_traits;
      CGAL::hilbert_sort(along_curve.begin(), along_curve.end(),
                         Sort_traits(CGAL::make_property_map(std::as_const(points))));
      rank.resize(vertices.size());
      for(std::size_t r = 0; r < along_curve.size(); ++r) rank[along_curve[r]] = r;
    }

    /// the cells around vertex i
    boost::iterator_range<const Cell_handle*> cells(std::size_t i) const
    {
      return {cells_.data() + first_[i], cells_.data() + first_[i + 1]};
    }

    // the vertices a move of vertex i reads: its one-ring, and on the convex
    // hull the vertices across its hull edges (the convexity check)
    void reads(std::size_t i, std::vector<std::size_t>& out) const
    {
      out.clear();
      for(const auto& c : cells(i)) {
        const bool infinite = tr.is_infinite(c);
        for(int k = 0; k < 4; ++k) {
          const Vertex_handle w = c->vertex(k);
          if(!tr.is_infinite(w)) out.push_back(std::as_const(index)[w]);
          if(infinite && k != c->index(tr.infinite_vertex())) {
            const auto nb = c->neighbor(k);
            const Vertex_handle d = nb->vertex(nb->index(c));
            if(!tr.is_infinite(d)) out.push_back(std::as_const(index)[d]);
          }
        }
      }
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
    }

  private:
    std::vector<std::size_t> first_; // the cells around vertex i: cells_[first_[i]] to cells_[first_[i + 1] - 1]
    std::vector<Cell_handle> cells_;
  };

  static constexpr double min_relative_step = 1e-4;

  C3T3& c3t3_;
  mutable bool stop_requested_ = false; // by the visitor
  GSM_options options_;
  Mesh_energy<C3T3> energy_;
  Smoother smoother_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_GSM_OPTIMIZER_H
