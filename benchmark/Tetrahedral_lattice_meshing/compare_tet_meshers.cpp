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

#include <iostream>
#include <string>
#include <vector>

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

Options parse_command_line(int argc, char** argv)
{
  Options o;
  vvm_benchmark::Command_line c(argc, argv, usage);
  while(c.next()) {
    if(c.is("--vertices")) o.target_vertices = c.number_in<std::size_t>(100, 20000000);
    else if(c.is("--sizing")) o.sizing = c.one_of({"uniform", "thickness"});
    else if(c.is("--field")) o.field = c.value();
    else if(c.is("--methods")) o.methods = c.list();
    else if(c.is("--levels")) o.levels = c.number_in<int>(0, 6);
    else if(c.is("--sliver-bound")) {
      o.sliver_bound = c.number<double>();
      if(!(o.sliver_bound >= 0 && o.sliver_bound < 70.5)) throw Input_error("--sliver-bound must be in [0, 70.5)");
    } else c.common(o);
  }
  vvm_benchmark::Command_line::require_input(o);
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
  return vvm_benchmark::benchmark_main("compare_tet_meshers", usage, argc, argv, parse_command_line,
                                       [](const Options& options) {
                                         return is_implicit_domain_name(options.input) ? run_implicit_domain(options)
                                                                                       : run_polyhedral_domain(options);
                                       });
}
