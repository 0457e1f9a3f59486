// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The part of compare_optimizers that does not depend on the domain type:
// the initial mesh at a target vertex count, the chains, and the reports.

#ifndef VVM_BENCHMARK_COMPARISON_DRIVER_H
#define VVM_BENCHMARK_COMPARISON_DRIVER_H

#include "compare_optimizers.h"
#include "dihedral_histogram_svg.h"

#include <CGAL/GSM_mesh_optimization/IO/write_VTU_with_quality.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

// make_mesh_3.h first: with CGAL_LINKED_WITH_TBB, CGAL 5.5.1's optimizer headers
// rely on TBB headers that only the mesher includes.
#include <CGAL/make_mesh_3.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/gsm_optimize_mesh_3.h>
#include <CGAL/lloyd_optimize_mesh_3.h>
#include <CGAL/odt_optimize_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace vvm_benchmark {

namespace GSM = CGAL::GSM_mesh_optimization;

inline const char* return_code_name(CGAL::Mesh_optimization_return_code c)
{
  switch(c) {
  case CGAL::BOUND_REACHED: return "BOUND_REACHED";
  case CGAL::TIME_LIMIT_REACHED: return "TIME_LIMIT_REACHED";
  case CGAL::CANT_IMPROVE_ANYMORE: return "CANT_IMPROVE_ANYMORE";
  case CGAL::CONVERGENCE_REACHED: return "CONVERGENCE_REACHED";
  case CGAL::MAX_ITERATION_NUMBER_REACHED: return "MAX_ITERATION_NUMBER_REACHED";
  case CGAL::ALL_VERTICES_FROZEN: return "ALL_VERTICES_FROZEN";
  default: return "UNKNOWN";
  }
}

// "odt+perturb+exude" -> {"odt", "perturb", "exude"}; "init" -> {}
inline std::vector<std::string> chain_steps(const std::string& chain)
{
  static const std::vector<std::string> known{"lloyd", "odt", "perturb", "exude", "gsm", "gsm-esm"};
  std::vector<std::string> steps;
  if(chain == "init") return steps;
  std::stringstream ss(chain);
  for(std::string step; std::getline(ss, step, '+');) {
    if(std::find(known.begin(), known.end(), step) == known.end())
      throw Input_error("unknown optimizer '" + step + "' in chain '" + chain +
                        "' (known: init, lloyd, odt, perturb, exude, gsm, gsm-esm, joined by '+')");
    steps.push_back(step);
  }
  if(steps.empty()) throw Input_error("empty chain");
  return steps;
}

struct Chain_result
{
  std::string chain;
  GSM::Mesh_quality_statistics quality;
  double opt_time_s = 0; // median over the repeats
  std::string return_codes;
};

template <class C3T3, class MeshDomain>
class Comparison_driver
{
  typedef typename C3T3::Triangulation Tr;
  typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;

public:
  Comparison_driver(const Options& options, const std::string& model, const MeshDomain& domain,
                    double domain_volume)
    : options_(options), model_(model), domain_(domain), domain_volume_(domain_volume)
  {}

  int run()
  {
    for(const std::string& chain : options_.chains) chain_steps(chain); // validate first
    make_initial_mesh();
    std::vector<Chain_result> results;
    for(const std::string& chain : options_.chains) {
      results.push_back(run_chain(chain));
      if(!options_.json_file.empty()) write_json(results.back());
    }
    print_table(results);
    return 0;
  }

private:
  // Uniform sizing: edge, facet and cell sizes all equal to s, searched so that
  // the number of vertices is within 10% of the target.
  C3T3 mesh_with_size(double s) const
  {
    namespace params = CGAL::parameters;
    Mesh_criteria criteria(params::edge_size = s, params::facet_angle = 25, params::facet_size = s,
                           params::facet_distance = s / 10., params::cell_radius_edge_ratio = 3,
                           params::cell_size = s);
    CGAL::get_default_random() = CGAL::Random(options_.seed);
    return CGAL::make_mesh_3<C3T3>(domain_, criteria, params::no_perturb(), params::no_exude());
  }

