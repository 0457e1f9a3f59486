// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Element quality measures against hand-computed values, and their aggregates
// over a Triangulation_3 and over the cells in a C3T3.
// Expected values: closed forms where they exist (in the comments), otherwise
// from an independent computation (dihedral angles by projecting onto the
// plane normal to the edge, circumcenter by solving the 3x3 linear system).

#include "vvm_test.h"

#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace GSM = CGAL::GSM_mesh_optimization;

namespace {

const double regular_dihedral = std::acos(1. / 3.) * 180. / CGAL_PI; // 70.528779...

std::vector<double> sorted_angles(const GSM::Tetrahedron_quality& q)
{
  std::vector<double> a(q.dihedral_angles.begin(), q.dihedral_angles.end());
  std::sort(a.begin(), a.end());
  return a;
}

void check_angles(const GSM::Tetrahedron_quality& q, std::vector<double> expected, double tol = 1e-9)
{
  std::sort(expected.begin(), expected.end());
  const std::vector<double> a = sorted_angles(q);
  for(int i = 0; i < 6; ++i) VVM_CHECK_CLOSE(a[i], expected[i], tol);
}

void test_regular_tetrahedron()
{
  // edge 2 sqrt(2): V = a^3 / (6 sqrt 2) = 8/3, all ratios 1
  const Point p0(1, 1, 1), p1(-1, 1, -1), p2(1, -1, -1), p3(-1, -1, 1);
  const GSM::Tetrahedron_quality q = GSM::tetrahedron_quality(p0, p1, p2, p3);
  check_angles(q, std::vector<double>(6, regular_dihedral));
  VVM_CHECK_CLOSE(regular_dihedral, 70.5287793655, 1e-9);
  VVM_CHECK_CLOSE(q.volume, 8. / 3., 1e-12);
  VVM_CHECK_CLOSE(q.radius_ratio, 1., 1e-12);
  VVM_CHECK_CLOSE(q.edge_radius_ratio, 1., 1e-12);
  VVM_CHECK_CLOSE(q.condition, 1., 1e-12);
  VVM_CHECK(!q.is_inverted());
  VVM_CHECK_CLOSE(q.min_dihedral_angle(), regular_dihedral, 1e-9);
  VVM_CHECK_CLOSE(q.max_dihedral_angle(), regular_dihedral, 1e-9);
}

void test_inverted_tetrahedron()
{
  // the regular tet with two vertices swapped: same angles, negative volume and ratios
  const GSM::Tetrahedron_quality q =
      GSM::tetrahedron_quality(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1));
  check_angles(q, std::vector<double>(6, regular_dihedral));
  VVM_CHECK_CLOSE(q.volume, -8. / 3., 1e-12);
  VVM_CHECK(q.is_inverted());
  VVM_CHECK_CLOSE(q.radius_ratio, -1., 1e-12);
  VVM_CHECK_CLOSE(q.condition, -1., 1e-12);
  VVM_CHECK_CLOSE(q.edge_radius_ratio, 1., 1e-12); // unsigned: a length ratio
}

void test_bcc_tetrahedron()
{
  // two adjacent cube centres and the edge of the cube face between them:
  // 90 deg at the two unit edges, 60 deg at the four sqrt(3)/2 edges;
  // V = 1/12; all three ratios equal 3/sqrt(10)
  const GSM::Tetrahedron_quality q = GSM::tetrahedron_quality(
      Point(0, 0, 0), Point(1, 0, 0), Point(.5, .5, -.5), Point(.5, .5, .5));
  check_angles(q, {60, 60, 60, 60, 90, 90});
  VVM_CHECK_CLOSE(q.dihedral_angles[0], 90., 1e-9); // edge (0,1), the cube edge
  VVM_CHECK_CLOSE(q.dihedral_angles[5], 90., 1e-9); // edge (2,3), the centre-centre edge
  VVM_CHECK_CLOSE(q.volume, 1. / 12., 1e-12);
  VVM_CHECK_CLOSE(q.radius_ratio, 3. / std::sqrt(10.), 1e-12);
  VVM_CHECK_CLOSE(q.edge_radius_ratio, 3. / std::sqrt(10.), 1e-12);
  VVM_CHECK_CLOSE(q.condition, 3. / std::sqrt(10.), 1e-12);
}

