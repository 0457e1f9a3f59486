// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// vvm-mesh: VVM from the command line. Mesh a closed surface or a labelled
// image with tetrahedra (GSM, lattices) or hex-dominant cells, clean up a tet
// mesh made by any mesher, measure any mesh, export a cross field, remesh a
// surface with field-aligned triangles.
// Exit codes: 0 done, 2 bad argument or input, 1 a run that failed midway.

#include "command_line.h"
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
using namespace vvm::command_line;

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
  if(a.command == "surface" && !vvm::is_surface_mesh_file(a.output))
    throw Input_error("unknown output extension in '" + a.output + "' (known: .off, .obj, .ply, .stl)");
  if(a.command != "quality" && a.command != "field" && a.command != "surface" && !vvm::is_volume_mesh_file(a.output))
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
  if(!full) std::printf("%-26s %.2f s (mesh %.2f s, %s %.2f s)%s\n", "time", r.mesh_time + r.optimize_time,
                        r.mesh_time, r.method.c_str(), r.optimize_time,
                        r.time_limit_reached ? ", stopped at the time limit" : "");
  std::fflush(stdout);
}

void print_surface_summary(const vvm::Surface_quality& q, const vvm::Run_report& r)
{
  std::printf("%-26s %zu\n", "vertices", q.number_of_vertices);
  std::printf("%-26s %zu\n", "faces", q.number_of_faces);
  std::printf("in the %s field's metric:\n", r.field.c_str());
  std::printf("%-26s %.3f\n", "degree-6 vertices (r6)", q.r6);
  std::printf("%-26s %.3f / %.3f\n", "xi mean / min", q.xi_mean, q.xi_min);
  std::printf("%-26s %.2f (mean smallest %.2f)\n", "smallest angle", q.min_angle, q.mean_min_angle);
  std::printf("%-26s %.2f\n", "edges off the lattice", q.alignment_error_mean);
  std::printf("%-26s %s\n", "closed manifold", q.is_closed_manifold ? "yes" : "no");
  std::printf("%-26s %.2f s (field %.2f s, lattice %.2f s)%s\n", "time", r.run_time, r.mesh_time, r.optimize_time,
              r.time_limit_reached ? ", stopped at the time limit" : "");
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
    const std::string field = vvm::cross_field(a.input, field_options(a), progress, &report);
    printer.finish();
    vvm::write_text_file(field, a.output);
    std::printf("cross field written to %s (%.2f s%s)\n", a.output.c_str(), report.mesh_time + report.optimize_time,
                report.time_limit_reached ? ", smoothing stopped at the time limit" : "");
    return 0;
  }
  if(a.command == "surface") {
    const vvm::Surface_mesh_result surface = vvm::surface_mesh(a.input, surface_options(a), progress, &report);
    printer.finish();
    vvm::write_surface_mesh(surface, a.output);
    if(!a.json.empty()) vvm::write_text_file(vvm::json_line(report, surface.quality), a.json);
    std::printf("surface written to %s\n", a.output.c_str());
    print_surface_summary(surface.quality, report);
    return 0;
  }
  if(a.command == "tet") {
    mesh = vvm::tet_mesh(a.input, tet_options(a), progress, &report);
  } else if(a.command == "hexdom") {
    mesh = vvm::hex_dominant_mesh(a.input, hex_dominant_options(a), progress, &report);
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
      mesh = vvm::optimize_tet_mesh(mesh, optimize_options(a), progress, &report);
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

} // namespace

int main(int argc, char** argv)
{
  std::string command = argc > 1 ? argv[1] : "";
  try {
    const Arguments a = parse(argc, argv);
    if(a.help) {
      std::cout << a.help;
      return 0;
    }
    return run(with_output_extension(a));
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
