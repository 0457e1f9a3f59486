// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The built-in shapes of the benchmarks as closed, outward-oriented triangle meshes: an
// axis-aligned box (two triangles per face) and the tube of Fig. 4.16.

#ifndef VVM_BENCHMARK_BOX_SURFACE_H
#define VVM_BENCHMARK_BOX_SURFACE_H

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <cmath>
#include <vector>

namespace vvm_benchmark {

template <class SurfaceMesh>
SurfaceMesh box_surface(double lo, double hi)
{
  typedef typename SurfaceMesh::Point Point;
  SurfaceMesh sm;
  std::vector<typename SurfaceMesh::Vertex_index> v;
  for(int i = 0; i < 8; ++i)
    v.push_back(sm.add_vertex(Point(i & 4 ? hi : lo, i & 2 ? hi : lo, i & 1 ? hi : lo)));
  // the six faces, outward oriented, as quads (corner bits: x=4, y=2, z=1)
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for(const auto& q : quads) sm.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  return sm;
}

// a tube about z: radii 0.5 and 1, z in [0, 1], n quadrilaterals around, triangulated
template <class SurfaceMesh>
SurfaceMesh tube_surface(int n)
{
  typedef typename SurfaceMesh::Point Point;
  SurfaceMesh sm;
  std::vector<typename SurfaceMesh::Vertex_index> v; // rings: outer bottom, outer top, inner bottom, inner top
  for(int ring = 0; ring < 4; ++ring)
    for(int k = 0; k < n; ++k) {
      const double a = 2 * CGAL_PI * k / n, r = ring < 2 ? 1. : 0.5, z = ring % 2 ? 1. : 0.;
      v.push_back(sm.add_vertex(Point(r * std::cos(a), r * std::sin(a), z)));
    }
  auto V = [&](int ring, int k) { return v[std::size_t(ring * n + (k % n))]; };
  for(int k = 0; k < n; ++k) {
    sm.add_face(V(0, k), V(0, k + 1), V(1, k + 1), V(1, k)); // outside, normal out
    sm.add_face(V(2, k), V(3, k), V(3, k + 1), V(2, k + 1)); // inside, normal towards the axis
    sm.add_face(V(1, k), V(1, k + 1), V(3, k + 1), V(3, k)); // top
    sm.add_face(V(0, k), V(2, k), V(2, k + 1), V(0, k + 1)); // bottom
  }
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  return sm;
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_BOX_SURFACE_H