  void make_initial_mesh()
  {
    const double target = double(options_.target_vertices);
    double s = std::cbrt(domain_volume_ / (0.2 * target)); // first guess, corrected below
    double prev_s = 0, prev_n = 0, best_error = 1e300;
    for(int attempt = 0; attempt < 8; ++attempt) {
      CGAL::Real_timer timer;
      timer.start();
      C3T3 c3t3 = mesh_with_size(s);
      timer.stop();
      const double n = double(GSM::mesh_quality_statistics(c3t3).number_of_vertices);
      std::cerr << "  make_mesh_3 size " << s << ": " << n << " vertices (" << timer.time()
                << " s)\n";
      if(n == 0)
        throw Input_error("make_mesh_3 produced an empty mesh for '" + model_ + "'");
      const double error = std::abs(n - target) / target;
      if(error < best_error) {
        best_error = error;
        initial_ = std::move(c3t3);
        edge_size_ = s;
        mesh_time_s_ = timer.time();
      }
      if(error <= 0.05) break;
      // n ~ s^-alpha; alpha from the last two meshes (between surface- and volume-dominated)
      double alpha = 3;
      if(prev_n > 0 && prev_s != s && prev_n != n)
        alpha = std::clamp(-std::log(n / prev_n) / std::log(s / prev_s), 1.5, 3.5);
      prev_s = s;
      prev_n = n;
      s *= std::pow(n / target, 1. / alpha);
    }
    if(best_error > 0.1)
      std::cerr << "warning: the initial mesh is " << 100 * best_error
                << "% away from the requested number of vertices\n";
  }

  Chain_result run_chain(const std::string& chain)
  {
    namespace params = CGAL::parameters;
    const std::vector<std::string> steps = chain_steps(chain);
    Chain_result result;
    result.chain = chain;
    std::vector<double> times;
    C3T3 c3t3;
    for(int r = 0; r < (std::max)(1, options_.repeat); ++r) {
      c3t3 = initial_;
      std::string codes;
      CGAL::Real_timer timer;
      timer.start();
      for(const std::string& step : steps) {
        CGAL::get_default_random() = CGAL::Random(options_.seed);
        CGAL::Mesh_optimization_return_code code;
        if(step == "lloyd")
          code = CGAL::lloyd_optimize_mesh_3(c3t3, domain_);
        else if(step == "odt")
          code = CGAL::odt_optimize_mesh_3(c3t3, domain_);
        else if(step == "gsm" || step == "gsm-esm")
          code = CGAL::gsm_optimize_mesh_3(
              c3t3, domain_,
              GSM::parameters::energy(step == "gsm" ? GSM::Shape_matching_energy::GSM
                                                    : GSM::Shape_matching_energy::ESM,
                                      CGAL::parameters::verbose(options_.verbose)));
        else if(step == "perturb")
          code = CGAL::perturb_mesh_3(c3t3, domain_, params::sliver_bound = 0);
        else
          code = CGAL::exude_mesh_3(c3t3, params::sliver_bound = 0);
        codes += (codes.empty() ? "" : ",") + step + ":" + return_code_name(code);
      }
      timer.stop();
      times.push_back(timer.time());
      result.return_codes = codes;
    }
    std::sort(times.begin(), times.end());
    result.opt_time_s = times.size() % 2 ? times[times.size() / 2]
                                         : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
    result.quality = GSM::mesh_quality_statistics(c3t3);
    if(!options_.out_dir.empty()) write_outputs(c3t3, result);
    return result;
  }

  std::string out_path(const std::string& chain, const std::string& extension) const
  {
    return options_.out_dir + "/" + model_ + "_" + chain + extension;
  }

  void write_outputs(const C3T3& c3t3, const Chain_result& result) const
  {
    std::ofstream medit(out_path(result.chain, ".mesh"));
    CGAL::IO::output_to_medit(medit, c3t3, false /*rebind*/, true /*show_patches*/);
    std::ofstream vtu(out_path(result.chain, ".vtu"), std::ios::binary);
    GSM::IO::write_VTU_with_quality(vtu, c3t3);
    std::ofstream svg(out_path(result.chain, ".svg"));
    write_dihedral_histogram_svg(svg, model_ + " / " + result.chain, result.quality);
    if(!medit || !vtu || !svg)
      throw std::runtime_error("cannot write into '" + options_.out_dir + "'");
  }

