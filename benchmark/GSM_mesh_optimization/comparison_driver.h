// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The part of compare_optimizers that does not depend on the domain type:
// the initial mesh at a target vertex count, the chains, and the reports.

#ifndef VVM_BENCHMARK_COMPARISON_DRIVER_H
#define VVM_BENCHMARK_COMPARISON_DRIVER_H

#include "boundary_layering.h"
#include "compare_optimizers.h"
#include "dihedral_histogram_svg.h"
#include "json_lines.h"
#include "mesh_3_optimizers.h"
#include "table.h"
#include "tetrahedral_remeshing_step.h"

#include <CGAL/GSM_mesh_optimization/IO/write_VTU_with_quality.h>
#include <CGAL/GSM_mesh_optimization/dissertation_metric_fields.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/GSM_mesh_optimization/mesh_with_vertex_count.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace vvm_benchmark {

namespace GSM = CGAL::GSM_mesh_optimization;

// "odt+perturb+exude" -> {"odt", "perturb", "exude"}; "init" -> {}
inline std::vector<std::string> chain_steps(const std::string& chain)
{
  static const std::vector<std::string> known{"lloyd", "odt", "perturb", "exude", "gsm", "gsm-esm", "gsm-uniform", "remesh"};
  std::vector<std::string> steps;
  if(chain == "init") return steps;
  for(const std::string& step : split(chain, '+')) {
    if(std::find(known.begin(), known.end(), step) == known.end())
      throw Input_error("unknown optimizer '" + step + "' in chain '" + chain +
                        "' (known: init, lloyd, odt, perturb, exude, gsm, gsm-esm, gsm-uniform, remesh, joined by '+')");
    // CGAL 5.5.1's Mesh_3 optimizers are not made for tetrahedral remeshing's output: lloyd
    // after remesh crashes in Mesh_global_optimizer::compute_move (fandisk at 3k vertices),
    // and remesh+perturb+exude on turbine at 10k
    if(step != "remesh" && step.compare(0, 3, "gsm") != 0 &&
       std::find(steps.begin(), steps.end(), "remesh") != steps.end())
      throw Input_error("chain '" + chain + "': only gsm can follow remesh (Mesh_3's " + step +
                        " can crash on the output of CGAL's tetrahedral remeshing)");
    steps.push_back(step);
  }
  if(steps.empty()) throw Input_error("empty chain");
  return steps;
}

// The target of --field: a sizing field or a metric (dissertation 3.4.4), or
// nothing (uniform isotropic meshing).
struct Target_field
{
  std::string name;
  std::function<double(const Eigen::Vector3d&)> sizing;
  std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> metric;
  // --sizing thickness: a sizing field made from the input, not a --field of the dissertation;
  // angles are measured in the mesh itself (an isotropic size does not change them)
  bool from_input = false;
  double typical_size = 1; // the size a field's scale factor is relative to

  /// --sizing NAME with the sizing field `size`, whose typical value is `typical`
  static Target_field input_sizing(const std::string& sizing_name,
                                   std::function<double(const Eigen::Vector3d&)> size, double typical)
  {
    Target_field f("");
    f.name = sizing_name;
    f.sizing = std::move(size);
    f.from_input = true;
    f.typical_size = typical;
    return f;
  }

  explicit Target_field(const std::string& field_name) : name(field_name)
  {
    namespace D = GSM::dissertation;
    if(name == "adaptive-sphere")
      sizing = D::adaptive_sphere_sizing;
    else if(name == "anisotropic-sphere")
      metric = D::anisotropic_sphere_metric;
    else if(name == "anisotropic-cube")
      metric = [](const Eigen::Vector3d& x) { return D::anisotropic_cube_metric(x); };
  }

  // isotropic edge length of the same density, for make_mesh_3
  double isotropic_size(const Eigen::Vector3d& x) const
  {
    if(sizing) return sizing(x);
    if(metric) return std::pow(metric(x).determinant(), -1. / 6.);
    return 1.;
  }

  // the map to the space where the target tetrahedron is regular: quality is measured there
  Eigen::Matrix3d B(const Eigen::Vector3d& x) const
  {
    if(sizing) return Eigen::Matrix3d::Identity() / sizing(x);
    if(metric) return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(metric(x)).operatorSqrt();
    return Eigen::Matrix3d::Identity();
  }
};

// make_mesh_3's sizing field for the cell, facet and edge size criteria
struct Scaled_isotropic_size
{
  double scale;
  const Target_field* field;
  template <class Point_3, class Index>
  double operator()(const Point_3& p, int, const Index&) const
  {
    return scale * field->isotropic_size(Eigen::Vector3d(p.x(), p.y(), p.z()));
  }
};

