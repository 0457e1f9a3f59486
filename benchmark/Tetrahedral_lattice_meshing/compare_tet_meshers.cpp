// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_tet_meshers INPUT [--vertices N] [--features-angle DEG]
//                     [--field identity|cross|rotation-y|fig4.8|fig4.9] [--methods m1,m2,...]
//                     [--threads N] [--json FILE] [--out-dir DIR] [--seed N] [--levels K] [--verbose]
//
// Lattice meshes (make_lattice_mesh_3, BCC / FCC, with or without GSM) against
// make_mesh_3 followed by CGAL's optimizers or GSM, all at one vertex count,
// with the columns of the dissertation's Table 4.2.

#include "compare_tet_meshers.h"

#include <tbb/global_control.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace vvm_tet_benchmark {

std::vector<std::string> default_methods()
{
  return {"make_mesh_3+perturb+exude", "make_mesh_3+odt", "make_mesh_3+gsm", "bcc", "fcc", "bcc+gsm", "fcc+gsm"};
}

namespace {

const char* usage =
    "usage: compare_tet_meshers INPUT [--vertices N] [--features-angle DEG]\n"
    "                           [--field identity|cross|rotation-y|fig4.8|fig4.9] [--methods m1,m2,...]\n"
    "                           [--threads N] [--json FILE] [--out-dir DIR] [--seed N] [--levels K]\n"
    "                           [--sliver-bound DEG] [--sizing uniform|thickness] [--verbose]\n"
    "  INPUT  a closed triangle surface (OFF, OBJ, PLY, STL, ...), or cube, sphere, torus\n"
    "         (cube is [-1,1]^3, [0.1,1.1]^3 with fig4.8, [1,11]^3 with fig4.9; torus: radii 1 and 0.4 about y)\n"
    "  --vertices N        the vertex count of every method (default 10000): the lattice methods ask\n"
    "                      for N particles (corrected once if over 10% off), make_mesh_3 for the\n"
    "                      lattice meshes' count (within 3%)\n"
    "  --features-angle D  sharp edges of surfaces (default 0 = none; 60 for cube)\n"
    "  --field F           the frame field: identity (default), cross (generate_cross_field_3 on the\n"
    "                      domain), rotation-y (Table 4.3, torus), fig4.8 / fig4.9 (Table 4.4, cube);\n"
    "                      quality is measured in the field's metric when it is not conformal\n"
    "  --methods LIST      comma-separated among make_mesh_3[+lloyd|+odt|+perturb|+exude|+gsm...],\n"
    "                      bcc, fcc (make_lattice_mesh_3: GSM flips and polishing), bcc+gsm, fcc+gsm\n"
    "                      (GSM in full), bcc+none, fcc+none (the particles' Delaunay triangulation)\n"
    "                      (default: make_mesh_3+perturb+exude,\n"
    "                      make_mesh_3+odt, make_mesh_3+gsm, bcc, fcc, bcc+gsm, fcc+gsm)\n"
    "  --threads N         maximum number of threads (default: all cores)\n"
    "  --json FILE         one JSON line per method\n"
    "  --out-dir DIR       write <model>_<method>.mesh and .vtu (with a per-cell alignment_error)\n"
    "  --seed N            seed of the particles and of make_mesh_3 (default 0)\n"
    "  --levels K          multiresolution levels of the particles, K in [0, 6] (default: the package's choice)\n"
    "  --sliver-bound DEG  the smallest angle sought by the polishing of bcc and fcc (default 30;\n"
    "                      0: none; higher lifts more boundary-layer cells for more alignment error)\n"
    "  --sizing S          uniform (default), or thickness: the field's frames and make_mesh_3's size\n"
    "                      scaled by the walls' and gaps' thickness, 3 cells across, graded by 0.3\n"
    "                      (CGAL::Thickness_sizing_field_3); surfaces only\n"
    "  --verbose           progress of the particle rounds\n";

using vvm_benchmark::parse_number;

Options parse_command_line(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Input_error("option " + arg + " expects a value");
      return argv[++i];
    };
    if(arg == "--vertices") {
      const long n = parse_number<long>(arg, value());
      if(n < 100 || n > 20000000) throw Input_error("--vertices must be between 100 and 2e7");
      o.target_vertices = std::size_t(n);
    } else if(arg == "--features-angle") {
      o.features_angle = parse_number<double>(arg, value());
      if(!(o.features_angle >= 0 && o.features_angle < 180)) throw Input_error("--features-angle must be in [0, 180)");
    } else if(arg == "--sizing") {
      o.sizing = value();
      if(o.sizing != "uniform" && o.sizing != "thickness")
        throw Input_error("unknown --sizing '" + o.sizing + "' (known: uniform, thickness)");
    } else if(arg == "--field") {
      o.field = value();
    } else if(arg == "--methods") {
      std::stringstream ss(value());
      for(std::string m; std::getline(ss, m, ',');)
        if(!m.empty()) o.methods.push_back(m);
    } else if(arg == "--threads") {
      o.threads = parse_number<int>(arg, value());
      if(o.threads < 0) throw Input_error("--threads must be non-negative");
    } else if(arg == "--json") {
      o.json_file = value();
    } else if(arg == "--out-dir") {
      o.out_dir = value();
    } else if(arg == "--seed") {
      o.seed = parse_number<unsigned int>(arg, value());
    } else if(arg == "--levels") {
      o.levels = parse_number<int>(arg, value());
      if(o.levels < 0 || o.levels > 6) throw Input_error("--levels must be in [0, 6]");
    } else if(arg == "--sliver-bound") {
      o.sliver_bound = parse_number<double>(arg, value());
      if(!(o.sliver_bound >= 0 && o.sliver_bound < 70.5)) throw Input_error("--sliver-bound must be in [0, 70.5)");
    } else if(arg == "--verbose") {
      o.verbose = true;
    } else if(arg == "--help" || arg == "-h") {
      std::cout << usage;
      std::exit(0);
    } else if(!arg.empty() && arg[0] == '-') {
      throw Input_error("unknown option " + arg);
    } else if(o.input.empty()) {
      o.input = arg;
    } else {
      throw Input_error("more than one INPUT given ('" + o.input + "', '" + arg + "')");
    }
  }
  if(o.input.empty()) throw Input_error("no INPUT given");
  const bool known_field = o.field == "identity" || o.field == "cross" || o.field == "rotation-y" ||
                           o.field == "fig4.8" || o.field == "fig4.9";
  if(!known_field) throw Input_error("unknown --field '" + o.field + "' (known: identity, cross, rotation-y, fig4.8, fig4.9)");
  if(o.sizing == "thickness" && (is_implicit_domain_name(o.input) || o.input == "cube"))
    throw Input_error("--sizing thickness needs a surface INPUT, not '" + o.input + "'");
  if(o.sizing == "thickness" && o.field != "identity" && o.field != "cross")
    throw Input_error("--sizing thickness scales the identity or the cross field, not " + o.field);
  if((o.field == "fig4.8" || o.field == "fig4.9") && o.input != "cube")
    throw Input_error("--field " + o.field + " is defined on INPUT cube");
  return o;
}

} // namespace
} // namespace vvm_tet_benchmark

int main(int argc, char** argv)
{
  using namespace vvm_tet_benchmark;
  try {
    const Options options = parse_command_line(argc, argv);
    std::unique_ptr<tbb::global_control> threads;
    if(options.threads > 0)
      threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      std::size_t(options.threads));
    if(!options.out_dir.empty()) {
      std::error_code error;
      std::filesystem::create_directories(options.out_dir, error);
      if(error) throw Input_error("cannot create '" + options.out_dir + "': " + error.message());
    }
    return is_implicit_domain_name(options.input) ? run_implicit_domain(options) : run_polyhedral_domain(options);
  } catch(const Input_error& e) {
    std::cerr << "compare_tet_meshers: error: " << e.what() << "\n" << usage;
    return 2;
  } catch(const std::invalid_argument& e) { // refused by a mesher: the input is at fault
    std::cerr << "compare_tet_meshers: error: " << e.what() << "\n";
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "compare_tet_meshers: failed: " << e.what() << "\n";
    return 1;
  }
}
