// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How much of a mesh lies on its boundary, and how far its first interior vertices are
// from it. Between a boundary and an interior much coarser than it, an optimizer that
// keeps the vertex count may not lift the tets: a tet with a boundary edge of length h
// and, at distance d above its midpoint, an interior edge across it has a dihedral angle
// of 2 atan(h / 2d) at the interior edge (19 degrees for d = 3h). make_mesh_3 gives such
// meshes with a tight facet_distance, or on parts whose surface takes most of the vertex
// budget; these figures tell them apart in the benchmark tables.

#ifndef VVM_BENCHMARK_BOUNDARY_LAYERING_H
#define VVM_BENCHMARK_BOUNDARY_LAYERING_H

#include <CGAL/Unique_hash_map.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace vvm_benchmark {

struct Boundary_layering
{
  /// vertices of the boundary facets (outer boundary and interfaces between subdomains)
  /// over the vertices of the cells in the complex
  double boundary_vertex_share = 0;
  /// lower median length of the edges of the cells in the complex with both ends on the boundary
  double boundary_edge_length = 0;
  /// lower median length of the edges from a boundary vertex to an interior one, over
  /// `boundary_edge_length`; 0 if there is no such edge
  double first_layer_ratio = 0;
};

template <class C3T3>
Boundary_layering boundary_layering(const C3T3& c3t3)
{
  typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
  const auto& tr = c3t3.triangulation();
  constexpr int not_in_complex = -1, interior = 0, on_boundary = 1;
  CGAL::Unique_hash_map<Vertex_handle, int> kind(not_in_complex, tr.number_of_vertices());
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(kind[c->vertex(i)] == not_in_complex) kind[c->vertex(i)] = interior;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    for(int i = 1; i < 4; ++i) {
      const Vertex_handle v = f->first->vertex((f->second + i) & 3);
      if(kind[v] == interior) kind[v] = on_boundary; // only vertices of the cells in the complex
    }

  std::size_t vertices = 0, boundary = 0;
  for(Vertex_handle v : tr.finite_vertex_handles()) {
    const int k = std::as_const(kind)[v];
    vertices += k != not_in_complex ? 1 : 0;
    boundary += k == on_boundary ? 1 : 0;
  }
  std::vector<double> boundary_edges, first_layer_edges;
  const auto point = tr.geom_traits().construct_point_3_object();
  const auto squared_distance = tr.geom_traits().compute_squared_distance_3_object();
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    const Vertex_handle a = e->first->vertex(e->second), b = e->first->vertex(e->third);
    const int ka = std::as_const(kind)[a], kb = std::as_const(kind)[b];
    if(ka == not_in_complex || kb == not_in_complex) continue;
    bool in_complex = false; // an edge of a cell in the complex
    auto c = tr.incident_cells(*e), done = c;
    do in_complex = c3t3.is_in_complex(c); while(!in_complex && ++c != done);
    if(!in_complex || ka + kb == 0) continue;
    const double length = std::sqrt(CGAL::to_double(squared_distance(point(tr.point(a)), point(tr.point(b)))));
    (ka + kb == 2 ? boundary_edges : first_layer_edges).push_back(length);
  }
  const auto lower_median = [](std::vector<double>& x) {
    std::nth_element(x.begin(), x.begin() + (x.size() - 1) / 2, x.end());
    return x[(x.size() - 1) / 2];
  };
  Boundary_layering result;
  if(vertices == 0) return result;
  result.boundary_vertex_share = double(boundary) / double(vertices);
  if(boundary_edges.empty()) return result;
  result.boundary_edge_length = lower_median(boundary_edges);
  if(!first_layer_edges.empty())
    result.first_layer_ratio = lower_median(first_layer_edges) / result.boundary_edge_length;
  return result;
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_BOUNDARY_LAYERING_H