void test_fcc_tetrahedra()
{
  // FCC tet 1: regular, from alternate cube corners
  const GSM::Tetrahedron_quality regular =
      GSM::tetrahedron_quality(Point(0, 0, 0), Point(1, 0, 1), Point(1, 1, 0), Point(0, 1, 1));
  check_angles(regular, std::vector<double>(6, regular_dihedral));
  VVM_CHECK_CLOSE(regular.volume, 1. / 3., 1e-12);
  VVM_CHECK_CLOSE(regular.radius_ratio, 1., 1e-12);

  // FCC tet 2: a quarter of the octahedron with vertices +-e_i: 90 deg at the
  // split diagonal, the octahedron's 109.47 = acos(-1/3) at the opposite edge,
  // half of it (54.74) at the four others. V = 1/3.
  const GSM::Tetrahedron_quality quarter =
      GSM::tetrahedron_quality(Point(0, 0, 1), Point(0, 0, -1), Point(0, 1, 0), Point(1, 0, 0));
  const double oct = std::acos(-1. / 3.) * 180. / CGAL_PI;
  check_angles(quarter, {oct / 2, oct / 2, oct / 2, oct / 2, 90, oct});
  VVM_CHECK_CLOSE(oct / 2, 54.7356103172, 1e-9);
  VVM_CHECK_CLOSE(quarter.volume, 1. / 3., 1e-12);
  // r_circ = 1, faces 1, 1, sqrt(3)/2, sqrt(3)/2: r_in = 3V / A = 2 - sqrt 3
  VVM_CHECK_CLOSE(quarter.radius_ratio, 6. - 3. * std::sqrt(3.), 1e-12);
  VVM_CHECK_CLOSE(quarter.edge_radius_ratio, std::sqrt(3.) / 2., 1e-12); // e_min = sqrt 2, r_circ = 1
  VVM_CHECK_CLOSE(quarter.condition, 6. / 7., 1e-12); // l_rms^2 = 14/6, A_rms^2 = 7/8
}

void test_sliver()
{
  // four points almost on a circle: two opposite edges at height 0 and h.
  // The dihedral angle at each of these edges is 180 - 2 atan(h).
  const double h = 0.05;
  const GSM::Tetrahedron_quality q =
      GSM::tetrahedron_quality(Point(1, 0, 0), Point(-1, 0, 0), Point(0, -1, h), Point(0, 1, h));
  const double big = 180. - 2. * std::atan(h) * 180. / CGAL_PI;
  VVM_CHECK_CLOSE(big, 174.2751895478, 1e-9);
  check_angles(q, {4.0472099826, 4.0472099826, 4.0472099826, 4.0472099826, big, big}, 1e-9);
  VVM_CHECK_CLOSE(q.volume, 1. / 30., 1e-12); // (1/6) * |det| = (1/6) * 4 h
  VVM_CHECK_CLOSE(q.radius_ratio, 0.0748830281248, 1e-11);
  VVM_CHECK_CLOSE(q.edge_radius_ratio, 0.866295825463, 1e-11);
  VVM_CHECK(q.min_dihedral_angle() < 5 && q.max_dihedral_angle() > 170);
}

void test_cap()
{
  // apex just above the centroid of an equilateral base (side 1, inradius sqrt(3)/6):
  // 3 small angles atan(h / (sqrt(3)/6)) at the base edges, 3 large ones at the apex
  const double h = 0.05, s3 = std::sqrt(3.);
  const GSM::Tetrahedron_quality q = GSM::tetrahedron_quality(
      Point(0, 0, 0), Point(1, 0, 0), Point(0.5, s3 / 2, 0), Point(0.5, s3 / 6, h));
  const double small = std::atan(h / (s3 / 6)) * 180. / CGAL_PI;
  VVM_CHECK_CLOSE(small, 9.8264298158, 1e-9);
  check_angles(q, {small, small, small, 163.0011608897, 163.0011608897, 163.0011608897}, 1e-9);
  VVM_CHECK_CLOSE(q.volume, s3 / 4 * h / 3, 1e-14); // base area * h / 3
  VVM_CHECK_CLOSE(q.radius_ratio, 0.0221674786738, 1e-11);
  VVM_CHECK_CLOSE(q.condition, 0.129298234095, 1e-11);
}

