// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// generate_frame_field [INPUT] [--vertices N] [--features-angle DEG] [--out FILE.vtu]
//                      [--frames FILE] [--singular FILE.vtu] [--curves FILE.vtu] [--json FILE] [--iterations K]
//                      [--tolerance X] [--seed S] [--verbose]
//
// Meshes the closed surface INPUT with make_mesh_3 at about N vertices (sharp
// edges protected above DEG), generates the boundary-aligned cross field on
// it, writes the field (VTU for ParaView, and/or the text format), its
// singular edges and curves and a JSON report. Exit code 2 with a message on bad input or options.
// With no INPUT it does so for the bundled fandisk.off, its sharp edges at 60 degrees, and writes
// fandisk.frames and fandisk_field.vtu in the current folder.

// make_mesh_3.h first: with CGAL_LINKED_WITH_TBB, Mesh_3 relies on TBB headers it includes
#include <CGAL/make_mesh_3.h>

#include <CGAL/Frame_fields/IO/frame_field_text_format.h>
#include <CGAL/Frame_fields/IO/write_VTU.h>
#include <CGAL/Frame_fields/boundary_alignment.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>

#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/GSM_mesh_optimization/mesh_with_vertex_count.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;
namespace GSM = CGAL::GSM_mesh_optimization;
namespace FF = CGAL::Frame_fields;

// bad input or options: exit code 2
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

const char* usage =
    "usage: generate_frame_field [INPUT] [--vertices N] [--features-angle DEG] [--out FILE.vtu]\n"
    "                            [--frames FILE] [--singular FILE.vtu] [--curves FILE.vtu] [--json FILE] [--iterations K]\n"
    "                            [--tolerance X] [--seed S] [--verbose]\n"
    "  INPUT             closed triangle surface (OFF, OBJ, PLY, STL, ...); none: the bundled fandisk.off\n"
    "                    with --features-angle 60 --frames fandisk.frames --out fandisk_field.vtu\n"
    "  --vertices N      about N mesh vertices (default 10000)\n"
    "  --features-angle  protect and align with the edges sharper than DEG degrees (default 0: none)\n"
    "  --out FILE.vtu    the field for ParaView (axis_1..3 point arrays)\n"
    "  --frames FILE     the field in the VVM frame field text format\n"
    "  --singular FILE   the singular edges as VTU lines\n"
    "  --curves FILE     the singular curves (chains of singular edges) as VTU polylines\n"
    "  --json FILE       the report (also printed on stdout)\n"
    "  --iterations K    at most K smoothing rounds (default 100)\n"
    "  --tolerance X     stop smoothing after a round lowering the energy by less than X times it (default 1e-4)\n"
    "  --seed S          random seed of make_mesh_3 (default 0)\n";

struct Options
{
  std::string input, vtu, frames, singular, curves, json;
  long vertices = 10000;
  double features_angle = 0;
  int iterations = 100;
  double tolerance = 1e-4;
  unsigned seed = 0;
  bool verbose = false;
};

double parse_number(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double x = 0;
  try { x = std::stod(text, &used); } catch(...) { used = 0; }
  if(used != text.size() || !std::isfinite(x))
    throw Usage_error(option + " needs a finite number, not '" + text + "'");
  return x;
}

