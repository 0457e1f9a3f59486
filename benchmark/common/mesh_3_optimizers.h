// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's Mesh_3 optimizers as steps of the drivers' chains ("odt+perturb+exude"),
// each run as CGAL's users run it after make_mesh_3, with no sliver bound for
// perturb and exude (they work until they cannot improve the worst angle).

#ifndef VVM_BENCHMARK_MESH_3_OPTIMIZERS_H
#define VVM_BENCHMARK_MESH_3_OPTIMIZERS_H

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers the optimizers' headers need

#include <CGAL/Mesh_optimization_return_code.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/lloyd_optimize_mesh_3.h>
#include <CGAL/odt_optimize_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>

#include <stdexcept>
#include <string>

namespace vvm_benchmark {

inline bool is_mesh_3_optimizer(const std::string& step)
{
  return step == "lloyd" || step == "odt" || step == "perturb" || step == "exude";
}

// runs the Mesh_3 optimizer named `step` on `c3t3`
template <class C3T3, class MeshDomain>
CGAL::Mesh_optimization_return_code run_mesh_3_optimizer(const std::string& step, C3T3& c3t3,
                                                         const MeshDomain& domain)
{
  namespace P = CGAL::parameters;
  if(step == "lloyd") return CGAL::lloyd_optimize_mesh_3(c3t3, domain);
  if(step == "odt") return CGAL::odt_optimize_mesh_3(c3t3, domain);
  if(step == "perturb") return CGAL::perturb_mesh_3(c3t3, domain, P::sliver_bound = 0);
  if(step == "exude") return CGAL::exude_mesh_3(c3t3, P::sliver_bound = 0);
  throw std::logic_error("not a Mesh_3 optimizer: '" + step + "'");
}

inline const char* return_code_name(CGAL::Mesh_optimization_return_code code)
{
  switch(code) {
  case CGAL::BOUND_REACHED: return "BOUND_REACHED";
  case CGAL::TIME_LIMIT_REACHED: return "TIME_LIMIT_REACHED";
  case CGAL::CANT_IMPROVE_ANYMORE: return "CANT_IMPROVE_ANYMORE";
  case CGAL::CONVERGENCE_REACHED: return "CONVERGENCE_REACHED";
  case CGAL::MAX_ITERATION_NUMBER_REACHED: return "MAX_ITERATION_NUMBER_REACHED";
  case CGAL::ALL_VERTICES_FROZEN: return "ALL_VERTICES_FROZEN";
  default: return "UNKNOWN";
  }
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_MESH_3_OPTIMIZERS_H
