// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_optimizers: one initial make_mesh_3 mesh, then each optimizer chain
// on its own copy, measured in the same process. Command line in usage().

#ifndef VVM_BENCHMARK_COMPARE_OPTIMIZERS_H
#define VVM_BENCHMARK_COMPARE_OPTIMIZERS_H

#include "command_line.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace vvm_benchmark {

// INPUT: a surface file, or sphere / cube / torus
struct Options : Common_options
{
  std::size_t target_vertices = 10000; // --vertices
  std::vector<std::string> chains;     // --chains
  int repeat = 1;                      // --repeat
  bool graded = false;                 // --graded
  bool refuse_self_intersecting = false; // --refuse-self-intersecting
  std::string field;                   // --field: adaptive-sphere, anisotropic-sphere, anisotropic-cube
  std::string sizing = "uniform";      // --sizing: uniform, thickness
  double cells_across = 3;             // --cells-across, with --sizing thickness
  double gradation = 0.3;              // --gradation, with --sizing thickness
};

// The chains run by default, in order.
std::vector<std::string> default_chains();

// Built-in domains, meshed from their implicit function (sphere, torus).
bool is_implicit_domain_name(const std::string& name);
int run_implicit_domain(const Options& options);

// Closed triangle surfaces read from a file, and the built-in polyhedral cube.
int run_polyhedral_domain(const Options& options);

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_COMPARE_OPTIMIZERS_H
