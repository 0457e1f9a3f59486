// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The part of compare_tet_meshers that does not depend on the domain type:
// the frame field, the methods, the measures and the reports.

#ifndef VVM_BENCHMARK_TET_MESHER_COMPARISON_H
#define VVM_BENCHMARK_TET_MESHER_COMPARISON_H

#include "compare_tet_meshers.h"
#include "json_lines.h"
#include "mesh_3_optimizers.h"
#include "table.h"

#include <CGAL/Frame_fields/Closed_form_frame_field_3.h>
#include <CGAL/Frame_fields/Scaled_frame_field_3.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/GSM_mesh_optimization/IO/write_VTU_with_quality.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/GSM_mesh_optimization/mesh_with_vertex_count.h>
#include <CGAL/Tetrahedral_lattice_meshing/alignment_error.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Domain_cross_field.h>
#include <CGAL/make_lattice_mesh_3.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace vvm_tet_benchmark {

namespace GSM = CGAL::GSM_mesh_optimization;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;

// "make_mesh_3+odt+perturb" -> {"odt", "perturb"}; "bcc+gsm" -> {"bcc", "gsm"}
inline std::vector<std::string> method_steps(const std::string& method)
{
  const std::vector<std::string> steps = vvm_benchmark::split(method, '+');
  const bool known_start = !steps.empty() && (steps[0] == "make_mesh_3" || steps[0] == "bcc" || steps[0] == "fcc");
  bool ok = known_start;
  for(std::size_t i = 1; ok && i < steps.size(); ++i)
    ok = (vvm_benchmark::is_mesh_3_optimizer(steps[i]) || steps[i] == "gsm") &&
         (steps[0] == "make_mesh_3" || (steps[i] == "gsm" && steps.size() == 2));
  if(known_start && steps[0] != "make_mesh_3" && steps.size() == 2 && steps[1] == "none") ok = true;
  if(!ok)
    throw Input_error("unknown method '" + method +
                      "' (known: make_mesh_3 followed by +lloyd, +odt, +perturb, +exude, +gsm; bcc, fcc, "
                      "bcc+gsm, fcc+gsm, bcc+none, fcc+none)");
  return steps;
}

struct Method_result
{
  std::string method;
  GSM::Mesh_quality_statistics quality;
  TLM::Alignment_statistics alignment;
  double boundary_distance = -1; // two-sided Hausdorff distance to the input surface
  double time_s = 0;             // particles + meshing (+ optimizers)
  double particle_time_s = 0;
  std::size_t particles_requested = 0;
};

/*
 * Domain: a MeshDomain_3; Distance: double(const C3T3&), the two-sided
 * Hausdorff distance of the complex's boundary to the input surface.
 */
template <class C3T3, class MeshDomain>
class Tet_mesher_comparison
{
  typedef typename MeshDomain::R K;
  typedef typename K::Point_3 Point_3;
  typedef CGAL::Frame_fields::Closed_form_frame_field_3<K> Field;
  typedef CGAL::Mesh_criteria_3<typename C3T3::Triangulation> Mesh_criteria;

public:
  /// `size`: with --sizing thickness, the sizing field that scales the frames (relative sizes)
  Tet_mesher_comparison(const Options& options, const std::string& model, const MeshDomain& domain,
                        double volume, std::function<double(const C3T3&)> boundary_distance,
                        std::function<double(const Point_3&)> size = {})
    : options_(options), model_(model), domain_(domain), volume_(volume),
      boundary_distance_(std::move(boundary_distance)), field_(identity()), size_(std::move(size))
  {
    if(size_) model_ += "_thickness";
  }

