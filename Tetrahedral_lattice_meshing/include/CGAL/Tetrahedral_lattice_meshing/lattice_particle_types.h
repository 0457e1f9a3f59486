// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the particle engine returns and reports: particle kinds, the result of
// lattice_particles_3() and the report given to the visitor after each round.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_LATTICE_PARTICLE_TYPES_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_LATTICE_PARTICLE_TYPES_H

#include <CGAL/Tetrahedral_lattice_meshing/Lattice.h>
#include <CGAL/VVM/Stage_report.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the kinds of particles (dissertation 4.2.2): what a particle may do during the optimization
enum class Particle_kind
{
  CORNER,     ///< fixed at a corner of the domain (where more than two sharp edges meet)
  SHARP_EDGE, ///< slides along a sharp edge (a feature curve)
  BOUNDARY,   ///< slides on the boundary surface
  FREE        ///< moves freely inside the domain
};

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the state of the particle optimization after one round (L-BFGS, then deletion and insertion),
/// for the visitor; `stage` is `VVM::Stage::PARTICLES`, `round` counts from 1 at each level
struct Lattice_round_report : VVM::Stage_report
{
  int level = 0;                  ///< multiresolution level: the edge length is \f$ 2^{level} l^* \f$
  double energy = 0;              ///< the GHK energy at the end of the L-BFGS run, per particle
  std::size_t number_of_particles = 0; ///< after deletion and insertion
  std::size_t number_deleted = 0;
  std::size_t number_inserted = 0;
  int lbfgs_iterations = 0;
};

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * The particles made by `lattice_particles_3()`: positions, kinds, and for boundary,
 * sharp-edge and corner particles the number of their surface patch, curve or corner
 * (in the order of the domain's indices met in its boundary sampling; -1 for free particles).
 *
 * \tparam Point_3 the point type of the kernel
 */
template <class Point_3>
struct Lattice_particles_3
{
  std::vector<Point_3> points;
  std::vector<Particle_kind> kinds;
  std::vector<int> features;
  Lattice lattice;            ///< the lattice and its constants
  double edge_length = 0;     ///< \f$ l^* \f$ used
  double energy = 0;          ///< the final GHK energy per particle
  int number_of_rounds = 0;   ///< rounds run, all levels together (of the run kept)
  int multiresolution_levels = 0; ///< the levels of the run kept
  double time = 0;            ///< seconds, boundary sampling included (but the generated cross field's, made beside the field)
  bool time_limit_reached = false; ///< `maximum_running_time` stopped the rounds
  bool stopped_by_visitor = false; ///< the visitor returned `false`: the rounds stopped there

  std::size_t size() const { return points.size(); }
  std::size_t number_of(Particle_kind k) const
  {
    std::size_t n = 0;
    for(Particle_kind x : kinds) n += (x == k);
    return n;
  }
};

} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_LATTICE_PARTICLE_TYPES_H
