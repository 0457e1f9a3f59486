// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The singular edges of a cross field chained into curves: a curve runs from
// node to node, a node being a vertex where other than two singular edges meet
// (the end of a curve, on the boundary or not, or a branching); chains with no
// node are closed loops. A curve end inside the volume (a vertex of a single
// singular edge, not on the boundary: a dead end) cannot happen in a smooth
// field, so counting them checks the field.

#ifndef CGAL_FRAME_FIELDS_SINGULAR_CURVE_H
#define CGAL_FRAME_FIELDS_SINGULAR_CURVE_H

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * A chain of singular edges of a cross field (see `Generated_cross_field_3::singular_curves`).
 */
struct Singular_curve
{
  /// the vertices along the curve; a closed curve repeats its first vertex last
  std::vector<std::size_t> vertices;
  /// the sum of its edges' lengths
  double length = 0;
  /// `true` if the curve ends where it starts: a loop, on its own or through a vertex
  /// where other singular edges meet
  bool is_closed() const { return vertices.size() > 2 && vertices.front() == vertices.back(); }
};

namespace internal {

struct Singular_curves_report
{
  std::vector<Singular_curve> curves;
  std::size_t number_of_dead_ends = 0; // curve ends at non-boundary vertices of one singular edge
};

/// chains `edges` (vertex index pairs, each once) into curves; `on_boundary[v]` tells
/// whether `v` is on the boundary (a wall), `xyz` gives the lengths
inline Singular_curves_report singular_curves(const std::vector<std::array<std::size_t, 2>>& edges,
                                              const std::vector<char>& on_boundary,
                                              const std::vector<Eigen::Vector3d>& xyz)
{
  const std::size_t n = xyz.size();
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> incident(n); // (other vertex, edge)
  for(std::size_t k = 0; k < edges.size(); ++k) {
    incident[edges[k][0]].emplace_back(edges[k][1], k);
    incident[edges[k][1]].emplace_back(edges[k][0], k);
  }
  auto is_node = [&](std::size_t v) { return incident[v].size() != 2; };
  Singular_curves_report report;
  std::vector<char> used(edges.size(), 0);
  // walks from v along edge k until a node, or back to the start of a loop
  auto walk = [&](std::size_t v, std::size_t w, std::size_t k) {
    Singular_curve c;
    c.vertices.push_back(v);
    for(;;) {
      used[k] = 1;
      c.length += (xyz[w] - xyz[v]).norm();
      c.vertices.push_back(w);
      if(is_node(w) || w == c.vertices.front()) break;
      std::size_t next = edges.size();
      for(const auto& vk : incident[w])
        if(!used[vk.second]) {
          v = w;
          w = vk.first;
          next = vk.second;
          break;
        }
      if(next == edges.size()) break;
      k = next;
    }
    return c;
  };
  for(std::size_t v = 0; v < n; ++v) {
    if(!is_node(v)) continue;
    for(const auto& wk : incident[v])
      if(!used[wk.second]) report.curves.push_back(walk(v, wk.first, wk.second));
    if(incident[v].size() == 1 && !on_boundary[v]) ++report.number_of_dead_ends;
  }
  for(std::size_t k = 0; k < edges.size(); ++k) // what is left is closed loops
    if(!used[k]) report.curves.push_back(walk(edges[k][0], edges[k][1], k));
  return report;
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_SINGULAR_CURVE_H