void test_needle()
{
  // tiny equilateral base (side 0.01) and a far apex right above its centroid:
  // angles -> 90 at the base, -> 60 along the spire; the ratios collapse
  const double e = 0.01, s3 = std::sqrt(3.);
  const GSM::Tetrahedron_quality q = GSM::tetrahedron_quality(
      Point(0, 0, 0), Point(e, 0, 0), Point(e / 2, e / 2 * s3, 0), Point(e / 2, e / 2 * s3 / 3, 1));
  const double base = std::atan(1. / (e * s3 / 6)) * 180. / CGAL_PI;
  VVM_CHECK_CLOSE(base, 89.8346017908, 1e-9);
  check_angles(q, {60.0008269830, 60.0008269830, 60.0008269830, base, base, base}, 1e-9);
  VVM_CHECK_CLOSE(q.volume, s3 / 4 * e * e / 3, 1e-16);
  VVM_CHECK_CLOSE(q.radius_ratio, 0.0172700045775, 1e-11);
  VVM_CHECK_CLOSE(q.edge_radius_ratio, 0.0122470404792, 1e-11);
  VVM_CHECK_CLOSE(q.condition, 0.0173190648419, 1e-11);
}

void test_flat_tetrahedron()
{
  // coplanar points: zero volume, ratios 0, counted as inverted, no NaN
  const GSM::Tetrahedron_quality q =
      GSM::tetrahedron_quality(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0));
  VVM_CHECK_EQUAL(q.volume, 0.);
  VVM_CHECK_EQUAL(q.radius_ratio, 0.);
  VVM_CHECK_EQUAL(q.condition, 0.);
  VVM_CHECK(q.is_inverted());
  for(double a : q.dihedral_angles) VVM_CHECK(a >= 0 && a <= 180);
}

// tetrahedron_min_dihedral_angle() gives exactly tetrahedron_quality()'s smallest angle: on the
// hand-made shapes above (regular, sliver, cap, needle, inverted, flat, a point repeated) and
// on 1000 random tetrahedra
void test_smallest_angle_alone()
{
  std::vector<std::array<Eigen::Vector3d, 4>> tets = {
      {{Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -1, -1), Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(-1, -1, 1)}},
      {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0.01)}},
      {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.5, 1, 0), Eigen::Vector3d(0.5, 0.3, 0.01)}},
      {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(0, 0.01, 0), Eigen::Vector3d(0, 0, 1)}},
      {{Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(1, -1, -1), Eigen::Vector3d(-1, -1, 1)}},
      {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0)}},
      {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}}};
  std::srand(7);
  const auto coordinate = []() { return double(std::rand()) / RAND_MAX - 0.5; };
  for(int n = 0; n < 1000; ++n) {
    std::array<Eigen::Vector3d, 4> t;
    for(auto& p : t) p = Eigen::Vector3d(coordinate(), coordinate(), coordinate());
    tets.push_back(t);
  }
  std::size_t equal = 0;
  for(const auto& t : tets) equal += GSM::tetrahedron_min_dihedral_angle(t) == GSM::tetrahedron_quality(t).min_dihedral_angle() ? 1 : 0;
  VVM_CHECK_EQUAL(equal, tets.size());
  VVM_CHECK_CLOSE(GSM::tetrahedron_min_dihedral_angle(tets[0]), regular_dihedral, 1e-12);
  VVM_CHECK_EQUAL(GSM::tetrahedron_min_dihedral_angle(tets[6]), 0.);
}

