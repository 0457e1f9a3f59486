// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Edge flips that make a triangle mesh of a surface Delaunay in a frame
// field's metric: an edge is flipped where its two opposite angles, measured
// in the imagined space of the frame at the centroid of its two triangles' four
// vertices, sum to more than pi
// (the restricted Delaunay triangles are Delaunay in Euclidean space, not in
// an anisotropic field's). Feature edges and border edges stay; a flip that
// would fold the surface (a new face turned more than 30 degrees from the two
// old ones) or repeat an edge is skipped. Flat triangles have their longest edge
// flipped first.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_METRIC_FLIPS_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_METRIC_FLIPS_H

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>

#include <algorithm>
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

/// whether the triangle (a, b, c) is flat: its circumradius over 1000 times its shortest edge
/// (R = ab bc ca / (4 area)), as three points along one straight curve
inline bool is_flat_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm(), twice_area = (b - a).cross(c - a).norm();
  return !(ab * bc * ca < 2000 * twice_area * (std::min)({ab, bc, ca}));
}

/*
 * Flips the longest edge of each triangle of `mesh` that is flat, or nearly (an angle over 170
 * degrees) with its two other edges on a feature curve (`is_feature(edge)`): the flip joins its
 * middle vertex to the triangle across the longest edge. A hole whose border runs along a curve
 * past a vertex and back along the chord is filled with such a triangle, and its edges all lie
 * along the curve, so that the metric flips keep it. Returns the number of flips.
 */
template <class Mesh, class IsFeature>
std::size_t flip_flat_triangles(Mesh& mesh, const IsFeature& is_feature)
{
  auto eig = [&](typename Mesh::Vertex_index v) {
    const auto& p = mesh.point(v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  const double cos_flat = std::cos(170 * CGAL_PI / 180);
  std::size_t flips = 0;
  for(int round = 0; round < 10; ++round) {
    std::size_t flipped = 0;
    for(auto f : mesh.faces()) {
      // h: the longest edge, opposite the largest angle
      auto h = mesh.halfedge(f);
      double longest = -1;
      for(auto g : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
        const double length = (eig(mesh.target(g)) - eig(mesh.source(g))).squaredNorm();
        if(length > longest) {
          longest = length;
          h = g;
        }
      }
      const Eigen::Vector3d a = eig(mesh.source(h)), b = eig(mesh.target(h)), m = eig(mesh.target(mesh.next(h)));
      const bool cap = (a - m).normalized().dot((b - m).normalized()) < cos_flat &&
                       is_feature(mesh.edge(mesh.next(h))) && is_feature(mesh.edge(mesh.prev(h)));
      if(!cap && !is_flat_triangle(a, b, m)) continue;
      const auto o = mesh.opposite(h);
      if(mesh.is_border(o) || mesh.degree(mesh.source(h)) <= 3 || mesh.degree(mesh.target(h)) <= 3) continue;
      const auto vc = mesh.target(mesh.next(h)), vd = mesh.target(mesh.next(o));
      if(vc == vd || mesh.halfedge(vc, vd) != Mesh::null_halfedge()) continue;
      // only if the two triangles' smallest angle grows (the flip cannot be undone, and cannot
      // make a worse triangle next to a curve)
      const Eigen::Vector3d d = eig(vd);
      auto smallest_angle = [](const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
        const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
        return (std::min)({angle_in_metric(I, q, r, p), angle_in_metric(I, r, p, q), angle_in_metric(I, p, q, r)});
      };
      if(!((std::min)(smallest_angle(m, a, d), smallest_angle(m, d, b)) > (std::min)(smallest_angle(a, b, m), smallest_angle(b, a, d))))
        continue;
      // and the new triangles (m, a, d) and (d, b, m) turned as the old (b, a, d), not folded
      const Eigen::Vector3d n = (a - b).cross(d - b);
      if(!((a - m).cross(d - m).dot(n) > 0 && (b - d).cross(m - d).dot(n) > 0)) continue;
      CGAL::Euler::flip_edge(h, mesh);
      ++flipped;
    }
    flips += flipped;
    if(flipped == 0) break;
  }
  return flips;
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
      // the metric at the quadrilateral's centroid, the same for both diagonals: with the frame
      // at the edge's midpoint, an edge and its flip may each want the other
      const Eigen::Vector3d a = eig(va), b = eig(vb), c = eig(vc), d = eig(vd), m = 0.25 * (a + b + c + d);
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
