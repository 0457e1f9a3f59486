// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_optimizers on a closed triangle surface read from a file, or on the
// built-in cube: Polyhedral_mesh_domain_with_features_3, sharp features
// protected when --features-angle > 0 (the cube's by default).

#include "comparison_driver.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <fstream>

namespace vvm_benchmark {
namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
namespace PMP = CGAL::Polygon_mesh_processing;

Surface_mesh make_cube()
{
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> v;
  for(int i = 0; i < 8; ++i)
    v.push_back(sm.add_vertex(K::Point_3(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1)));
  // the six faces, outward oriented, as quads (corner bits: x=4, y=2, z=1)
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for(const auto& q : quads)
    sm.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  PMP::triangulate_faces(sm);
  return sm;
}

std::string stem(const std::string& path)
{
  std::string name = path.substr(path.find_last_of("/\\") + 1);
  return name.substr(0, name.find_last_of('.'));
}

// Reads a closed, non self-intersecting surface; anything else is an Input_error.
Surface_mesh read_closed_surface(const std::string& path)
{
  std::ifstream probe(path, std::ios::binary | std::ios::ate);
  if(!probe) throw Input_error("cannot open '" + path + "'");
  if(probe.tellg() <= 0) throw Input_error("'" + path + "' is an empty file");
  Surface_mesh sm;
  if(!CGAL::IO::read_polygon_mesh(path, sm))
    throw Input_error("cannot read '" + path + "' as a polygon mesh (OFF, OBJ, PLY, STL, ...)");
  if(sm.number_of_faces() == 0) throw Input_error("'" + path + "' contains no faces");
  for(auto v : sm.vertices()) {
    const K::Point_3& p = sm.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error("'" + path + "' has a vertex with a non-finite coordinate");
  }
  if(!CGAL::is_triangle_mesh(sm)) PMP::triangulate_faces(sm);
  if(!CGAL::is_closed(sm)) throw Input_error("the surface in '" + path + "' is open (it has border edges); a closed surface is needed");
  if(PMP::does_self_intersect(sm)) throw Input_error("the surface in '" + path + "' self-intersects");
  return sm;
}

} // namespace

int run_polyhedral_domain(const Options& options)
{
  const bool is_cube = options.input == "cube";
  const Surface_mesh surface = is_cube ? make_cube() : read_closed_surface(options.input);
  Domain domain(surface);
  const double angle = options.features_angle >= 0 ? options.features_angle : (is_cube ? 60. : 0.);
  if(angle > 0) domain.detect_features(angle);
  const double volume = std::abs(PMP::volume(surface));
  if(!(volume > 0)) throw Input_error("the surface in '" + options.input + "' encloses no volume");
  Comparison_driver<C3T3, Domain> driver(options, is_cube ? "cube" : stem(options.input), domain, volume);
  return driver.run();
}

} // namespace vvm_benchmark