struct Chain_result
{
  std::string chain;
  GSM::Mesh_quality_statistics quality;
  double opt_time_s = 0; // median over the repeats
  std::string return_codes;
  double boundary_distance = -1; // Hausdorff distance to the input surface; < 0: not measured
  Boundary_layering layering;
};

template <class C3T3, class MeshDomain>
class Comparison_driver
{
  typedef typename C3T3::Triangulation Tr;
  typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;

public:
  Comparison_driver(const Options& options, const std::string& model, const MeshDomain& domain,
                    double domain_volume, Target_field input_sizing = Target_field(""))
    : options_(options), model_(model), domain_(domain), domain_volume_(domain_volume),
      field_(input_sizing.from_input ? std::move(input_sizing) : Target_field(options.field))
  {
    if(!field_.name.empty()) model_ += "_" + field_.name;
  }

  /// `distance(c3t3)`: the Hausdorff distance from its boundary to the input
  /// surface, reported for each chain against the initial mesh's (column hd/hd0)
  void set_boundary_distance(std::function<double(const C3T3&)> distance)
  {
    boundary_distance_ = std::move(distance);
  }

  int run()
  {
    for(const std::string& chain : options_.chains) chain_steps(chain); // validate first
    make_initial_mesh();
    if(boundary_distance_) initial_boundary_distance_ = boundary_distance_(initial_);
    std::vector<Chain_result> results;
    Json_lines_file json(options_.json_file, Json_lines_file::REPLACE);
    for(const std::string& chain : options_.chains) {
      results.push_back(run_chain(chain));
      json.write(json_line(results.back()));
    }
    print_table(results);
    return 0;
  }

private:
  // Uniform sizing: edge, facet and cell sizes all equal to s, searched so that
  // the number of vertices is within 10% of the target (with --graded: facet and
  // cell sizes 3 s, facet distance s / 100).
  // With --field, the sizes are s times the field's isotropic size (its density).
  C3T3 mesh_with_size(double s) const
  {
    namespace params = CGAL::parameters;
    CGAL::get_default_random() = CGAL::Random(options_.seed);
    if(field_.name.empty() && options_.graded) {
      // what a make_mesh_3 user gets from a tight facet_distance: fine where the surface
      // is curved, coarse elsewhere and inside
      Mesh_criteria criteria(params::edge_size = s, params::facet_angle = 25, params::facet_size = 3 * s,
                             params::facet_distance = s / 100., params::cell_radius_edge_ratio = 3,
                             params::cell_size = 3 * s);
      return CGAL::make_mesh_3<C3T3>(domain_, criteria, params::no_perturb(), params::no_exude());
    }
    if(field_.name.empty()) {
      Mesh_criteria criteria(params::edge_size = s, params::facet_angle = 25, params::facet_size = s,
                             params::facet_distance = s / 10., params::cell_radius_edge_ratio = 3,
                             params::cell_size = s);
      return CGAL::make_mesh_3<C3T3>(domain_, criteria, params::no_perturb(), params::no_exude());
    }
    const Scaled_isotropic_size size{s, &field_};
    if(field_.from_input) {
      // as the uniform sizing's criteria, the size s replaced by the field's size
      const Scaled_isotropic_size distance{0.1 * s, &field_};
      Mesh_criteria criteria(params::edge_size = size, params::facet_angle = 25, params::facet_size = size,
                             params::facet_distance = distance, params::cell_radius_edge_ratio = 3,
                             params::cell_size = size);
      return CGAL::make_mesh_3<C3T3>(domain_, criteria, params::no_perturb(), params::no_exude());
    }
    // the fields' isotropic sizes on the boundary are 0.1 s or more
    Mesh_criteria criteria(params::edge_size = size, params::facet_angle = 25, params::facet_size = size,
                           params::facet_distance = 0.01 * s, params::cell_radius_edge_ratio = 3,
                           params::cell_size = size);
    return CGAL::make_mesh_3<C3T3>(domain_, criteria, params::no_perturb(), params::no_exude());
  }

  GSM::Mesh_quality_statistics quality(const C3T3& c3t3) const
  {
    if(field_.name.empty() || field_.from_input) return GSM::mesh_quality_statistics(c3t3);
    return GSM::mesh_quality_statistics(c3t3, [this](const auto& p) {
      return field_.B(Eigen::Vector3d(p.x(), p.y(), p.z()));
    });
  }

