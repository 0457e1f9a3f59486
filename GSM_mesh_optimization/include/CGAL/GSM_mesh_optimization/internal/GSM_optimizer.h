// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The GSM optimization loop (dissertation Alg. 1, after the initial mesh):
// rounds of vertex smoothing, worst vertices first, and energy-guided flips,
// until convergence, the round limit or the time limit.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_GSM_OPTIMIZER_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_GSM_OPTIMIZER_H

#include <CGAL/GSM_mesh_optimization/internal/Energy_guided_flips.h>
#include <CGAL/GSM_mesh_optimization/internal/Mesh_energy.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_smoother.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {

/*!
 * \ingroup PkgGSMMeshOptimizationRef
 * What `gsm_optimize_mesh_3()` reports to its visitor after each round.
 */
struct Round_report
{
  int round = 0;              ///< 1 for the first round
  double energy = 0;          ///< mean energy of the cells in the complex (eq. 3.9)
  double min_dihedral_angle = 0; ///< degrees, over the cells in the complex
  std::size_t number_of_moves = 0; ///< vertices moved in this round
  std::size_t number_of_flips = 0; ///< flips done in this round
  double elapsed_time = 0;   ///< seconds since the start
};

namespace internal {

struct GSM_options
{
  int max_rounds = 50;
  double time_limit = 0; // seconds; 0: none
  double convergence = 1e-4;
  bool do_flip = true;
  bool freeze_boundary = false;
  bool verbose = false;
  Shape_matching_energy energy = Shape_matching_energy::GSM;
  std::function<void(const Round_report&)> visitor;
};

template <class C3T3, class MeshDomain>
class GSM_optimizer
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef Vertex_smoother<C3T3, MeshDomain> Smoother;
  typedef typename Smoother::Ring Ring;

public:
  GSM_optimizer(C3T3& c3t3, const MeshDomain* domain, const Metric_field& metric,
                const GSM_options& options)
    : c3t3_(c3t3), options_(options), energy_(c3t3, metric, options.energy),
      smoother_(c3t3, domain, energy_, options.freeze_boundary)
  {}

  Mesh_optimization_return_code operator()()
  {
    CGAL::Real_timer timer;
    timer.start();
    std::pair<double, std::size_t> total = energy_.total();
    double sum = total.first;
    std::size_t count = total.second;
    Energy_guided_flips<C3T3> flips(c3t3_, energy_, sum, count);
    double previous_mean = sum / double(count);
    if(options_.verbose)
      std::cerr << "GSM: " << count << " cells, mean energy " << previous_mean << "\n";

    for(int round = 1; round <= options_.max_rounds; ++round) {
      Round_report report;
      report.round = round;
      report.number_of_moves = smoothing_pass(sum, timer);
      if(options_.do_flip && !time_is_up(timer))
        for(int pass = 0; pass < max_flip_passes; ++pass) {
          const std::size_t n = flips.flip_pass().total();
          report.number_of_flips += n;
          if(n == 0 || time_is_up(timer)) break;
        }
      // recompute exactly: the running sum only guides the flips
      total = energy_.total();
      sum = total.first;
      count = total.second;
      report.energy = sum / double(count);
      report.elapsed_time = timer.time();
      if(options_.visitor || options_.verbose)
        report.min_dihedral_angle = mesh_quality_statistics(c3t3_).min_dihedral_angle;
      if(options_.verbose)
        std::cerr << "GSM round " << round << ": mean energy " << report.energy << ", min dihedral "
                  << report.min_dihedral_angle << ", " << report.number_of_moves << " moves, "
                  << report.number_of_flips << " flips, " << report.elapsed_time << " s\n";
      if(options_.visitor) options_.visitor(report);

      if(time_is_up(timer)) return TIME_LIMIT_REACHED;
      const double decrease = (previous_mean - report.energy) / previous_mean;
      previous_mean = report.energy;
      if(report.number_of_moves == 0 && report.number_of_flips == 0) return CANT_IMPROVE_ANYMORE;
      if(decrease < options_.convergence) return CONVERGENCE_REACHED;
    }
    return MAX_ITERATION_NUMBER_REACHED;
  }

private:
  static constexpr int max_flip_passes = 5;

  bool time_is_up(const CGAL::Real_timer& timer) const
  {
    return options_.time_limit > 0 && timer.time() >= options_.time_limit;
  }

  // every movable vertex once, those with the largest Newton step first
  std::size_t smoothing_pass(double& sum, const CGAL::Real_timer& timer)
  {
    std::vector<std::pair<double, Vertex_handle>> order;
    Ring ring;
    for(Vertex_handle v : c3t3_.triangulation().finite_vertex_handles()) {
      if(!smoother_.is_movable(v) || !smoother_.make_ring(v, ring)) continue;
      bool is_descent;
      const double step = smoother_.newton_step(ring, is_descent).norm();
      if(step > min_relative_step * ring.max_neighbor_distance) order.emplace_back(step, v);
    }
    std::sort(order.begin(), order.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    std::size_t moves = 0;
    for(std::size_t k = 0; k < order.size(); ++k) {
      if((k & 255) == 0 && time_is_up(timer)) break;
      if(!smoother_.make_ring(order[k].second, ring)) continue;
      if(smoother_.smooth(ring)) {
        ++moves;
        sum += smoother_.last_energy_change();
      }
    }
    return moves;
  }

  static constexpr double min_relative_step = 1e-4;

  C3T3& c3t3_;
  GSM_options options_;
  Mesh_energy<C3T3> energy_;
  Smoother smoother_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_GSM_OPTIMIZER_H
