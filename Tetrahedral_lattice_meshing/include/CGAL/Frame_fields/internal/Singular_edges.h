// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Singular edges of a cross field with one frame per cell: going once around
// an interior edge, each step from a cell to the next matches the two frames
// by the rotation of the cube's symmetry group closest to their difference;
// the edge is singular when the product of these matchings is not the identity.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_SINGULAR_EDGES_H
#define CGAL_FRAME_FIELDS_INTERNAL_SINGULAR_EDGES_H

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

/// the 24 rotations of the cube: signed permutation matrices of determinant 1
inline const std::vector<Eigen::Matrix3d>& cube_rotations()
{
  static const std::vector<Eigen::Matrix3d> rotations = [] {
    std::vector<Eigen::Matrix3d> r;
    const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for(const auto& p : perms)
      for(int signs = 0; signs < 8; ++signs) {
        Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
        for(int i = 0; i < 3; ++i) P(i, p[i]) = (signs >> i) & 1 ? -1 : 1;
        if(P.determinant() > 0) r.push_back(P);
      }
    return r;
  }();
  return rotations;
}

/// the cube rotation P minimizing |Ra P - Rb|: Rb's axes as a relabelling of Ra's
inline const Eigen::Matrix3d& matching(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb)
{
  const Eigen::Matrix3d M = Ra.transpose() * Rb; // maximize trace(P^T M)
  const std::vector<Eigen::Matrix3d>& group = cube_rotations();
  std::size_t best = 0;
  double best_score = -1e300;
  for(std::size_t k = 0; k < group.size(); ++k) {
    const double score = group[k].cwiseProduct(M).sum();
    if(score > best_score) best_score = score, best = k;
  }
  return group[best];
}

struct Singular_edge_report
{
  std::vector<std::array<std::size_t, 2>> singular_edges;
  std::size_t number_of_interior_edges = 0;
};

/// `cells`, their frames (rotations), and the facets that are walls (the
/// boundary): an edge is interior if the ring of cells around it closes
/// without crossing a wall.
inline Singular_edge_report
singular_edges(const std::vector<std::array<std::size_t, 4>>& cells,
               const std::vector<Eigen::Matrix3d>& cell_frames,
               const std::vector<std::array<std::size_t, 3>>& walls)
{
  typedef std::array<std::size_t, 3> Face;
  auto sorted = [](Face f) { std::sort(f.begin(), f.end()); return f; };
  std::map<Face, std::array<std::ptrdiff_t, 2>> cells_of_face;
  for(std::size_t c = 0; c < cells.size(); ++c)
    for(int i = 0; i < 4; ++i) {
      Face f;
      for(int k = 0, j = 0; k < 4; ++k)
        if(k != i) f[std::size_t(j++)] = cells[c][std::size_t(k)];
      auto it = cells_of_face.emplace(sorted(f), std::array<std::ptrdiff_t, 2>{{-1, -1}}).first;
      (it->second[0] < 0 ? it->second[0] : it->second[1]) = std::ptrdiff_t(c);
    }
  std::set<Face> wall_set;
  for(const Face& w : walls) wall_set.insert(sorted(w));

  Singular_edge_report report;
  std::set<std::array<std::size_t, 2>> seen;
  for(std::size_t c0 = 0; c0 < cells.size(); ++c0)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const std::size_t a = cells[c0][std::size_t(i)], b = cells[c0][std::size_t(j)];
        const std::array<std::size_t, 2> edge{{(std::min)(a, b), (std::max)(a, b)}};
        if(!seen.insert(edge).second) continue;
        // the two other vertices of c0: walk across the face (a, b, next)
        std::size_t other[2], n = 0;
        for(int k = 0; k < 4; ++k)
          if(k != i && k != j) other[n++] = cells[c0][std::size_t(k)];
        std::size_t cell = c0, next = other[1];
        Eigen::Matrix3d holonomy = Eigen::Matrix3d::Identity();
        bool closed = false;
        for(std::size_t steps = 0; steps <= cells.size(); ++steps) {
          const Face f = sorted({{a, b, next}});
          if(wall_set.count(f)) break;
          const std::array<std::ptrdiff_t, 2>& pair = cells_of_face[f];
          const std::ptrdiff_t to = pair[0] == std::ptrdiff_t(cell) ? pair[1] : pair[0];
          if(to < 0) break; // the edge is on the border of the cell set
          holonomy = holonomy * matching(cell_frames[cell], cell_frames[std::size_t(to)]);
          if(std::size_t(to) == c0) { closed = true; break; }
          std::size_t fourth = 0;
          for(std::size_t v : cells[std::size_t(to)])
            if(v != a && v != b && v != next) fourth = v;
          next = fourth;
          cell = std::size_t(to);
        }
        if(!closed) continue;
        ++report.number_of_interior_edges;
        if(!holonomy.isIdentity(0.5)) report.singular_edges.push_back(edge);
      }
  return report;
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_SINGULAR_EDGES_H