  template <class NamedParameters>
  CGAL::Mesh_optimization_return_code run_gsm(C3T3& c3t3, const NamedParameters& np) const
  {
    if(field_.sizing)
      return CGAL::gsm_optimize_mesh_3(c3t3, domain_, GSM::parameters::sizing_field(field_.sizing, np));
    if(field_.metric)
      return CGAL::gsm_optimize_mesh_3(c3t3, domain_, GSM::parameters::metric_field(field_.metric, np));
    return CGAL::gsm_optimize_mesh_3(c3t3, domain_, np);
  }

  void make_initial_mesh()
  {
    const double first_size = std::cbrt(domain_volume_ / (0.2 * double(options_.target_vertices))) // corrected below
                              / (field_.from_input ? field_.typical_size
                                                   : field_.isotropic_size(Eigen::Vector3d::Zero()));
    GSM::Mesh_with_vertex_count_result<C3T3> r;
    try {
      r = GSM::mesh_with_vertex_count([this](double s) { return mesh_with_size(s); }, options_.target_vertices,
                                      first_size, 0.05, CGAL::parameters::verbose(true));
    } catch(const std::invalid_argument&) { // a mesh with no vertex
      throw Input_error("make_mesh_3 produced an empty mesh for '" + model_ + "'");
    }
    initial_ = std::move(r.c3t3);
    initial_layering_ = boundary_layering(initial_);
    edge_size_ = r.size;
    mesh_time_s_ = r.time_s;
    if(r.relative_error > 0.1)
      std::cerr << "warning: the initial mesh is " << 100 * r.relative_error
                << "% away from the requested number of vertices\n";
  }

  Chain_result run_chain(const std::string& chain)
  {
    const std::vector<std::string> steps = chain_steps(chain);
    Chain_result result;
    result.chain = chain;
    std::vector<double> times;
    C3T3 c3t3;
    // the remeshing's edge length is searched once, before the timer
    const double remeshing_length =
        std::find(steps.begin(), steps.end(), "remesh") != steps.end() ? remeshing_edge_length() : 0.;
    for(int r = 0; r < (std::max)(1, options_.repeat); ++r) {
      c3t3 = initial_;
      std::string codes;
      CGAL::Real_timer timer;
      timer.start();
      for(const std::string& step : steps) {
        CGAL::get_default_random() = CGAL::Random(options_.seed);
        CGAL::Mesh_optimization_return_code code;
        if(is_mesh_3_optimizer(step))
          code = run_mesh_3_optimizer(step, c3t3, domain_);
        else if(step == "gsm" || step == "gsm-esm" || step == "gsm-uniform")
          code = run_gsm(
              c3t3, GSM::parameters::uniform_sizing(step == "gsm-uniform",
                    GSM::parameters::energy(step == "gsm-esm" ? GSM::Shape_matching_energy::ESM
                                                              : GSM::Shape_matching_energy::GSM,
                                            CGAL::parameters::verbose(options_.verbose))));
        else if(step == "remesh") {
          tetrahedral_remeshing_step(c3t3, remeshing_length);
          code = CGAL::MAX_ITERATION_NUMBER_REACHED;
        }
        codes += (codes.empty() ? "" : ",") + step + ":" + return_code_name(code);
      }
      timer.stop();
      times.push_back(timer.time());
      result.return_codes = codes;
    }
    std::sort(times.begin(), times.end());
    result.opt_time_s = times.size() % 2 ? times[times.size() / 2]
                                         : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
    result.quality = quality(c3t3);
    result.layering = boundary_layering(c3t3);
    if(boundary_distance_) result.boundary_distance = boundary_distance_(c3t3);
    if(!options_.out_dir.empty()) write_outputs(c3t3, result);
    return result;
  }

