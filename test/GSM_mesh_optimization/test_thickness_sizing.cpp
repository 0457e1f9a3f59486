// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Local_thickness_3 and Thickness_sizing_field_3: the thickness and gap of a slab,
// a tube and a spherical shell against their exact values, the widths of the faces
// between feature curves (a slab's sides, a step), the sizing field's sizes and
// gradation bound, and bad inputs refused.

#include "vvm_test.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Local_thickness_3.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Thickness_sizing_field_3.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef CGAL::Local_thickness_3<K> Local_thickness;
typedef CGAL::Thickness_sizing_field_3<K> Sizing_field;
namespace VVM = CGAL::VVM;

namespace {

// the box [0, a] x [0, b] x [0, c], two triangles a face
Surface_mesh box(double a, double b, double c)
{
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> v;
  for(int i = 0; i < 8; ++i) v.push_back(sm.add_vertex(Point_3(i & 4 ? a : 0, i & 2 ? b : 0, i & 1 ? c : 0)));
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for(const auto& q : quads) sm.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  return sm;
}

// the closed polygon (r, z) of the half plane r > 0 turned around the z axis in `segments` steps
Surface_mesh surface_of_revolution(const std::vector<std::pair<double, double>>& profile, int segments)
{
  Surface_mesh sm;
  const int m = int(profile.size());
  std::vector<Surface_mesh::Vertex_index> v;
  for(int j = 0; j < segments; ++j) {
    const double phi = 2 * CGAL_PI * j / segments;
    for(const auto& rz : profile)
      v.push_back(sm.add_vertex(Point_3(rz.first * std::cos(phi), rz.first * std::sin(phi), rz.second)));
  }
  for(int j = 0; j < segments; ++j)
    for(int i = 0; i < m; ++i) {
      const int j1 = (j + 1) % segments, i1 = (i + 1) % m;
      sm.add_face(v[j * m + i], v[j * m + i1], v[j1 * m + i1], v[j1 * m + i]);
    }
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  return sm;
}

// the tube of radii 0.8 and 1, of length 4, with 60 rings along it
Surface_mesh tube()
{
  std::vector<std::pair<double, double>> profile;
  for(int i = 0; i <= 60; ++i) profile.push_back({1., 4. * i / 60});
  for(int i = 60; i >= 0; --i) profile.push_back({0.8, 4. * i / 60});
  return surface_of_revolution(profile, 128);
}

// a sphere of radius r, made of an icosahedron's faces divided 4^4 times
Surface_mesh sphere(double r)
{
  Surface_mesh sm;
  CGAL::make_icosahedron(sm, Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(4));
  for(auto v : sm.vertices()) {
    const Point_3 p = sm.point(v);
    sm.point(v) = CGAL::ORIGIN + r * ((p - CGAL::ORIGIN) / std::sqrt((p - CGAL::ORIGIN).squared_length()));
  }
  return sm;
}

// the shell between the spheres of radii 0.9 and 1
Surface_mesh spherical_shell()
{
  Surface_mesh shell = sphere(1.), inner = sphere(0.9);
  CGAL::Polygon_mesh_processing::reverse_face_orientations(inner);
  shell += inner;
  return shell;
}

// the polygon (y, z), counterclockwise, extruded along x from 0 to 1
Surface_mesh prism(const std::vector<std::pair<double, double>>& profile)
{
  Surface_mesh sm;
  const std::size_t m = profile.size();
  std::vector<Surface_mesh::Vertex_index> v;
  for(double x : {0., 1.})
    for(const auto& yz : profile) v.push_back(sm.add_vertex(Point_3(x, yz.first, yz.second)));
  std::vector<Surface_mesh::Vertex_index> near_cap(v.rbegin() + std::ptrdiff_t(m), v.rend()), far_cap(v.begin() + std::ptrdiff_t(m), v.end());
  sm.add_face(near_cap);
  sm.add_face(far_cap);
  for(std::size_t i = 0; i < m; ++i) sm.add_face(v[i], v[(i + 1) % m], v[m + (i + 1) % m], v[m + i]);
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  return sm;
}

// the widths of the faces between `surface`'s edges sharper than 60 degrees
Local_thickness with_sharp_edges(Surface_mesh& surface)
{
  auto sharp = surface.add_property_map<Surface_mesh::Edge_index, bool>("e:sharp", false).first;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(surface, 60., sharp);
  return Local_thickness(surface, CGAL::parameters::edge_is_constrained_map(sharp));
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? std::numeric_limits<double>::quiet_NaN() : v[v.size() / 2];
}

// the fraction of `values` within `tolerance` (relative) of `exact`
double share_within(const std::vector<double>& values, double exact, double tolerance)
{
  std::size_t n = 0;
  for(double x : values) n += std::abs(x - exact) <= tolerance * exact ? 1 : 0;
  return values.empty() ? 0. : double(n) / double(values.size());
}

void test_slab()
{
  const Local_thickness thickness(box(4, 3, 0.2));
  std::vector<double> across, along, gaps;
  for(const auto& s : thickness.samples()) {
    if(std::abs(s.normal.z()) > 0.99) across.push_back(s.thickness);
    if(std::abs(s.normal.x()) > 0.99) along.push_back(s.thickness);
    gaps.push_back(s.gap);
  }
  VVM_CHECK(across.size() > 1000);
  // the rays from the large faces meet the opposite face: 0.2 along the normal, exactly
  VVM_CHECK_EQUAL(share_within(across, 0.2, 1e-9), 1.);
  // from the end faces x = 0 and x = 4, the slab is 4 long, or no wall is seen (the rays that
  // leave through the large faces are not kept)
  VVM_CHECK(!along.empty() && std::all_of(along.begin(), along.end(), [](double t) {
    return std::isinf(t) || std::abs(t - 4) < 1e-9;
  }));
  // no part of a convex surface faces another across the outside
  VVM_CHECK(std::all_of(gaps.begin(), gaps.end(), [](double g) { return std::isinf(g); }));
  VVM_CHECK_CLOSE(thickness.thickness(Point_3(2, 1.5, 0.1)), 0.2, 1e-9);
  VVM_CHECK_CLOSE(thickness.thickness(Point_3(2, 1.5, 5)), 0.2, 1e-9);

  // a size of 0.2 / 3 at the slab, growing by at most 0.3 times the distance
  const Sizing_field size(thickness);
  VVM_CHECK_CLOSE(size(Point_3(2, 1.5, 0.1)), 0.2 / 3, 0.3 * size.grid_spacing());
  VVM_CHECK_CLOSE(size(Point_3(2, 1.5, 0.2)), 0.2 / 3, 0.3 * size.grid_spacing());
  VVM_CHECK(size.scaled(2)(Point_3(2, 1.5, 0.1)) == 2 * size(Point_3(2, 1.5, 0.1)));
  // most samples are on the large faces, 0.2 thick
  VVM_CHECK_CLOSE(size.typical_size(), 0.2 / 3, 0.3 * size.grid_spacing());
  VVM_CHECK_CLOSE(size.scaled(2).typical_size(), 2 * size.typical_size(), 1e-15);
  VVM_CHECK(size(Point_3(2, 1.5, 0.1), 3, 0) == size(Point_3(2, 1.5, 0.1)));
}

void test_tube()
{
  const Local_thickness thickness(tube());
  std::vector<double> outer, inner, inner_gap;
  for(const auto& s : thickness.samples()) {
    const double r = std::hypot(s.point.x(), s.point.y());
    if(s.point.z() < 0.3 || s.point.z() > 3.7) continue; // away from the ends
    if(r > 0.99) outer.push_back(s.thickness);
    if(r < 0.81) inner.push_back(s.thickness), inner_gap.push_back(s.gap);
  }
  VVM_CHECK(outer.size() > 1000 && inner.size() > 1000);
  // the wall is 0.2 thick; the hole 1.6 wide (the polygon's radii, cos(pi/128) of the circles')
  VVM_CHECK(share_within(outer, 0.2, 0.1) > 0.99);
  VVM_CHECK(share_within(inner, 0.2, 0.1) > 0.99);
  VVM_CHECK_CLOSE(median(outer), 0.2, 0.02);
  VVM_CHECK_CLOSE(median(inner), 0.2, 0.02);
  VVM_CHECK(share_within(inner_gap, 1.6, 0.1) > 0.99);
  VVM_CHECK_CLOSE(thickness.thickness(Point_3(0.9, 0, 2)), 0.2, 0.02);
  VVM_CHECK_CLOSE(thickness.gap(Point_3(0.7, 0, 2)), 1.6, 0.16);
}

void test_spherical_shell()
{
  const Local_thickness thickness(spherical_shell());
  std::vector<double> outer, inner, outer_gap, inner_gap;
  for(const auto& s : thickness.samples()) {
    const bool is_outer = std::sqrt((s.point - CGAL::ORIGIN).squared_length()) > 0.95;
    (is_outer ? outer : inner).push_back(s.thickness);
    (is_outer ? outer_gap : inner_gap).push_back(s.gap);
  }
  VVM_CHECK(share_within(outer, 0.1, 0.1) > 0.99);
  VVM_CHECK(share_within(inner, 0.1, 0.1) > 0.99);
  VVM_CHECK(std::all_of(outer_gap.begin(), outer_gap.end(), [](double g) { return std::isinf(g); }));
  VVM_CHECK(share_within(inner_gap, 1.8, 0.1) > 0.99);
  // the same shell, its faces all reversed: the thickness does not depend on the orientation
  Surface_mesh reversed = spherical_shell();
  CGAL::Polygon_mesh_processing::reverse_face_orientations(reversed);
  VVM_CHECK_CLOSE(Local_thickness(reversed).thickness(Point_3(0, 0.95, 0)), thickness.thickness(Point_3(0, 0.95, 0)), 1e-12);
}

// the feature curves of a slab are its 12 edges: a side face between two rims is as wide as the
// slab is thick; the large faces' opposite rims and the curves that meet at a corner are near
// each other along the curves
void test_narrow_faces_of_a_slab()
{
  Surface_mesh slab = box(4, 3, 0.2);
  const Local_thickness thickness = with_sharp_edges(slab);
  std::size_t away_from_corners = 0, exact = 0;
  double narrowest = std::numeric_limits<double>::infinity();
  for(const auto& f : thickness.feature_samples()) {
    narrowest = (std::min)(narrowest, f.width);
    const double x = f.point.x(), y = f.point.y();
    const bool on_rim = std::abs(f.point.z()) < 1e-12 || std::abs(f.point.z() - 0.2) < 1e-12;
    // 0.9 from the corners, the path around the corner is more than ten times 0.2
    const bool far = (std::min)({x, 4 - x}) > 0.91 || (std::min)({y, 3 - y}) > 0.91;
    if(!on_rim || !far || (x > 1e-12 && x < 4 - 1e-12 && y > 1e-12 && y < 3 - 1e-12)) continue;
    ++away_from_corners;
    // facing the other rim of the same side face, straight across it
    if(std::abs(f.width - 0.2) < 1e-9 && std::abs(f.facing.x() - x) < 1e-9 && std::abs(f.facing.y() - y) < 1e-9)
      ++exact;
  }
  std::cout << "    slab: " << thickness.feature_samples().size() << " feature samples, " << away_from_corners
            << " on the rims away from the corners, " << exact << " of them 0.2 wide; narrowest " << narrowest << "\n";
  VVM_CHECK(away_from_corners > 100);
  VVM_CHECK_EQUAL(exact, away_from_corners);
  VVM_CHECK(narrowest > 0.2 - 1e-9);
  VVM_CHECK(std::all_of(thickness.feature_samples().begin(), thickness.feature_samples().end(), [&](const auto& f) {
    return f.length > 0 && f.length <= thickness.sample_spacing() / 2 + 1e-12;
  }));
}

// a prism on the triangle of angles 8 (at y = 0), 20 (at y = 1) and 152 degrees. On a cap, the
// edge from the 8-degree corner to the 20-degree one faces the 8-degree corner's other edge at
// y sin 8 where the path along the curves either way is more than ten times that (y < 0.6).
// Near the 20-degree corner (y > 0.7), every other curve is near along the curves: no width
// (with four times instead of ten, the 20-degree corner's other edge would be narrow)
void test_narrow_faces_at_corners()
{
  const double degree = CGAL_PI / 180;
  const double side = std::sin(20 * degree) / std::sin(152 * degree); // from the 8-degree corner
  Surface_mesh wedge = prism({{0, 0}, {1, 0}, {side * std::cos(8 * degree), side * std::sin(8 * degree)}});
  const Local_thickness thickness = with_sharp_edges(wedge);
  std::size_t near_sharp = 0, exact = 0, near_other = 0, none = 0;
  for(const auto& f : thickness.feature_samples()) {
    const double y = f.point.y();
    const bool on_cap = std::abs(f.point.x()) < 1e-12 || std::abs(f.point.x() - 1) < 1e-12;
    if(!on_cap || std::abs(f.point.z()) > 1e-12) continue;
    if(y > 0.1 && y < 0.5) {
      ++near_sharp;
      exact += std::abs(f.width - y * std::sin(8 * degree)) < 1e-9 ? 1 : 0;
    } else if(y > 0.7 && y < 0.95) {
      ++near_other;
      none += std::isinf(f.width) ? 1 : 0;
    }
  }
  std::cout << "    corners: " << exact << " of " << near_sharp << " samples near the 8-degree corner y sin 8 wide, "
            << none << " of " << near_other << " near the 20-degree corner with no width\n";
  VVM_CHECK(near_sharp > 20 && near_other > 20);
  VVM_CHECK_EQUAL(exact, near_sharp);
  VVM_CHECK_EQUAL(none, near_other);
}

// a step 0.05 wide on a unit block: no wall is thin, but the face between the step's two edges
// holds only as large a mesh as it is wide
void test_narrow_face_of_a_step()
{
  Surface_mesh step = prism({{0, 0}, {1, 0}, {1, 1}, {0.95, 1}, {0.95, 1.2}, {0, 1.2}});
  VVM_CHECK(CGAL::is_closed(step) && CGAL::is_triangle_mesh(step));
  const Local_thickness plain(step), featured = with_sharp_edges(step);
  std::vector<double> step_widths;
  for(const auto& f : featured.feature_samples())
    if(std::abs(f.point.z() - 1) < 1e-12 && f.point.x() > 0.3 && f.point.x() < 0.7) step_widths.push_back(f.width);
  VVM_CHECK(step_widths.size() > 10);
  VVM_CHECK_EQUAL(share_within(step_widths, 0.05, 1e-9), 1.);
  const Sizing_field without(plain), with(featured);
  const Point_3 on_step(0.5, 0.975, 1.), below(0.5, 0.975, 0.5);
  std::cout << "    step: size on the step " << with(on_step) << " with its feature curves, " << without(on_step)
            << " without; 0.5 below it " << with(below) << "\n";
  VVM_CHECK_CLOSE(with(on_step), 0.05 / 3, 0.3 * with.grid_spacing());
  VVM_CHECK(without(on_step) > 0.1);
  // graded away from the step
  VVM_CHECK(with(below) > 0.05 / 3 + 0.3 * (0.5 - 0.1) && with(below) <= 0.05 / 3 + 1.1 * 0.3 * 0.5);
}

// |h(x) - h(y)| <= g |x - y| for points three grid cells apart or more; the size is h_s at the
// walls, and the caps and the scale hold
void test_sizing_field_bounds()
{
  const Local_thickness thickness(tube());
  const double g = 0.25;
  const Sizing_field size(thickness, VVM::parameters::gradation(g, VVM::parameters::cells_across(
                                         4, VVM::parameters::maximum_size(0.3))));
  VVM_CHECK_EQUAL(size.gradation(), g);
  VVM_CHECK_EQUAL(size.cells_across(), 4.);
  VVM_CHECK_CLOSE(size(Point_3(0.9, 0, 2)), 0.05, 0.02 * 0.05 + g * size.grid_spacing());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(-1.2, 1.2), z(-0.2, 4.2);
  double worst_ratio = 0, largest = 0, smallest = 1e9;
  for(int i = 0; i < 20000; ++i) {
    const Point_3 p(x(random), x(random), z(random)), q(x(random), x(random), z(random));
    const double distance = std::sqrt(CGAL::squared_distance(p, q));
    if(distance < 3 * size.grid_spacing()) continue;
    worst_ratio = (std::max)(worst_ratio, std::abs(size(p) - size(q)) / distance);
    largest = (std::max)(largest, size(p));
    smallest = (std::min)(smallest, size(p));
  }
  std::cout << "    tube: largest |dh| / |dx| " << worst_ratio << " for g " << g << "; sizes in [" << smallest
            << ", " << largest << "]\n";
  VVM_CHECK(worst_ratio <= 1.1 * g);
  VVM_CHECK(largest <= 0.3 + 1e-6 && smallest >= 0.05 - 1e-3);
  // the tube's axis is 0.8 from the wall, less the samples' spacing by which the cones' apexes
  // are thickened
  VVM_CHECK_CLOSE(size(Point_3(0, 0, 2)), 0.05 + g * (0.8 - thickness.sample_spacing()), 0.01);
  const Sizing_field capped(thickness, VVM::parameters::minimum_size(0.1));
  VVM_CHECK_CLOSE(capped(Point_3(0.9, 0, 2)), 0.1, 0.3 * capped.grid_spacing());
}

void test_bad_inputs()
{
  Surface_mesh open = box(1, 1, 1);
  CGAL::Euler::remove_face(halfedge(*open.faces().begin(), open), open);
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { Local_thickness t(open); }, "not closed"));
  VVM_CHECK(vvm_test::throws_invalid_argument([] { Local_thickness t{Surface_mesh()}; }, "no face"));
  Surface_mesh nan = box(1, 1, 1);
  nan.point(*nan.vertices().begin()) = Point_3(std::nan(""), 0, 0);
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { Local_thickness t(nan); }, "not finite"));
  Surface_mesh flat; // a triangle and its back: closed, and flat
  const auto a = flat.add_vertex(Point_3(0, 0, 0)), b = flat.add_vertex(Point_3(1, 0, 0)),
             c = flat.add_vertex(Point_3(0, 1, 0));
  flat.add_face(a, b, c);
  flat.add_face(a, c, b);
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { Local_thickness t(flat); }, "no volume"));
  const Surface_mesh cube = box(1, 1, 1);
  VVM_CHECK(vvm_test::throws_invalid_argument(
      [&] { Local_thickness t(cube, VVM::parameters::sample_spacing(1e-6)); }, "20 million"));
  VVM_CHECK(vvm_test::throws_invalid_argument(
      [&] { Local_thickness t(cube, VVM::parameters::sample_spacing(-1.)); }, "positive"));
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { Local_thickness t(cube, VVM::parameters::cone_angle(180.)); },
                                              "cone angle"));
  const Local_thickness thickness(cube);
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { Sizing_field f(thickness, VVM::parameters::cells_across(0.)); },
                                              "cells_across"));
  VVM_CHECK(vvm_test::throws_invalid_argument(
      [&] { Sizing_field f(thickness, VVM::parameters::minimum_size(-1.)); }, "minimum_size"));
  VVM_CHECK(vvm_test::throws_invalid_argument(
      [&] { Sizing_field f(thickness, VVM::parameters::minimum_size(1., VVM::parameters::maximum_size(0.5))); },
      "maximum_size"));
  VVM_CHECK(vvm_test::throws_invalid_argument(
      [&] { Sizing_field f(thickness, VVM::parameters::gradation(std::nan(""))); }, "gradation"));
  VVM_CHECK(vvm_test::throws_invalid_argument(
      [&] { Sizing_field f(thickness, CGAL::parameters::grid_spacing(1e-5)); }, "2^27"));
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { Sizing_field(thickness).scaled(0); }, "scale"));
}

} // namespace

int main(int argc, char** argv)
{
  return vvm_test::run(argc, argv, "test_thickness_sizing",
                       {{"slab", test_slab},
                        {"tube", test_tube},
                        {"spherical_shell", test_spherical_shell},
                        {"narrow_faces_of_a_slab", test_narrow_faces_of_a_slab},
                        {"narrow_faces_at_corners", test_narrow_faces_at_corners},
                        {"narrow_face_of_a_step", test_narrow_face_of_a_step},
                        {"sizing_field_bounds", test_sizing_field_bounds},
                        {"bad_inputs", test_bad_inputs}});
}
