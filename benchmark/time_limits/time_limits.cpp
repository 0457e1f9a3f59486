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

#include "command_line.h"
#include "json_lines.h"
#include "mesh_3_optimizers.h"
#include "surface_input.h"
#include "table.h"

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

typedef vvm_benchmark::K K;
typedef vvm_benchmark::Surface_mesh Surface_mesh;
typedef vvm_benchmark::Polyhedral_domain Domain;
typedef vvm_benchmark::Polyhedral_tr Tr;
typedef vvm_benchmark::Polyhedral_c3t3 C3T3;
namespace GSM = CGAL::GSM_mesh_optimization;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace params = CGAL::parameters;

const char* usage = "usage: time_limits INPUT.off [--particles N] [--vertices N] [--features-angle DEG] "
                    "[--threads N] [--json FILE]\n";

struct Options : vvm_benchmark::Common_options
{
  std::size_t particles = 30000, vertices = 30000;
  Options() { features_angle = 60, threads = 2; }
};

Options parse(int argc, char** argv)
{
  Options o;
  vvm_benchmark::Command_line c(argc, argv, usage);
  while(c.next()) {
    if(c.is("--particles")) o.particles = c.number_in<std::size_t>(8, 20000000);
    else if(c.is("--vertices")) o.vertices = c.number_in<std::size_t>(100, 20000000);
    else c.common(o);
  }
  vvm_benchmark::Command_line::require_input(o);
  return o;
}

// one entry point: `run(limit)` (0: none) returns what it reported about stopping
typedef std::function<std::string(double)> Run;

int run(const Options& o)
{
  Surface_mesh surface;
  vvm_benchmark::read_surface_input(o.input, surface);
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

  auto flag = [](bool reached) { return std::string(reached ? "time_limit_reached" : "-"); };
  const std::vector<std::pair<std::string, Run>> entries = {
      {"gsm_optimize_mesh_3", [&](double limit) {
         C3T3 c3t3 = input;
         return std::string(vvm_benchmark::return_code_name(CGAL::gsm_optimize_mesh_3(c3t3, domain, params::maximum_running_time(limit))));
       }},
      {"generate_cross_field_3", [&](double limit) {
         return flag(CGAL::Frame_fields::generate_cross_field_3(input, params::maximum_running_time(limit)).time_limit_reached);
       }},
      {"lattice_particles_3", [&](double limit) {
         return flag(CGAL::lattice_particles_3(domain, particles.maximum_running_time(limit)).time_limit_reached);
       }},
      {"make_lattice_mesh_3", [&](double limit) {
         TLM::Lattice_mesh_report r;
         CGAL::make_lattice_mesh_3<C3T3>(domain, TLM::parameters::report(&r, particles.maximum_running_time(limit)));
         return flag(r.time_limit_reached);
       }},
      {"make_hex_dominant_mesh_3", [&](double limit) {
         HDM::Hex_dominant_report r;
         C3T3 t;
         CGAL::make_hex_dominant_mesh_3<C3T3>(domain, HDM::parameters::report(&r,
             HDM::parameters::tetrahedral_mesh(&t, particles.maximum_running_time(limit))));
         if(limit == 0) tets = std::move(t);
         return flag(r.time_limit_reached);
       }},
      {"tets_to_hex_dominant", [&](double limit) {
         HDM::Hex_dominant_merge_report r;
         CGAL::tets_to_hex_dominant(tets, HDM::parameters::report(&r, params::maximum_running_time(limit)));
         return flag(r.stopped);
       }},
  };

  vvm_benchmark::Json_lines_file json(o.json_file, vvm_benchmark::Json_lines_file::APPEND);
  std::printf("%s: %zu vertices for GSM and the field, %zu particles, %d threads\n", model.c_str(),
              made.number_of_vertices, o.particles, o.threads);
  typedef vvm_benchmark::Table::Cell Cell;
  const vvm_benchmark::Table table({{"entry point", 26, -1, true}, {"fraction", 8, 2}, {"limit_s", 9, 2},
                                    {"time_s", 9, 2}, {"bar_s", 9, 2}, {"over_s", 9, 2}, {"kept", 5},
                                    {" stop reported", 0, -1, true}});
  table.print_header();
  int failures = 0;
  for(const auto& [name, run_entry] : entries) {
    CGAL::Real_timer timer;
    timer.start();
    const std::string unlimited = run_entry(0.);
    const double full = timer.time();
    table.print_row({name, "none", Cell::none(), full, Cell::none(), Cell::none(), Cell::none(), " " + unlimited});
    for(double fraction : {0., 0.25, 0.5, 0.75}) {
      const double limit = fraction > 0 ? fraction * full : 1e-9;
      timer.reset();
      const std::string stop = run_entry(limit);
      const double t = timer.time();
      const double bar = std::max(1.1 * limit, limit + 1.);
      const bool kept = fraction == 0 || t <= bar;
      failures += !kept;
      table.print_row({name, fraction, limit, t, fraction > 0 ? bar : 0., t - limit,
                       fraction == 0 ? "floor" : kept ? "yes" : "NO", " " + stop});
      json.write(vvm_benchmark::Json_line()
                     .add("model", model).add("entry_point", name).add("threads", o.threads)
                     .add("particles", o.particles).add("vertices", made.number_of_vertices)
                     .add("unlimited_s", full).add("fraction", fraction).add("limit_s", limit).add("time_s", t)
                     .add("bar_s", bar).add("kept", kept).add("stop", stop));
    }
  }
  std::printf("%d run(s) over the bar\n", failures);
  return failures == 0 ? EXIT_SUCCESS : 3;
}

} // namespace

int main(int argc, char** argv)
{
  return vvm_benchmark::benchmark_main("time_limits", usage, argc, argv, parse, run);
}
