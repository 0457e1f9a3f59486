// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The progress lines of the front end's lattice meshers (tet lattices,
// hex-dominant and surface meshes): the particles' and GSM's rounds, and the
// end of each stage, from the packages' visitor reports.

#ifndef VVM_FRONT_END_LATTICE_PROGRESS_H
#define VVM_FRONT_END_LATTICE_PROGRESS_H

#include "optimizer_chain.h"

#include <CGAL/Tetrahedral_lattice_meshing/lattice_particle_types.h>
#include <CGAL/VVM/Stage_report.h>

#include <cstdio>
#include <string>
#include <type_traits>

namespace vvm {
namespace internal {

inline std::string particle_round_text(const CGAL::Tetrahedral_lattice_meshing::Lattice_round_report& r)
{
  char text[160];
  std::snprintf(text, sizeof text, "level %d round %d: %zu particles, energy %.4g", r.level, r.round,
                r.number_of_particles, r.energy);
  return text;
}

inline std::string stage_end_text(const CGAL::VVM::Stage_report& r)
{
  typedef CGAL::VVM::Stage S;
  const char* name = r.stage == S::FRAME_FIELD ? "cross field" : r.stage == S::PARTICLES ? "particles"
                     : r.stage == S::TETRAHEDRA ? "tetrahedra" : r.stage == S::OPTIMIZATION ? "gsm rounds"
                     : r.stage == S::POLISHING ? "gsm polishing" : "merging";
  char text[160];
  std::snprintf(text, sizeof text, "%s done at %.2f s", name, r.elapsed_time);
  return text;
}

/// the progress lines of a lattice mesher: the particles' and GSM's rounds, and each stage's end
inline auto progress_visitor(const Stage& stage)
{
  return [&stage](const auto& r) {
    typedef std::decay_t<decltype(r)> Report;
    if constexpr(std::is_same<Report, CGAL::Tetrahedral_lattice_meshing::Lattice_round_report>::value)
      stage.report(particle_round_text(r));
    else if constexpr(std::is_same<Report, CGAL::GSM_mesh_optimization::Round_report>::value)
      stage.report(gsm_round_text(r));
    else if constexpr(std::is_same<Report, CGAL::VVM::Stage_report>::value) {
      if(r.stage_done) stage.report(stage_end_text(r));
    }
  };
}

} // namespace internal
} // namespace vvm

#endif // VVM_FRONT_END_LATTICE_PROGRESS_H
