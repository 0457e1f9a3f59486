// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Edge flips that make a triangle mesh of a surface Delaunay in a frame
// field's metric: an edge is flipped where its two opposite angles, measured
// in the imagined space of the frame at its midpoint, sum to more than pi
// (the restricted Delaunay triangles are Delaunay in Euclidean space, not in
// an anisotropic field's). Feature edges and border edges stay; a flip that
// would fold the surface (a new face turned more than 30 degrees from the two
// old ones) or repeat an edge is skipped.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_METRIC_FLIPS_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_METRIC_FLIPS_H

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/// the angle at `c` of the triangle (a, b, c), in the space `B` maps to
inline double angle_in_metric(const Eigen::Matrix3d& B, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c)
{
  const Eigen::Vector3d u = B * (a - c), v = B * (b - c);
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/*
 * Flips the edges of `mesh` (a CGAL::Surface_mesh) that are not Delaunay in the metric of
 * `field`, in rounds until none is left or after `max_rounds`; `is_feature(edge)` tells
 * the edges that stay. Returns the number of flips.
 */
template <class Mesh, class FrameField, class IsFeature>
std::size_t flip_to_metric_Delaunay(Mesh& mesh, const FrameField& field, const IsFeature& is_feature, int max_rounds = 50)
{
  typedef typename Mesh::Point Point;
  auto eig = [&](typename Mesh::Vertex_index v) {
    const Point& p = mesh.point(v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  const double cos_fold = std::cos(30 * CGAL_PI / 180);
  std::size_t flips = 0;
  for(int round = 0; round < max_rounds; ++round) {
    std::size_t flipped = 0;
    std::vector<typename Mesh::Edge_index> edges(mesh.edges().begin(), mesh.edges().end());
    for(auto e : edges) {
      if(mesh.is_border(e) || is_feature(e)) continue;
      const auto h = mesh.halfedge(e), o = mesh.opposite(h);
      const auto va = mesh.source(h), vb = mesh.target(h), vc = mesh.target(mesh.next(h)), vd = mesh.target(mesh.next(o));
      if(vc == vd || mesh.degree(va) <= 3 || mesh.degree(vb) <= 3) continue;
      if(mesh.halfedge(vc, vd) != Mesh::null_halfedge()) continue;
      const Eigen::Vector3d a = eig(va), b = eig(vb), c = eig(vc), d = eig(vd), m = 0.5 * (a + b);
      const Eigen::Matrix3d B = field.B(Point(m[0], m[1], m[2]));
      if(angle_in_metric(B, a, b, c) + angle_in_metric(B, b, a, d) <= CGAL_PI + 1e-12) continue;
      const Eigen::Vector3d n1 = (b - a).cross(c - a), n2 = (a - b).cross(d - b);
      if(!(n1.norm() > 0 && n2.norm() > 0)) continue;
      const Eigen::Vector3d n = n1.normalized() + n2.normalized();
      const Eigen::Vector3d new1 = (a - c).cross(d - c), new2 = (b - d).cross(c - d); // (c, a, d), (d, b, c)
      auto unfolded = [&](const Eigen::Vector3d& x) {
        return x.norm() > 0 && x.normalized().dot(n1.normalized()) >= cos_fold && x.normalized().dot(n2.normalized()) >= cos_fold &&
               x.dot(n) > 0;
      };
      if(!unfolded(new1) || !unfolded(new2)) continue;
      CGAL::Euler::flip_edge(h, mesh);
      ++flipped;
    }
    flips += flipped;
    if(flipped == 0) break;
  }
  return flips;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_METRIC_FLIPS_H