  int run()
  {
    std::vector<std::string> methods = options_.methods.empty() ? default_methods() : options_.methods;
    for(const std::string& m : methods) method_steps(m); // validate first
    make_field();
    // lattice methods first: their vertex count is the one make_mesh_3 is asked for
    std::stable_sort(methods.begin(), methods.end(), [](const std::string& a, const std::string& b) {
      return (a.rfind("make_mesh_3", 0) != 0) > (b.rfind("make_mesh_3", 0) != 0);
    });
    std::vector<Method_result> results;
    for(const std::string& m : methods) {
      std::cerr << "compare_tet_meshers: " << model_ << " / " << m << "\n";
      results.push_back(method_steps(m)[0] == "make_mesh_3" ? run_make_mesh_3(m) : run_lattice(m));
      print_line(results.back(), results.size() == 1);
    }
    print_table(results);
    if(!options_.json_file.empty()) write_json(results);
    return 0;
  }

private:
  static Field identity()
  {
    return Field([](const Point_3&) { return Eigen::Matrix3d(Eigen::Matrix3d::Identity()); });
  }

  void make_field()
  {
    namespace FF = CGAL::Frame_fields;
    const std::string& f = options_.field;
    CGAL::Real_timer timer;
    timer.start();
    if(f == "identity") field_ = identity();
    else if(f == "rotation-y") field_ = FF::rotation_about_y_frame_field<K>();
    else if(f == "fig4.8") field_ = FF::single_direction_anisotropy_frame_field<K>();
    else if(f == "fig4.9") field_ = FF::cylindrical_anisotropy_frame_field<K>();
    else if(f == "cross") {
      // on a mesh about as fine as a BCC lattice of the requested count
      const double size = std::cbrt(2. * volume_ / double(options_.target_vertices));
      auto cross = std::make_shared<FF::Discrete_frame_field_3<typename CGAL::Kernel_traits<Point_3>::Kernel>>(
          TLM::internal::domain_cross_field(domain_, size));
      field_ = Field([cross](const Point_3& p) { return cross->T(p); });
    } else
      throw Input_error("unknown --field '" + f + "' (known: identity, cross, rotation-y, fig4.8, fig4.9)");
    if(size_) // T(x) h(x): the lattice's spacing follows the size
      field_ = Field([scaled = FF::Scaled_frame_field_3<Field, std::function<double(const Point_3&)>>(field_, size_, 1.)](
                         const Point_3& p) { return scaled.T(p); });
    field_time_s_ = timer.time();
    // conformal (rotations, uniform scale): quality is measured as is, else in the metric
    std::vector<Point_3> samples;
    const auto bb = domain_.bbox();
    CGAL::Random random(1);
    for(int i = 0; i < 200; ++i)
      samples.emplace_back(random.get_double(bb.xmin(), bb.xmax()), random.get_double(bb.ymin(), bb.ymax()),
                           random.get_double(bb.zmin(), bb.zmax()));
    conformal_ = f != "fig4.8" && f != "fig4.9" && TLM::internal::is_conformal(field_, samples);
  }

  // whether make_mesh_3 gets one size: the field's density is uniform (the cross field's unit
  // frames are, up to interpolation, but make_mesh_3 follows them anyway)
  bool uniform_density() const { return conformal_ && options_.field != "cross" && !size_; }

  // the isotropic edge length of the lattice's density, up to a constant (make_mesh_3's sizing)
  double relative_size(const Point_3& p) const { return std::cbrt(std::abs(field_.T(p).determinant())); }

  C3T3 mesh_with_size(double s) const
  {
    namespace P = CGAL::parameters;
    CGAL::get_default_random() = CGAL::Random(options_.seed);
    if(uniform_density()) {
      Mesh_criteria criteria(P::edge_size = s, P::facet_angle = 25, P::facet_size = s, P::facet_distance = s / 10.,
                             P::cell_radius_edge_ratio = 3, P::cell_size = s);
      return CGAL::make_mesh_3<C3T3>(domain_, criteria, P::no_perturb(), P::no_exude());
    }
    // the field's density (the cross field has unit frames: uniform too, up to interpolation)
    auto size = [this, s](const Point_3& p, int, const auto&) { return s * relative_size(p); };
    Mesh_criteria criteria(P::edge_size = size, P::facet_angle = 25, P::facet_size = size,
                           P::facet_distance = s / 100., P::cell_radius_edge_ratio = 3, P::cell_size = size);
    return CGAL::make_mesh_3<C3T3>(domain_, criteria, P::no_perturb(), P::no_exude());
  }