Options parse(int argc, char** argv)
{
  Options o;
  bool features_angle_given = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Usage_error(a + " needs a value");
      return argv[++i];
    };
    if(a == "--vertices") {
      const double n = parse_number(a, value());
      if(!(n >= 1) || n != std::floor(n) || n > 1e8) throw Usage_error("--vertices must be a positive integer");
      o.vertices = long(n);
    } else if(a == "--features-angle") {
      o.features_angle = parse_number(a, value());
      features_angle_given = true;
      if(o.features_angle < 0 || o.features_angle > 180)
        throw Usage_error("--features-angle must be in [0, 180] degrees");
    } else if(a == "--iterations") {
      const double k = parse_number(a, value());
      if(!(k >= 0) || k != std::floor(k) || k > 1e6) throw Usage_error("--iterations must be a non-negative integer");
      o.iterations = int(k);
    } else if(a == "--tolerance") {
      o.tolerance = parse_number(a, value());
      if(!(o.tolerance >= 0)) throw Usage_error("--tolerance must be non-negative");
    } else if(a == "--seed") {
      const double s = parse_number(a, value());
      if(!(s >= 0) || s != std::floor(s) || s > 4e9) throw Usage_error("--seed must be a non-negative integer");
      o.seed = unsigned(s);
    } else if(a == "--out") o.vtu = value();
    else if(a == "--frames") o.frames = value();
    else if(a == "--singular") o.singular = value();
    else if(a == "--curves") o.curves = value();
    else if(a == "--json") o.json = value();
    else if(a == "--verbose") o.verbose = true;
    else if(a == "--help" || a == "-h") {
      std::cout << usage;
      std::exit(0);
    } else if(!a.empty() && a[0] == '-') throw Usage_error("unknown option '" + a + "'");
    else if(o.input.empty()) o.input = a;
    else throw Usage_error("more than one input ('" + o.input + "', '" + a + "')");
  }
  if(o.input.empty()) {
    o.input = vvm_example::data_file("fandisk.off");
    if(!features_angle_given) o.features_angle = 60;
    if(o.vtu.empty() && o.frames.empty() && o.singular.empty() && o.curves.empty() && o.json.empty())
      o.frames = "fandisk.frames", o.vtu = "fandisk_field.vtu";
  }
  return o;
}

// make_mesh_3 with uniform size s (no optimizers: the field does not need them)
C3T3 mesh_with_size(const Domain& domain, double s, unsigned seed)
{
  namespace params = CGAL::parameters;
  Mesh_criteria criteria(params::edge_size = s, params::facet_angle = 25, params::facet_size = s,
                         params::facet_distance = s / 10., params::cell_radius_edge_ratio = 3,
                         params::cell_size = s);
  CGAL::get_default_random() = CGAL::Random(seed);
  return CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
}

// `s` as a JSON string: quotes, backslashes and control characters escaped
std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for(const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if(c == '"' || c == '\\') out += '\\', out += ch;
    else if(c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
      out += buf;
    } else out += ch;
  }
  return out + "\"";
}

// a JSON number, or null if it is not finite (JSON has no NaN or infinity)
struct Json_number
{
  double x;
  friend std::ostream& operator<<(std::ostream& os, const Json_number& n)
  {
    if(std::isfinite(n.x)) return os << n.x;
    return os << "null";
  }
};