void test_mapped_tetrahedron()
{
  // the regular tet stretched by diag(4, 1, 1) is poor; mapped back by
  // B = diag(1/4, 1, 1) it is regular again
  const Point p0(4, 1, 1), p1(-4, 1, -1), p2(4, -1, -1), p3(-4, -1, 1);
  const GSM::Tetrahedron_quality raw = GSM::tetrahedron_quality(p0, p1, p2, p3);
  VVM_CHECK(raw.radius_ratio < 0.6);
  Eigen::Matrix3d B = Eigen::Vector3d(0.25, 1, 1).asDiagonal();
  const GSM::Tetrahedron_quality q = GSM::tetrahedron_quality(p0, p1, p2, p3, B);
  check_angles(q, std::vector<double>(6, regular_dihedral));
  VVM_CHECK_CLOSE(q.radius_ratio, 1., 1e-12);
  VVM_CHECK_CLOSE(q.condition, 1., 1e-12);
  VVM_CHECK_CLOSE(q.volume, 8. / 3., 1e-12);

  // a non-diagonal map: a rotation leaves the measures unchanged
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const GSM::Tetrahedron_quality rotated = GSM::tetrahedron_quality(p0, p1, p2, p3, R * B);
  check_angles(rotated, std::vector<double>(6, regular_dihedral), 1e-9);
  VVM_CHECK_CLOSE(rotated.radius_ratio, 1., 1e-12);
}

// Two regular tets glued on a face (a convex bipyramid; its Delaunay
// triangulation is the two tets) plus a statistics pass over them.
std::vector<Point> bipyramid()
{
  return {Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1),
          Point(-5. / 3, -5. / 3, -5. / 3)}; // (1,1,1) mirrored across the plane x+y+z = -1
}

void test_triangulation_statistics()
{
  CGAL::Delaunay_triangulation_3<K> dt;
  const std::vector<Point> pts = bipyramid();
  dt.insert(pts.begin(), pts.end());
  VVM_CHECK_EQUAL(dt.number_of_finite_cells(), std::size_t(2));

  const GSM::Mesh_quality_statistics s = GSM::triangulation_quality_statistics(dt);
  VVM_CHECK_EQUAL(s.number_of_cells, std::size_t(2));
  VVM_CHECK_EQUAL(s.number_of_vertices, std::size_t(5));
  VVM_CHECK_EQUAL(s.number_of_inverted_cells, std::size_t(0));
  VVM_CHECK_CLOSE(s.min_dihedral_angle, regular_dihedral, 1e-9);
  VVM_CHECK_CLOSE(s.max_dihedral_angle, regular_dihedral, 1e-9);
  VVM_CHECK_CLOSE(s.mean_min_dihedral_angle, regular_dihedral, 1e-9);
  VVM_CHECK_CLOSE(s.min_radius_ratio, 1., 1e-12);
  VVM_CHECK_CLOSE(s.mean_radius_ratio, 1., 1e-12);
  VVM_CHECK_CLOSE(s.mean_condition, 1., 1e-12);
  for(std::size_t count : s.n_min_dihedral_below) VVM_CHECK_EQUAL(count, std::size_t(0));
  VVM_CHECK_EQUAL(s.dihedral_angle_histogram[70], std::size_t(12));
  VVM_CHECK_EQUAL(s.min_dihedral_angle_histogram[70], std::size_t(2));
  VVM_CHECK_EQUAL(s.radius_ratio_histogram[99], std::size_t(2));

  // measured through B = diag(2, 1, 1), the tets are no longer regular
  const GSM::Mesh_quality_statistics a = GSM::triangulation_quality_statistics(
      dt, [](const Point&) { return Eigen::Matrix3d(Eigen::Vector3d(2, 1, 1).asDiagonal()); });
  VVM_CHECK(a.min_dihedral_angle < regular_dihedral - 1);
  VVM_CHECK(a.min_radius_ratio < 0.99);
  VVM_CHECK_EQUAL(a.number_of_inverted_cells, std::size_t(0));
}

