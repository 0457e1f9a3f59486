// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_optimizers INPUT [--vertices N] [--features-angle DEG] [--chains c1,c2,...]
//                    [--repeat N] [--threads N] [--json FILE] [--out-dir DIR] [--seed N]
//
// Builds one initial mesh with make_mesh_3 (no optimizer) at about N vertices,
// runs each optimizer chain on its own copy and prints the quality table.

#include "compare_optimizers.h"

#include <tbb/global_control.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

namespace vvm_benchmark {

std::vector<std::string> default_chains()
{
  return {"init",          "lloyd",       "odt",   "perturb",   "exude", "perturb+exude",
          "lloyd+perturb+exude", "odt+perturb+exude", "gsm", "odt+gsm", "lloyd+gsm"};
}

namespace {

const char* usage =
    "usage: compare_optimizers INPUT [--vertices N] [--features-angle DEG] [--chains c1,c2,...]\n"
    "                          [--repeat N] [--threads N] [--json FILE] [--out-dir DIR] [--seed N]\n"
    "                          [--field NAME] [--sizing uniform|thickness] [--graded] [--verbose]\n"
    "                          [--cells-across K] [--gradation G] [--refuse-self-intersecting]\n"
    "  INPUT  a closed triangle surface (OFF, OBJ, PLY, STL, ...) or one of sphere, cube, torus,\n"
    "         torus-in-ball (the torus inside a ball of radius 2: two subdomains)\n"
    "  --vertices N        target vertex count of the initial mesh, within 10% (default 10000)\n"
    "  --features-angle D  protect sharp edges whose dihedral angle deviates by more than D\n"
    "                      degrees (surfaces only; default 0 = none, 60 for cube)\n"
    "  --chains LIST       comma-separated chains of init, lloyd, odt, perturb, exude, gsm, gsm-esm,\n"
    "                      gsm-uniform (gsm with one target size instead of the input's local size),\n"
    "                      remesh (CGAL's tetrahedral_isotropic_remeshing, 3 iterations, feature\n"
    "                      edges constrained, the edge length that keeps the vertex count within\n"
    "                      10%; only gsm may follow it), joined by '+'\n"
    "                      (default: init,lloyd,odt,perturb,exude,perturb+exude,\n"
    "                       lloyd+perturb+exude,odt+perturb+exude,gsm,odt+gsm,lloyd+gsm)\n"
    "  --repeat N          runs per chain; optimizer times are medians (default 1)\n"
    "  --threads N         maximum number of threads (default: all cores)\n"
    "  --json FILE         write one JSON line per chain\n"
    "  --out-dir DIR       write <model>_<chain>.mesh, .vtu and a dihedral histogram .svg\n"
    "  --seed N            random seed of the mesher and the optimizers (default 0)\n"
    "  --field NAME        the dissertation's adaptive / anisotropic cases (section 3.4.4):\n"
    "                      adaptive-sphere (Fig. 3.7, INPUT sphere), anisotropic-sphere (Fig. 3.8,\n"
    "                      INPUT sphere), anisotropic-cube (Fig. 3.9, INPUT cube): the initial mesh\n"
    "                      follows the field's density, gsm gets the field, and quality is\n"
    "                      measured in the metric\n"
    "  --sizing S          uniform (default), or thickness: the initial mesh's size and gsm's sizing\n"
    "                      field follow the walls' and gaps' thickness, K cells across, graded by\n"
    "                      G (CGAL::Thickness_sizing_field_3), scaled to the vertex count; surfaces only\n"
    "  --cells-across K    with --sizing thickness (default 3)\n"
    "  --gradation G       with --sizing thickness: the size grows by at most G times the distance\n"
    "                      (default 0.3)\n"
    "  --graded            a graded initial mesh: facet distance s/100, facet and cell sizes 3s for\n"
    "                      the edge size s (fine where the surface curves, coarse inside)\n"
    "  --verbose           progress of the optimizers that report it (gsm)\n"
    "  --refuse-self-intersecting  stop with an error on a self-intersecting surface (default: a\n"
    "                      warning, and make_mesh_3 meshes what its inside test sees)\n";


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
      if(!(o.features_angle >= 0 && o.features_angle < 180))
        throw Input_error("--features-angle must be in [0, 180)");
    } else if(arg == "--chains") {
      std::stringstream ss(value());
      for(std::string c; std::getline(ss, c, ',');)
        if(!c.empty()) o.chains.push_back(c);
    } else if(arg == "--repeat") {
      o.repeat = parse_number<int>(arg, value());
      if(o.repeat < 1) throw Input_error("--repeat must be at least 1");
    } else if(arg == "--threads") {
      o.threads = parse_number<int>(arg, value());
      if(o.threads < 0) throw Input_error("--threads must be non-negative");
    } else if(arg == "--json") {
      o.json_file = value();
    } else if(arg == "--out-dir") {
      o.out_dir = value();
    } else if(arg == "--seed") {
      o.seed = parse_number<unsigned int>(arg, value());
    } else if(arg == "--field") {
      o.field = value();
    } else if(arg == "--sizing") {
      o.sizing = value();
      if(o.sizing != "uniform" && o.sizing != "thickness")
        throw Input_error("unknown --sizing '" + o.sizing + "' (known: uniform, thickness)");
    } else if(arg == "--cells-across") {
      o.cells_across = parse_number<double>(arg, value());
      if(!(o.cells_across > 0 && o.cells_across <= 100)) throw Input_error("--cells-across must be in (0, 100]");
    } else if(arg == "--gradation") {
      o.gradation = parse_number<double>(arg, value());
      if(!(o.gradation > 0 && o.gradation <= 10)) throw Input_error("--gradation must be in (0, 10]");
    } else if(arg == "--verbose") {
      o.verbose = true;
    } else if(arg == "--graded") {
      o.graded = true;
    } else if(arg == "--refuse-self-intersecting") {
      o.refuse_self_intersecting = true;
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
  if(o.chains.empty()) o.chains = default_chains();
  const std::string field_domain = o.field == "anisotropic-cube" ? "cube" : "sphere";
  if(!o.field.empty() && o.field != "adaptive-sphere" && o.field != "anisotropic-sphere" &&
     o.field != "anisotropic-cube")
    throw Input_error("unknown --field '" + o.field +
                      "' (known: adaptive-sphere, anisotropic-sphere, anisotropic-cube)");
  if(o.sizing == "thickness" && (!o.field.empty() || o.graded))
    throw Input_error("--sizing thickness sets the size itself: it cannot go with --field or --graded");
  if(o.sizing == "thickness" && is_implicit_domain_name(o.input))
    throw Input_error("--sizing thickness needs a surface INPUT, not '" + o.input + "'");
  if(!o.field.empty() && o.input != field_domain)
    throw Input_error("--field " + o.field + " is defined on INPUT " + field_domain);
  return o;
}

} // namespace
} // namespace vvm_benchmark

int main(int argc, char** argv)
{
  using namespace vvm_benchmark;
  try {
    const Options options = parse_command_line(argc, argv);
    std::unique_ptr<tbb::global_control> threads;
    if(options.threads > 0)
      threads = std::make_unique<tbb::global_control>(
          tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
    if(!options.out_dir.empty()) {
      std::error_code error;
      std::filesystem::create_directories(options.out_dir, error);
      if(error) throw Input_error("cannot create '" + options.out_dir + "': " + error.message());
    }
    if(is_implicit_domain_name(options.input))
      return run_implicit_domain(options);
    return run_polyhedral_domain(options);
  } catch(const Input_error& e) {
    std::cerr << "compare_optimizers: error: " << e.what() << "\n" << usage;
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "compare_optimizers: failed: " << e.what() << "\n";
    return 1;
  }
}
