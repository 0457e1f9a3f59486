// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The built-in cube of the benchmarks: an axis-aligned box as a closed,
// outward-oriented triangle mesh (two triangles per face).

#ifndef VVM_BENCHMARK_BOX_SURFACE_H
#define VVM_BENCHMARK_BOX_SURFACE_H

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

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

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_BOX_SURFACE_H
