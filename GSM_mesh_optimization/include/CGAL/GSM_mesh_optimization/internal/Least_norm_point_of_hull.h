// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The point of least norm in the convex hull of a few vectors, by Gilbert's algorithm
// (1966): from one of them, repeatedly the nearest point to the origin on the segment
// to the vector that lies furthest back along the current point. For the gradients of
// the smallest angles of the cells around a vertex, it is the direction in which they all
// rise fastest together (Freitag and Ollivier-Gooch 1997): each rises at least at its
// norm's rate along it, and it is zero when no direction raises them all.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_LEAST_NORM_POINT_OF_HULL_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_LEAST_NORM_POINT_OF_HULL_H

#include <Eigen/Dense>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

/// the point `z` of least norm in the convex hull of `v` (not empty): `v[i] . z >= |z|^2`
/// for every `i`, up to `tolerance` times `|z|^2` or `max_iterations` steps
inline Eigen::Vector3d least_norm_point_of_hull(const std::vector<Eigen::Vector3d>& v, double tolerance = 1e-9,
                                               int max_iterations = 64)
{
  Eigen::Vector3d z = v.front();
  for(int it = 0; it < max_iterations; ++it) {
    const Eigen::Vector3d* back = &v.front();
    for(const Eigen::Vector3d& w : v)
      if(w.dot(z) < back->dot(z)) back = &w;
    const double z2 = z.squaredNorm();
    if(!(z2 - back->dot(z) > tolerance * z2)) break;
    const Eigen::Vector3d step = *back - z;
    z += (std::min)(1., -z.dot(step) / step.squaredNorm()) * step;
  }
  return z;
}

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_LEAST_NORM_POINT_OF_HULL_H
