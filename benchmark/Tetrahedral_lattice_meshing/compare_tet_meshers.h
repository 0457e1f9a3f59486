// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_tet_meshers: lattice meshes (BCC, FCC, with or without GSM) against
// make_mesh_3 with CGAL's optimizers and GSM, at the same vertex count
// (dissertation Tables 4.2-4.4).

#ifndef VVM_BENCHMARK_COMPARE_TET_MESHERS_H
#define VVM_BENCHMARK_COMPARE_TET_MESHERS_H

#include "command_line.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace vvm_tet_benchmark {

// INPUT: a surface file, or cube / sphere / torus
struct Options : vvm_benchmark::Common_options
{
  std::size_t target_vertices = 10000;
  std::string field = "identity";   // identity, cross, rotation-y, fig4.8, fig4.9
  std::string sizing = "uniform";   // uniform, thickness (the field's frames scaled by the thickness sizing)
  std::vector<std::string> methods; // empty: the default list
  int levels = -1;                  // multiresolution levels; < 0: the package's choice
  double sliver_bound = 30;         // the lattice meshes' polishing bound (degrees; 0: none)
};

// a user error (bad command line or input): printed with the usage, exit code 2
using vvm_benchmark::Input_error;

std::vector<std::string> default_methods();
bool is_implicit_domain_name(const std::string& name);
int run_implicit_domain(const Options& options);
int run_polyhedral_domain(const Options& options);

} // namespace vvm_tet_benchmark

#endif // VVM_BENCHMARK_COMPARE_TET_MESHERS_H