  // the target edge length of `remesh` that keeps the initial mesh's vertex count within 10%:
  // the mean edge length, corrected by the cube root of the count ratio (untimed, once)
  double remeshing_edge_length()
  {
    if(remeshing_edge_length_ > 0) return remeshing_edge_length_;
    const double n0 = double(initial_.triangulation().number_of_vertices());
    double length = mean_edge_length(initial_);
    for(int attempt = 0; attempt < 4; ++attempt) {
      C3T3 trial = initial_;
      tetrahedral_remeshing_step(trial, length);
      const double ratio = double(trial.triangulation().number_of_vertices()) / n0;
      if(std::abs(ratio - 1) < 0.05) break;
      length *= std::cbrt(ratio);
    }
    return remeshing_edge_length_ = length;
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

  Json_line json_line(const Chain_result& r) const
  {
    const GSM::Mesh_quality_statistics& q = r.quality;
    Json_line j;
    j.add("model", model_).add("chain", r.chain).add("n_vertices", q.number_of_vertices)
        .add("n_tets", q.number_of_cells).add("theta_min", q.min_dihedral_angle)
        .add("theta_max", q.max_dihedral_angle).add("mean_min_dihedral", q.mean_min_dihedral_angle);
    for(std::size_t i = 0; i < q.n_min_dihedral_below.size(); ++i)
      j.add("n_min_dih_lt" + std::to_string(int(q.dihedral_thresholds[i])), q.n_min_dihedral_below[i]);
    return j.add("gamma_min", q.min_radius_ratio).add("gamma_mean", q.mean_radius_ratio)
        .add("n_inverted", q.number_of_inverted_cells).add("opt_time_s", r.opt_time_s)
        .add("hausdorff_to_input", r.boundary_distance)
        .add("boundary_vertex_share", r.layering.boundary_vertex_share)
        .add("boundary_edge_length", r.layering.boundary_edge_length)
        .add("first_layer_ratio", r.layering.first_layer_ratio)
        .add("field", field_.from_input ? std::string() : field_.name)
        .add("sizing", field_.from_input ? field_.name : std::string("uniform"))
        .add("repeat", (std::max)(1, options_.repeat)).add("threads", options_.threads)
        .add("edge_size", edge_size_).add("mesh_time_s", mesh_time_s_).add("return_codes", r.return_codes);
  }

  void print_table(const std::vector<Chain_result>& results) const
  {
    double perturb_exude_time = 0;
    for(const Chain_result& r : results)
      if(r.chain == "perturb+exude") perturb_exude_time = r.opt_time_s;
    std::printf("\nmodel %s: initial make_mesh_3 mesh, %s size %.4g, %.2f s; "
                "optimizer times are medians of %d run(s)\n",
                model_.c_str(), field_.name.empty() ? "uniform" : field_.from_input ? "thickness-scaled" : "field-scaled",
                edge_size_,
                mesh_time_s_, (std::max)(1, options_.repeat));
    std::printf("initial mesh: %.0f%% of the vertices on the boundary; edges from it to the first interior "
                "vertices %.2fx the edges between two boundary vertices (medians)\n",
                100 * initial_layering_.boundary_vertex_share, initial_layering_.first_layer_ratio);
    if(!field_.name.empty() && !field_.from_input)
      std::printf("quality measured in the metric of %s (each tet mapped by M^1/2)\n", field_.name.c_str());
    std::vector<Table::Column> columns{{"chain", 22, -1, true}, {"verts", 7}, {"tets", 7}, {"th_min", 7, 2},
                                       {"th_max", 7, 2}, {"mean_mn", 7, 2}, {"<10", 6}, {"<20", 6}, {"<30", 6},
                                       {"<40", 6}, {"g_min", 6, 3}, {"g_mean", 6, 3}, {"inv", 4}, {"opt_s", 9, 3},
                                       {"/p+e", 7, 2}};
    const bool distances = bool(boundary_distance_);
    if(distances) columns.push_back({" hd/hd0", 7, 3});
    const Table table(columns);
    table.print_header();
    for(const Chain_result& r : results) {
      const GSM::Mesh_quality_statistics& q = r.quality;
      std::vector<Table::Cell> row{r.chain, q.number_of_vertices, q.number_of_cells, q.min_dihedral_angle,
                                   q.max_dihedral_angle, q.mean_min_dihedral_angle, q.n_min_dihedral_below[0],
                                   q.n_min_dihedral_below[1], q.n_min_dihedral_below[2], q.n_min_dihedral_below[3],
                                   q.min_radius_ratio, q.mean_radius_ratio, q.number_of_inverted_cells, r.opt_time_s,
                                   perturb_exude_time > 0 ? Table::Cell(r.opt_time_s / perturb_exude_time)
                                                          : Table::Cell::none()};
      if(distances)
        row.push_back(r.boundary_distance >= 0 && initial_boundary_distance_ > 0
                          ? Table::Cell(r.boundary_distance / initial_boundary_distance_)
                          : Table::Cell::none());
      table.print_row(row);
    }
  }

  const Options& options_;
  std::string model_;
  const MeshDomain& domain_;
  double domain_volume_;
  Target_field field_;
  std::function<double(const C3T3&)> boundary_distance_;
  Boundary_layering initial_layering_;
  double initial_boundary_distance_ = -1;
  C3T3 initial_;
  double edge_size_ = 0;
  double mesh_time_s_ = 0;
  double remeshing_edge_length_ = 0;
};

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_COMPARISON_DRIVER_H
