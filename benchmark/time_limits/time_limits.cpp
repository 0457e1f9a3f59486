// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How well every entry point keeps `maximum_running_time`: each runs once without a limit
// (time T), then with limits at fractions of T; the table gives each run's time against its
// limit, the bar max(1.1 limit, limit + 1 s), and the stop it reported. The limit 0+ (1e-9 s)
// measures what always runs (the stages without which there is no result).
//
//   time_limits INPUT.off [--particles N] [--vertices N] [--features-angle DEG] [--threads N]
//               [--json FILE]

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/GSM_mesh_optimization/mesh_with_vertex_count.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/gsm_optimize_mesh_3.h>
#include <CGAL/lattice_particles_3.h>
#include <CGAL/make_hex_dominant_mesh_3.h>
#include <CGAL/make_lattice_mesh_3.h>
#include <CGAL/tets_to_hex_dominant.h>

#include <tbb/global_control.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
namespace GSM = CGAL::GSM_mesh_optimization;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace params = CGAL::parameters;

struct Options
{
  std::string input;
  std::size_t particles = 30000, vertices = 30000;
  double features_angle = 60;
  int threads = 2;
  std::string json_file;
};

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if(a == "--particles") o.particles = std::stoul(value());
    else if(a == "--vertices") o.vertices = std::stoul(value());
    else if(a == "--features-angle") o.features_angle = std::stod(value());
    else if(a == "--threads") o.threads = std::stoi(value());
    else if(a == "--json") o.json_file = value();
    else if(!a.empty() && a[0] == '-') throw std::invalid_argument("unknown option " + a);
    else o.input = a;
  }
  if(o.input.empty()) throw std::invalid_argument("usage: time_limits INPUT.off [--particles N] [--vertices N] "
                                                  "[--features-angle DEG] [--threads N] [--json FILE]");
  return o;
}

// one entry point: `run(limit)` (0: none) returns what it reported about stopping
typedef std::function<std::string(double)> Run;

} // namespace

