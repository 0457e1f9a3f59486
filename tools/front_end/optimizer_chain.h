// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optimizers of `vvm-mesh tet` after make_mesh_3, on any domain: gsm,
// odt+gsm, perturb+exude; GSM reports its rounds as progress.

#ifndef VVM_FRONT_END_OPTIMIZER_CHAIN_H
#define VVM_FRONT_END_OPTIMIZER_CHAIN_H

#include "surface_domain.h"

#include <CGAL/exude_mesh_3.h>
#include <CGAL/gsm_optimize_mesh_3.h>
#include <CGAL/odt_optimize_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <string>

namespace vvm {
namespace internal {

/// "round 3: min angle 21.4, 12 cells under 30"
inline std::string gsm_round_text(const CGAL::GSM_mesh_optimization::Round_report& r)
{
  char text[160];
  std::snprintf(text, sizeof text, "round %d%s: min angle %.2f, %zu cells under the bound", r.round,
                r.is_polishing ? " (polishing)" : "", r.min_dihedral_angle, r.number_of_cells_under_bound);
  return text;
}

/// GSM with the run's threads, seed, time limit (0: none) and progress; `metric` (may be empty)
/// is the target metric, `boundary_distance` the least bound of its boundary-fidelity guard;
/// `freeze_boundary`: only interior vertices move; `sizing` (may be null) the target size.
/// Returns whether the time limit stopped it.
template <class C3T3, class MeshDomain>
bool run_gsm(C3T3& c3t3, const MeshDomain& domain, int threads, unsigned int seed, double time_limit,
             const Progress& progress, const std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>& metric = {},
             double boundary_distance = 0, bool freeze_boundary = false, const Thickness_size* sizing = nullptr)
{
  namespace GSM = CGAL::GSM_mesh_optimization;
  const Stage stage(progress, "gsm");
  CGAL::get_default_random() = CGAL::Random(seed);
  auto np = GSM::parameters::freeze_boundary(freeze_boundary, GSM::parameters::boundary_distance(
      boundary_distance, GSM::parameters::number_of_threads(threads, CGAL::parameters::maximum_running_time(time_limit).visitor(
          [&stage](const GSM::Round_report& r) { stage.report(gsm_round_text(r)); }))));
  const auto code = metric   ? CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::metric_field(metric, np))
                    : sizing ? CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::sizing_field(std::cref(*sizing), np))
                             : CGAL::gsm_optimize_mesh_3(c3t3, domain, np);
  return code == CGAL::TIME_LIMIT_REACHED;
}

inline bool is_optimizer_chain(const std::string& method)
{
  return method == "gsm" || method == "odt+gsm" || method == "perturb+exude";
}

/// the optimizers of `method` on a make_mesh_3 mesh, sharing `o.time_limit` (CGAL's optimizers
/// through their `time_limit`); returns whether the time limit stopped one
template <class C3T3, class MeshDomain>
bool run_optimizer_chain(C3T3& c3t3, const MeshDomain& domain, const Tet_options& o, const Progress& progress,
                         const std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>& metric = {},
                         const Thickness_size* sizing = nullptr)
{
  namespace P = CGAL::parameters;
  const CGAL::VVM::internal::Time_limit limit(o.time_limit);
  bool reached = false;
  if(o.method == "odt+gsm") {
    const Stage stage(progress, "odt");
    stage.report("CGAL::odt_optimize_mesh_3");
    CGAL::get_default_random() = CGAL::Random(o.seed);
    reached = CGAL::odt_optimize_mesh_3(c3t3, domain, P::time_limit = limit.remaining()) == CGAL::TIME_LIMIT_REACHED;
    if(reached) return true;
  }
  if(o.method == "perturb+exude") {
    const Stage stage(progress, "perturb+exude");
    stage.report("CGAL::perturb_mesh_3");
    CGAL::get_default_random() = CGAL::Random(o.seed);
    reached = CGAL::perturb_mesh_3(c3t3, domain, P::sliver_bound = 0, P::time_limit = limit.remaining()) ==
              CGAL::TIME_LIMIT_REACHED;
    if(reached) return true;
    stage.report("CGAL::exude_mesh_3");
    return CGAL::exude_mesh_3(c3t3, P::sliver_bound = 0, P::time_limit = limit.remaining()) == CGAL::TIME_LIMIT_REACHED;
  }
  return run_gsm(c3t3, domain, o.threads, o.seed, limit.remaining(), progress, metric, 0., false, sizing);
}

// the units of the front end that instantiate other domains
Volume_mesh image_tet_mesh(const std::string& input, const Tet_options& options, const Progress& progress,
                           Run_report& report);
Volume_mesh lattice_tet_mesh(const Surface_source& input, const Tet_options& options, const Progress& progress,
                             Run_report& report);

} // namespace internal
} // namespace vvm

#endif // VVM_FRONT_END_OPTIMIZER_CHAIN_H
