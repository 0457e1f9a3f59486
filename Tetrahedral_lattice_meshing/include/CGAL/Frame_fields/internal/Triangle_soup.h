// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The points and index triangles of a triangle mesh (a FaceListGraph), as the
// surface field and mesher classes take them, with the mesh's faces checked.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_TRIANGLE_SOUP_H
#define CGAL_FRAME_FIELDS_INTERNAL_TRIANGLE_SOUP_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

/// `who` names the caller in the error on a face that is no triangle
template <class TriangleMesh, class VertexPointMap, class Point>
void triangle_soup(const TriangleMesh& tm, VertexPointMap vpm, std::vector<Point>& points,
                   std::vector<std::array<std::size_t, 3>>& triangles, const std::string& who)
{
  std::map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, std::size_t> index;
  for(auto v : vertices(tm)) {
    index.emplace(v, points.size());
    points.push_back(get(vpm, v));
  }
  for(auto f : faces(tm)) {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if(k == 3) throw std::invalid_argument(who + ": the surface has a face that is no triangle");
      t[k++] = index[v];
    }
    if(k != 3) throw std::invalid_argument(who + ": the surface has a face that is no triangle");
    triangles.push_back(t);
  }
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_TRIANGLE_SOUP_H
