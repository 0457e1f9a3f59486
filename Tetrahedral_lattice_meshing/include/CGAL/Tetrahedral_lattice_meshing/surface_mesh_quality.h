// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality of a triangle mesh of a surface measured in a frame field's
// metric (dissertation section 4.3.4): per-triangle quality xi, smallest
// angles, the share of degree-6 vertices r6, closed 2-manifoldness.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_SURFACE_MESH_QUALITY_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_SURFACE_MESH_QUALITY_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * returns \f$ \xi = 4 \sqrt{3}\, a / (p\, h) \f$ of the triangle (`a`, `b`, `c`) mapped by `B`:
 * \f$ a \f$ its area, \f$ p \f$ its perimeter, \f$ h \f$ its longest edge there. 1 for an
 * equilateral triangle, 0 for a flat one.
 */
inline double triangle_quality_in_metric(const Eigen::Matrix3d& B, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                         const Eigen::Vector3d& c)
{
  const Eigen::Vector3d u = B * (b - a), v = B * (c - b), w = B * (a - c);
  const double area = 0.5 * u.cross(w).norm(), p = u.norm() + v.norm() + w.norm();
  const double h = (std::max)({u.norm(), v.norm(), w.norm()});
  return p > 0 && h > 0 ? 4 * std::sqrt(3.) * area / (p * h) : 0.;
}

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the smallest angle, in degrees, of the triangle (`a`, `b`, `c`) mapped by `B`
inline double smallest_angle_in_metric(const Eigen::Matrix3d& B, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c)
{
  const Eigen::Vector3d p[3] = {B * a, B * b, B * c};
  double smallest = 180;
  for(int k = 0; k < 3; ++k) {
    const Eigen::Vector3d u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
    smallest = (std::min)(smallest, std::atan2(u.cross(v).norm(), u.dot(v)) * 180 / CGAL_PI);
  }
  return smallest;
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * returns the angle, in degrees, between the edge from `a` to `b` mapped by `B` and the nearest
 * direction of the hexagonal lattice in the plane of the frame's first two axes (a multiple of
 * 60 degrees): 0 for an edge of the lattice, at most 30
 */
inline double hexagonal_alignment_error(const Eigen::Matrix3d& B, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const Eigen::Vector3d u = B * (b - a);
  const double angle = std::fmod(std::atan2(u[1], u[0]) * 180 / CGAL_PI + 360., 60.);
  return (std::min)(angle, 60. - angle);
}

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the figures of `surface_mesh_quality()`
struct Surface_mesh_quality
{
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  /// the share of degree-6 vertices among those off the borders and the sharp edges
  double r6 = 0;
  double xi_mean = 0;
  double xi_min = 0;
  /// the smallest angle of all triangles, and the mean of each triangle's smallest, in degrees
  double min_angle = 0;
  double mean_min_angle = 0;
  /// the mean of `hexagonal_alignment_error()` over the edges off the borders and the sharp edges
  double alignment_error_mean = 0;
  /// no border, and every vertex's faces form one fan
  bool is_closed_manifold = false;
};

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * measures `mesh` in the metric of `field` (each triangle mapped by \f$ B \f$ at its centroid,
 * each edge at its midpoint).
 * An edge whose faces' normals make an angle over `features_angle` degrees is sharp; its
 * vertices, and those on a border, do not count in \f$ r_6 \f$.
 *
 * \tparam Point_3 the mesh's point type
 * \tparam FrameField a model of `FrameField_3`
 */
template <class Point_3, class FrameField>
Surface_mesh_quality surface_mesh_quality(const CGAL::Surface_mesh<Point_3>& mesh, const FrameField& field,
                                          double features_angle = 60)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  auto eig = [&](typename Mesh::Vertex_index v) {
    const Point_3& p = mesh.point(v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  auto normal = [&](typename Mesh::Face_index f) {
    const auto h = mesh.halfedge(f);
    const Eigen::Vector3d a = eig(mesh.source(h)), b = eig(mesh.target(h)), c = eig(mesh.target(mesh.next(h)));
    return Eigen::Vector3d((b - a).cross(c - a));
  };
  Surface_mesh_quality q;
  q.number_of_vertices = mesh.number_of_vertices();
  q.number_of_faces = mesh.number_of_faces();
  q.min_angle = 180;
  q.xi_min = std::numeric_limits<double>::infinity();
  for(auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Eigen::Vector3d a = eig(mesh.source(h)), b = eig(mesh.target(h)), c = eig(mesh.target(mesh.next(h)));
    const Eigen::Vector3d m = (a + b + c) / 3.;
    const Eigen::Matrix3d B = field.B(Point_3(m[0], m[1], m[2]));
    const double xi = triangle_quality_in_metric(B, a, b, c), angle = smallest_angle_in_metric(B, a, b, c);
    q.xi_mean += xi;
    q.xi_min = (std::min)(q.xi_min, xi);
    q.min_angle = (std::min)(q.min_angle, angle);
    q.mean_min_angle += angle;
  }
  if(q.number_of_faces) {
    q.xi_mean /= double(q.number_of_faces);
    q.mean_min_angle /= double(q.number_of_faces);
  } else
    q.xi_min = q.min_angle = 0;
  const double cos_features = std::cos(features_angle * CGAL_PI / 180);
  auto is_sharp = [&](typename Mesh::Halfedge_index h) {
    if(mesh.is_border(mesh.edge(h))) return true;
    const Eigen::Vector3d n1 = normal(mesh.face(h)), n2 = normal(mesh.face(mesh.opposite(h)));
    return !(n1.norm() > 0 && n2.norm() > 0) || n1.normalized().dot(n2.normalized()) < cos_features;
  };
  std::size_t edges = 0;
  for(auto e : mesh.edges()) {
    if(is_sharp(mesh.halfedge(e))) continue;
    const Eigen::Vector3d a = eig(mesh.vertex(e, 0)), b = eig(mesh.vertex(e, 1)), m = 0.5 * (a + b);
    q.alignment_error_mean += hexagonal_alignment_error(field.B(Point_3(m[0], m[1], m[2])), a, b);
    ++edges;
  }
  if(edges) q.alignment_error_mean /= double(edges);
  std::size_t counted = 0, six = 0;
  bool closed = true;
  for(auto v : mesh.vertices()) {
    bool off_features = true;
    std::size_t degree = 0;
    if(mesh.is_border(v, false)) {
      closed = false;
      off_features = false;
    }
    for(auto h : CGAL::halfedges_around_target(v, mesh)) {
      ++degree;
      if(is_sharp(h)) off_features = false;
    }
    if(off_features) {
      ++counted;
      six += (degree == 6);
    }
  }
  q.r6 = counted ? double(six) / double(counted) : 0.;
  // a vertex whose faces form more than one fan has more faces around it than one walk finds
  std::vector<std::size_t> faces_at(mesh.number_of_vertices(), 0);
  for(auto f : mesh.faces())
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) ++faces_at[std::size_t(v)];
  for(auto v : mesh.vertices()) {
    std::size_t walk = 0;
    for(auto f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) walk += (f != Mesh::null_face());
    if(walk != faces_at[std::size_t(v)]) closed = false;
  }
  q.is_closed_manifold = closed && mesh.number_of_faces() > 0 && !mesh.has_garbage();
  return q;
}

} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_SURFACE_MESH_QUALITY_H
