// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// vvm-mesh: VVM from the command line. Mesh a closed surface or a labelled
// image with tetrahedra (GSM, lattices) or hex-dominant cells, clean up a tet
// mesh made by any mesher, measure any mesh, export a cross field.
// Exit codes: 0 done, 2 bad argument or input, 1 a run that failed midway.

#include "vvm_front_end.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using vvm::Input_error;

const char* main_usage =
    "usage: vvm-mesh COMMAND [ARGS] (vvm-mesh COMMAND --help for each)\n"
    "\n"
    "commands:\n"
    "  tet INPUT -o OUT       tetrahedral mesh of a closed surface (OFF, OBJ, PLY, STL, ...) or of a\n"
    "                         labelled 3D image (.inr, .inr.gz): make_mesh_3 + GSM, or a BCC/FCC lattice\n"
    "  hexdom INPUT -o OUT    hex-dominant mesh of a closed surface (hexahedra, prisms, pyramids, tets)\n"
    "  optimize MESH -o OUT   GSM on a tet mesh made by any mesher (TetGen, Gmsh, ...), labels kept\n"
    "  quality MESH           the quality table of a tet or hex-dominant mesh\n"
    "  field INPUT -o FIELD   the boundary-aligned cross field of a closed surface (text format)\n"
    "\n"
    "Mesh files: .mesh (MEDIT), .msh (Gmsh; 2.2 and 4.1 read, 4.1 written, physical groups =\n"
    "subdomains), .vtu (VTK; written with the per-cell quality). Exit codes: 0 done, 2 bad argument\n"
    "or input (nothing written), 1 a run that failed midway (nothing written).\n";

const char* tet_usage =
    "usage: vvm-mesh tet INPUT -o OUT [--method gsm|odt+gsm|perturb+exude|bcc|fcc]\n"
    "                    [--size H | --vertices N] [--features-angle DEG] [--field cross|identity|FILE]\n"
    "                    [--threads N] [--seed N] [--json FILE] [--quiet]\n"
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
    "  --threads N         at most N threads (default: all cores)\n"
    "  --seed N            random seed (default 0): the same seed gives the same mesh\n"
    "  --json FILE         the summary figures as one JSON line\n"
    "  --quiet             no progress on stderr\n"
    "example: vvm-mesh tet data/fandisk.off -o fandisk.msh\n";

const char* hexdom_usage =
    "usage: vvm-mesh hexdom INPUT -o OUT [--particles N | --size H] [--q-bound Q] [--boundary-distance D]\n"
    "                       [--features-angle DEG] [--field cross|identity|FILE] [--threads N] [--seed N]\n"
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
    "  --threads N, --seed N, --json FILE, --quiet  as for tet\n";

const char* optimize_usage =
    "usage: vvm-mesh optimize MESH -o OUT [--features-angle DEG] [--boundary-distance D] [--fixed-boundary]\n"
    "                         [--threads N] [--seed N] [--json FILE] [--quiet]\n"
    "  MESH                a tetrahedral mesh (.mesh, .msh, .vtu) made by any mesher, with its subdomain\n"
    "                      labels (MEDIT references, Gmsh physical groups, a VTU cell array)\n"
    "  -o OUT              the optimized mesh, labels kept; without an extension, MESH's is used\n"
    "  --features-angle D  boundary and interface edges sharper than D degrees stay in place, the\n"
    "                      surfaces between them are the ones boundary vertices slide on (default 60;\n"
    "                      0: only the edges where surfaces meet)\n"
    "  --boundary-distance D  how far the boundary facets may stray from MESH's boundary (default 1% of\n"
    "                      its mean edge length; 0: boundary vertices slide on its flat parts only)\n"
    "  --fixed-boundary    move interior vertices only\n"
    "  --threads N, --seed N, --json FILE, --quiet  as for tet\n"
    "Refused (exit 2): inverted or flat tetrahedra, a facet of three tetrahedra, a boundary that is not\n"
    "a manifold, non-finite coordinates, cells other than tetrahedra.\n";

const char* quality_usage =
    "usage: vvm-mesh quality MESH [--json FILE]\n"
    "  MESH                a tetrahedral or hex-dominant mesh (.mesh, .msh, .vtu)\n"
    "  prints the cell counts, the tets' dihedral angles (extremes, mean smallest, counts under\n"
    "  10-40 degrees, histogram of the smallest), radius ratios, the scaled Jacobians, H_vol% and\n"
    "  the number of inverted cells\n";

