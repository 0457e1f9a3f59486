// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The gradient the polishing climbs: the smallest angle of a star and the
// penalties of its angles are only piecewise smooth, so it is taken by central
// differences, not by derivatives.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_CENTRAL_DIFFERENCES_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_CENTRAL_DIFFERENCES_H

#include <Eigen/Core>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

/// `f(x + h e_k) - f(x - h e_k)` for the axes `e_k`: `2 h` times the gradient of `f` at `x`
/// where `f` is smooth (the callers that only need a direction skip the division)
template <class F>
Eigen::Vector3d central_differences(const F& f, const Eigen::Vector3d& x, double h)
{
  Eigen::Vector3d g;
  for(int k = 0; k < 3; ++k) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[k] = h;
    g[k] = f(x + e) - f(x - e);
  }
  return g;
}

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_CENTRAL_DIFFERENCES_H