void test_accumulated_counts()
{
  GSM::Mesh_quality_statistics s;
  const double h = 0.05, s3 = std::sqrt(3.);
  s.add(GSM::tetrahedron_quality(Point(0, 0, 0), Point(1, 0, 0), Point(.5, .5, -.5), Point(.5, .5, .5))); // BCC, min 60
  s.add(GSM::tetrahedron_quality(Point(1, 0, 0), Point(-1, 0, 0), Point(0, -1, h), Point(0, 1, h)));      // sliver, 4.05
  s.add(GSM::tetrahedron_quality(Point(0, 0, 0), Point(1, 0, 0), Point(0.5, s3 / 2, 0),
                                 Point(0.5, s3 / 6, h)));                                              // cap, 9.83
  s.add(GSM::tetrahedron_quality(Point(0, 0, 1), Point(0, 0, -1), Point(0, 1, 0), Point(1, 0, 0))); // FCC, 54.7
  s.add(GSM::tetrahedron_quality(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1))); // inverted
  s.finish();
  VVM_CHECK_EQUAL(s.number_of_cells, std::size_t(5));
  VVM_CHECK_EQUAL(s.number_of_inverted_cells, std::size_t(1));
  VVM_CHECK_EQUAL(s.n_min_dihedral_below[0], std::size_t(2)); // < 10: sliver, cap
  VVM_CHECK_EQUAL(s.n_min_dihedral_below[1], std::size_t(2)); // < 20
  VVM_CHECK_EQUAL(s.n_min_dihedral_below[2], std::size_t(2)); // < 30
  VVM_CHECK_EQUAL(s.n_min_dihedral_below[3], std::size_t(2)); // < 40
  VVM_CHECK_CLOSE(s.min_dihedral_angle, 4.0472099826, 1e-9);
  VVM_CHECK_CLOSE(s.max_dihedral_angle, 174.2751895478, 1e-9);
  VVM_CHECK_CLOSE(s.mean_min_dihedral_angle,
                  (60 + 4.0472099826 + 9.8264298158 + 54.7356103172 + regular_dihedral) / 5, 1e-9);
  VVM_CHECK_CLOSE(s.min_radius_ratio, -1., 1e-12);
  VVM_CHECK_EQUAL(s.min_dihedral_angle_histogram[4], std::size_t(1));
  VVM_CHECK_EQUAL(s.min_dihedral_angle_histogram[9], std::size_t(1));
  VVM_CHECK_EQUAL(s.min_dihedral_angle_histogram[60], std::size_t(1));
  VVM_CHECK_EQUAL(s.radius_ratio_histogram[0], std::size_t(1)); // the inverted one
}

void test_c3t3_statistics()
{
  typedef CGAL::Labeled_mesh_domain_3<K> Domain;
  typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
  typedef Tr::Bare_point Bare_point;

  C3T3 c3t3;
  Tr& tr = c3t3.triangulation();
  for(const Point& p : bipyramid()) tr.insert(Tr::Point(Bare_point(p.x(), p.y(), p.z())));
  VVM_CHECK_EQUAL(tr.number_of_finite_cells(), std::size_t(2));

  GSM::Mesh_quality_statistics s = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK_EQUAL(s.number_of_cells, std::size_t(0)); // nothing in the complex yet
  VVM_CHECK_EQUAL(s.number_of_vertices, std::size_t(0));

  c3t3.add_to_complex(tr.finite_cells_begin(), 1);
  s = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK_EQUAL(s.number_of_cells, std::size_t(1));
  VVM_CHECK_EQUAL(s.number_of_vertices, std::size_t(4));
  VVM_CHECK_CLOSE(s.min_dihedral_angle, regular_dihedral, 1e-9);
  VVM_CHECK_CLOSE(s.min_radius_ratio, 1., 1e-12);

  // the whole triangulation of the same complex: both cells
  VVM_CHECK_EQUAL(GSM::triangulation_quality_statistics(tr).number_of_cells, std::size_t(2));
}

} // namespace

int main(int argc, char** argv)
{
  return vvm_test::run(argc, argv, "test_quality_measures", {
      {"regular_tetrahedron", test_regular_tetrahedron},
      {"inverted_tetrahedron", test_inverted_tetrahedron},
      {"bcc_tetrahedron", test_bcc_tetrahedron},
      {"fcc_tetrahedra", test_fcc_tetrahedra},
      {"sliver", test_sliver},
      {"cap", test_cap},
      {"needle", test_needle},
      {"flat_tetrahedron", test_flat_tetrahedron},
      {"smallest_angle_alone", test_smallest_angle_alone},
      {"mapped_tetrahedron", test_mapped_tetrahedron},
      {"triangulation_statistics", test_triangulation_statistics},
      {"accumulated_counts", test_accumulated_counts},
      {"c3t3_statistics", test_c3t3_statistics}});
}