int main(int argc, char** argv)
{
  try {
    const Options o = parse(argc, argv);
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads));
    Surface_mesh surface;
    GSM::IO::read_closed_surface(o.input, surface);
    const std::string model = GSM::IO::file_stem(o.input);
    Domain domain(surface);
    if(o.features_angle > 0) domain.detect_features(o.features_angle);

    // GSM's input: make_mesh_3 at about `vertices` vertices
    const auto made = GSM::mesh_with_vertex_count(
        [&](double size) {
          CGAL::Mesh_criteria_3<Tr> criteria(params::edge_size = size, params::facet_angle = 25,
                                             params::facet_size = size, params::facet_distance = 0.1 * size,
                                             params::cell_radius_edge_ratio = 3, params::cell_size = size);
          CGAL::get_default_random() = CGAL::Random(0);
          return CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
        },
        o.vertices, 0.05 * std::sqrt(CGAL::squared_distance(K::Point_3(domain.bbox().xmin(), domain.bbox().ymin(), domain.bbox().zmin()),
                                                              K::Point_3(domain.bbox().xmax(), domain.bbox().ymax(), domain.bbox().zmax()))),
        0.1);
    const C3T3& input = made.c3t3;
    const auto particles = TLM::parameters::number_of_particles(o.particles);
    C3T3 tets; // the hex-dominant mesh's tets, for tets_to_hex_dominant

    auto code_name = [](CGAL::Mesh_optimization_return_code c) {
      return c == CGAL::TIME_LIMIT_REACHED ? "TIME_LIMIT_REACHED" : c == CGAL::CONVERGENCE_REACHED ? "CONVERGENCE_REACHED"
             : c == CGAL::CANT_IMPROVE_ANYMORE ? "CANT_IMPROVE_ANYMORE" : "MAX_ITERATION_NUMBER_REACHED";
    };
    auto flag = [](bool reached) { return std::string(reached ? "time_limit_reached" : "-"); };
    const std::vector<std::pair<std::string, Run>> entries = {
        {"gsm_optimize_mesh_3", [&](double limit) {
           C3T3 c3t3 = input;
           return std::string(code_name(CGAL::gsm_optimize_mesh_3(c3t3, domain, params::maximum_running_time(limit))));
         }},
        {"generate_cross_field_3", [&](double limit) {
           return flag(CGAL::Frame_fields::generate_cross_field_3(input, params::maximum_running_time(limit)).time_limit_reached);
         }},
        {"lattice_particles_3", [&](double limit) {
           return flag(CGAL::lattice_particles_3(domain, particles.maximum_running_time(limit)).time_limit_reached);
         }},
        {"make_lattice_mesh_3", [&](double limit) {
           TLM::Lattice_mesh_report r;
           CGAL::make_lattice_mesh_3<C3T3>(domain, TLM::parameters::mesh_report(&r, particles.maximum_running_time(limit)));
           return flag(r.time_limit_reached);
         }},
        {"make_hex_dominant_mesh_3", [&](double limit) {
           HDM::Hex_dominant_report r;
           C3T3 t;
           CGAL::make_hex_dominant_mesh_3<C3T3>(domain, HDM::parameters::hex_dominant_report(&r,
               HDM::parameters::tetrahedral_mesh(&t, particles.maximum_running_time(limit))));
           if(limit == 0) tets = std::move(t);
           return flag(r.time_limit_reached);
         }},
        {"tets_to_hex_dominant", [&](double limit) {
           HDM::Hex_dominant_merge_report r;
           CGAL::tets_to_hex_dominant(tets, HDM::parameters::merge_report(&r, params::maximum_running_time(limit)));
           return flag(r.stopped);
         }},
    };

    std::ofstream json;
    if(!o.json_file.empty()) json.open(o.json_file, std::ios::app);
    std::printf("%s: %zu vertices for GSM and the field, %zu particles, %d threads\n", model.c_str(),
                made.number_of_vertices, o.particles, o.threads);
    std::printf("%-26s %8s %9s %9s %9s %9s %5s  %s\n", "entry point", "fraction", "limit_s", "time_s", "bar_s",
                "over_s", "kept", "stop reported");
    int failures = 0;
    for(const auto& [name, run] : entries) {
      CGAL::Real_timer timer;
      timer.start();
      const std::string unlimited = run(0.);
      const double full = timer.time();
      std::printf("%-26s %8s %9s %9.2f %9s %9s %5s  %s\n", name.c_str(), "none", "-", full, "-", "-", "-", unlimited.c_str());
      for(double fraction : {0., 0.25, 0.5, 0.75}) {
        const double limit = fraction > 0 ? fraction * full : 1e-9;
        timer.reset();
        const std::string stop = run(limit);
        const double t = timer.time();
        const double bar = std::max(1.1 * limit, limit + 1.);
        const bool kept = fraction == 0 || t <= bar;
        failures += !kept;
        std::printf("%-26s %8.2f %9.2f %9.2f %9.2f %9.2f %5s  %s\n", name.c_str(), fraction, limit, t,
                    fraction > 0 ? bar : 0., t - limit, fraction == 0 ? "floor" : kept ? "yes" : "NO", stop.c_str());
        if(json)
          json << "{\"model\": \"" << model << "\", \"entry_point\": \"" << name << "\", \"threads\": " << o.threads
               << ", \"particles\": " << o.particles << ", \"vertices\": " << made.number_of_vertices
               << ", \"unlimited_s\": " << full << ", \"fraction\": " << fraction << ", \"limit_s\": " << limit
               << ", \"time_s\": " << t << ", \"bar_s\": " << bar << ", \"kept\": " << (kept ? "true" : "false")
               << ", \"stop\": \"" << stop << "\"}\n";
      }
    }
    std::printf("%d run(s) over the bar\n", failures);
    return failures == 0 ? EXIT_SUCCESS : 3;
  } catch(const std::exception& e) {
    std::cerr << "time_limits: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
