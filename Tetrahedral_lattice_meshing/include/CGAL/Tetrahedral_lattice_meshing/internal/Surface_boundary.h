// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A triangle mesh as the particle engine's boundary, for surface meshing: its
// own triangles (not a resampling), its sharp edges (the dihedral angle over
// the features angle), its border edges and its non-manifold edges as feature
// curves, corners where a curve ends, branches or turns by more than the
// features angle, and patches: the faces connected across non-feature edges.
// Every particle lies on the surface, so nothing is inside.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_BOUNDARY_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_BOUNDARY_H

#include <CGAL/Frame_fields/internal/Triangle_mesh_features.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Boundary_samples.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

template <class GeomTraits>
class Surface_boundary : public Boundary_samples<GeomTraits>
{
  typedef Boundary_samples<GeomTraits> Base;

public:
  typedef std::array<std::size_t, 3> Face;

  /// `points` and `faces` (indices into `points`) a triangle mesh; an edge is a feature if
  /// the normals of its two faces make an angle over `features_angle` degrees, or if it has
  /// one face or more than two
  Surface_boundary(const std::vector<Eigen::Vector3d>& points, const std::vector<Face>& faces, double features_angle)
  {
    const Frame_fields::internal::Triangle_mesh_features mesh(points, faces, features_angle, "make_lattice_surface_mesh");
    const auto& edge_faces = mesh.edge_faces();
    const auto& feature_edges = mesh.feature_edges();
    // patches: the faces joined across smooth edges
    std::vector<std::size_t> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::size_t x) {
      while(parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for(const auto& e : edge_faces)
      if(mesh.is_smooth(e.second)) parent[find(e.second[0])] = find(e.second[1]);
    // numbered in the order of their first face
    std::vector<int> patch_of_root(faces.size(), -1);
    face_patches_.resize(faces.size());
    for(std::size_t f = 0; f < faces.size(); ++f) {
      int& p = patch_of_root[find(f)];
      if(p < 0) p = number_of_patches_++;
      face_patches_[f] = p;
    }
    // corners: where feature edges do not continue as one smooth curve
    std::map<std::size_t, std::vector<std::size_t>> vertex_edges;
    for(std::size_t e = 0; e < feature_edges.size(); ++e) {
      vertex_edges[feature_edges[e].first].push_back(e);
      vertex_edges[feature_edges[e].second].push_back(e);
    }
    const double cos_features = std::cos(features_angle * CGAL_PI / 180);
    std::set<std::size_t> corner_vertices;
    for(const auto& ve : vertex_edges) {
      if(ve.second.size() != 2) {
        corner_vertices.insert(ve.first);
        continue;
      }
      auto other = [&](std::size_t e) {
        return feature_edges[e].first == ve.first ? feature_edges[e].second : feature_edges[e].first;
      };
      const Eigen::Vector3d a = (points[ve.first] - points[other(ve.second[0])]).normalized(),
                            b = (points[other(ve.second[1])] - points[ve.first]).normalized();
      if(a.dot(b) < cos_features) corner_vertices.insert(ve.first);
    }
    // curves: feature edges joined at vertices that are no corners
    std::vector<std::size_t> curve_parent(feature_edges.size());
    std::iota(curve_parent.begin(), curve_parent.end(), 0);
    auto find_curve = [&](std::size_t x) {
      while(curve_parent[x] != x) x = curve_parent[x] = curve_parent[curve_parent[x]];
      return x;
    };
    for(const auto& ve : vertex_edges)
      if(!corner_vertices.count(ve.first) && ve.second.size() == 2)
        curve_parent[find_curve(ve.second[0])] = find_curve(ve.second[1]);
    std::vector<int> curve_of_root(feature_edges.size(), -1);
    for(std::size_t e = 0; e < feature_edges.size(); ++e) {
      int& c = curve_of_root[find_curve(e)];
      if(c < 0) {
        c = int(curve_patches_.size());
        curve_patches_.emplace_back();
        curve_is_border_.push_back(0);
      }
      if(edge_faces.at(feature_edges[e]).size() == 1) curve_is_border_[std::size_t(c)] = 1;
      for(std::size_t f : edge_faces.at(feature_edges[e])) curve_patches_[std::size_t(c)].insert(face_patches_[f]);
      this->add_segment(points[feature_edges[e].first], points[feature_edges[e].second], c);
    }
    for(std::size_t f = 0; f < faces.size(); ++f)
      this->add_triangle(points[faces[f][0]], points[faces[f][1]], points[faces[f][2]], face_patches_[f]);
    // corners and the patches around them
    std::map<std::size_t, std::set<int>> vertex_patches;
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(std::size_t v : faces[f])
        if(corner_vertices.count(v)) vertex_patches[v].insert(face_patches_[f]);
    for(std::size_t v : corner_vertices) {
      this->corner_numbers_.push_back(int(this->corners_.size()));
      this->corners_.push_back(points[v]);
      corner_patches_.push_back(vertex_patches[v]);
    }
    this->build_trees();
  }

  /// nothing is inside a surface: a site off it goes onto it
  bool inside(const Eigen::Vector3d&) const { return false; }
  static constexpr bool has_thread_safe_inside = true;
  /// no volume to sample
  const std::vector<std::array<Eigen::Vector3d, 4>>& cells() const { return no_cells_; }

  int number_of_patches() const { return number_of_patches_; }
  const std::vector<int>& face_patches() const { return face_patches_; }
  /// the patches next to each curve, and around each corner
  const std::vector<std::set<int>>& curve_patches() const { return curve_patches_; }
  const std::vector<std::set<int>>& corner_patches() const { return corner_patches_; }
  /// whether each curve is (in part) a border of the surface: edges with one face
  bool is_border_curve(int c) const { return curve_is_border_[std::size_t(c)] != 0; }

private:
  int number_of_patches_ = 0;
  std::vector<int> face_patches_;
  std::vector<std::set<int>> curve_patches_, corner_patches_;
  std::vector<char> curve_is_border_;
  std::vector<std::array<Eigen::Vector3d, 4>> no_cells_;
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_BOUNDARY_H
