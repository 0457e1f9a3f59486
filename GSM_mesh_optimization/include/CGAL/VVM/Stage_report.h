// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every VVM entry point tells its `visitor`, whatever the package.

#ifndef CGAL_VVM_STAGE_REPORT_H
#define CGAL_VVM_STAGE_REPORT_H

namespace CGAL {
namespace VVM {

/// \ingroup PkgVVMVisitors
/// the stages of the VVM entry points, as their visitors see them
enum class Stage
{
  FRAME_FIELD,  ///< the cross field's smoothing rounds (`generate_cross_field_3()`)
  PARTICLES,    ///< the particles' rounds (`lattice_particles_3()`)
  TETRAHEDRA,   ///< the particles connected into tets, the boundary refinement and the metric flips
  OPTIMIZATION, ///< GSM's rounds of vertex smoothing and flips (`gsm_optimize_mesh_3()`)
  POLISHING,    ///< GSM's polishing passes
  MERGING       ///< the tets merged into hexahedra, prisms and pyramids (`tets_to_hex_dominant()`)
};

/*!
 * \ingroup PkgVVMVisitors
 * What every VVM entry point tells the callable given as its `visitor` named parameter: after
 * each round of a stage, that round's report (a type derived from this one, with the stage's own
 * figures: `GSM_mesh_optimization::Round_report`,
 * `Tetrahedral_lattice_meshing::Lattice_round_report`,
 * `Frame_fields::Cross_field_round_report`), and once a stage is over, a `Stage_report` with
 * `stage_done` set. The visitor is called with the reports it can take: one taking
 * `const VVM::Stage_report&` sees every stage of every entry point, one taking a derived type
 * only the rounds of that type. If it returns `false`, the entry point stops as it does at its
 * time limit and returns a valid result.
 *
 * \code
 * auto visitor = [](const CGAL::VVM::Stage_report& r) {
 *   if(r.stage_done) std::cout << "stage " << int(r.stage) << " done at " << r.elapsed_time << " s\n";
 * };
 * CGAL::make_hex_dominant_mesh_3<C3T3>(domain, CGAL::parameters::visitor(visitor));
 * \endcode
 */
struct Stage_report
{
  Stage stage = Stage::OPTIMIZATION;
  /// the round, 1 for the stage's first (GSM counts its polishing passes on from its rounds;
  /// the particles count from 1 at each multiresolution level); when `stage_done`, the number
  /// of rounds the stage ran (0 for a stage without rounds)
  int round = 0;
  double elapsed_time = 0; ///< seconds since the stage's entry point was called
  bool stage_done = false; ///< the stage is over
};

} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_STAGE_REPORT_H