const char* field_usage =
    "usage: vvm-mesh field INPUT -o FIELD [--size H | --vertices N] [--features-angle DEG] [--seed N]\n"
    "                      [--quiet]\n"
    "  INPUT               a closed triangle surface (OFF, OBJ, PLY, STL, ...)\n"
    "  -o FIELD            the cross field, one frame per vertex of a tet mesh of INPUT, in the text\n"
    "                      format --field reads\n"
    "  --size H, --vertices N  the size of that tet mesh (default 10000 vertices)\n";

// Progress on stderr: on a terminal one line rewritten in place; otherwise one line per stage
class Progress_printer
{
public:
  explicit Progress_printer(bool quiet) : quiet_(quiet), terminal_(isatty(STDERR_FILENO) != 0) {}
  ~Progress_printer() { finish(); }

  void operator()(const vvm::Progress_event& e)
  {
    if(quiet_) return;
    if(e.stage != stage_) {
      finish();
      stage_ = e.stage;
      shown_ = -1;
    }
    if(!e.detail.empty()) detail_ = e.detail;
    elapsed_ = e.elapsed;
    if(e.fraction >= 1) { // the stage ended
      finish();
      return;
    }
    if(terminal_ && (e.elapsed >= 1 || shown_ < 0) && e.elapsed - shown_ >= 0.1) {
      std::fprintf(stderr, "\r\033[K%s: %s (%.1f s)", stage_.c_str(), detail_.c_str(), elapsed_);
      std::fflush(stderr);
      shown_ = e.elapsed;
    }
  }

  void finish()
  {
    if(quiet_ || stage_.empty()) return;
    std::fprintf(stderr, "%s%s: %s (%.1f s)\n", terminal_ ? "\r\033[K" : "", stage_.c_str(), detail_.c_str(), elapsed_);
    stage_.clear();
    detail_.clear();
  }

private:
  bool quiet_, terminal_;
  std::string stage_, detail_;
  double elapsed_ = 0, shown_ = -1;
};

