// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The edges in a Mesh_complex_3_in_triangulation_3, in the order of its
// edges_in_complex_begin(), without a complex lookup for every edge of the
// triangulation: that iterator tests each finite edge, which costs as much as
// a pass over a large mesh even when the complex has no edge at all.

#ifndef CGAL_VVM_INTERNAL_EDGES_IN_COMPLEX_H
#define CGAL_VVM_INTERNAL_EDGES_IN_COMPLEX_H

#include <vector>

namespace CGAL {
namespace VVM {
namespace internal {

/// the edges in the complex of `c3t3`, in the order `edges_in_complex_begin()` gives them
template <class C3T3>
std::vector<typename C3T3::Edge> edges_in_complex(const C3T3& c3t3)
{
  std::vector<typename C3T3::Edge> edges;
  const std::size_t n = c3t3.number_of_edges_in_complex();
  if(n == 0) return edges;
  edges.reserve(n);
  // Mesh_3 puts the complex's edges between the vertices of its feature curves and corners
  // (dimension 1 and 0): other edges need no lookup
  const auto& tr = c3t3.triangulation();
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    const auto a = e->first->vertex(e->second), b = e->first->vertex(e->third);
    if(a->in_dimension() >= 0 && a->in_dimension() <= 1 && b->in_dimension() >= 0 && b->in_dimension() <= 1 &&
       c3t3.is_in_complex(*e))
      edges.push_back(*e);
  }
  if(edges.size() == n) return edges;
  // a complex whose vertices' dimensions were not set that way: every edge is tested
  edges.clear();
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) edges.push_back(*e);
  return edges;
}

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_EDGES_IN_COMPLEX_H
