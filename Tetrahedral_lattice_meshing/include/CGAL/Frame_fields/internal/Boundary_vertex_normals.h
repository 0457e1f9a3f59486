// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normal of a boundary vertex: the principal direction (largest eigenvalue)
// of the area-weighted tensor sum_f A_f n_f n_f^T of its boundary facets, which
// does not depend on the facets' orientations. One definition for the boundary
// constraint of the cross field and for the measure of how much the surface
// turns between vertices, so that the two cannot drift apart.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_BOUNDARY_VERTEX_NORMALS_H
#define CGAL_FRAME_FIELDS_INTERNAL_BOUNDARY_VERTEX_NORMALS_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

/// per vertex, the sum of `A n n^T` over its boundary facets (zero off the boundary);
/// `position(v)` gives the `Eigen::Vector3d` of vertex `v`, `facets` three vertex indices each
template <class Facets, class Position>
std::vector<Eigen::Matrix3d> boundary_normal_tensors(std::size_t number_of_vertices, const Facets& facets,
                                                     const Position& position)
{
  std::vector<Eigen::Matrix3d> tensors(number_of_vertices, Eigen::Matrix3d::Zero());
  for(const auto& f : facets) {
    const Eigen::Vector3d N = (position(f[1]) - position(f[0])).cross(position(f[2]) - position(f[0]));
    const double twice_area = N.norm();
    if(twice_area > 0)
      for(std::size_t v : f) tensors[v] += N * N.transpose() / (2 * twice_area); // area n n^T
  }
  return tensors;
}

/// the unit principal direction of a normal tensor, zero for a zero tensor
inline Eigen::Vector3d principal_normal(const Eigen::Matrix3d& tensor)
{
  if(!(tensor.trace() > 0)) return Eigen::Vector3d::Zero();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensor).eigenvectors().col(2);
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_BOUNDARY_VERTEX_NORMALS_H