struct Arguments
{
  std::string command, input, output, json;
  bool quiet = false, fixed_boundary = false;
  std::map<std::string, std::string> values; // --option -> value
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

std::size_t count(const Arguments& a, const std::string& option, std::size_t fallback)
{
  const double n = number<double>(a, option, double(fallback));
  if(!(n >= 1 && n <= 2e7) || n != std::floor(n))
    throw Input_error("option " + option + " expects a whole number between 1 and 2e7");
  return std::size_t(n);
}

unsigned int seed(const Arguments& a)
{
  const long long s = number<long long>(a, "--seed", 0);
  if(s < 0 || s > 4294967295LL) throw Input_error("--seed must be between 0 and 4294967295");
  return static_cast<unsigned int>(s);
}

std::string text(const Arguments& a, const std::string& option, const std::string& fallback)
{
  const auto it = a.values.find(option);
  return it == a.values.end() ? fallback : it->second;
}

const char* usage_of(const std::string& command)
{
  if(command == "tet") return tet_usage;
  if(command == "hexdom") return hexdom_usage;
  if(command == "optimize") return optimize_usage;
  if(command == "quality") return quality_usage;
  if(command == "field") return field_usage;
  return main_usage;
}

Arguments parse(int argc, char** argv)
{
  Arguments a;
  if(argc < 2) throw Input_error("no command given");
  a.command = argv[1];
  if(a.command == "--help" || a.command == "-h" || a.command == "help") {
    std::cout << main_usage;
    std::exit(0);
  }
  static const std::map<std::string, std::vector<std::string>> options{
      {"tet", {"--method", "--size", "--vertices", "--features-angle", "--field", "--threads", "--seed"}},
      {"hexdom", {"--particles", "--size", "--q-bound", "--boundary-distance", "--features-angle", "--field",
                  "--threads", "--seed"}},
      {"optimize", {"--features-angle", "--boundary-distance", "--threads", "--seed"}},
      {"quality", {}},
      {"field", {"--size", "--vertices", "--features-angle", "--seed"}}};
  const auto known = options.find(a.command);
  if(known == options.end()) throw Input_error("unknown command '" + a.command + "'");
  for(int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Input_error("option " + arg + " expects a value");
      return argv[++i];
    };
    if(arg == "--help" || arg == "-h") {
      std::cout << usage_of(a.command);
      std::exit(0);
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

// the output's folder exists and its extension is known, before any long work
void check_output(const Arguments& a)
{
  namespace fs = std::filesystem;
  for(const std::string& out : {a.output, a.json}) {
    if(out.empty()) continue;
    const fs::path p(out);
    std::error_code error;
    if(p.has_parent_path() && !fs::is_directory(p.parent_path(), error))
      throw Input_error("cannot write '" + out + "': no folder '" + p.parent_path().string() + "'");
    if(fs::is_directory(p, error)) throw Input_error("cannot write '" + out + "': it is a folder");
  }
  if(a.command != "quality" && a.command != "field" && !vvm::is_volume_mesh_file(a.output))
    throw Input_error("unknown output extension in '" + a.output + "' (known: .mesh, .msh, .vtu)");
  if(!a.json.empty() && (fs::path(a.json) == fs::path(a.output) || fs::path(a.json) == fs::path(a.input)))
    throw Input_error("--json '" + a.json + "' would overwrite the input or the output");
  if(a.command != "quality" && fs::path(a.output) == fs::path(a.input))
    throw Input_error("the output '" + a.output + "' is the input: write elsewhere");
}

void print_summary(const vvm::Mesh_quality& q, const vvm::Run_report& r, bool full)
{
  std::printf("%-26s %zu\n", "vertices", q.vertices);
  std::printf("%-26s %zu", "cells", q.cells);
  if(q.hexahedra + q.prisms + q.pyramids > 0)
    std::printf(" (%zu hexahedra, %zu prisms, %zu pyramids, %zu tetrahedra)", q.hexahedra, q.prisms, q.pyramids,
                q.tetrahedra);
  std::printf("\n");
  if(q.labels.size() > 1 || full) {
    std::printf("%-26s", "subdomain labels");
    for(int l : q.labels) std::printf(" %d", l);
    std::printf("\n");
  }
  if(q.tetrahedra > 0) {
    std::printf("%-26s %.2f\n", "smallest dihedral angle", q.min_dihedral);
    if(full) std::printf("%-26s %.2f\n", "largest dihedral angle", q.max_dihedral);
    std::printf("%-26s %.2f\n", "mean smallest angle", q.mean_min_dihedral);
    std::printf("%-26s %zu / %zu / %zu / %zu\n", "tets under 10/20/30/40", q.tets_under[0], q.tets_under[1],
                q.tets_under[2], q.tets_under[3]);
    if(full) {
      std::printf("%-26s %.4f / %.4f\n", "radius ratio min / mean", q.min_radius_ratio, q.mean_radius_ratio);
      std::printf("smallest angle histogram (tets per 10 degrees):\n");
      for(std::size_t b = 0; b < q.min_dihedral_histogram.size(); ++b)
        if(q.min_dihedral_histogram[b] > 0)
          std::printf("  %3zu-%3zu  %zu\n", 10 * b, 10 * b + 10, q.min_dihedral_histogram[b]);
    }
  }
  if(q.hexahedra + q.prisms + q.pyramids > 0 || full) {
    std::printf("%-26s %.2f\n", "hex volume (H_vol%)", q.hex_volume_percent);
    std::printf("%-26s %.4f\n", "smallest scaled Jacobian", q.min_scaled_jacobian);
    if(q.hexahedra > 0) std::printf("%-26s %.4f\n", "mean hex scaled Jacobian", q.mean_hex_scaled_jacobian);
  }
  std::printf("%-26s %zu\n", "inverted cells", q.inverted);
  if(r.boundary_hausdorff >= 0)
    std::printf("%-26s %.3g (bound %.3g)\n", "boundary moved by", r.boundary_hausdorff, r.boundary_distance_bound);
  if(!full) std::printf("%-26s %.2f s (mesh %.2f s, %s %.2f s)\n", "time", r.mesh_time + r.optimize_time,
                        r.mesh_time, r.method.c_str(), r.optimize_time);
  std::fflush(stdout);
}

int run(const Arguments& a)
{
  check_output(a);
  Progress_printer printer(a.quiet);
  const vvm::Progress progress = [&printer](const vvm::Progress_event& e) { printer(e); };
  vvm::Run_report report;
  vvm::Volume_mesh mesh;
  if(a.command == "field") {
    vvm::Field_options o;
    o.size.size = number<double>(a, "--size", 0.);
    o.size.vertices = count(a, "--vertices", o.size.vertices);
    o.features_angle = number<double>(a, "--features-angle", o.features_angle);
    o.seed = seed(a);
    const std::string field = vvm::cross_field(a.input, o, progress, &report);
    printer.finish();
    vvm::write_text_file(field, a.output);
    std::printf("cross field written to %s (%.2f s)\n", a.output.c_str(), report.mesh_time + report.optimize_time);
    return 0;
  }
  if(a.command == "tet") {
    vvm::Tet_options o;
    o.method = text(a, "--method", o.method);
    o.size.size = number<double>(a, "--size", 0.);
    o.size.vertices = count(a, "--vertices", o.size.vertices);
    o.features_angle = number<double>(a, "--features-angle", o.features_angle);
    o.field = text(a, "--field", o.field);
    o.threads = number<int>(a, "--threads", 0);
    o.seed = seed(a);
    mesh = vvm::tet_mesh(a.input, o, progress, &report);
  } else if(a.command == "hexdom") {
    vvm::Hex_dominant_options o;
    o.size.size = number<double>(a, "--size", 0.);
    o.size.vertices = count(a, "--particles", o.size.vertices);
    o.quality_bound = number<double>(a, "--q-bound", o.quality_bound);
    o.boundary_distance = number<double>(a, "--boundary-distance", 0.);
    o.features_angle = number<double>(a, "--features-angle", o.features_angle);
    o.field = text(a, "--field", o.field);
    o.threads = number<int>(a, "--threads", 0);
    o.seed = seed(a);
    mesh = vvm::hex_dominant_mesh(a.input, o, progress, &report);
  } else {
    mesh = vvm::read_volume_mesh(a.input);
    report.input = a.input;
    report.method = "quality";
    if(a.command == "optimize") {
      if(std::filesystem::path(a.output).extension() == ".msh")
        for(const vvm::Volume_mesh::Cell& c : mesh.cells)
          if(c.subdomain_index <= 0)
            throw Input_error("'" + a.input + "' has the label " + std::to_string(c.subdomain_index) +
                              ", which Gmsh files cannot hold (positive tags only): write .mesh or .vtu");
      vvm::Optimize_options o;
      o.features_angle = number<double>(a, "--features-angle", o.features_angle);
      o.fixed_boundary = a.fixed_boundary;
      o.boundary_distance = number<double>(a, "--boundary-distance", -1.);
      if(a.values.count("--boundary-distance") && !(o.boundary_distance >= 0))
        throw Input_error("--boundary-distance must be non-negative");
      o.threads = number<int>(a, "--threads", 0);
      o.seed = seed(a);
      mesh = vvm::optimize_tet_mesh(mesh, o, progress, &report);
      report.input = a.input;
    }
  }
  printer.finish();
  const vvm::Mesh_quality q = vvm::mesh_quality(mesh);
  if(a.command != "quality") vvm::write_volume_mesh(mesh, a.output);
  if(!a.json.empty()) vvm::write_text_file(vvm::json_line(report, q), a.json);
  if(a.command != "quality") std::printf("%s written to %s\n", a.command.c_str(), a.output.c_str());
  print_summary(q, report, a.command == "quality");
  return 0;
}

// -o without an extension takes the input's (optimize)
Arguments with_output_extension(Arguments a)
{
  namespace fs = std::filesystem;
  if(a.command == "optimize" && !a.output.empty() && !fs::path(a.output).has_extension())
    a.output += fs::path(a.input).extension().string();
  return a;
}

} // namespace

int main(int argc, char** argv)
{
  std::string command = argc > 1 ? argv[1] : "";
  try {
    return run(with_output_extension(parse(argc, argv)));
  } catch(const Input_error& e) {
    std::cerr << "vvm-mesh: error: " << e.what() << "\n"
              << "(vvm-mesh " << (usage_of(command) == main_usage ? "" : command + " ") << "--help for the usage)\n";
    return 2;
  } catch(const std::bad_alloc&) {
    std::cerr << "vvm-mesh: failed: out of memory\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "vvm-mesh: failed: " << e.what() << "\n";
    return 1;
  }
}
