// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of vvm-mesh: its usage texts, its parser, and the front end's
// options it gives. Apart from the program so that the parser can be fuzzed
// (fuzz/vvm_mesh_arguments.cpp) without running anything.

#ifndef VVM_MESH_COMMAND_LINE_H
#define VVM_MESH_COMMAND_LINE_H

#include "vvm_front_end.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace vvm {
namespace command_line {

inline const char* main_usage =
    "usage: vvm-mesh COMMAND [ARGS] (vvm-mesh COMMAND --help for each)\n"
    "\n"
    "commands:\n"
    "  tet INPUT -o OUT       tetrahedral mesh of a closed surface (OFF, OBJ, PLY, STL, ...) or of a\n"
    "                         labelled 3D image (.inr, .inr.gz): make_mesh_3 + GSM, or a BCC/FCC lattice\n"
    "  hexdom INPUT -o OUT    hex-dominant mesh of a closed surface (hexahedra, prisms, pyramids, tets)\n"
    "  optimize MESH -o OUT   GSM on a tet mesh made by any mesher (TetGen, Gmsh, ...), labels kept\n"
    "  quality MESH           the quality table of a tet or hex-dominant mesh\n"
    "  field INPUT -o FIELD   the boundary-aligned cross field of a closed surface (text format)\n"
    "  surface INPUT -o OUT   triangle mesh of a surface on a hexagonal lattice aligned with its\n"
    "                         principal curvature directions (.off, .obj, .ply, .stl)\n"
    "\n"
    "Mesh files: .mesh (MEDIT), .msh (Gmsh; 2.2 and 4.1 read, 4.1 written, physical groups =\n"
    "subdomains), .vtu (VTK; written with the per-cell quality). Exit codes: 0 done, 2 bad argument\n"
    "or input (nothing written), 1 a run that failed midway (nothing written).\n";

inline const char* tet_usage =
    "usage: vvm-mesh tet INPUT -o OUT [--method gsm|odt+gsm|perturb+exude|bcc|fcc]\n"
    "                    [--size H | --vertices N] [--features-angle DEG] [--field cross|identity|FILE]\n"
    "                    [--sizing uniform|thickness] [--threads N] [--seed N] [--time-limit S]\n"
    "                    [--json FILE] [--quiet]\n"
    "  INPUT               a closed triangle surface (OFF, OBJ, PLY, STL, ...), or a labelled 3D image\n"
    "                      (.inr, .inr.gz: each non-zero label a subdomain)\n"
    "  -o OUT              the mesh: .mesh, .msh or .vtu\n"
    "  --method M          gsm (default): CGAL's make_mesh_3, then GSM; odt+gsm: ODT first;\n"
    "                      perturb+exude: CGAL's own optimizers; bcc / fcc: a lattice mesh aligned\n"
    "                      with the field (surfaces)\n"
    "  --size H            the edge length sought\n"
    "  --vertices N        the number of vertices sought instead (default 10000; within 5% for\n"
    "                      make_mesh_3, the particle count of a lattice)\n"
    "  --features-angle D  protect the edges of the surface sharper than D degrees (default 60; 0: none)\n"
    "  --field F           cross (default): the boundary-aligned cross field; identity; or a frame-field\n"
    "                      file (vvm-mesh field): the lattice's field, GSM's target metric B^T B\n"
    "  --sizing S          uniform (default), or thickness: the size follows the surface's walls, gaps\n"
    "                      and the faces between its protected features, 3 cells across, graded by\n"
    "                      0.3 (surfaces); --size is then its median\n"
    "                      over the surface, --vertices still the count\n"
    "  --threads N         at most N threads (default: all cores)\n"
    "  --seed N            random seed (default 0): the same seed gives the same mesh\n"
    "  --time-limit S      stop the optimizer (or the lattice) after S seconds, with a valid mesh\n"
    "                      (default 0: none; make_mesh_3 is not counted)\n"
    "  --json FILE         the summary figures as one JSON line\n"
    "  --quiet             no progress on stderr\n"
    "example: vvm-mesh tet data/fandisk.off -o fandisk.msh\n";

inline const char* hexdom_usage =
    "usage: vvm-mesh hexdom INPUT -o OUT [--particles N | --size H] [--q-bound Q] [--boundary-distance D]\n"
    "                       [--features-angle DEG] [--field cross|identity|FILE] [--threads N] [--seed N]\n"
    "                       [--sizing uniform|thickness] [--maximum-size-ratio R] [--time-limit S]\n"
    "                       [--json FILE] [--quiet]\n"
    "  INPUT               a closed triangle surface (OFF, OBJ, PLY, STL, ...)\n"
    "  -o OUT              the mesh: .mesh, .msh or .vtu (hexahedra, prisms, pyramids, tetrahedra)\n"
    "  --particles N       the number of cubic-lattice particles sought (default 30000)\n"
    "  --size H            the lattice's edge length instead\n"
    "  --q-bound Q         the merging's quality bound Q_bound in [0, 1] (default 0.5; lower: more\n"
    "                      hexahedra, of lower quality)\n"
    "  --boundary-distance D  refine the boundary until it is within D of the surface (default 0: no\n"
    "                      refinement)\n"
    "  --features-angle D  sharp edges of the surface (default 60; 0: none)\n"
    "  --field F           cross (default), identity, or a frame-field file\n"
    "  --sizing S          uniform (default), or thickness: the field's frames scaled as for tet (the\n"
    "                      lattice breaks into non-hex cells where its size changes: on parts with\n"
    "                      walls of very different thicknesses, far fewer hexahedra)\n"
    "  --maximum-size-ratio R  the cross field's scales are corrected so that the lattice's layers\n"
    "                      follow its turning, within a ratio R of each other (default 2; 1: none)\n"
    "  --time-limit S      stop after S seconds (field, particles, merging), with a valid mesh whose\n"
    "                      unmerged tets stay tetrahedra (default 0: none)\n"
    "  --threads N, --seed N, --json FILE, --quiet  as for tet\n";

inline const char* optimize_usage =
    "usage: vvm-mesh optimize MESH -o OUT [--features-angle DEG] [--boundary-distance D] [--fixed-boundary]\n"
    "                         [--threads N] [--seed N] [--time-limit S] [--json FILE] [--quiet]\n"
    "  MESH                a tetrahedral mesh (.mesh, .msh, .vtu) made by any mesher, with its subdomain\n"
    "                      labels (MEDIT references, Gmsh physical groups, a VTU cell array)\n"
    "  -o OUT              the optimized mesh, labels kept; without an extension, MESH's is used\n"
    "  --features-angle D  boundary and interface edges sharper than D degrees stay in place, the\n"
    "                      surfaces between them are the ones boundary vertices slide on (default 60;\n"
    "                      0: only the edges where surfaces meet)\n"
    "  --boundary-distance D  how far the boundary may stray from MESH's boundary, both ways (default 1%\n"
    "                      of its mean edge length; 0: boundary vertices slide on its flat parts only)\n"
    "  --fixed-boundary    move interior vertices only\n"
    "  --threads N, --seed N, --time-limit S, --json FILE, --quiet  as for tet\n"
    "Parts that touch at a vertex or along edges are taken (the vertices where they touch stay in place).\n"
    "Refused (exit 2): inverted or flat tetrahedra, a facet of three tetrahedra, non-finite coordinates,\n"
    "cells other than tetrahedra.\n";

inline const char* quality_usage =
    "usage: vvm-mesh quality MESH [--json FILE]\n"
    "  MESH                a tetrahedral or hex-dominant mesh (.mesh, .msh, .vtu)\n"
    "  prints the cell counts, the tets' dihedral angles (extremes, mean smallest, counts under\n"
    "  10-40 degrees, histogram of the smallest), radius ratios, the scaled Jacobians, H_vol% and\n"
    "  the number of inverted cells\n";

inline const char* field_usage =
    "usage: vvm-mesh field INPUT -o FIELD [--size H | --vertices N] [--features-angle DEG] [--seed N]\n"
    "                      [--time-limit S] [--quiet]\n"
    "  INPUT               a closed triangle surface (OFF, OBJ, PLY, STL, ...)\n"
    "  -o FIELD            the cross field, one frame per vertex of a tet mesh of INPUT, in the text\n"
    "                      format --field reads\n"
    "  --size H, --vertices N  the size of that tet mesh (default 10000 vertices)\n"
    "  --time-limit S      stop the field's smoothing after S seconds (default 0: none)\n";

inline const char* surface_usage =
    "usage: vvm-mesh surface INPUT -o OUT [--vertices N | --size H] [--field curvature|isotropic|identity|FILE]\n"
    "                        [--maximum-anisotropy A] [--maximum-size-ratio R] [--features-angle DEG]\n"
    "                        [--threads N] [--seed N] [--time-limit S] [--json FILE] [--quiet]\n"
    "  INPUT               a triangle surface, open or closed (OFF, OBJ, PLY, STL, ...)\n"
    "  -o OUT              the triangle mesh: .off, .obj, .ply or .stl (binary)\n"
    "  --vertices N        the number of vertices sought (default 10000; within about 5%)\n"
    "  --size H            the lattice's edge length in the field's metric instead (curvature: the\n"
    "                      edges are about H times 1/sqrt|k|; identity: H)\n"
    "  --field F           curvature (default): along the principal curvature directions, the edges\n"
    "                      1/sqrt|k| long, so that each leaves the surface by about as much;\n"
    "                      isotropic: the same directions, one length; identity: the x axis\n"
    "                      projected, one length everywhere; or a frame-field file (a frame per vertex\n"
    "                      of INPUT, or a volume field as vvm-mesh field writes): at each vertex the\n"
    "                      two axes nearest to the tangent plane\n"
    "  --maximum-anisotropy A  curvature: the largest ratio of an edge across to one along (default 3)\n"
    "  --maximum-size-ratio R  curvature, isotropic: the largest ratio of two edge lengths (default 4)\n"
    "  --features-angle D  keep the edges of the surface sharper than D degrees (default 60; 0: none);\n"
    "                      its borders are always kept\n"
    "  --time-limit S      stop the particles after S seconds, with a valid mesh (default 0: none)\n"
    "  --threads N, --seed N, --json FILE, --quiet  as for tet\n"
    "  The summary gives the quality in the field's metric: r6 (the share of degree-6 vertices off the\n"
    "  sharp edges), xi (4 sqrt(3) area / (perimeter x longest edge), 1 for equilateral), the smallest\n"
    "  angle, the edges' angle to the lattice's directions.\n"
    "example: vvm-mesh surface data/surfaces/torus.off -o torus.off --vertices 3000\n";

/// a command line of vvm-mesh, parsed
struct Arguments
{
  std::string command, input, output, json;
  bool quiet = false, fixed_boundary = false;
  std::map<std::string, std::string> values; ///< --option -> value
  const char* help = nullptr;                 ///< --help: the usage to print, and nothing to run
};

template <class T>
T number(const Arguments& a, const std::string& option, T fallback)
{
  const auto it = a.values.find(option);
  if(it == a.values.end()) return fallback;
  std::istringstream is(it->second);
  T value;
  if(!(is >> value) || !is.eof()) throw Input_error("option " + option + " expects a number, got '" + it->second + "'");
  return value;
}

inline std::size_t count(const Arguments& a, const std::string& option, std::size_t fallback)
{
  const double n = number<double>(a, option, double(fallback));
  if(!(n >= 1 && n <= 2e7) || n != std::floor(n))
    throw Input_error("option " + option + " expects a whole number between 1 and 2e7");
  return std::size_t(n);
}

inline unsigned int seed(const Arguments& a)
{
  const long long s = number<long long>(a, "--seed", 0);
  if(s < 0 || s > 4294967295LL) throw Input_error("--seed must be between 0 and 4294967295");
  return static_cast<unsigned int>(s);
}

/// --time-limit: seconds, non-negative and finite (0: none)
inline double time_limit(const Arguments& a)
{
  const double s = number<double>(a, "--time-limit", 0.);
  if(!(s >= 0 && s < 1e12)) throw Input_error("--time-limit must be a non-negative number of seconds");
  return s;
}

inline std::string text(const Arguments& a, const std::string& option, const std::string& fallback)
{
  const auto it = a.values.find(option);
  return it == a.values.end() ? fallback : it->second;
}

inline const char* usage_of(const std::string& command)
{
  if(command == "tet") return tet_usage;
  if(command == "hexdom") return hexdom_usage;
  if(command == "optimize") return optimize_usage;
  if(command == "quality") return quality_usage;
  if(command == "field") return field_usage;
  if(command == "surface") return surface_usage;
  return main_usage;
}

/// the command line `argv[0..argc)`; Input_error if it is not one vvm-mesh takes
inline Arguments parse(int argc, const char* const* argv)
{
  Arguments a;
  if(argc < 2) throw Input_error("no command given");
  a.command = argv[1];
  if(a.command == "--help" || a.command == "-h" || a.command == "help") {
    a.help = main_usage;
    return a;
  }
  static const std::map<std::string, std::vector<std::string>> options{
      {"tet", {"--method", "--size", "--vertices", "--features-angle", "--field", "--sizing", "--threads", "--seed",
               "--time-limit"}},
      {"hexdom", {"--particles", "--size", "--q-bound", "--boundary-distance", "--features-angle", "--field",
                  "--sizing", "--maximum-size-ratio", "--threads", "--seed", "--time-limit"}},
      {"optimize", {"--features-angle", "--boundary-distance", "--threads", "--seed", "--time-limit"}},
      {"quality", {}},
      {"field", {"--size", "--vertices", "--features-angle", "--seed", "--time-limit"}},
      {"surface", {"--vertices", "--size", "--field", "--maximum-anisotropy", "--maximum-size-ratio", "--features-angle",
                   "--threads", "--seed", "--time-limit"}}};
  const auto known = options.find(a.command);
  if(known == options.end()) throw Input_error("unknown command '" + a.command + "'");
  for(int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Input_error("option " + arg + " expects a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") {
      a.help = usage_of(a.command);
      return a;
    } else if(arg == "-o" || arg == "--output") {
      if(a.command == "quality") throw Input_error("quality writes no mesh (use --json FILE)");
      a.output = value();
    } else if(arg == "--json") {
      if(a.command == "field") throw Input_error("field has no --json");
      a.json = value();
    } else if(arg == "--quiet") {
      a.quiet = true;
    } else if(arg == "--fixed-boundary" && a.command == "optimize") {
      a.fixed_boundary = true;
    } else if(std::find(known->second.begin(), known->second.end(), arg) != known->second.end()) {
      if(a.values.count(arg)) throw Input_error("option " + arg + " given twice");
      a.values[arg] = value();
    } else if(!arg.empty() && arg[0] == '-' && arg != "-") {
      throw Input_error("unknown option " + arg + " for " + a.command);
    } else if(a.input.empty()) {
      a.input = arg;
    } else {
      throw Input_error("more than one input given ('" + a.input + "', '" + arg + "')");
    }
  }
  if(a.input.empty()) throw Input_error("no input file given");
  if(a.command != "quality" && a.output.empty()) throw Input_error("no output given (-o OUT)");
  if(a.values.count("--size") && (a.values.count("--vertices") || a.values.count("--particles")))
    throw Input_error("give --size or a count, not both");
  return a;
}


/// the options of `vvm-mesh field`
inline vvm::Field_options field_options(const Arguments& a)
{
  vvm::Field_options o;
  o.size.size = number<double>(a, "--size", 0.);
  o.size.vertices = count(a, "--vertices", o.size.vertices);
  o.features_angle = number<double>(a, "--features-angle", o.features_angle);
  o.seed = seed(a);
  o.time_limit = time_limit(a);
  return o;
}

/// the options of `vvm-mesh tet`
inline vvm::Tet_options tet_options(const Arguments& a)
{
  vvm::Tet_options o;
  o.method = text(a, "--method", o.method);
  o.size.size = number<double>(a, "--size", 0.);
  o.size.vertices = count(a, "--vertices", o.size.vertices);
  o.features_angle = number<double>(a, "--features-angle", o.features_angle);
  o.field = text(a, "--field", o.field);
  o.sizing = text(a, "--sizing", o.sizing);
  o.threads = number<int>(a, "--threads", 0);
  o.seed = seed(a);
  o.time_limit = time_limit(a);
  return o;
}

/// the options of `vvm-mesh hexdom`
inline vvm::Hex_dominant_options hex_dominant_options(const Arguments& a)
{
  vvm::Hex_dominant_options o;
  o.size.size = number<double>(a, "--size", 0.);
  o.size.vertices = count(a, "--particles", o.size.vertices);
  o.quality_bound = number<double>(a, "--q-bound", o.quality_bound);
  o.boundary_distance = number<double>(a, "--boundary-distance", 0.);
  o.features_angle = number<double>(a, "--features-angle", o.features_angle);
  o.field = text(a, "--field", o.field);
  o.sizing = text(a, "--sizing", o.sizing);
  o.maximum_size_ratio = number<double>(a, "--maximum-size-ratio", o.maximum_size_ratio);
  o.threads = number<int>(a, "--threads", 0);
  o.seed = seed(a);
  o.time_limit = time_limit(a);
  return o;
}

/// the options of `vvm-mesh surface`
inline vvm::Surface_options surface_options(const Arguments& a)
{
  vvm::Surface_options o;
  o.size.size = number<double>(a, "--size", 0.);
  o.size.vertices = count(a, "--vertices", o.size.vertices);
  o.field = text(a, "--field", o.field);
  o.maximum_anisotropy = number<double>(a, "--maximum-anisotropy", o.maximum_anisotropy);
  o.maximum_size_ratio = number<double>(a, "--maximum-size-ratio", o.maximum_size_ratio);
  o.features_angle = number<double>(a, "--features-angle", o.features_angle);
  o.threads = number<int>(a, "--threads", 0);
  o.seed = seed(a);
  o.time_limit = time_limit(a);
  return o;
}

/// the options of `vvm-mesh optimize`
inline vvm::Optimize_options optimize_options(const Arguments& a)
{
  vvm::Optimize_options o;
  o.features_angle = number<double>(a, "--features-angle", o.features_angle);
  o.fixed_boundary = a.fixed_boundary;
  o.boundary_distance = number<double>(a, "--boundary-distance", -1.);
  if(a.values.count("--boundary-distance") && !(o.boundary_distance >= 0))
    throw Input_error("--boundary-distance must be non-negative");
  o.threads = number<int>(a, "--threads", 0);
  o.seed = seed(a);
  o.time_limit = time_limit(a);
  return o;
}

// -o without an extension takes the input's (optimize)
inline Arguments with_output_extension(Arguments a)
{
  namespace fs = std::filesystem;
  if(a.command == "optimize" && !a.output.empty() && !fs::path(a.output).has_extension())
    a.output += fs::path(a.input).extension().string();
  return a;
}

} // namespace command_line
} // namespace vvm

#endif // VVM_MESH_COMMAND_LINE_H
