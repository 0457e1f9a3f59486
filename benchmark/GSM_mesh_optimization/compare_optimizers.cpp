// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_optimizers INPUT [--vertices N] [--features-angle DEG] [--chains c1,c2,...]
//                    [--repeat N] [--threads N] [--json FILE] [--out-dir DIR] [--seed N]
//
// Builds one initial mesh with make_mesh_3 (no optimizer) at about N vertices,
// runs each optimizer chain on its own copy and prints the quality table.

#include "compare_optimizers.h"

#include <iostream>
#include <string>
#include <vector>

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
  Command_line c(argc, argv, usage);
  while(c.next()) {
    if(c.is("--vertices")) o.target_vertices = c.number_in<std::size_t>(100, 20000000);
    else if(c.is("--chains")) o.chains = c.list();
    else if(c.is("--repeat")) o.repeat = c.number_in<int>(1, 1000);
    else if(c.is("--field")) o.field = c.value();
    else if(c.is("--sizing")) o.sizing = c.one_of({"uniform", "thickness"});
    else if(c.is("--cells-across")) {
      o.cells_across = c.number<double>();
      if(!(o.cells_across > 0 && o.cells_across <= 100)) throw Input_error("--cells-across must be in (0, 100]");
    } else if(c.is("--gradation")) {
      o.gradation = c.number<double>();
      if(!(o.gradation > 0 && o.gradation <= 10)) throw Input_error("--gradation must be in (0, 10]");
    } else if(c.is("--graded")) o.graded = true;
    else if(c.is("--refuse-self-intersecting")) o.refuse_self_intersecting = true;
    else c.common(o);
  }
  Command_line::require_input(o);
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
  return benchmark_main("compare_optimizers", usage, argc, argv, parse_command_line, [](const Options& options) {
    return is_implicit_domain_name(options.input) ? run_implicit_domain(options) : run_polyhedral_domain(options);
  });
}