  GSM::Mesh_quality_statistics quality(const C3T3& c3t3) const
  {
    if(conformal_) return GSM::mesh_quality_statistics(c3t3);
    return GSM::mesh_quality_statistics(c3t3, [this](const auto& p) {
      return field_.B(Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    });
  }

  auto metric() const
  {
    return [this](const Eigen::Vector3d& x) {
      const Eigen::Matrix3d B = field_.B(Point_3(x[0], x[1], x[2]));
      return Eigen::Matrix3d(B.transpose() * B);
    };
  }

  void measure(const C3T3& c3t3, const TLM::Lattice& lattice, Method_result& r) const
  {
    r.quality = quality(c3t3);
    r.alignment = TLM::alignment_statistics(c3t3, field_, lattice);
    if(boundary_distance_) r.boundary_distance = boundary_distance_(c3t3);
    if(!options_.out_dir.empty()) write_outputs(c3t3, lattice, r);
  }

  Method_result run_lattice(const std::string& method)
  {
    const std::vector<std::string> steps = method_steps(method);
    const TLM::Lattice_type type = steps[0] == "bcc" ? TLM::Lattice_type::BCC : TLM::Lattice_type::FCC;
    const TLM::Lattice_mesh_optimization stage = steps.size() == 1 ? TLM::Lattice_mesh_optimization::FLIPS
                                                 : steps[1] == "gsm" ? TLM::Lattice_mesh_optimization::GSM
                                                                     : TLM::Lattice_mesh_optimization::NONE;
    Method_result r;
    r.method = method;
    Lattice_run& run = lattice_runs_[steps[0]];
    if(!run.done) {
      // one correction of the particle count when the vertex count is more than 10% off the target.
      // Not tighter: a box's whole lattices have only some counts (BCC cube: 9,009 or 10,745 near
      // 10k), and a count forced between them is a lattice with a partial layer (a dislocation)
      double wanted = double(options_.target_vertices);
      for(int attempt = 0; attempt < 2; ++attempt) {
        run.requested = std::size_t(std::llround(wanted));
        namespace TP = TLM::parameters;
        auto np = TP::lattice(type, TP::number_of_particles(run.requested, TP::number_of_threads(options_.threads,
            TP::mesh_optimization(TLM::Lattice_mesh_optimization::NONE, TP::report(&run.report,
                CGAL::parameters::random_seed(options_.seed).verbose(options_.verbose))))));
        run.c3t3 = options_.levels < 0
                       ? CGAL::make_lattice_mesh_3<C3T3>(domain_, field_, np)
                       : CGAL::make_lattice_mesh_3<C3T3>(domain_, field_, TP::multiresolution_levels(options_.levels, np));
        run.time_s = run.report.particle_time + run.report.connection_time;
        const double n = double(GSM::number_of_vertices_in_complex(run.c3t3));
        if(std::abs(n - double(options_.target_vertices)) <= 0.1 * double(options_.target_vertices)) break;
        wanted *= double(options_.target_vertices) / n;
      }
      run.done = true;
    }
    r.particles_requested = run.requested;
    r.particle_time_s = run.report.particle_time;
    C3T3 c3t3 = run.c3t3;
    TLM::Lattice_mesh_report report = run.report;
    // what make_lattice_mesh_3 does after the connection: the same function
    TLM::internal::optimize_lattice_mesh(c3t3, domain_, field_, TLM::Lattice::make(type), stage, options_.sliver_bound, options_.threads, 0.,
                                         report);
    r.time_s = run.time_s + report.gsm_time;
    if(options_.verbose)
      std::cerr << "  " << method << ": l* " << report.edge_length << ", particles " << report.particle_time
                << " s, connection " << report.connection_time << " s, last stage " << report.gsm_time << " s\n";
    measure(c3t3, TLM::Lattice::make(type), r);
    return r;
  }

  void make_initial_mesh()
  {
    if(initial_done_) return;
    std::size_t target = options_.target_vertices;
    if(!lattice_runs_.empty()) { // the lattice meshes' vertex count
      double sum = 0;
      for(const auto& run : lattice_runs_) sum += double(GSM::number_of_vertices_in_complex(run.second.c3t3));
      target = std::size_t(std::llround(sum / double(lattice_runs_.size())));
    }
    const Point_3 c(0.5 * (domain_.bbox().xmin() + domain_.bbox().xmax()),
                    0.5 * (domain_.bbox().ymin() + domain_.bbox().ymax()),
                    0.5 * (domain_.bbox().zmin() + domain_.bbox().zmax()));
    const double first = std::cbrt(volume_ / (0.2 * double(target))) / (uniform_density() ? 1. : relative_size(c));
    auto r = GSM::mesh_with_vertex_count([this](double s) { return mesh_with_size(s); }, target, first, 0.03,
                                         CGAL::parameters::verbose(options_.verbose));
    initial_ = std::move(r.c3t3);
    initial_time_s_ = r.time_s;
    if(boundary_distance_) initial_distance_ = boundary_distance_(initial_);
    initial_done_ = true;
  }

  Method_result run_make_mesh_3(const std::string& method)
  {
    namespace P = CGAL::parameters;
    make_initial_mesh();
    Method_result r;
    r.method = method;
    C3T3 c3t3 = initial_;
    CGAL::Real_timer timer;
    timer.start();
    const std::vector<std::string> steps = method_steps(method);
    for(std::size_t i = 1; i < steps.size(); ++i) {
      CGAL::get_default_random() = CGAL::Random(options_.seed);
      const std::string& s = steps[i];
      if(vvm_benchmark::is_mesh_3_optimizer(s)) vvm_benchmark::run_mesh_3_optimizer(s, c3t3, domain_);
      else if(conformal_)
        CGAL::gsm_optimize_mesh_3(c3t3, domain_, GSM::parameters::number_of_threads(options_.threads));
      else
        CGAL::gsm_optimize_mesh_3(c3t3, domain_,
                                  GSM::parameters::metric_field(metric(), GSM::parameters::number_of_threads(options_.threads)));
    }
    r.time_s = initial_time_s_ + timer.time();
    measure(c3t3, TLM::Lattice::make(TLM::Lattice_type::BCC), r);
    return r;
  }

  std::string out_path(const std::string& method, const std::string& extension) const
  {
    return options_.out_dir + "/" + model_ + "_" + method + extension;
  }

  void write_outputs(const C3T3& c3t3, const TLM::Lattice& lattice, const Method_result& r) const
  {
    std::ofstream medit(out_path(r.method, ".mesh"));
    CGAL::IO::output_to_medit(medit, c3t3, false /*rebind*/, true /*show_patches*/);
    std::ofstream vtu(out_path(r.method, ".vtu"), std::ios::binary);
    auto B = [this](const auto& p) -> Eigen::Matrix3d {
      if(conformal_) return Eigen::Matrix3d::Identity();
      return field_.B(Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    };
    GSM::IO::write_VTU_with_quality(vtu, c3t3, CGAL::IO::BINARY, B,
                                    {{"alignment_error", TLM::cell_alignment_errors(c3t3, field_, lattice)}});
    if(!medit || !vtu) throw std::runtime_error("cannot write into '" + options_.out_dir + "'");
  }

  double hausdorff_ratio(const Method_result& r) const
  {
    // make_mesh_3's distance is ~0 on a polyhedron it meshes exactly (a cube): no ratio then
    const auto& b = domain_.bbox();
    const double diagonal = std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                                      CGAL::square(b.zmax() - b.zmin()));
    return r.boundary_distance >= 0 && initial_distance_ > 1e-9 * diagonal ? r.boundary_distance / initial_distance_
                                                                            : -1.;
  }

  static const vvm_benchmark::Table& table()
  {
    static const vvm_benchmark::Table t({{"method", 26, -1, true}, {"#V", 7}, {"#T", 7}, {"th_min", 6, 2},
                                         {"mean", 6, 2}, {"th_max", 6, 2}, {"mean", 7, 2}, {"rho", 5, 3},
                                         {"kappa", 5, 3}, {"eps", 6, 2}, {"<20", 5}, {"<40", 6}, {"inv", 4},
                                         {"hd/hd0", 6, 3}, {"time_s", 8, 2}, {"part_s", 8, 2}});
    return t;
  }

  void print_line(const Method_result& r, bool header) const
  {
    const GSM::Mesh_quality_statistics& q = r.quality;
    if(header) table().print_header();
    table().print_row({r.method, q.number_of_vertices, q.number_of_cells, q.min_dihedral_angle,
                       q.mean_min_dihedral_angle, q.max_dihedral_angle, q.mean_max_dihedral_angle,
                       q.mean_edge_radius_ratio, q.mean_condition, r.alignment.mean, q.n_min_dihedral_below[1],
                       q.n_min_dihedral_below[3], q.number_of_inverted_cells,
                       hausdorff_ratio(r) >= 0 ? vvm_benchmark::Table::Cell(hausdorff_ratio(r))
                                               : vvm_benchmark::Table::Cell::none(),
                       r.time_s, r.particle_time_s});
  }

  void print_table(const std::vector<Method_result>& results) const
  {
    std::printf("\nmodel %s, field %s (%s), target %zu vertices, %s, lattice polishing bound %g; "
                "make_mesh_3 at %.2f s, field %.2f s\n",
                model_.c_str(), options_.field.c_str(), conformal_ ? "quality as is" : "quality in the metric",
                options_.target_vertices, options_.threads > 0 ? (std::to_string(options_.threads) + " threads").c_str()
                                                               : "all threads",
                options_.sliver_bound, initial_time_s_, field_time_s_);
    bool first = true;
    for(const Method_result& r : results) {
      print_line(r, first);
      first = false;
    }
  }

  void write_json(const std::vector<Method_result>& results) const
  {
    vvm_benchmark::Json_lines_file json(options_.json_file, vvm_benchmark::Json_lines_file::REPLACE);
    for(const Method_result& r : results) {
      const GSM::Mesh_quality_statistics& q = r.quality;
      json.write(vvm_benchmark::Json_line()
                     .add("model", model_).add("method", r.method).add("field", options_.field)
                     .add("sizing", options_.sizing).add("n_vertices", q.number_of_vertices)
                     .add("n_tets", q.number_of_cells).add("theta_min", q.min_dihedral_angle)
                     .add("mean_min_dihedral", q.mean_min_dihedral_angle).add("theta_max", q.max_dihedral_angle)
                     .add("mean_max_dihedral", q.mean_max_dihedral_angle).add("rho_mean", q.mean_edge_radius_ratio)
                     .add("kappa_mean", q.mean_condition).add("alignment_error_mean_deg", r.alignment.mean)
                     .add("n_min_dih_lt20", q.n_min_dihedral_below[1]).add("n_min_dih_lt40", q.n_min_dihedral_below[3])
                     .add("n_inverted", q.number_of_inverted_cells).add("hausdorff", r.boundary_distance)
                     .add("hausdorff_ratio", hausdorff_ratio(r)).add("time_s", r.time_s)
                     .add("particle_time_s", r.particle_time_s).add("field_time_s", field_time_s_)
                     .add("particles_requested", r.particles_requested).add("threads", options_.threads)
                     .add("sliver_bound", options_.sliver_bound));
    }
  }

  struct Lattice_run
  {
    bool done = false;
    C3T3 c3t3;
    TLM::Lattice_mesh_report report;
    double time_s = 0;
    std::size_t requested = 0;
  };

  const Options& options_;
  std::string model_;
  const MeshDomain& domain_;
  double volume_;
  std::function<double(const C3T3&)> boundary_distance_;
  Field field_;
  std::function<double(const Point_3&)> size_; // --sizing thickness
  bool conformal_ = true;
  double field_time_s_ = 0;
  std::map<std::string, Lattice_run> lattice_runs_;
  bool initial_done_ = false;
  C3T3 initial_;
  double initial_time_s_ = 0;
  double initial_distance_ = -1;
};

} // namespace vvm_tet_benchmark

#endif // VVM_BENCHMARK_TET_MESHER_COMPARISON_H