  void write_json(const Chain_result& r) const
  {
    std::ofstream os(options_.json_file, first_json_line_ ? std::ios::trunc : std::ios::app);
    first_json_line_ = false;
    const GSM::Mesh_quality_statistics& q = r.quality;
    os.precision(17);
    os << "{\"model\": \"" << model_ << "\", \"chain\": \"" << r.chain
       << "\", \"n_vertices\": " << q.number_of_vertices << ", \"n_tets\": " << q.number_of_cells
       << ", \"theta_min\": " << q.min_dihedral_angle << ", \"theta_max\": " << q.max_dihedral_angle
       << ", \"mean_min_dihedral\": " << q.mean_min_dihedral_angle;
    for(std::size_t i = 0; i < q.n_min_dihedral_below.size(); ++i)
      os << ", \"n_min_dih_lt" << int(q.dihedral_thresholds[i]) << "\": " << q.n_min_dihedral_below[i];
    os << ", \"gamma_min\": " << q.min_radius_ratio << ", \"gamma_mean\": " << q.mean_radius_ratio
       << ", \"n_inverted\": " << q.number_of_inverted_cells << ", \"opt_time_s\": " << r.opt_time_s
       << ", \"repeat\": " << (std::max)(1, options_.repeat) << ", \"threads\": " << options_.threads
       << ", \"edge_size\": " << edge_size_ << ", \"mesh_time_s\": " << mesh_time_s_
       << ", \"return_codes\": \"" << r.return_codes << "\"}\n";
    if(!os) throw std::runtime_error("cannot write '" + options_.json_file + "'");
  }

  void print_table(const std::vector<Chain_result>& results) const
  {
    double perturb_exude_time = 0;
    for(const Chain_result& r : results)
      if(r.chain == "perturb+exude") perturb_exude_time = r.opt_time_s;
    std::printf("\nmodel %s: initial make_mesh_3 mesh, uniform size %.4g, %.2f s; "
                "optimizer times are medians of %d run(s)\n",
                model_.c_str(), edge_size_, mesh_time_s_, (std::max)(1, options_.repeat));
    std::printf("%-22s %7s %7s %7s %7s %7s %6s %6s %6s %6s %6s %6s %4s %9s %7s\n", "chain", "verts",
                "tets", "th_min", "th_max", "mean_mn", "<10", "<20", "<30", "<40", "g_min",
                "g_mean", "inv", "opt_s", "/p+e");
    for(const Chain_result& r : results) {
      const GSM::Mesh_quality_statistics& q = r.quality;
      char ratio[32] = "-";
      if(perturb_exude_time > 0)
        std::snprintf(ratio, sizeof ratio, "%.2f", r.opt_time_s / perturb_exude_time);
      std::printf("%-22s %7zu %7zu %7.2f %7.2f %7.2f %6zu %6zu %6zu %6zu %6.3f %6.3f %4zu %9.3f %7s\n",
                  r.chain.c_str(), q.number_of_vertices, q.number_of_cells, q.min_dihedral_angle,
                  q.max_dihedral_angle, q.mean_min_dihedral_angle, q.n_min_dihedral_below[0],
                  q.n_min_dihedral_below[1], q.n_min_dihedral_below[2], q.n_min_dihedral_below[3],
                  q.min_radius_ratio, q.mean_radius_ratio, q.number_of_inverted_cells, r.opt_time_s,
                  ratio);
    }
    std::fflush(stdout);
  }

  const Options& options_;
  std::string model_;
  const MeshDomain& domain_;
  double domain_volume_;
  C3T3 initial_;
  double edge_size_ = 0;
  double mesh_time_s_ = 0;
  mutable bool first_json_line_ = true;
};

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_COMPARISON_DRIVER_H
