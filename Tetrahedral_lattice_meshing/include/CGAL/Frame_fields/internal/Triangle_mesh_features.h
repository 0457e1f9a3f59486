// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the surface field and the surface mesher both read off a triangle mesh
// given as points and index triangles: the faces' normals, the faces around
// each vertex and each edge, and the feature edges (a border, a non-manifold
// edge, or one whose two faces' normals are more than the features angle
// apart), with the corners' normals on each side of them.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_TRIANGLE_MESH_FEATURES_H
#define CGAL_FRAME_FIELDS_INTERNAL_TRIANGLE_MESH_FEATURES_H

#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

class Triangle_mesh_features
{
public:
  typedef std::array<std::size_t, 3> Face;
  typedef std::pair<std::size_t, std::size_t> Edge; ///< its vertices, the smaller first

  /// `who` names the caller in the errors: no face, a non-finite coordinate, an index out of
  /// range, a degenerate face
  Triangle_mesh_features(const std::vector<Eigen::Vector3d>& points, const std::vector<Face>& faces,
                         double features_angle, const std::string& who)
    : cos_features_(std::cos(features_angle * CGAL_PI / 180)), vertex_faces_(points.size())
  {
    if(faces.empty()) throw std::invalid_argument(who + ": the surface has no face");
    for(const Eigen::Vector3d& p : points)
      if(!p.allFinite()) throw std::invalid_argument(who + ": a vertex has a non-finite coordinate");
    for(std::size_t f = 0; f < faces.size(); ++f) {
      for(std::size_t v : faces[f]) {
        if(v >= points.size()) throw std::invalid_argument(who + ": a face refers to vertex " + std::to_string(v) + ", which is not there");
        vertex_faces_[v].push_back(f);
      }
      const Eigen::Vector3d c = (points[faces[f][1]] - points[faces[f][0]]).cross(points[faces[f][2]] - points[faces[f][0]]);
      if(!(c.norm() > 0)) throw std::invalid_argument(who + ": the surface has a degenerate face");
      area_normals_.push_back(c);
      normals_.push_back(c.normalized());
      for(int k = 0; k < 3; ++k) edge_faces_[std::minmax(faces[f][k], faces[f][(k + 1) % 3])].push_back(f);
    }
    for(const auto& e : edge_faces_)
      if(!is_smooth(e.second)) feature_edges_.push_back(e.first);
  }

  /// the faces' unit normals
  const std::vector<Eigen::Vector3d>& face_normals() const { return normals_; }
  /// the faces around each vertex
  const std::vector<std::vector<std::size_t>>& vertex_faces() const { return vertex_faces_; }
  /// the faces of each edge
  const std::map<Edge, std::vector<std::size_t>>& edge_faces() const { return edge_faces_; }
  /// the feature edges, in the order of `edge_faces()`
  const std::vector<Edge>& feature_edges() const { return feature_edges_; }

  /// whether faces `f` and `g` turn by at most the features angle
  bool are_smoothly_joined(std::size_t f, std::size_t g) const { return normals_[f].dot(normals_[g]) >= cos_features_; }
  /// whether an edge with the faces `edge_faces` is no feature
  bool is_smooth(const std::vector<std::size_t>& edge_faces) const
  {
    return edge_faces.size() == 2 && are_smoothly_joined(edge_faces[0], edge_faces[1]);
  }

  /// the unit normal at each corner of each face: the area-weighted mean of the normals of the
  /// faces around the corner's vertex smoothly joined to the face (a vertex on a sharp edge has
  /// a normal per side)
  std::vector<std::array<Eigen::Vector3d, 3>> corner_normals(const std::vector<Face>& faces) const
  {
    std::vector<std::array<Eigen::Vector3d, 3>> out(faces.size());
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for(std::size_t g : vertex_faces_[faces[f][k]])
          if(are_smoothly_joined(g, f)) sum += area_normals_[g];
        out[f][k] = sum.norm() > 0 ? Eigen::Vector3d(sum.normalized()) : normals_[f];
      }
    return out;
  }

private:
  double cos_features_;
  std::vector<Eigen::Vector3d> normals_, area_normals_;
  std::vector<std::vector<std::size_t>> vertex_faces_;
  std::map<Edge, std::vector<std::size_t>> edge_faces_;
  std::vector<Edge> feature_edges_;
};

/// the direction `d` (unit, normal to the unit `n`) or, among the same lattice line turned about
/// `n` by multiples of 180 degrees (of 60 for `isotropic` frames, the hexagonal lattice's
/// symmetry), the one nearest to `reference`
inline Eigen::Vector3d matched_direction(const Eigen::Vector3d& d, const Eigen::Vector3d& n,
                                         const Eigen::Vector3d& reference, bool isotropic)
{
  Eigen::Vector3d best = d.dot(reference) >= 0 ? d : Eigen::Vector3d(-d);
  if(isotropic) {
    const Eigen::Vector3d turned = n.cross(d);
    for(int turn = 1; turn < 6; ++turn) {
      const double angle = turn * CGAL_PI / 3;
      const Eigen::Vector3d candidate = std::cos(angle) * d + std::sin(angle) * turned;
      if(candidate.dot(reference) > best.dot(reference)) best = candidate;
    }
  }
  return best;
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_TRIANGLE_MESH_FEATURES_H
