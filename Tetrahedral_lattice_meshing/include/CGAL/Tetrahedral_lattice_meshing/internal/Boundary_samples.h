// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the particle engine asks of a boundary, whoever sampled it: triangles
// with their normals and patches, sharp-edge segments with their tangents and
// curves, corners, and the closest point on the surface and on the sharp
// edges (AABB trees). Domain_boundary fills it from Mesh_3's sampling of a
// domain, Surface_boundary from a triangle mesh.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_BOUNDARY_SAMPLES_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_BOUNDARY_SAMPLES_H

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/assertions.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

inline Eigen::Vector3d to_vector(double x, double y, double z) { return Eigen::Vector3d(x, y, z); }

template <class GeomTraits>
class Boundary_samples
{
public:
  typedef GeomTraits K;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Triangle_3 Triangle_3;
  typedef typename K::Segment_3 Segment_3;
  typedef typename std::vector<Triangle_3>::const_iterator Triangle_iterator;
  typedef typename std::vector<Segment_3>::const_iterator Segment_iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangle_iterator>>> Surface_tree;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segment_iterator>>> Edge_tree;

  struct Closest
  {
    Eigen::Vector3d point;
    Eigen::Vector3d direction; // the unit normal of the triangle, or the unit tangent of the segment
    int feature = -1;           // patch or curve number
    double distance = 0;
  };

  Boundary_samples() = default;
  // the trees point into the vectors
  Boundary_samples(const Boundary_samples&) = delete;
  Boundary_samples& operator=(const Boundary_samples&) = delete;

  Closest closest_on_surface(const Eigen::Vector3d& p) const
  {
    const auto r = surface_tree_.closest_point_and_primitive(Point_3(p[0], p[1], p[2]));
    const std::size_t t = std::size_t(r.second - triangles_.begin());
    Closest c;
    c.point = to_vector(r.first.x(), r.first.y(), r.first.z());
    c.direction = triangle_normals_[t];
    c.feature = triangle_patches_[t];
    c.distance = (c.point - p).norm();
    return c;
  }

  bool has_sharp_edges() const { return !segments_.empty(); }

  Closest closest_on_sharp_edge(const Eigen::Vector3d& p) const
  {
    CGAL_precondition(has_sharp_edges());
    const auto r = edge_tree_.closest_point_and_primitive(Point_3(p[0], p[1], p[2]));
    const std::size_t s = std::size_t(r.second - segments_.begin());
    Closest c;
    c.point = to_vector(r.first.x(), r.first.y(), r.first.z());
    c.direction = segment_tangents_[s];
    c.feature = segment_curves_[s];
    c.distance = (c.point - p).norm();
    return c;
  }

  const std::vector<Eigen::Vector3d>& corners() const { return corners_; }
  const std::vector<int>& corner_numbers() const { return corner_numbers_; }
  const std::vector<Triangle_3>& triangles() const { return triangles_; }
  const std::vector<Eigen::Vector3d>& triangle_normals() const { return triangle_normals_; }
  const std::vector<int>& triangle_patches() const { return triangle_patches_; }
  const std::vector<Segment_3>& segments() const { return segments_; }
  const std::vector<int>& segment_curves() const { return segment_curves_; }
  const Surface_tree& surface_tree() const { return surface_tree_; }

  Eigen::Vector3d bbox_min() const { return lo_; }
  Eigen::Vector3d bbox_max() const { return hi_; }

protected:
  template <class P>
  static Eigen::Vector3d eig(const P& p) { return to_vector(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())); }

  /// a triangle, unless it is flat (it tells no normal)
  void add_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int patch)
  {
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if(!(n.norm() > 0)) return;
    triangles_.emplace_back(Point_3(a[0], a[1], a[2]), Point_3(b[0], b[1], b[2]), Point_3(c[0], c[1], c[2]));
    triangle_normals_.push_back(n.normalized());
    triangle_patches_.push_back(patch);
  }

  /// a sharp-edge segment, unless it has no length; returns whether it was added
  bool add_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int curve)
  {
    if(!((b - a).norm() > 0)) return false;
    segments_.emplace_back(Point_3(a[0], a[1], a[2]), Point_3(b[0], b[1], b[2]));
    segment_tangents_.push_back((b - a).normalized());
    segment_curves_.push_back(curve);
    return true;
  }

  /// the bounding box and the trees, once the triangles and segments are in (at least one triangle)
  void build_trees()
  {
    CGAL_precondition(!triangles_.empty());
    lo_ = hi_ = eig(triangles_[0][0]);
    for(const Triangle_3& t : triangles_)
      for(int k = 0; k < 3; ++k) {
        lo_ = lo_.cwiseMin(eig(t[k]));
        hi_ = hi_.cwiseMax(eig(t[k]));
      }
    surface_tree_.insert(triangles_.begin(), triangles_.end());
    surface_tree_.build();
    surface_tree_.accelerate_distance_queries();
    if(!segments_.empty()) {
      edge_tree_.insert(segments_.begin(), segments_.end());
      edge_tree_.build();
      edge_tree_.accelerate_distance_queries();
    }
  }

  std::vector<Triangle_3> triangles_;
  std::vector<Eigen::Vector3d> triangle_normals_;
  std::vector<int> triangle_patches_;
  std::vector<Segment_3> segments_;
  std::vector<Eigen::Vector3d> segment_tangents_;
  std::vector<int> segment_curves_;
  std::vector<Eigen::Vector3d> corners_;
  std::vector<int> corner_numbers_;
  Eigen::Vector3d lo_, hi_;
  Surface_tree surface_tree_;
  Edge_tree edge_tree_;
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_BOUNDARY_SAMPLES_H
