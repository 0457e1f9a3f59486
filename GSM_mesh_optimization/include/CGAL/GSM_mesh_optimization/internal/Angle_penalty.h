// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the final polishing (Sliver_polisher.h) lowers: the sum, over the cells
// a change touches, of a penalty of each cell's smallest dihedral angle, steep
// under a threshold 30 degrees above the sliver bound (60 for the bound 30) and
// zero over it. Lifting the worst cell of a star alone (max-min) buys a degree
// there at the price of many cells pushed under 40 and 30 degrees: on a mesh
// with thousands of cells under the bound (steeply graded, thin-walled) that
// made the bulk worse than the rounds had left it. With the fourth power a cell
// at 10 degrees weighs as much as sixteen at 35, so the worst cells still go first, but a
// cell pushed from 45 to 39 degrees costs half a degree gained at 20. (A
// threshold of 40 left the cells over it free and pushed thousands of them just
// under it.) The critical cells are the worst ones, whose vertex moves and
// splits the polishing takes whatever the penalty says.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ANGLE_PENALTY_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ANGLE_PENALTY_H

#include <cmath>
#include <limits>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

struct Angle_penalty
{
  /// degrees: cells whose smallest dihedral angle is over it cost nothing
  double threshold = 60;
  int power = 4;
  /// degrees: a vertex move or a split that raises the smallest angle of cells under it
  /// is taken whatever it costs the others (the polisher sets it each pass)
  double critical = 30;
  /// the least share of the penalty a change must save
  static constexpr double min_relative_gain = 1e-4;

  bool is_critical(double q) const { return q < critical; }

  /// penalty of a cell whose smallest dihedral angle is `q` degrees
  double operator()(double q) const
  {
    const double d = threshold - q;
    if(std::isnan(d)) return std::numeric_limits<double>::infinity();
    if(d <= 0) return 0;
    double p = d;
    for(int k = 1; k < power; ++k) p *= d;
    return p;
  }

  /// the penalty for the sliver bound `bound` (degrees), every cell under it critical
  static Angle_penalty for_bound(double bound)
  {
    Angle_penalty p;
    p.threshold = bound + 30;
    p.critical = bound;
    return p;
  }
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ANGLE_PENALTY_H
