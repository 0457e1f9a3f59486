// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tests of Hex_dominant_meshing share: types and the check that a call throws.

#ifndef VVM_HEX_DOMINANT_TEST_SUPPORT_H
#define VVM_HEX_DOMINANT_TEST_SUPPORT_H

#include "vvm_test.h"

#include <CGAL/make_hex_dominant_mesh_3.h>
#include <CGAL/tets_to_hex_dominant.h>
#include <CGAL/Frame_fields/Constant_frame_field_3.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/Hex_dominant_meshing/cell_quality.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Metric_Delaunay_flips.h>
#include <CGAL/GSM_mesh_optimization/internal/Triangulation_complex.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Regular_triangulation_3.h>

#include <cassert>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Weighted_point_3 Weighted_point_3;
typedef CGAL::Delaunay_triangulation_3<K> Delaunay;
typedef CGAL::Regular_triangulation_3<K> Regular;
typedef CGAL::Triangulation_vertex_base_with_info_3<int, K> Vb_info;
typedef CGAL::Regular_triangulation_vertex_base_3<K, Vb_info> Rvb;
typedef CGAL::Triangulation_data_structure_3<Rvb, CGAL::Regular_triangulation_cell_base_3<K>> Rtds;
typedef CGAL::Regular_triangulation_3<K, Rtds> Regular_with_info;
typedef CGAL::Hex_dominant_mesh_3<Point_3> Mesh;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Cube_domain;
typedef CGAL::Mesh_triangulation_3<Cube_domain, CGAL::Default, CGAL::Sequential_tag>::type Cube_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Cube_tr, Cube_domain::Corner_index, Cube_domain::Curve_index> Cube_c3t3;
typedef CGAL::Frame_fields::Constant_frame_field_3<K> Constant_field;

namespace {


// true if `f` throws std::invalid_argument (its message printed)
template <class F>
bool throws(F f)
{
  try {
    f();
  } catch(const std::invalid_argument& e) {
    std::cout << "  refused: " << e.what() << "\n";
    return true;
  }
  return false;
}

// the hexahedron's edges (VTK order) join cube corners that differ in one coordinate
bool has_cube_corner_order(const Mesh::Cell& c, const std::vector<int>& corner_of_point)
{
  static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for(const auto& e : edges) {
    const int x = corner_of_point[c.vertices[std::size_t(e[0])]] ^ corner_of_point[c.vertices[std::size_t(e[1])]];
    if(x != 1 && x != 2 && x != 4) return false;
  }
  return true;
}

} // namespace

#endif // VVM_HEX_DOMINANT_TEST_SUPPORT_H
