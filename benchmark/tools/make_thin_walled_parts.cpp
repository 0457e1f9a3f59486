// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes the thin-walled test parts of data/thin_walled/ (issue #44): machined-part
// shapes whose walls are thin against the part, built from boxes, prisms and
// cylinders by CGAL's corefinement, then remeshed to edges of 0.05.
//
//   make_thin_walled_parts OUTPUT_DIR
//
// - plate_with_holes.off: a 4 x 3 plate, 0.15 thick, with six holes of radius 0.25;
// - open_box.off: a 2 x 1.5 x 1 tray whose walls and floor are 0.1 thick;
// - ribbed_bracket.off: an L bracket (a 4 x 2 base and a 1.5 high wall, both 0.12
//   thick) held by three triangular ribs 0.1 thick;
// - heat_sink.off: a 2 x 1.5 x 0.5 block carrying five fins 0.08 thick and 1 high, 0.32
//   apart: thin walls and thin gaps on a thick part.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// the prism over the convex polygon `base` (counterclockwise in x, y), from z0 to z1
Surface_mesh prism(const std::vector<std::pair<double, double>>& base, double z0, double z1)
{
  Surface_mesh sm;
  const std::size_t n = base.size();
  std::vector<Surface_mesh::Vertex_index> bottom, top;
  for(const auto& p : base) bottom.push_back(sm.add_vertex(Point_3(p.first, p.second, z0)));
  for(const auto& p : base) top.push_back(sm.add_vertex(Point_3(p.first, p.second, z1)));
  std::vector<Surface_mesh::Vertex_index> down(bottom.rbegin(), bottom.rend());
  sm.add_face(down);
  sm.add_face(top);
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    sm.add_face(bottom[i], bottom[j], top[j], top[i]);
  }
  PMP::triangulate_faces(sm);
  return sm;
}

Surface_mesh box(double x0, double y0, double z0, double x1, double y1, double z1)
{
  return prism({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, z0, z1);
}

Surface_mesh cylinder(double x, double y, double r, double z0, double z1, int segments = 64)
{
  std::vector<std::pair<double, double>> circle;
  for(int i = 0; i < segments; ++i)
    circle.push_back({x + r * std::cos(2 * CGAL_PI * i / segments), y + r * std::sin(2 * CGAL_PI * i / segments)});
  return prism(circle, z0, z1);
}

// the prism over the triangle `yz` of the (y, z) plane, from x0 to x1: a prism along z over
// (y, z), its coordinates turned (x, y, z) -> (z, x, y), which keeps the orientation
Surface_mesh prism_along_x(const std::vector<std::pair<double, double>>& yz, double x0, double x1)
{
  Surface_mesh sm = prism(yz, x0, x1);
  for(auto v : sm.vertices()) {
    const Point_3 p = sm.point(v);
    sm.point(v) = Point_3(p.z(), p.x(), p.y());
  }
  return sm;
}

void subtract(Surface_mesh& a, Surface_mesh b)
{
  if(!PMP::corefine_and_compute_difference(a, b, a)) throw std::runtime_error("a difference failed");
}

void unite(Surface_mesh& a, Surface_mesh b)
{
  if(!PMP::corefine_and_compute_union(a, b, a)) throw std::runtime_error("a union failed");
}

// corefinement leaves long slivers, which make every AABB-tree query slow: the surface is
// remeshed to edges of about `length`, its sharp edges kept
void write(Surface_mesh sm, const std::string& path, double length)
{
  auto sharp = sm.add_property_map<Surface_mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(sm, 60, sharp);
  PMP::isotropic_remeshing(faces(sm), length, sm,
                           CGAL::parameters::edge_is_constrained_map(sharp).protect_constraints(false)
                               .relax_constraints(false).number_of_iterations(5));
  sm.collect_garbage();
  if(!CGAL::IO::write_polygon_mesh(path, sm, CGAL::parameters::stream_precision(9)))
    throw std::runtime_error("cannot write " + path);
  std::cout << path << ": " << sm.number_of_vertices() << " vertices, " << sm.number_of_faces() << " faces\n";
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 2) {
    std::cerr << "usage: make_thin_walled_parts OUTPUT_DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  try {
    Surface_mesh plate = box(0, 0, 0, 4, 3, 0.15);
    for(double x : {0.8, 2.0, 3.2})
      for(double y : {0.9, 2.1}) subtract(plate, cylinder(x, y, 0.25, -1, 1));
    write(plate, dir + "/plate_with_holes.off", 0.05);

    Surface_mesh tray = box(0, 0, 0, 2, 1.5, 1);
    subtract(tray, box(0.1, 0.1, 0.1, 1.9, 1.4, 2));
    write(tray, dir + "/open_box.off", 0.05);

    Surface_mesh bracket = box(0, 0, 0, 4, 2, 0.12);
    unite(bracket, box(0, 0, 0, 4, 0.12, 1.5));
    // ribs in the planes x = const, in the corner between the base and the wall
    for(double x : {0.3, 1.95, 3.6})
      unite(bracket, prism_along_x({{0.06, 0.06}, {1.2, 0.06}, {0.06, 1.2}}, x, x + 0.1));
    write(bracket, dir + "/ribbed_bracket.off", 0.05);

    Surface_mesh sink = box(0, 0, 0, 2, 1.5, 0.5);
    for(double x : {0.1, 0.5, 0.9, 1.3, 1.7}) unite(sink, box(x, 0, 0.4, x + 0.08, 1.5, 1.5));
    write(sink, dir + "/heat_sink.off", 0.04);
  } catch(const std::exception& e) {
    std::cerr << "make_thin_walled_parts: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
