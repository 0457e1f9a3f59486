// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Singular edges of a cross field with one frame per cell: going once around
// an interior edge, each step from a cell to the next matches the two frames
// by the rotation of the cube's symmetry group closest to their difference;
// the edge is singular when the product of these matchings is not the identity.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_SINGULAR_EDGES_H
#define CGAL_FRAME_FIELDS_INTERNAL_SINGULAR_EDGES_H

#include <CGAL/VVM/internal/Parallel_for.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
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
/// without crossing a wall. The edges are reported in the order of their first
/// cell, then of their place in it; each ring is walked on its own, in parallel.
inline Singular_edge_report
singular_edges(const std::vector<std::array<std::size_t, 4>>& cells,
               const std::vector<Eigen::Matrix3d>& cell_frames,
               const std::vector<std::array<std::size_t, 3>>& walls)
{
  typedef std::array<std::size_t, 3> Face;
  typedef std::array<std::size_t, 2> Edge;
  constexpr std::size_t none = std::size_t(-1);
  auto sorted = [](Face f) { std::sort(f.begin(), f.end()); return f; };
  auto facet = [&](std::size_t c, int k) { // the facet opposite vertex k
    Face f;
    for(int i = 0, j = 0; i < 4; ++i)
      if(i != k) f[std::size_t(j++)] = cells[c][std::size_t(i)];
    return sorted(f);
  };
  // the cell across each facet (none on the border of the cell set or across a wall)
  std::vector<std::pair<Face, std::size_t>> facets; // (facet, 4 c + k)
  facets.reserve(4 * cells.size());
  for(std::size_t c = 0; c < cells.size(); ++c)
    for(int k = 0; k < 4; ++k) facets.emplace_back(facet(c, k), 4 * c + std::size_t(k));
  std::sort(facets.begin(), facets.end());
  std::vector<Face> wall_keys;
  for(const Face& w : walls) wall_keys.push_back(sorted(w));
  std::sort(wall_keys.begin(), wall_keys.end());
  std::vector<std::size_t> across(4 * cells.size(), none);
  for(std::size_t i = 0; i + 1 < facets.size(); ++i)
    if(facets[i].first == facets[i + 1].first &&
       !std::binary_search(wall_keys.begin(), wall_keys.end(), facets[i].first)) {
      across[facets[i].second] = facets[i + 1].second / 4;
      across[facets[i + 1].second] = facets[i].second / 4;
    }

  // each edge once, with its first cell and place in it (6 c + pair)
  static const int pairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  std::vector<std::pair<Edge, std::size_t>> edges;
  edges.reserve(6 * cells.size());
  for(std::size_t c = 0; c < cells.size(); ++c)
    for(std::size_t p = 0; p < 6; ++p) {
      const std::size_t a = cells[c][std::size_t(pairs[p][0])], b = cells[c][std::size_t(pairs[p][1])];
      edges.emplace_back(Edge{{(std::min)(a, b), (std::max)(a, b)}}, 6 * c + p);
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
              edges.end());
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.second < y.second; });

  // 0: the ring does not close, 1: it closes with the identity, 2: singular
  std::vector<char> kind(edges.size(), 0);
  CGAL::VVM::internal::parallel_for_each_index(edges.size(), [&](std::size_t e) {
    const std::size_t c0 = edges[e].second / 6, p = edges[e].second % 6;
    const std::size_t a = cells[c0][std::size_t(pairs[p][0])], b = cells[c0][std::size_t(pairs[p][1])];
    // walk across the facet (a, b, next), next the later of c0's two other vertices
    std::size_t next = none;
    for(int k = 3; k >= 0 && next == none; --k)
      if(k != pairs[p][0] && k != pairs[p][1]) next = cells[c0][std::size_t(k)];
    std::size_t cell = c0;
    Eigen::Matrix3d holonomy = Eigen::Matrix3d::Identity();
    for(std::size_t steps = 0; steps <= cells.size(); ++steps) {
      int opposite = 0; // the vertex of `cell` not on the facet
      for(int k = 0; k < 4; ++k) {
        const std::size_t v = cells[cell][std::size_t(k)];
        if(v != a && v != b && v != next) opposite = k;
      }
      const std::size_t to = across[4 * cell + std::size_t(opposite)];
      if(to == none) return;
      holonomy = holonomy * matching(cell_frames[cell], cell_frames[to]);
      if(to == c0) {
        kind[e] = holonomy.isIdentity(0.5) ? 1 : 2;
        return;
      }
      std::size_t fourth = 0;
      for(std::size_t v : cells[to])
        if(v != a && v != b && v != next) fourth = v;
      next = fourth;
      cell = to;
    }
  });
  Singular_edge_report report;
  for(std::size_t e = 0; e < edges.size(); ++e) {
    if(kind[e] != 0) ++report.number_of_interior_edges;
    if(kind[e] == 2) report.singular_edges.push_back(edges[e].first);
  }
  return report;
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_SINGULAR_EDGES_H