int run(const Options& o)
{
  CGAL::Real_timer total;
  total.start();
  Surface_mesh surface;
  const double volume = GSM::IO::read_closed_surface(o.input, surface);
  Domain domain(surface);
  if(o.features_angle > 0) domain.detect_features(o.features_angle);

  CGAL::Real_timer mesh_timer;
  mesh_timer.start();
  // about 6 tets of volume s^3/6 per vertex
  GSM::Mesh_with_vertex_count_result<C3T3> meshed = GSM::mesh_with_vertex_count(
      [&](double s) { return mesh_with_size(domain, s, o.seed); }, std::size_t(o.vertices),
      std::cbrt(6 * volume / double(o.vertices)), 0.05, CGAL::parameters::verbose(o.verbose));
  const C3T3& c3t3 = meshed.c3t3;
  const double size = meshed.size;
  mesh_timer.stop();

  CGAL::Real_timer timer;
  timer.start();
  const FF::Generated_cross_field_3<K> g = FF::generate_cross_field_3(
      c3t3, FF::parameters::smoothing_tolerance(
             o.tolerance, CGAL::parameters::number_of_iterations(o.iterations).verbose(o.verbose)));
  timer.stop();
  const FF::Boundary_alignment_statistics a = FF::boundary_alignment_statistics(g);

  if(!o.vtu.empty()) {
    std::ofstream os(o.vtu);
    if(!os) throw std::runtime_error("cannot write '" + o.vtu + "'");
    FF::IO::write_VTU(os, g.field);
  }
  if(!o.frames.empty()) {
    std::ofstream os(o.frames);
    if(!os) throw std::runtime_error("cannot write '" + o.frames + "'");
    FF::IO::write_frame_field(os, g.field);
  }
  if(!o.singular.empty()) {
    std::ofstream os(o.singular);
    if(!os) throw std::runtime_error("cannot write '" + o.singular + "'");
    FF::IO::write_edges_VTU(os, g.field.points(), g.singular_edges);
  }
  if(!o.curves.empty()) {
    std::ofstream os(o.curves);
    if(!os) throw std::runtime_error("cannot write '" + o.curves + "'");
    FF::IO::write_polylines_VTU(os, g.field.points(), g.singular_curves);
  }
  // stdout holds the JSON report only
  for(const std::string& file : {o.vtu, o.frames, o.singular, o.curves})
    if(!file.empty()) std::cerr << "wrote " << vvm_example::absolute(file) << "\n";
  total.stop();
  double longest_curve = 0, curves_length = 0;
  std::size_t closed_curves = 0;
  for(const FF::Singular_curve& c : g.singular_curves) {
    longest_curve = (std::max)(longest_curve, c.length);
    curves_length += c.length;
    closed_curves += c.is_closed();
  }

  std::ostringstream js;
  js.precision(6);
  typedef Json_number N;
  js << "{\"model\": " << json_string(GSM::IO::file_stem(o.input)) << ", \"n_vertices\": " << g.field.points().size()
     << ", \"n_tets\": " << g.field.cells().size() << ", \"n_boundary_facets\": " << g.boundary_facets.size()
     << ", \"n_feature_edges\": " << g.feature_edges.size() << ", \"n_edges\": " << g.number_of_edges
     << ", \"n_interior_edges\": " << g.number_of_interior_edges
     << ", \"n_singular_edges\": " << g.singular_edges.size()
     << ", \"singular_edge_ratio\": "
     << N{g.number_of_interior_edges ? double(g.singular_edges.size()) / double(g.number_of_interior_edges) : 0.}
     << ", \"boundary_alignment_error_mean_deg\": " << N{a.mean}
     << ", \"boundary_alignment_error_p95_deg\": " << N{a.p95}
     << ", \"boundary_alignment_error_max_deg\": " << N{a.max}
     << ", \"vertex_alignment_error_mean_deg\": " << N{a.vertex_mean}
     << ", \"vertex_alignment_error_p95_deg\": " << N{a.vertex_p95}
     << ", \"vertex_alignment_error_max_deg\": " << N{a.vertex_max}
     << ", \"facet_normal_deviation_mean_deg\": " << N{a.normal_deviation_mean}
     << ", \"facet_normal_deviation_p95_deg\": " << N{a.normal_deviation_p95}
     << ", \"n_singular_curves\": " << g.singular_curves.size()
     << ", \"n_closed_singular_curves\": " << closed_curves
     << ", \"n_dead_ends\": " << g.number_of_dead_ends
     << ", \"singular_curves_length\": " << N{curves_length}
     << ", \"longest_singular_curve\": " << N{longest_curve}
     << ", \"smoothness_energy\": " << N{g.smoothness_energy}
     << ", \"smoothness_energy_per_edge\": " << N{g.smoothness_energy / double(g.number_of_edges)}
     << ", \"solver_iterations\": " << g.solver_iterations << ", \"solver_error\": " << N{g.solver_error}
     << ", \"features_angle\": " << N{o.features_angle} << ", \"iterations\": " << o.iterations
     << ", \"smoothing_rounds\": " << g.round_energies.size() - 1
     << ", \"mesh_size\": " << N{size} << ", \"mesh_time_s\": " << N{mesh_timer.time()}
     << ", \"time_s\": " << N{timer.time()} << ", \"total_time_s\": " << N{total.time()} << "}\n";
  std::cout << js.str();
  if(!o.json.empty()) {
    std::ofstream os(o.json);
    os << js.str();
    if(!os) throw std::runtime_error("cannot write '" + o.json + "'");
  }
  return 0;
}

int main(int argc, char** argv)
{
  try {
    return run(parse(argc, argv));
  } catch(const Usage_error& e) {
    std::cerr << "generate_frame_field: error: " << e.what() << "\n" << usage;
    return 2;
  } catch(const std::invalid_argument& e) { // the library refused the mesh
    std::cerr << "generate_frame_field: error: " << e.what() << "\n";
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "generate_frame_field: error: " << e.what() << "\n";
    return 1;
  }
}
