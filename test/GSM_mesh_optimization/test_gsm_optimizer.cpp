// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// gsm_optimize_mesh_3 and its parts:
// - energies: known values, gradient and Hessian against finite differences;
// - flips: 2-3, 3-2, 4-4 and the boundary peel on hand-made configurations,
//   energy change as predicted, valid complex with correct labels and counters;
// - whole runs on an implicit sphere and on a polyhedral cube with features:
//   mean energy never increases between rounds, no inverted cell, surface
//   vertices on the surface, feature vertices on their edges, corners fixed,
//   boundary frozen on request, time limit, ESM;
// - bad input: empty complex, inverted cell, bad sizing field: a clear
//   exception and the mesh unchanged.

#include "test_utilities.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedral_complex_mesh_domain_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>

#include <CGAL/GSM_mesh_optimization/internal/Angle_penalty.h>
#include <CGAL/GSM_mesh_optimization/internal/Boundary_fidelity.h>
#include <CGAL/GSM_mesh_optimization/internal/Edge_split.h>
#include <CGAL/GSM_mesh_optimization/internal/Surface_edge_split.h>
#include <CGAL/GSM_mesh_optimization/internal/Surface_vertex_collapse.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_collapse.h>
#include <CGAL/GSM_mesh_optimization/internal/Energy_guided_flips.h>
#include <CGAL/GSM_mesh_optimization/internal/Input_mesh_sizing.h>
#include <CGAL/GSM_mesh_optimization/internal/Least_norm_point_of_hull.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_sizes.h>
#include <CGAL/GSM_mesh_optimization/dissertation_metric_fields.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/GSM_mesh_optimization/shape_matching_energy.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace GSM = CGAL::GSM_mesh_optimization;
namespace params = CGAL::parameters;

namespace {

// ---------------------------------------------------------------------------
// energies

typedef std::function<GSM::Energy_derivatives(const Eigen::Vector3d&)> Energy_at;

void check_derivatives(const Energy_at& f, const Eigen::Vector3d& x, const char* what)
{
  const GSM::Energy_derivatives d = f(x);
  const double h = 1e-6 * (1 + x.norm());
  Eigen::Vector3d g;
  Eigen::Matrix3d H;
  for(int i = 0; i < 3; ++i) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[i] = h;
    const GSM::Energy_derivatives p = f(x + e), m = f(x - e);
    g[i] = (p.value - m.value) / (2 * h);
    H.col(i) = (p.gradient - m.gradient) / (2 * h);
  }
  const double gtol = 1e-5 * (1 + d.gradient.norm()), htol = 1e-4 * (1 + d.hessian.norm());
  if(!VVM_CHECK((g - d.gradient).norm() < gtol)) std::cerr << "    " << what << " gradient\n";
  if(!VVM_CHECK((H - d.hessian).norm() < htol)) std::cerr << "    " << what << " Hessian\n";
  VVM_CHECK((d.hessian - d.hessian.transpose()).norm() < 1e-9 * (1 + d.hessian.norm()));
}

void test_energies()
{
  // known values: regular simplices of edge 1 match the template
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.) / 2, 0),
      d(0.5, std::sqrt(3.) / 6, std::sqrt(2. / 3.));
  VVM_CHECK_CLOSE(GSM::gsm_tetrahedron_energy(a, b, c, d), 3., 1e-12);
  VVM_CHECK_CLOSE(GSM::gsm_tetrahedron_energy_derivatives(d, a, b, c).value, 3., 1e-12);
  VVM_CHECK_CLOSE(GSM::gsm_triangle_energy_derivatives(a, b, c).value, 2., 1e-12);
  VVM_CHECK_CLOSE(GSM::gsm_segment_energy_derivatives(a, b).value, 1., 1e-12);
  VVM_CHECK_CLOSE(GSM::esm_tetrahedron_energy_derivatives(d, a, b, c).value, 3., 1e-12);
  // (a^2/2) sum 1/h_i^2 form of eq. 3.8 for the BCC tet (heights from 6V / (2 area))
  {
    const Eigen::Vector3d p0(0, 0, 0), p1(1, 0, 0), p2(.5, .5, -.5), p3(.5, .5, .5);
    const double six_v = std::abs((p1 - p0).dot((p2 - p0).cross(p3 - p0)));
    double sum = 0;
    const Eigen::Vector3d* q[4] = {&p0, &p1, &p2, &p3};
    for(int i = 0; i < 4; ++i) {
      const Eigen::Vector3d &u = *q[(i + 1) % 4], &v = *q[(i + 2) % 4], &w = *q[(i + 3) % 4];
      const double h = six_v / (v - u).cross(w - u).norm();
      sum += 1 / (h * h);
    }
    VVM_CHECK_CLOSE(GSM::gsm_tetrahedron_energy(p0, p1, p2, p3), sum / 2, 1e-12);
  }
  // a sliver costs far more than a regular tet
  VVM_CHECK(GSM::gsm_tetrahedron_energy(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0),
                                        Eigen::Vector3d(0, -1, 0.05), Eigen::Vector3d(0, 1, 0.05)) > 100);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  auto rnd = [&] { return Eigen::Vector3d(u(rng), u(rng), u(rng)); };
  for(int t = 0; t < 20; ++t) {
    const Eigen::Vector3d p = rnd(), q = rnd(), r = rnd(), x = rnd();
    check_derivatives([&](const Eigen::Vector3d& v) { return GSM::gsm_tetrahedron_energy_derivatives(v, p, q, r); }, x, "gsm tet");
    check_derivatives([&](const Eigen::Vector3d& v) { return GSM::gsm_triangle_energy_derivatives(v, p, q); }, x, "gsm triangle");
    check_derivatives([&](const Eigen::Vector3d& v) { return GSM::gsm_segment_energy_derivatives(v, p); }, x, "gsm segment");
    check_derivatives([&](const Eigen::Vector3d& v) { return GSM::esm_tetrahedron_energy_derivatives(v, p, q, r); }, x, "esm tet");
    // mapped by a constant B (anisotropic metric): d/dx E(Bx)
    Eigen::Matrix3d B = Eigen::Matrix3d::Identity() + 0.4 * Eigen::Matrix3d::Random();
    check_derivatives([&](const Eigen::Vector3d& v) {
      return GSM::gsm_tetrahedron_energy_derivatives(B * v, B * p, B * q, B * r).mapped_back(B);
    }, x, "mapped gsm tet");
    VVM_CHECK_CLOSE(GSM::gsm_tetrahedron_energy_derivatives(x, p, q, r).value,
                    GSM::gsm_tetrahedron_energy(x, p, q, r), 1e-9 * GSM::gsm_tetrahedron_energy(x, p, q, r));
  }
}

// ---------------------------------------------------------------------------
// flips on hand-made complexes

typedef CGAL::Labeled_mesh_domain_3<K> Implicit_domain;
typedef CGAL::Mesh_triangulation_3<Implicit_domain>::type Implicit_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Implicit_tr> Implicit_c3t3;
typedef Implicit_tr::Vertex_handle Vertex_handle;
typedef Implicit_tr::Bare_point Bare_point;

// every finite cell positively oriented, the triangulation data structure
// valid (not the regular property: GSM drops it on purpose), and the
// complex's counters equal to what its iterators see
template <class C3T3>
bool complex_is_valid(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  bool ok = tr.tds().is_valid();
  for(auto c : tr.finite_cell_handles())
    ok = ok && CGAL::orientation(tr.point(c, 0).point(), tr.point(c, 1).point(), tr.point(c, 2).point(),
                                 tr.point(c, 3).point()) == CGAL::POSITIVE;
  std::size_t cells = 0, facets = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) ++cells;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    ++facets;
    const auto m = tr.mirror_facet(*f);
    ok = ok && f->first->surface_patch_index(f->second) == m.first->surface_patch_index(m.second);
  }
  if(!ok || cells != c3t3.number_of_cells_in_complex() || facets != c3t3.number_of_facets_in_complex())
    std::cerr << "    complex: geometry/labels " << ok << ", cells " << cells << " / " << c3t3.number_of_cells_in_complex()
              << ", facets " << facets << " / " << c3t3.number_of_facets_in_complex() << "\n";
  return ok && cells == c3t3.number_of_cells_in_complex() && facets == c3t3.number_of_facets_in_complex();
}

// all finite cells into subdomain 1, the convex hull facets into patch (1,0)
void fill_complex(Implicit_c3t3& c3t3)
{
  Implicit_tr& tr = c3t3.triangulation();
  for(auto c : tr.finite_cell_handles()) c3t3.add_to_complex(c, 1);
  for(auto c : tr.finite_cell_handles())
    for(int i = 0; i < 4; ++i)
      if(tr.is_infinite(c->neighbor(i))) c3t3.add_to_complex(c, i, std::make_pair(1, 0));
}

Vertex_handle insert(Implicit_tr& tr, double x, double y, double z)
{
  return tr.insert(Implicit_tr::Point(Bare_point(x, y, z)));
}

// every edge of the complex's surface facets in exactly two of them
bool surface_is_closed(const Implicit_c3t3& c3t3)
{
  std::map<std::pair<Vertex_handle, Vertex_handle>, int> edge_use;
  for(auto fit = c3t3.facets_in_complex_begin(); fit != c3t3.facets_in_complex_end(); ++fit)
    for(int n = 1; n <= 3; ++n) {
      Vertex_handle u = fit->first->vertex((fit->second + n) & 3), w = fit->first->vertex((fit->second + n % 3 + 1) & 3);
      if(w < u) std::swap(u, w);
      ++edge_use[{u, w}];
    }
  bool closed = true;
  for(const auto& e : edge_use) closed = closed && e.second == 2;
  return closed;
}

// the distance from `p` to the complex's surface facets
template <class C3T3>
double distance_to_boundary(const C3T3& c3t3, const Bare_point& p)
{
  double d2 = std::numeric_limits<double>::infinity();
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    const auto& c = f->first;
    const int i = f->second;
    d2 = (std::min)(d2, CGAL::squared_distance(p, K::Triangle_3(c->vertex((i + 1) & 3)->point().point(),
                                                                c->vertex((i + 2) & 3)->point().point(),
                                                                c->vertex((i + 3) & 3)->point().point())));
  }
  return std::sqrt(d2);
}

struct Flip_fixture
{
  Implicit_c3t3 c3t3;
  GSM::internal::Metric_field metric = GSM::internal::Metric_field::uniform(1.);
  GSM::internal::Mesh_energy<Implicit_c3t3> energy{c3t3, metric, GSM::Shape_matching_energy::GSM};
  double sum = 0;
  std::size_t count = 0;

  void start()
  {
    fill_complex(c3t3);
    std::tie(sum, count) = energy.total();
  }
  GSM::internal::Energy_guided_flips<Implicit_c3t3> flips() { return {c3t3, energy, sum, count}; }
};

// A triangle (a, b, c) pierced by the segment (p, q) at height h: GSM prefers
// the two tets (a, b, c, p), (a, b, c, q) when h is large (1.2: total energy
// 2.25 against 7.49) and the three around (p, q) when h is small (0.15: 40.3
// against 60.6). Starting from the worse one, the flip must be taken.
// the triangle (a, b, c) pierced by the segment (p, q) at height h, not yet in the complex
struct Pierced_triangle : Flip_fixture
{
  Implicit_tr& tr = c3t3.triangulation();
  const Vertex_handle a, b, c, p, q;

  explicit Pierced_triangle(double h)
    : a(insert(tr, 1, 0, 0)), b(insert(tr, -0.5, 0.87, 0)), c(insert(tr, -0.5, -0.87, 0)), p(insert(tr, 0, 0, h)),
      q(insert(tr, 0, 0, -h))
  {}
};

void check_flip_from_worse(double h, bool expect_three)
{
  Pierced_triangle f(h);
  Implicit_tr& tr = f.tr;
  const Vertex_handle a = f.a, b = f.b, c = f.c, p = f.p, q = f.q;
  Implicit_tr::Cell_handle cell;
  int i, j, k;
  // Delaunay picks the other configuration; go to the worse one with CGAL's flips
  if(expect_three) {
    VVM_CHECK(tr.is_edge(p, q, cell, i, j) && tr.flip(Implicit_tr::Edge(cell, i, j)));
  } else {
    VVM_CHECK(tr.is_facet(a, b, c, cell, i, j, k) && tr.flip(cell, 6 - i - j - k));
  }
  f.start();
  const std::size_t n = expect_three ? 2 : 3;
  VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), n);
  const double before = f.sum;
  auto flips = f.flips();
  if(expect_three) {
    VVM_CHECK(tr.is_facet(a, b, c, cell, i, j, k) && flips.try_flip_2_3(Implicit_tr::Facet(cell, 6 - i - j - k)));
    VVM_CHECK(tr.is_edge(p, q, cell, i, j));
  } else {
    VVM_CHECK(tr.is_edge(p, q, cell, i, j) && flips.try_flip_3_2(Implicit_tr::Edge(cell, i, j)));
    VVM_CHECK(tr.is_facet(a, b, c, cell, i, j, k));
  }
  const std::size_t m = expect_three ? 3 : 2;
  VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), m);
  VVM_CHECK_EQUAL(tr.number_of_finite_cells(), m);
  VVM_CHECK(complex_is_valid(f.c3t3));
  VVM_CHECK_EQUAL(f.c3t3.number_of_facets_in_complex(), std::size_t(6)); // hull facets kept their patch
  // the running sum is the exact new energy, and the mean went down
  VVM_CHECK_CLOSE(f.sum, f.energy.total().first, 1e-9 * f.sum);
  VVM_CHECK(f.sum / double(m) < before / double(n));
  // and the flip back is refused
  if(expect_three) {
    VVM_CHECK(tr.is_edge(p, q, cell, i, j) && !flips.try_flip_3_2(Implicit_tr::Edge(cell, i, j)));
  } else {
    VVM_CHECK(tr.is_facet(a, b, c, cell, i, j, k) && !flips.try_flip_2_3(Implicit_tr::Facet(cell, 6 - i - j - k)));
  }
  VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), m);
}

void test_flip_2_3_and_3_2()
{
  check_flip_from_worse(0.15, true);  // 2-3
  check_flip_from_worse(1.2, false);  // 3-2
}

void test_flip_4_4()
{
  // an octahedron: four tets around its long diagonal (a, b) are worse than
  // four around one of its short diagonals; the 4-4 flip makes the change
  Flip_fixture f;
  Implicit_tr& tr = f.c3t3.triangulation();
  const Vertex_handle r0 = insert(tr, 1, 0, 0), r1 = insert(tr, 0, 1.05, 0), r2 = insert(tr, -1, 0, 0),
                      r3 = insert(tr, 0, -1.05, 0);
  const Vertex_handle a = insert(tr, 0.2, 0.2, 1.6), b = insert(tr, 0.2, 0.2, -1.6);
  Implicit_tr::Cell_handle cell;
  int i, j, k;
  if(!tr.is_edge(a, b, cell, i, j)) {
    // Delaunay chose a short diagonal (s0, s2): move to (a, b) by a 2-3 then a 3-2 flip
    const bool x_axis = tr.is_edge(r0, r2, cell, i, j);
    VVM_CHECK(x_axis || tr.is_edge(r1, r3, cell, i, j));
    const Vertex_handle s0 = x_axis ? r0 : r1, s2 = x_axis ? r2 : r3, m = x_axis ? r1 : r0;
    VVM_CHECK(tr.is_facet(s0, s2, m, cell, i, j, k) && tr.flip(cell, 6 - i - j - k));
    VVM_CHECK(tr.is_edge(s0, s2, cell, i, j) && tr.flip(Implicit_tr::Edge(cell, i, j)));
  }
  f.start();
  VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(4));
  if(VVM_CHECK(tr.is_edge(a, b, cell, i, j))) {
    const double before = f.sum;
    auto flips = f.flips();
    VVM_CHECK(flips.try_flip_4_4(Implicit_tr::Edge(cell, i, j)));
    VVM_CHECK(!tr.is_edge(a, b, cell, i, j));
    VVM_CHECK(tr.is_edge(r0, r2, cell, i, j) || tr.is_edge(r1, r3, cell, i, j));
    VVM_CHECK(f.sum < before);
  }
  VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(4));
  VVM_CHECK(complex_is_valid(f.c3t3));
  VVM_CHECK_CLOSE(f.sum, f.energy.total().first, 1e-9 * f.sum);
}

void test_boundary_peel()
{
  // a flat tet lying on the hull of a square pyramid base: four points almost
  // coplanar under a cap; its two hull facets are surface facets of one patch
  Flip_fixture f;
  Implicit_tr& tr = f.c3t3.triangulation();
  const Vertex_handle a = insert(tr, 1, 0, 0), b = insert(tr, -1, 0, 0), c = insert(tr, 0, 1, 0.02),
                      d = insert(tr, 0, -1, 0.02);
  insert(tr, 0, 0, 1.5);
  f.start();
  // find the flat cell (a, b, c, d)
  Implicit_tr::Cell_handle cell;
  int i, j, k, l;
  if(VVM_CHECK(tr.is_cell(a, b, c, d, cell, i, j, k, l))) {
    int surface = 0;
    for(int n = 0; n < 4; ++n) surface += f.c3t3.is_in_complex(cell, n) ? 1 : 0;
    VVM_CHECK_EQUAL(surface, 2);
    const std::size_t cells = f.c3t3.number_of_cells_in_complex();
    auto flips = f.flips();
    VVM_CHECK(flips.try_peel_boundary_cell(cell));
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), cells - 1);
    VVM_CHECK(!f.c3t3.is_in_complex(cell));
    VVM_CHECK(complex_is_valid(f.c3t3));
    VVM_CHECK(surface_is_closed(f.c3t3));
  }
}

void test_boundary_cap_peel()
{
  // a flat cap: p just under the facet (b, c, d) of the tet (a, b, c, d), the cell
  // (p, b, c, d) has three surface facets around p; peeled, (b, c, d) is the surface
  Flip_fixture f;
  Implicit_tr& tr = f.c3t3.triangulation();
  const Vertex_handle a = insert(tr, 0, 0, 1.5), b = insert(tr, 1, 0, 0), c = insert(tr, -0.5, 0.87, 0),
                      d = insert(tr, -0.5, -0.87, 0), p = insert(tr, 0, 0, -0.03);
  Implicit_tr::Cell_handle cell;
  int i, j, k, l;
  // p is inside the sphere of (a, b, c, d): Delaunay gives the three tets around (a, p)
  if(tr.is_edge(a, p, cell, i, j)) VVM_CHECK(tr.flip(Implicit_tr::Edge(cell, i, j)));
  f.start();
  for(const Vertex_handle& v : tr.finite_vertex_handles()) f.c3t3.set_dimension(v, 2);
  if(VVM_CHECK(tr.is_cell(p, b, c, d, cell, i, j, k, l))) {
    int surface = 0;
    for(int n = 0; n < 4; ++n) surface += f.c3t3.is_in_complex(cell, n) ? 1 : 0;
    VVM_CHECK_EQUAL(surface, 3);
    auto flips = f.flips();
    f.c3t3.set_dimension(p, 1); // on a feature curve: stays
    VVM_CHECK(!flips.try_peel_boundary_cell(cell));
    f.c3t3.set_dimension(p, 2);
    VVM_CHECK(flips.try_peel_boundary_cell(cell));
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(1));
    VVM_CHECK(tr.is_facet(b, c, d, cell, i, j, k) && f.c3t3.is_in_complex(cell, 6 - i - j - k));
    VVM_CHECK_EQUAL(f.c3t3.number_of_facets_in_complex(), std::size_t(4));
    VVM_CHECK(complex_is_valid(f.c3t3));
    VVM_CHECK(surface_is_closed(f.c3t3));
    VVM_CHECK_CLOSE(f.sum, f.energy.total().first, 1e-9 * f.sum);
  }
}

// ---------------------------------------------------------------------------
// edge removal and multi-face removal (Shewchuk 2002)

void test_polygon_triangulation()
{
  const double inf = std::numeric_limits<double>::infinity();
  for(int m = 3; m <= 8; ++m) {
    // triangles on vertex 0 are cheap: the fan from 0 is best
    const GSM::internal::Polygon_triangulation fan = GSM::internal::best_polygon_triangulation(
        m, [](int i, int, int) { return i == 0 ? 1. : 10.; });
    VVM_CHECK_EQUAL(fan.triangles.size(), std::size_t(m - 2));
    VVM_CHECK_CLOSE(fan.cost, double(m - 2), 1e-12);
    // every triangle on vertex 0 forbidden: none
    const GSM::internal::Polygon_triangulation none = GSM::internal::best_polygon_triangulation(
        m, [&](int i, int, int) { return i == 0 ? inf : 1.; });
    VVM_CHECK(none.triangles.empty() && none.cost == inf);
    // ear order: each triangle has two edges on the polygon left by those before
    std::vector<bool> gone(m, false);
    bool ears = true;
    for(const auto& t : fan.triangles) {
      ears = ears && !gone[t[0]] && !gone[t[2]];
      for(int v = t[0] + 1; v < t[2]; ++v) ears = ears && (v == t[1] ? !gone[v] : gone[v]);
      gone[t[1]] = true;
    }
    VVM_CHECK(ears);
  }
}

// exact bookkeeping, every finite cell in subdomain 1, the hull facets in patch (1, 0)
void check_after_replacement(Flip_fixture& f, std::size_t cells, std::size_t hull_facets)
{
  const Implicit_tr& tr = f.c3t3.triangulation();
  VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), cells);
  VVM_CHECK_EQUAL(tr.number_of_finite_cells(), cells);
  VVM_CHECK_EQUAL(f.count, cells);
  VVM_CHECK(complex_is_valid(f.c3t3));
  VVM_CHECK_EQUAL(f.c3t3.number_of_facets_in_complex(), hull_facets);
  bool labels = true;
  for(auto c : tr.finite_cell_handles()) labels = labels && f.c3t3.subdomain_index(c) == 1;
  for(auto fit = f.c3t3.facets_in_complex_begin(); fit != f.c3t3.facets_in_complex_end(); ++fit)
    labels = labels && tr.is_infinite(fit->first->neighbor(fit->second)) == !tr.is_infinite(fit->first) &&
             fit->first->surface_patch_index(fit->second) == std::make_pair(1, 0);
  VVM_CHECK(labels);
  VVM_CHECK_CLOSE(f.sum, f.energy.total().first, 1e-9 * f.sum);
}

// moves v (keeping the connectivity)
void move(const Vertex_handle& v, double x, double y, double z)
{
  v->set_point(Implicit_tr::Point(Bare_point(x, y, z)));
}

// the ring r_k at angles: r_0, r_1 at -+`half_wedge` degrees, the others evenly
// spaced round the rest of the unit circle in z = 0
void place_ring(const std::vector<Vertex_handle>& r, double half_wedge)
{
  const int m = int(r.size());
  for(int k = 0; k < m; ++k) {
    const double t = (k == 0 ? -half_wedge : half_wedge + (360 - 2 * half_wedge) * (k - 1) / (m - 1)) * CGAL_PI / 180;
    move(r[k], std::cos(t), std::sin(t), 0);
  }
}

// the edge (a, b) = (0, 0, +-0.5) through the regular m-gon of radius 1 in z = 0:
// the m cells around it (Delaunay), then a and b moved to +-z and, for a sliver,
// the ring moved so that the cell (a, b, r_0, r_1) has a dihedral angle of 176
// degrees at (a, b): GSM prefers the edge removed (z = 1: mean energy 84 against
// 7 for m = 5, 71 against 13 for m = 6, 62 against 22 for m = 7); not for
// the regular ring (m = 6, z = 0.5: 2.7 against 7.8)
struct Ring_fixture : Flip_fixture
{
  Vertex_handle a, b;
  std::vector<Vertex_handle> r;

  Ring_fixture(int m, double z, bool sliver)
  {
    Implicit_tr& tr = c3t3.triangulation();
    for(int k = 0; k < m; ++k) r.push_back(insert(tr, std::cos(2 * CGAL_PI * k / m), std::sin(2 * CGAL_PI * k / m), 0));
    a = insert(tr, 0, 0, 0.5);
    b = insert(tr, 0, 0, -0.5);
    move(a, 0, 0, z);
    move(b, 0, 0, -z);
    if(sliver) place_ring(r, 88);
    start();
  }
  bool edge(Implicit_tr::Edge& e)
  {
    return c3t3.triangulation().is_edge(a, b, e.first, e.second, e.third);
  }
};

void test_edge_removal()
{
  for(int m = 5; m <= 7; ++m) {
    Ring_fixture f(m, 1., true);
    Implicit_tr::Edge e;
    VVM_CHECK(f.edge(e));
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(m));
    const double before = f.sum, mean_before = f.sum / m;
    // the fan from r_0 is one candidate: the chosen triangulation is no worse
    double fan = 0;
    for(int k = 1; k + 1 < m; ++k) {
      const auto p = [&](const Vertex_handle& v) { return f.energy.position(v); };
      fan += f.energy.tetrahedron(p(f.a), p(f.r[0]), p(f.r[k]), p(f.r[k + 1])) +
             f.energy.tetrahedron(p(f.b), p(f.r[0]), p(f.r[k]), p(f.r[k + 1]));
    }
    auto flips = f.flips();
    VVM_CHECK(flips.try_remove_edge(e));
    VVM_CHECK(!f.edge(e));
    check_after_replacement(f, std::size_t(2 * (m - 2)), std::size_t(2 * m));
    VVM_CHECK(f.sum <= fan * (1 + 1e-12));
    VVM_CHECK(f.sum / double(2 * (m - 2)) < mean_before);
    VVM_CHECK(f.sum - before < (m - 4) * mean_before);
  }

  // refusals, the complex unchanged: a short edge (removal worse), a feature edge,
  // a surface facet on the edge, a cell of another subdomain
  for(int refusal = 0; refusal < 4; ++refusal) {
    Ring_fixture f(6, refusal == 0 ? 0.5 : 1., refusal != 0);
    Implicit_tr::Edge e;
    VVM_CHECK(f.edge(e));
    std::size_t facets = 12;
    if(refusal == 1) f.c3t3.add_to_complex(f.a, f.b, 1);
    if(refusal == 2) {
      Implicit_tr::Cell_handle c;
      int i, j, k;
      VVM_CHECK(f.c3t3.triangulation().is_facet(f.a, f.b, f.r[2], c, i, j, k));
      f.c3t3.add_to_complex(c, 6 - i - j - k, std::make_pair(1, 2));
      ++facets;
    }
    if(refusal == 3) {
      f.c3t3.remove_from_complex(e.first);
      f.c3t3.add_to_complex(e.first, 2);
    }
    const double before = f.sum;
    auto flips = f.flips();
    VVM_CHECK(!flips.try_remove_edge(e));
    VVM_CHECK(f.edge(e));
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(6));
    VVM_CHECK_EQUAL(f.c3t3.number_of_facets_in_complex(), facets);
    VVM_CHECK(complex_is_valid(f.c3t3));
    VVM_CHECK_EQUAL(f.sum, before);
  }
}

// The max-min direction of the polisher (Least_norm_point_of_hull.h), by hand: the point
// of least norm of one vector is itself, of (1, 0, 0) and (-1, 1, 0) it is (0.2, 0.4, 0),
// of two opposite vectors 0, of (1, 0, 1), (-1, 0, 1), (0, 1, 1) it is (0, 0, 1). Then on
// pairs of tetrahedra sharing a vertex v, where a step along the gradient of either one's
// smallest angle lowers the other's: a step along the point of least norm of the two
// gradients raises both, at no less than its norm's rate.
void test_least_norm_point_of_hull()
{
  using GSM::internal::least_norm_point_of_hull;
  typedef Eigen::Vector3d V;
  VVM_CHECK(least_norm_point_of_hull({V(1, 2, 3)}) == V(1, 2, 3));
  VVM_CHECK((least_norm_point_of_hull({V(1, 0, 0), V(-1, 1, 0)}) - V(0.2, 0.4, 0)).norm() < 1e-12);
  VVM_CHECK(least_norm_point_of_hull({V(1, 0, 0), V(-1, 0, 0)}).norm() < 1e-12);
  VVM_CHECK((least_norm_point_of_hull({V(1, 0, 1), V(-1, 0, 1), V(0, 1, 1)}) - V(0, 0, 1)).norm() < 1e-9);
  VVM_CHECK((least_norm_point_of_hull({V(2, 1, 0), V(2, -1, 0), V(3, 0, 0)}) - V(2, 0, 0)).norm() < 1e-12);

  CGAL::Random random(7);
  const auto point = [&]() { return V(random.get_double(-1, 1), random.get_double(-1, 1), random.get_double(-1, 1)); };
  const auto angle = [](const std::array<V, 3>& t, const V& v) {
    return GSM::tetrahedron_min_dihedral_angle({{v, t[0], t[1], t[2]}});
  };
  const V v = V::Zero();
  const double h = 1e-6, step = 1e-3;
  const auto gradient = [&](const std::array<V, 3>& t) {
    V g;
    for(int k = 0; k < 3; ++k) g[k] = (angle(t, v + h * V::Unit(k)) - angle(t, v - h * V::Unit(k))) / (2 * h);
    return g;
  };
  int opposed = 0;
  for(int trial = 0; trial < 5000 && opposed < 20; ++trial) {
    const std::array<V, 3> a{{point(), point(), point()}}, b{{point(), point(), point()}};
    if(angle(a, v) < 5 || angle(b, v) < 5) continue;
    const V ga = gradient(a), gb = gradient(b);
    // each gradient alone lowers the other cell's angle
    if(!(angle(b, v + step * ga.normalized()) < angle(b, v)) || !(angle(a, v + step * gb.normalized()) < angle(a, v)))
      continue;
    const V z = least_norm_point_of_hull({ga, gb});
    VVM_CHECK(ga.dot(z) >= z.squaredNorm() * (1 - 1e-9) && gb.dot(z) >= z.squaredNorm() * (1 - 1e-9));
    if(z.norm() < 1e-3 * ga.norm()) continue; // nearly opposite gradients: v is at a local max-min
    ++opposed;
    const V d = z.normalized();
    VVM_CHECK(angle(a, v + step * d) > angle(a, v) && angle(b, v + step * d) > angle(b, v));
  }
  VVM_CHECK(opposed >= 20);
  std::printf("  least-norm point of hull: %d pairs of cells whose gradients oppose, both raised\n", opposed);
}

// The polishing's angle penalty, by hand: (60 - q)^4 under 60 degrees for the bound 30,
// and 0 over.
// Edge removal for quality on the pierced triangle of check_flip_from_worse: from the
// three cells around (p, q), the 3-2 flip to (a, b, c, p), (a, b, c, q) is taken exactly
// when the two cells' penalty sum is lower and their worst angle no lower, the running
// energy sum stays exact, and at
// the heights tried both outcomes occur.
void test_angle_penalty_and_edge_removal_for_quality()
{
  const GSM::internal::Angle_penalty penalty = GSM::internal::Angle_penalty::for_bound(30);
  VVM_CHECK_EQUAL(penalty(50), 10000.);
  VVM_CHECK_EQUAL(penalty(20), 2560000.);
  VVM_CHECK_EQUAL(penalty(60), 0.);
  VVM_CHECK_EQUAL(penalty(75), 0.);
  VVM_CHECK_EQUAL(penalty.critical, 30.); // every cell under the bound, until the polisher narrows it

  int removed = 0, kept = 0;
  for(double h : {0.05, 0.15, 0.3, 0.6, 1.2}) {
    Pierced_triangle f(h);
    Implicit_tr& tr = f.tr;
    const Vertex_handle a = f.a, b = f.b, c = f.c, p = f.p, q = f.q;
    Implicit_tr::Cell_handle cell;
    int i, j, k;
    if(!tr.is_edge(p, q, cell, i, j)) VVM_CHECK(tr.is_facet(a, b, c, cell, i, j, k) && tr.flip(cell, 6 - i - j - k));
    f.start();
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(3));
    const auto angle = [&](const Vertex_handle& w, const Vertex_handle& x, const Vertex_handle& y,
                           const Vertex_handle& z) {
      return f.energy.min_dihedral_angle(f.energy.position(w), f.energy.position(x), f.energy.position(y),
                                         f.energy.position(z));
    };
    const double three = penalty(angle(a, b, p, q)) + penalty(angle(b, c, p, q)) + penalty(angle(c, a, p, q));
    const double two = penalty(angle(a, b, c, p)) + penalty(angle(a, b, c, q));
    const double worst_three = (std::min)({angle(a, b, p, q), angle(b, c, p, q), angle(c, a, p, q)});
    const double worst_two = (std::min)(angle(a, b, c, p), angle(a, b, c, q));
    VVM_CHECK(tr.is_edge(p, q, cell, i, j));
    auto flips = f.flips();
    const bool done = flips.try_remove_edge_for_quality(Implicit_tr::Edge(cell, i, j), penalty);
    std::printf("  pierced triangle h = %.2f: penalty %.4g around (p, q), %.4g for the two cells: %s\n", h, three,
                two, done ? "removed" : "kept");
    VVM_CHECK_EQUAL(done, two < (1 - 1e-4) * three && worst_two >= worst_three);
    VVM_CHECK_EQUAL(tr.is_edge(p, q, cell, i, j), !done);
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(done ? 2 : 3));
    VVM_CHECK(complex_is_valid(f.c3t3));
    VVM_CHECK_EQUAL(f.c3t3.number_of_facets_in_complex(), std::size_t(6));
    VVM_CHECK_CLOSE(f.sum, f.energy.total().first, 1e-9 * f.sum);
    (done ? removed : kept) += 1;
  }
  VVM_CHECK(removed > 0 && kept > 0);
}

void test_multi_face_removal()
{
  // the inverse: Delaunay on the pentagon with a and b far (no edge (a, b): three
  // triangles between them), then a and b moved close to the pentagon, whose six
  // flat cells are worse than five around a new edge (a, b) (mean energy 9.5 against
  // 3.6); or the pentagon moved as in Ring_fixture for a sliver, and (a, b) at +-1.5:
  // a new edge would make a sliver (mean energy 38 against 5)
  for(int refusal = 0; refusal < 4; ++refusal) {
    Flip_fixture f;
    Implicit_tr& tr = f.c3t3.triangulation();
    std::vector<Vertex_handle> r;
    for(int k = 0; k < 5; ++k) r.push_back(insert(tr, std::cos(2 * CGAL_PI * k / 5) + 0.01 * k, std::sin(2 * CGAL_PI * k / 5), 0));
    const Vertex_handle a = insert(tr, 0.02, 0.01, 1.5), b = insert(tr, -0.01, 0.02, -1.5);
    const double z = refusal == 1 ? 1.5 : 0.35;
    move(a, 0.02, 0.01, z);
    move(b, -0.01, 0.02, -z);
    if(refusal == 1) place_ring(r, 87);
    f.start();
    Implicit_tr::Cell_handle c;
    int i, j;
    VVM_CHECK(!tr.is_edge(a, b, c, i, j));
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(6));
    // the triangle of the pentagon that (a, b) crosses, and a diagonal of the pentagon
    Implicit_tr::Facet start;
    std::pair<Vertex_handle, Vertex_handle> diagonal;
    for(auto fit : tr.finite_facets()) {
      const Implicit_tr::Cell_handle fc = fit.first;
      if(fc->vertex(fit.second) != a && fc->vertex(fit.second) != b) continue;
      if(fc->neighbor(fit.second)->has_vertex(a) == fc->has_vertex(a)) continue; // not between a and b
      std::array<Vertex_handle, 3> t;
      for(int n = 0; n < 3; ++n) t[n] = fc->vertex((fit.second + n + 1) & 3);
      for(int n = 0; n < 3; ++n) {
        const int gap = std::abs(int(std::find(r.begin(), r.end(), t[n]) - std::find(r.begin(), r.end(), t[(n + 1) % 3])));
        if(gap == 2 || gap == 3) diagonal = std::make_pair(t[n], t[(n + 1) % 3]);
      }
      const auto p = [&](const Vertex_handle& v) { return v->point().point(); };
      if(CGAL::do_intersect(K::Segment_3(p(a), p(b)), K::Triangle_3(p(t[0]), p(t[1]), p(t[2])))) start = fit;
    }
    std::size_t facets = 10;
    if(refusal == 2) {
      f.c3t3.add_to_complex(start, std::make_pair(1, 2));
      ++facets;
    }
    if(refusal == 3) f.c3t3.add_to_complex(diagonal.first, diagonal.second, 1);
    const double before = f.sum, mean_before = f.sum / 6;
    auto flips = f.flips();
    const int removed = flips.try_remove_faces(start);
    if(refusal == 0) {
      VVM_CHECK_EQUAL(removed, 3);
      VVM_CHECK(tr.is_edge(a, b, c, i, j));
      check_after_replacement(f, 5, 10);
      VVM_CHECK(f.sum / 5 < mean_before);
      VVM_CHECK(f.sum - before < -mean_before);
    } else {
      // too good to change, a surface facet to remove, a feature edge to remove
      VVM_CHECK(refusal == 3 ? removed < 3 : removed == 0);
      VVM_CHECK(refusal == 3 || !tr.is_edge(a, b, c, i, j));
      VVM_CHECK(tr.is_edge(diagonal.first, diagonal.second, c, i, j));
      VVM_CHECK_EQUAL(f.c3t3.number_of_facets_in_complex(), facets);
      VVM_CHECK(complex_is_valid(f.c3t3));
      VVM_CHECK_CLOSE(f.sum, f.energy.total().first, 1e-9 * f.sum);
    }
  }
}

// ---------------------------------------------------------------------------
// whole runs

double sphere_function(const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

typedef std::function<double(const K::Point_3&)> Implicit_function;

Implicit_domain implicit_domain(const Implicit_function& f)
{
  return Implicit_domain::create_implicit_mesh_domain(f, K::Sphere_3(CGAL::ORIGIN, 4.),
                                                      params::relative_error_bound = 1e-9);
}

Implicit_domain sphere_domain() { return implicit_domain(sphere_function); }

Implicit_c3t3 make_implicit_mesh(const Implicit_function& f, double size)
{
  const Implicit_domain domain = implicit_domain(f);
  CGAL::Mesh_criteria_3<Implicit_tr> criteria(params::facet_angle = 25, params::facet_size = size,
                                              params::facet_distance = size / 10,
                                              params::cell_radius_edge_ratio = 3, params::cell_size = size);
  CGAL::get_default_random() = CGAL::Random(1);
  return CGAL::make_mesh_3<Implicit_c3t3>(domain, criteria, params::no_perturb(), params::no_exude());
}

Implicit_c3t3 make_sphere_mesh(double size) { return make_implicit_mesh(sphere_function, size); }

// a torus of radii 0.6 and 0.25 about the z axis: saddle-shaped inside
double torus_function(const K::Point_3& p)
{
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y()) - 0.6;
  return r * r + p.z() * p.z() - 0.25 * 0.25;
}

template <class C3T3>
std::map<typename C3T3::Triangulation::Vertex_handle, Eigen::Vector3d> positions(const C3T3& c3t3)
{
  std::map<typename C3T3::Triangulation::Vertex_handle, Eigen::Vector3d> m;
  for(auto v : c3t3.triangulation().finite_vertex_handles()) {
    const auto& p = c3t3.triangulation().point(v);
    m[v] = Eigen::Vector3d(p.x(), p.y(), p.z());
  }
  return m;
}

// the mean length of the edges in region 1 over that in region 0, `region(midpoint)`
// giving 0, 1 or -1 (neither); each edge counted once per cell it is in
template <class Region>
double mean_edge_length_ratio(const Implicit_c3t3& c3t3, const Region& region)
{
  double sum[2] = {0, 0};
  int n[2] = {0, 0};
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const auto& a = c->vertex(i)->point();
        const auto& b = c->vertex(j)->point();
        const Eigen::Vector3d pa(a.x(), a.y(), a.z()), pb(b.x(), b.y(), b.z());
        const int k = region(Eigen::Vector3d(0.5 * (pa + pb)));
        if(k >= 0) { sum[k] += (pa - pb).norm(); ++n[k]; }
      }
  return (sum[1] / n[1]) / (sum[0] / n[0]);
}

void test_sphere_run()
{
  const Implicit_domain domain = sphere_domain();
  Implicit_c3t3 c3t3 = make_sphere_mesh(0.2);
  const GSM::Mesh_quality_statistics before = GSM::mesh_quality_statistics(c3t3);
  const std::size_t vertices_before = c3t3.triangulation().number_of_vertices();
  VVM_CHECK(before.number_of_cells > 1000);
  double initial_energy;
  {
    GSM::internal::Metric_field metric = GSM::internal::Metric_field::uniform(GSM::internal::estimated_edge_length(c3t3));
    GSM::internal::Mesh_energy<Implicit_c3t3> e(c3t3, metric, GSM::Shape_matching_energy::GSM);
    const auto t = e.total();
    initial_energy = t.first / double(t.second);
  }
  std::vector<GSM::Round_report> reports;
  const CGAL::Mesh_optimization_return_code code = CGAL::gsm_optimize_mesh_3(
      c3t3, domain, params::visitor([&](const GSM::Round_report& r) { reports.push_back(r); }));
  VVM_CHECK(code == CGAL::CONVERGENCE_REACHED || code == CGAL::CANT_IMPROVE_ANYMORE ||
            code == CGAL::MAX_ITERATION_NUMBER_REACHED);
  VVM_CHECK(!reports.empty() && reports.size() <= 50);
  // the energy rounds, then the polishing ones; the energy never increases in the former
  double previous = initial_energy;
  bool polishing = false;
  for(const GSM::Round_report& r : reports) {
    VVM_CHECK(polishing <= r.is_polishing);
    polishing = r.is_polishing;
    if(!polishing) VVM_CHECK(r.energy <= previous * (1 + 1e-12));
    previous = r.energy;
  }
  VVM_CHECK(polishing);
  VVM_CHECK(reports.front().number_of_moves > 0 && reports.front().number_of_flips > 0);
  VVM_CHECK(complex_is_valid(c3t3));
  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
  VVM_CHECK(after.min_dihedral_angle > before.min_dihedral_angle + 10);
  VVM_CHECK(after.min_dihedral_angle > 25);
  std::printf("  sphere (random make_mesh_3 start): min dihedral %.2f -> %.2f, vertices %zu -> %zu\n",
              before.min_dihedral_angle, after.min_dihedral_angle, std::size_t(vertices_before),
              c3t3.triangulation().number_of_vertices());
  // the polishing adds at most 3% of the vertices (its removals pay for any more)
  VVM_CHECK(c3t3.triangulation().number_of_vertices() <= vertices_before + vertices_before * 3 / 100 + 1);
  VVM_CHECK(after.n_min_dihedral_below[2] < before.n_min_dihedral_below[2] / 5);
  VVM_CHECK_CLOSE(reports.back().min_dihedral_angle, after.min_dihedral_angle, 1e-12);
  // surface vertices are on the sphere (to the domain's intersection accuracy)
  double worst = 0;
  for(auto v : c3t3.triangulation().finite_vertex_handles())
    if(v->in_dimension() == 2) worst = (std::max)(worst, std::abs(std::sqrt(sphere_function(v->point().point()) + 1) - 1));
  VVM_CHECK(worst < 1e-6);
  if(worst >= 1e-6) std::cerr << "    surface vertex off the sphere by " << worst << "\n";

  // with no energy threshold, the rounds stop once the worst cells stop improving: two
  // rounds in a row that neither raise the smallest angle by 0.05 deg nor lower the number
  // of cells under 30 deg by a 100th (the energy alone creeps down for all 50 rounds)
  {
    Implicit_c3t3 stalled = make_sphere_mesh(0.2);
    std::vector<GSM::Round_report> rounds;
    const CGAL::Mesh_optimization_return_code stop = CGAL::gsm_optimize_mesh_3(
        stalled, domain,
        GSM::parameters::convergence_threshold(0., GSM::parameters::sliver_bound(0., params::visitor(
            [&](const GSM::Round_report& r) { rounds.push_back(r); }))));
    VVM_CHECK(stop == CGAL::CONVERGENCE_REACHED);
    VVM_CHECK(rounds.size() >= 3 && rounds.size() < 50);
    VVM_CHECK(rounds.back().number_of_moves > 0); // the rounds were still moving vertices
    // the last two rounds improved neither the smallest angle nor the count under 30 over
    // the best before them (the count, every round, is that of the visitor's report)
    double best = 0;
    std::size_t fewest = std::size_t(-1);
    for(std::size_t k = 0; k + 2 < rounds.size(); ++k) {
      best = (std::max)(best, rounds[k].min_dihedral_angle);
      fewest = (std::min)(fewest, rounds[k].number_of_cells_under_bound);
    }
    VVM_CHECK(rounds[rounds.size() - 2].min_dihedral_angle <= best + 0.05);
    VVM_CHECK(rounds.back().min_dihedral_angle <= best + 0.1);
    VVM_CHECK(double(rounds[rounds.size() - 2].number_of_cells_under_bound) >= 0.99 * double(fewest));
    VVM_CHECK(double(rounds.back().number_of_cells_under_bound) >= 0.99 * 0.99 * double(fewest));
    VVM_CHECK(complex_is_valid(stalled));
    std::printf("  sphere, energy rounds without threshold: %zu rounds, min dihedral %.2f\n", rounds.size(),
                rounds.back().min_dihedral_angle);
  }

  // ESM runs too, and is no match for GSM on slivers
  Implicit_c3t3 esm = make_sphere_mesh(0.2);
  CGAL::gsm_optimize_mesh_3(esm, domain, GSM::parameters::energy(GSM::Shape_matching_energy::ESM));
  VVM_CHECK(complex_is_valid(esm));
  VVM_CHECK(GSM::mesh_quality_statistics(esm).min_dihedral_angle < after.min_dihedral_angle);

  // a frozen boundary stays where it was; a time limit is honoured
  Implicit_c3t3 frozen = make_sphere_mesh(0.2);
  const auto start = positions(frozen);
  CGAL::gsm_optimize_mesh_3(frozen, domain,
                            GSM::parameters::freeze_boundary(true, params::number_of_iterations(3)));
  bool boundary_fixed = true, interior_moved = false;
  for(auto v : frozen.triangulation().finite_vertex_handles()) {
    const Eigen::Vector3d p(v->point().x(), v->point().y(), v->point().z());
    if(v->in_dimension() < 3) boundary_fixed = boundary_fixed && p == start.at(v);
    else interior_moved = interior_moved || p != start.at(v);
  }
  VVM_CHECK(boundary_fixed && interior_moved);
  Implicit_c3t3 timed = make_sphere_mesh(0.2);
  VVM_CHECK(CGAL::gsm_optimize_mesh_3(timed, domain, params::maximum_running_time(1e-9)) ==
            CGAL::TIME_LIMIT_REACHED);
  VVM_CHECK(complex_is_valid(timed));

  // a sizing field (the dissertation's s(x) of Fig. 3.7) is accepted and keeps the mesh valid
  Implicit_c3t3 adaptive = make_sphere_mesh(0.2);
  CGAL::gsm_optimize_mesh_3(adaptive, domain, GSM::parameters::sizing_field([](const Eigen::Vector3d& x) {
    return 0.025 + 0.2 * std::abs(x.norm() - 0.5);
  }, params::number_of_iterations(3)));
  VVM_CHECK(complex_is_valid(adaptive));
}

// a make_mesh_3 sphere with the uniform metric fitted to it and its energy sum
struct Sphere_energy_fixture
{
  Implicit_c3t3 c3t3;
  GSM::internal::Metric_field metric =
      GSM::internal::Metric_field::uniform(GSM::internal::estimated_edge_length(c3t3));
  GSM::internal::Mesh_energy<Implicit_c3t3> energy{c3t3, metric, GSM::Shape_matching_energy::GSM};
  double sum = 0;
  std::size_t count = 0;

  explicit Sphere_energy_fixture(double size = 0.2, const Implicit_function& f = sphere_function)
      : c3t3(make_implicit_mesh(f, size))
  {
    std::tie(sum, count) = energy.total();
  }
};

// flip passes alone on a make_mesh_3 sphere: edge and multi-face removals happen,
// the complex stays valid, the running sum exact
void test_flip_pass_on_sphere()
{
  Sphere_energy_fixture f;
  Implicit_c3t3& c3t3 = f.c3t3;
  auto& energy = f.energy;
  double& sum = f.sum;
  std::size_t& count = f.count;
  const double mean_before = sum / double(count);
  GSM::internal::Energy_guided_flips<Implicit_c3t3> flips(c3t3, energy, sum, count);
  GSM::internal::Flip_counts done;
  for(int pass = 0; pass < 5; ++pass) {
    const GSM::internal::Flip_counts n = flips.flip_pass();
    done.flips_2_3 += n.flips_2_3;
    done.flips_3_2 += n.flips_3_2;
    done.flips_4_4 += n.flips_4_4;
    done.edge_removals += n.edge_removals;
    done.multi_face_removals += n.multi_face_removals;
    if(n.total() == 0) break;
  }
  std::cerr << "    sphere flip passes: " << done.flips_2_3 << " 2-3, " << done.flips_3_2 << " 3-2, "
            << done.flips_4_4 << " 4-4, " << done.edge_removals << " edge removals, "
            << done.multi_face_removals << " multi-face removals\n";
  // a beneficial 2-3 flip here is always outdone by the removal of more faces
  // (4-4 flips are edge removals of rings of four; larger rings are rare around
  // the cells worse than the mean, the only ones the pass looks at, and the
  // hand-made rings of 5 to 7 above exercise them)
  VVM_CHECK(done.flips_3_2 > 0 && done.flips_4_4 > 0);
  VVM_CHECK(done.multi_face_removals > 0);
  VVM_CHECK(complex_is_valid(c3t3));
  const auto total = energy.total();
  VVM_CHECK_EQUAL(count, total.second);
  VVM_CHECK_CLOSE(sum, total.first, 1e-9 * total.first);
  VVM_CHECK(total.first / double(total.second) < mean_before);

  // the passes after the first look only where the last one changed cells (GSM's rounds):
  // nothing around no vertex, and the second pass restricted to the first one's changes
  // finds most of what an unrestricted one finds, on two identical complexes (elsewhere only
  // the lower mean, which the flips must beat, lets more through: the next round finds them)
  Sphere_energy_fixture g;
  GSM::internal::Energy_guided_flips<Implicit_c3t3> g_flips(g.c3t3, g.energy, g.sum, g.count);
  std::vector<Implicit_c3t3::Triangulation::Vertex_handle> changed, none;
  const std::size_t first = g_flips.flip_pass(nullptr, &changed).total();
  VVM_CHECK(first > 0 && !changed.empty() && changed.size() % 4 == 0);
  VVM_CHECK_EQUAL(g_flips.flip_pass(&none).total(), std::size_t(0));
  Sphere_energy_fixture h;
  GSM::internal::Energy_guided_flips<Implicit_c3t3> h_flips(h.c3t3, h.energy, h.sum, h.count);
  VVM_CHECK_EQUAL(h_flips.flip_pass().total(), first);
  const std::size_t restricted = g_flips.flip_pass(&changed).total();
  const std::size_t unrestricted = h_flips.flip_pass().total();
  std::cerr << "    sphere flips: first pass " << first << ", second pass " << restricted
            << " where the first changed cells, " << unrestricted << " everywhere\n";
  VVM_CHECK(restricted > 0 && restricted <= unrestricted && 5 * restricted >= 4 * unrestricted);
}

// edge splits on the worst cells of a make_mesh_3 sphere: each taken split adds one
// interior vertex of the cells' subdomain and raises the smallest angle around its
// edge; the complex stays valid with its counters, the running sum exact
void test_edge_split_on_sphere()
{
  Sphere_energy_fixture f;
  Implicit_c3t3& c3t3 = f.c3t3;
  auto& energy = f.energy;
  double& sum = f.sum;
  std::size_t& count = f.count;
  GSM::internal::Edge_split<Implicit_c3t3> splits(c3t3, energy, sum, count);
  const GSM::Mesh_quality_statistics before = GSM::mesh_quality_statistics(c3t3);
  const std::size_t vertices_before = c3t3.triangulation().number_of_vertices();
  std::vector<std::pair<double, std::array<Vertex_handle, 4>>> worst;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    worst.push_back({energy.min_dihedral_angle(c), {{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}}});
  std::sort(worst.begin(), worst.end());
  std::size_t done = 0, tried = 0;
  for(const auto& w : worst) {
    if(!(w.first < 10)) break;
    Implicit_tr::Cell_handle c;
    int i, j, k, l;
    const auto& t = w.second;
    if(!c3t3.triangulation().is_cell(t[0], t[1], t[2], t[3], c, i, j, k, l)) continue;
    ++tried;
    if(splits.try_split_cell(c)) ++done;
  }
  std::cerr << "    sphere edge splits: " << done << " of " << tried << " cells under 10 degrees\n";
  VVM_CHECK(done > 0);
  VVM_CHECK_EQUAL(c3t3.triangulation().number_of_vertices(), vertices_before + done);
  VVM_CHECK(complex_is_valid(c3t3));
  std::size_t new_interior = 0;
  for(auto v : c3t3.triangulation().finite_vertex_handles())
    if(v->in_dimension() == 3) {
      VVM_CHECK(v->index() == Implicit_c3t3::Index(Implicit_c3t3::Subdomain_index(1)));
      ++new_interior;
    }
  VVM_CHECK(new_interior > 0);
  const auto total = energy.total();
  VVM_CHECK_EQUAL(count, total.second);
  VVM_CHECK_CLOSE(sum, total.first, 1e-9 * total.first);
  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK(after.n_min_dihedral_below[0] < before.n_min_dihedral_below[0]); // under 10 degrees
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
}

// vertex removal by edge collapse. Hand-made: the centroid o of a regular tetrahedron
// (a, b, c, d) has a star of 4 cells; removed into a, the 3 cells with a go and (o, b, c, d)
// becomes (a, b, c, d), the regular one (70.53 degrees); a hull vertex is never removed. On
// a make_mesh_3 sphere: each removal takes one interior vertex, leaves the surface as it was
// and every new cell over the bound asked for, the complex valid with its counters exact.
void test_vertex_collapse()
{
  {
    Flip_fixture f;
    Implicit_tr& tr = f.c3t3.triangulation();
    const Vertex_handle a = insert(tr, 1, 1, 1), b = insert(tr, 1, -1, -1), c = insert(tr, -1, 1, -1),
                        d = insert(tr, -1, -1, 1), o = insert(tr, 0, 0, 0.01);
    f.start();
    for(const Vertex_handle& v : {a, b, c, d}) f.c3t3.set_dimension(v, 2);
    f.c3t3.set_dimension(o, 3);
    GSM::internal::Vertex_collapse<Implicit_c3t3> collapses(f.c3t3, f.energy, f.sum, f.count);
    GSM::internal::Vertex_collapse<Implicit_c3t3>::Collapse k;
    VVM_CHECK(!collapses.best_collapse(a, 0, k)); // on the surface
    VVM_CHECK(!collapses.best_collapse(o, 71, k)); // nothing as good as that
    VVM_CHECK(collapses.best_collapse(o, 70, k));
    VVM_CHECK_CLOSE(k.angle, std::acos(1. / 3) * 180 / CGAL_PI, 1e-9);
    collapses.apply(k);
    VVM_CHECK_EQUAL(tr.number_of_vertices(), std::size_t(4));
    VVM_CHECK_EQUAL(f.c3t3.number_of_cells_in_complex(), std::size_t(1));
    VVM_CHECK_EQUAL(f.c3t3.number_of_facets_in_complex(), std::size_t(4));
    VVM_CHECK(complex_is_valid(f.c3t3) && surface_is_closed(f.c3t3));
    VVM_CHECK_EQUAL(f.count, std::size_t(1));
    VVM_CHECK_CLOSE(f.sum, f.energy.total().first, 1e-9 * f.sum);
  }
  Sphere_energy_fixture f;
  Implicit_c3t3& c3t3 = f.c3t3;
  const std::size_t vertices_before = c3t3.triangulation().number_of_vertices();
  const std::size_t facets_before = c3t3.number_of_facets_in_complex();
  std::set<Bare_point> surface_before;
  for(auto v : c3t3.triangulation().finite_vertex_handles())
    if(v->in_dimension() < 3) surface_before.insert(v->point().point());
  const double min_before = GSM::mesh_quality_statistics(c3t3).min_dihedral_angle;
  GSM::internal::Vertex_collapse<Implicit_c3t3> collapses(c3t3, f.energy, f.sum, f.count);
  const double least = 25;
  const std::size_t done = collapses.collapse_vertices(30, least);
  std::cerr << "    sphere vertex removals: " << done << " (new cells over " << least << " degrees)\n";
  VVM_CHECK(done > 0 && done <= 30);
  VVM_CHECK_EQUAL(c3t3.triangulation().number_of_vertices(), vertices_before - done);
  VVM_CHECK(complex_is_valid(c3t3) && surface_is_closed(c3t3));
  VVM_CHECK_EQUAL(c3t3.number_of_facets_in_complex(), facets_before);
  std::set<Bare_point> surface_after;
  for(auto v : c3t3.triangulation().finite_vertex_handles())
    if(v->in_dimension() < 3) surface_after.insert(v->point().point());
  VVM_CHECK(surface_after == surface_before);
  const auto total = f.energy.total();
  VVM_CHECK_EQUAL(f.count, total.second);
  VVM_CHECK_CLOSE(f.sum, total.first, 1e-9 * total.first);
  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK(after.min_dihedral_angle >= (std::min)(min_before, least) - 1e-9);
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
}

// surface edge splits on a make_mesh_3 mesh's cells under 30 degrees, then under 40 with the bound
// at 40: each new vertex lies on the surface, on the edge's patch, with two more surface facets;
// the surface stays closed, the complex valid (outside cells too), the counters and the running
// sum exact, and the smallest angle of the mesh never lower; returns the number of splits that
// replaced outside cells beyond the edge's ring
std::size_t check_surface_edge_splits(const Implicit_function& surface, double size)
{
  std::cerr << "    facet size " << size << ":\n";
  const Implicit_domain domain = implicit_domain(surface);
  Sphere_energy_fixture f(size, surface);
  Implicit_c3t3& c3t3 = f.c3t3;
  typedef GSM::internal::Vertex_smoother<Implicit_c3t3, Implicit_domain> Smoother;
  const Smoother smoother(c3t3, &domain, f.energy, false);
  GSM::internal::Surface_edge_split<Implicit_c3t3, Implicit_domain> splits(
      c3t3, f.energy, f.sum, f.count, smoother, GSM::internal::Angle_penalty::for_bound(30));
  std::set<Vertex_handle> old_vertices;
  for(auto v : c3t3.triangulation().finite_vertex_handles()) old_vertices.insert(v);
  const std::size_t facets_before = c3t3.number_of_facets_in_complex();
  const double min_before = GSM::mesh_quality_statistics(c3t3).min_dihedral_angle;
  // tries `s` on each cell under `bound` degrees; the number of splits made and of cells tried
  const auto split_cells_under = [&](double bound, auto& s) {
    std::vector<std::array<Vertex_handle, 4>> bad;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
      if(f.energy.min_dihedral_angle(c) < bound) bad.push_back({{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}});
    std::size_t made = 0;
    for(const auto& t : bad) {
      Implicit_tr::Cell_handle c;
      int i, j, k, l;
      if(c3t3.triangulation().is_cell(t[0], t[1], t[2], t[3], c, i, j, k, l) && s.try_split_cell(c)) ++made;
    }
    return std::make_pair(made, bad.size());
  };
  const auto under_30 = split_cells_under(30, splits);
  std::size_t done = under_30.first;
  std::cerr << "    surface edge splits: " << done << " of " << under_30.second << " cells under 30 degrees\n";
  VVM_CHECK(done > 0);
  // then for the cells under 40, with the bound at 40: more splits, some of which replace
  // outside cells beyond the edge's ring, where the new vertex would invert them
  GSM::internal::Surface_edge_split<Implicit_c3t3, Implicit_domain> splits_40(
      c3t3, f.energy, f.sum, f.count, smoother, GSM::internal::Angle_penalty::for_bound(40));
  const auto under_40 = split_cells_under(40, splits_40);
  const std::size_t done_40 = under_40.first;
  const std::size_t grown = splits_40.number_of_grown_holes() + splits.number_of_grown_holes();
  std::cerr << "    surface edge splits: " << done_40 << " of " << under_40.second << " cells under 40 degrees, "
            << grown << " in all past the edge's ring\n";
  done += done_40;
  VVM_CHECK_EQUAL(c3t3.triangulation().number_of_vertices(), old_vertices.size() + done);
  VVM_CHECK_EQUAL(c3t3.number_of_facets_in_complex(), facets_before + 2 * done);
  VVM_CHECK(complex_is_valid(c3t3) && surface_is_closed(c3t3)); // every finite cell positive, outside ones too
  std::size_t new_vertices = 0, more_facets = 0;
  for(auto v : c3t3.triangulation().finite_vertex_handles()) {
    if(old_vertices.count(v) > 0) continue;
    ++new_vertices;
    const auto& p = v->point().point();
    VVM_CHECK_EQUAL(c3t3.in_dimension(v), 2);
    VVM_CHECK(std::abs(surface(K::Point_3(p.x(), p.y(), p.z()))) < 1e-6);
    // it is on the surface of the complex, on the patch of its facets
    std::vector<Implicit_tr::Facet> facets;
    c3t3.triangulation().finite_incident_facets(v, std::back_inserter(facets));
    std::size_t on_surface = 0;
    for(const auto& g : facets)
      if(c3t3.is_in_complex(g)) {
        ++on_surface;
        VVM_CHECK(c3t3.surface_patch_index(g) == boost::get<Implicit_c3t3::Surface_patch_index>(c3t3.index(v)));
      }
    // four from its own split, one more for each later split of an edge opposite it
    VVM_CHECK(on_surface >= 4);
    more_facets += on_surface - 4;
  }
  VVM_CHECK_EQUAL(new_vertices, done);
  VVM_CHECK(more_facets <= done);
  const auto total = f.energy.total();
  VVM_CHECK_EQUAL(f.count, total.second);
  VVM_CHECK_CLOSE(f.sum, total.first, 1e-9 * total.first);
  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK(after.min_dihedral_angle >= min_before - 1e-9);
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
  return grown;
}

void test_surface_edge_split()
{
  // a torus's saddle: new vertices beyond outside cells of the ring
  std::size_t grown = check_surface_edge_splits(sphere_function, 0.2);
  grown += check_surface_edge_splits(torus_function, 0.1);
  VVM_CHECK(grown > 0);
}

void test_bad_input()
{
  const Implicit_domain domain = sphere_domain();
  Implicit_c3t3 empty;
  bool thrown = false;
  try { CGAL::gsm_optimize_mesh_3(empty, domain); } catch(const std::invalid_argument& e) {
    thrown = std::string(e.what()).find("no cell") != std::string::npos;
  }
  VVM_CHECK(thrown);

  Implicit_c3t3 c3t3 = make_sphere_mesh(0.3);
  // a bad sizing field: refused before any change
  const auto start = positions(c3t3);
  thrown = false;
  try {
    CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::sizing_field([](const Eigen::Vector3d& x) { return x.x(); }));
  } catch(const std::invalid_argument& e) {
    thrown = std::string(e.what()).find("sizing field") != std::string::npos;
  }
  VVM_CHECK(thrown);
  VVM_CHECK(positions(c3t3) == start);
  thrown = false;
  try {
    CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::metric_field([](const Eigen::Vector3d&) {
      return Eigen::Matrix3d(Eigen::Vector3d(1, -1, 1).asDiagonal());
    }));
  } catch(const std::invalid_argument& e) {
    thrown = std::string(e.what()).find("positive definite") != std::string::npos;
  }
  VVM_CHECK(thrown);
  VVM_CHECK(positions(c3t3) == start);
  for(double bound : {-1., 75., std::nan("")}) {
    thrown = false;
    try { CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::sliver_bound(bound)); }
    catch(const std::invalid_argument& e) { thrown = std::string(e.what()).find("sliver bound") != std::string::npos; }
    VVM_CHECK(thrown);
    VVM_CHECK(positions(c3t3) == start);
  }

  // an inverted cell: pull an interior vertex through its opposite facet
  Implicit_tr& tr = c3t3.triangulation();
  for(auto c : tr.finite_cell_handles()) {
    if(!c3t3.is_in_complex(c) || c->vertex(0)->in_dimension() != 3) continue;
    const Vertex_handle v = c->vertex(0);
    Bare_point q = CGAL::centroid(tr.point(c, 1).point(), tr.point(c, 2).point(), tr.point(c, 3).point());
    const Bare_point p = v->point().point();
    v->set_point(Implicit_tr::Point(Bare_point(2 * q.x() - p.x(), 2 * q.y() - p.y(), 2 * q.z() - p.z())));
    break;
  }
  const auto inverted_start = positions(c3t3);
  thrown = false;
  try { CGAL::gsm_optimize_mesh_3(c3t3, domain); } catch(const std::invalid_argument& e) {
    thrown = std::string(e.what()).find("inverted") != std::string::npos;
  }
  VVM_CHECK(thrown);
  VVM_CHECK(positions(c3t3) == inverted_start);
}

// the polyhedral cube [-1,1]^3 with its 12 edges and 8 corners protected
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Cube_domain;
typedef CGAL::Mesh_triangulation_3<Cube_domain>::type Cube_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Cube_tr, Cube_domain::Corner_index, Cube_domain::Curve_index> Cube_c3t3;

void test_cube_with_features()
{
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> v;
  for(int i = 0; i < 8; ++i) v.push_back(sm.add_vertex(K::Point_3(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1)));
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for(const auto& q : quads) sm.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  Cube_domain domain(sm);
  domain.detect_features(60);
  CGAL::Mesh_criteria_3<Cube_tr> criteria(params::edge_size = 0.3, params::facet_angle = 25,
                                          params::facet_size = 0.3, params::facet_distance = 0.03,
                                          params::cell_radius_edge_ratio = 3, params::cell_size = 0.3);
  CGAL::get_default_random() = CGAL::Random(1);
  Cube_c3t3 c3t3 = CGAL::make_mesh_3<Cube_c3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  const auto start = positions(c3t3);
  const double before = GSM::mesh_quality_statistics(c3t3).min_dihedral_angle;
  CGAL::gsm_optimize_mesh_3(c3t3, domain);
  VVM_CHECK(complex_is_valid(c3t3));
  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
  VVM_CHECK(after.min_dihedral_angle > before + 5);
  bool corners_fixed = true, on_edges = true, on_faces = true, curve_moved = false, surface_moved = false;
  for(auto vh : c3t3.triangulation().finite_vertex_handles()) {
    const Eigen::Vector3d p(vh->point().x(), vh->point().y(), vh->point().z());
    int on_planes = 0;
    for(int k = 0; k < 3; ++k) on_planes += std::abs(std::abs(p[k]) - 1) < 1e-9 ? 1 : 0;
    switch(vh->in_dimension()) {
    case 0: corners_fixed = corners_fixed && p == start.at(vh); break;
    case 1: on_edges = on_edges && on_planes >= 2; curve_moved = curve_moved || p != start.at(vh); break;
    case 2: on_faces = on_faces && on_planes >= 1; surface_moved = surface_moved || p != start.at(vh); break;
    default: break;
    }
  }
  VVM_CHECK(corners_fixed);
  VVM_CHECK(on_edges && curve_moved);
  VVM_CHECK(on_faces && surface_moved);
}

// Boundary_fidelity's measure of how far a facet strays, on a hand-made crease: a box with a
// shallow roof z = 0.2 (1 - |x|) (a ridge of 22.6 degrees, one patch) and a facet at z = 0.1
// under the ridge, x from -0.6 to 0.4. Along the facet's normal the roof is 0.1 - 0.2 |x| away:
// the grid with edges in 4 (x = 0.4 - i/4, and the centroid at x = 1/15) misses the ridge by
// 1/15, the grid with edges in 8 reaches x = 0.025.
void test_boundary_fidelity_on_a_crease()
{
  Surface_mesh house;
  std::vector<Surface_mesh::Vertex_index> v;
  for(const auto& p : {K::Point_3(-1, -1, -1), K::Point_3(1, -1, -1), K::Point_3(1, 1, -1), K::Point_3(-1, 1, -1),
                       K::Point_3(-1, -1, 0), K::Point_3(1, -1, 0), K::Point_3(1, 1, 0), K::Point_3(-1, 1, 0),
                       K::Point_3(0, -1, 0.2), K::Point_3(0, 1, 0.2)})
    v.push_back(house.add_vertex(p));
  const std::vector<std::vector<int>> faces = {{0, 3, 2, 1}, {0, 1, 5, 8, 4}, {2, 3, 7, 9, 6}, {1, 2, 6, 5},
                                               {3, 0, 4, 7}, {4, 8, 9, 7}, {8, 5, 6, 9}};
  for(const auto& f : faces) {
    std::vector<Surface_mesh::Vertex_index> fv;
    for(int i : f) fv.push_back(v[std::size_t(i)]);
    house.add_face(fv);
  }
  CGAL::Polygon_mesh_processing::triangulate_faces(house);
  if(!CGAL::Polygon_mesh_processing::is_outward_oriented(house)) CGAL::Polygon_mesh_processing::reverse_face_orientations(house);
  const Cube_domain domain(house);
  const auto hit = domain.construct_intersection_object()(K::Segment_3(K::Point_3(0, 0, 0), K::Point_3(0, 0, 1)));
  VVM_CHECK(std::get<2>(hit) == 2);
  const auto patch = domain.surface_patch_index(std::get<1>(hit));
  const Cube_c3t3 empty;
  const GSM::internal::Boundary_fidelity<Cube_c3t3, Cube_domain> fidelity(empty, &domain);
  typedef GSM::internal::Boundary_fidelity<Cube_c3t3, Cube_domain> Fidelity;
  const Fidelity::Triangle t = {{K::Point_3(-0.6, -0.3, 0.1), K::Point_3(0.4, -0.3, 0.1), K::Point_3(0.4, 0.5, 0.1)}};
  const double coarse = fidelity.deviation(t, patch, Fidelity::coarse_grid);
  const double fine = fidelity.deviation(t, patch, Fidelity::fine_grid);
  std::printf("  crease under a facet: deviation %.6f on the coarse grid, %.6f on the fine one (ridge 0.1)\n",
              coarse, fine);
  VVM_CHECK_CLOSE(coarse, 0.1 - 0.2 / 15, 1e-9);
  VVM_CHECK_CLOSE(fine, 0.1 - 0.2 * 0.025, 1e-9);
  // the fine grid's new points only (the coarse ones measured already), the centroid included
  VVM_CHECK_CLOSE(fidelity.deviation(t, patch, Fidelity::fine_grid, Fidelity::coarse_grid), fine, 1e-9);
  // the test with a limit (short queries first) agrees with the measures on both sides of them
  for(const auto& grid : {std::make_pair(Fidelity::coarse_grid, coarse), std::make_pair(Fidelity::fine_grid, fine)}) {
    VVM_CHECK(fidelity.deviates_at_most(t, patch, grid.first, 0, grid.second + 1e-6));
    VVM_CHECK(!fidelity.deviates_at_most(t, patch, grid.first, 0, grid.second - 1e-6));
  }
  VVM_CHECK(fidelity.deviates_at_most(t, patch, Fidelity::coarse_grid, 0, 1.)); // beyond the normal segments' reach
  VVM_CHECK(!fidelity.deviates_at_most(t, patch, Fidelity::coarse_grid, 0, 0.));
}

// Boundary_fidelity's bounds on a make_mesh_3 sphere, whose distance to its inscribed boundary
// is known: a facet is 1 - |x| from the sphere at its point x nearest the centre (both ways).
// The estimate of the largest distance reaches it from below; every bound lies between 90% of
// it and it; a facet pulled towards the centre is refused, the initial ones are kept.
void test_boundary_fidelity_bounds_on_sphere()
{
  const Implicit_c3t3 c3t3 = make_sphere_mesh(0.2);
  const Implicit_domain domain = sphere_domain();
  typedef GSM::internal::Boundary_fidelity<Implicit_c3t3, Implicit_domain> Fidelity;
  const Fidelity fidelity(c3t3, &domain);
  const Implicit_tr& tr = c3t3.triangulation();
  double exact = 0;
  std::vector<std::pair<Fidelity::Triangle, std::array<Vertex_handle, 3>>> facets;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    Fidelity::Triangle t;
    std::array<Vertex_handle, 3> v;
    for(int k = 0; k < 3; ++k) {
      v[k] = f->first->vertex((f->second + 1 + k) & 3);
      t[k] = tr.point(v[k]).point();
    }
    exact = (std::max)(exact, 1 - std::sqrt(CGAL::squared_distance(K::Point_3(CGAL::ORIGIN), K::Triangle_3(t[0], t[1], t[2]))));
    facets.emplace_back(t, v);
  }
  const double largest = fidelity.largest_initial_distance();
  std::printf("  sphere: largest distance %.6f estimated, %.6f exact\n", largest, exact);
  VVM_CHECK(largest <= exact * (1 + 1e-6));
  VVM_CHECK(largest >= 0.95 * exact);
  bool bounds_in_range = true;
  for(auto v : tr.finite_vertex_handles()) {
    if(c3t3.in_dimension(v) != 2) continue;
    for(bool fine : {false, true})
      bounds_in_range = bounds_in_range && fidelity.bound(v, fine) >= Fidelity::floor_share * largest - 1e-12 &&
                        fidelity.bound(v, fine) <= largest + 1e-12;
  }
  VVM_CHECK(bounds_in_range);
  const auto patch = c3t3.surface_patch_index(*c3t3.facets_in_complex_begin()); // one patch
  int under_floor = 0, kept = 0, refused = 0;
  for(const auto& f : facets) {
    if(fidelity.deviation(f.first, patch, Fidelity::fine_grid) <= Fidelity::floor_share * largest) {
      ++under_floor;
      kept += fidelity.is_faithful(f.first, patch, f.second) ? 1 : 0;
    }
    Fidelity::Triangle in = f.first;
    for(auto& p : in) p = CGAL::ORIGIN + (p - CGAL::ORIGIN) * (1 - 1.2 * exact);
    refused += fidelity.is_faithful(in, patch, f.second) ? 0 : 1;
  }
  VVM_CHECK(under_floor > 0);
  VVM_CHECK_EQUAL(kept, under_floor);
  VVM_CHECK_EQUAL(refused, int(facets.size()));
}

// Parallel sweeps are deterministic: the batches do not depend on the threads.
// A sizing field matters only up to a constant factor (fitted to the vertex
// count). The adaptive run follows the field. The boundary does not get
// farther from the input surface (Hausdorff distance, both ways, within 10%).
void test_threads_fields_and_boundary()
{
  const Implicit_domain domain = sphere_domain();
  const Implicit_c3t3 initial = make_sphere_mesh(0.2);
  Implicit_c3t3 one = initial, two = initial;
  CGAL::gsm_optimize_mesh_3(one, domain, GSM::parameters::number_of_threads(1, params::number_of_iterations(4)));
  CGAL::gsm_optimize_mesh_3(two, domain, GSM::parameters::number_of_threads(2, params::number_of_iterations(4)));
  VVM_CHECK(complex_is_valid(two));
  VVM_CHECK(GSM::mesh_quality_statistics(one).number_of_cells == GSM::mesh_quality_statistics(two).number_of_cells);
  std::vector<Eigen::Vector3d> p1, p2;
  for(const auto& vp : positions(one)) p1.push_back(vp.second);
  for(const auto& vp : positions(two)) p2.push_back(vp.second);
  VVM_CHECK(p1 == p2);
  // the same again after other work: the copy's vertices and cells now lie elsewhere in
  // memory, in another order of addresses (a heap with holes of every size)
  {
    std::vector<std::vector<char>> blocks;
    for(int i = 0; i < 4000; ++i) blocks.emplace_back(std::size_t(64 + (i * 7919) % 20000));
    for(std::size_t i = 0; i < blocks.size(); i += 2) std::vector<char>().swap(blocks[i]);
    Implicit_c3t3 other = initial;
    CGAL::gsm_optimize_mesh_3(other, domain, params::number_of_iterations(2));
    Implicit_c3t3 again = initial;
    CGAL::gsm_optimize_mesh_3(again, domain, GSM::parameters::number_of_threads(1, params::number_of_iterations(4)));
    std::vector<Eigen::Vector3d> p3;
    for(const auto& vp : positions(again)) p3.push_back(vp.second);
    std::sort(p1.begin(), p1.end(), [](const auto& a, const auto& b) { return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3); });
    std::sort(p3.begin(), p3.end(), [](const auto& a, const auto& b) { return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3); });
    VVM_CHECK(p1 == p3);
  }

  // polishing without splits keeps the vertex set and, with a bound above what the
  // rounds reach (31 degrees), lifts the worst cell; sliver_bound(0) skips it
  Implicit_c3t3 no_split = initial, no_polish = initial;
  CGAL::gsm_optimize_mesh_3(no_split, domain, GSM::parameters::split_edges(false, GSM::parameters::sliver_bound(40)));
  VVM_CHECK_EQUAL(no_split.triangulation().number_of_vertices(), initial.triangulation().number_of_vertices());
  VVM_CHECK(complex_is_valid(no_split));
  std::size_t polishing_rounds = 0;
  CGAL::gsm_optimize_mesh_3(no_polish, domain, GSM::parameters::sliver_bound(0, params::visitor(
      [&](const GSM::Round_report& r) { polishing_rounds += r.is_polishing ? 1 : 0; })));
  VVM_CHECK_EQUAL(polishing_rounds, std::size_t(0));
  VVM_CHECK(GSM::mesh_quality_statistics(no_split).min_dihedral_angle >
            GSM::mesh_quality_statistics(no_polish).min_dihedral_angle);

  // shortest_polishing_moves: with flips only in the rounds and no splits, only the polishing
  // moves vertices (each vertex's distance to the nearest initial one: the moves are shorter
  // than half an edge), otherwise than without it, the worst cell still lifted. (The option
  // changes the critical cells' moves only; the penalty moves of the others, the same in both,
  // make most of the sum: since penalty moves near the bound trade no more cells under it + 10
  // than they lift over it, the two sums are close, 10.69 without the option and 10.98 with it,
  // where they were 11.10 and 10.86 without that rule.)
  auto displacement = [&initial](const Implicit_c3t3& c3t3) {
    std::vector<Eigen::Vector3d> before;
    for(const auto& vp : positions(initial)) before.push_back(vp.second);
    double sum = 0;
    for(const auto& vp : positions(c3t3)) {
      double d = std::numeric_limits<double>::infinity();
      for(const Eigen::Vector3d& b : before) d = (std::min)(d, (vp.second - b).norm());
      sum += d;
    }
    return sum;
  };
  Implicit_c3t3 flips_only = initial, farthest = initial, shortest = initial;
  CGAL::gsm_optimize_mesh_3(flips_only, domain, GSM::parameters::smooth_vertices(false, GSM::parameters::sliver_bound(0)));
  auto polish_only = GSM::parameters::smooth_vertices(false, GSM::parameters::split_edges(false,
      GSM::parameters::sliver_bound(40)));
  CGAL::gsm_optimize_mesh_3(farthest, domain, polish_only);
  CGAL::gsm_optimize_mesh_3(shortest, domain, GSM::parameters::shortest_polishing_moves(true, polish_only));
  VVM_CHECK(complex_is_valid(shortest));
  const auto q_flips = GSM::mesh_quality_statistics(flips_only), q_far = GSM::mesh_quality_statistics(farthest),
             q_short = GSM::mesh_quality_statistics(shortest);
  std::printf("  polishing moves (bound 40, flips only, no splits): displacement %.4f (max-min) against %.4f "
              "(shortest), min %.2f / %.2f, tets under 40 %zu / %zu (before the polishing: min %.2f, %zu)\n",
              displacement(farthest), displacement(shortest), q_far.min_dihedral_angle, q_short.min_dihedral_angle,
              q_far.n_min_dihedral_below[3], q_short.n_min_dihedral_below[3], q_flips.min_dihedral_angle,
              q_flips.n_min_dihedral_below[3]);
  VVM_CHECK_EQUAL(displacement(flips_only), 0.);
  VVM_CHECK(displacement(shortest) > 0);
  VVM_CHECK(displacement(shortest) != displacement(farthest));
  VVM_CHECK(q_short.min_dihedral_angle > q_flips.min_dihedral_angle);
  VVM_CHECK(q_short.n_min_dihedral_below[3] < q_flips.n_min_dihedral_below[3]);

  // mean_angle_moves after the same polishing: a higher mean smallest angle, no cell under 40
  // that was not (each move keeps its star's count under the bound + 10 and its worst cell
  // over the bound or where it was); a cost that no move can pay leaves the polished mesh as
  // it is; a negative threshold is refused
  Implicit_c3t3 raised = initial, unpaid = initial;
  CGAL::gsm_optimize_mesh_3(raised, domain, GSM::parameters::mean_angle_moves(60, polish_only));
  typedef Implicit_c3t3::Triangulation::Vertex_handle Implicit_vertex;
  CGAL::gsm_optimize_mesh_3(unpaid, domain, GSM::parameters::vertex_move_cost(
      [&unpaid](const Implicit_vertex& v, const Eigen::Vector3d& x) {
        return 1e12 * (x - GSM::internal::to_eigen(unpaid.triangulation().point(v))).norm();
      }, GSM::parameters::mean_angle_moves(60, polish_only)));
  VVM_CHECK(complex_is_valid(raised));
  const auto q_raised = GSM::mesh_quality_statistics(raised);
  std::printf("  mean-angle moves (under 60) after the polishing: mean smallest angle %.3f against %.3f, "
              "min %.2f / %.2f, tets under 40 %zu / %zu\n", q_raised.mean_min_dihedral_angle,
              q_far.mean_min_dihedral_angle, q_raised.min_dihedral_angle, q_far.min_dihedral_angle,
              q_raised.n_min_dihedral_below[3], q_far.n_min_dihedral_below[3]);
  VVM_CHECK(q_raised.mean_min_dihedral_angle > q_far.mean_min_dihedral_angle + 0.1);
  VVM_CHECK(q_raised.min_dihedral_angle >= (std::min)(q_far.min_dihedral_angle, 40.) - 1e-9);
  VVM_CHECK(q_raised.n_min_dihedral_below[3] <= q_far.n_min_dihedral_below[3]);
  auto sorted_points = [](const Implicit_c3t3& c3t3) {
    std::vector<std::array<double, 3>> points;
    for(const auto& vp : positions(c3t3)) points.push_back({vp.second[0], vp.second[1], vp.second[2]});
    std::sort(points.begin(), points.end());
    return points;
  };
  VVM_CHECK(sorted_points(unpaid) == sorted_points(farthest));
  VVM_CHECK(sorted_points(raised) != sorted_points(farthest));
  bool refused = false;
  try {
    Implicit_c3t3 copy = initial;
    CGAL::gsm_optimize_mesh_3(copy, domain, GSM::parameters::mean_angle_moves(-1));
  } catch(const std::invalid_argument& e) { refused = std::string(e.what()).find("mean-angle") != std::string::npos; }
  VVM_CHECK(refused);

  // h and 4h (a power of two: the fitted scale is then exactly the same)
  auto h = [](const Eigen::Vector3d& x) { return GSM::dissertation::adaptive_sphere_sizing(x); };
  Implicit_c3t3 small = initial, large = initial;
  CGAL::gsm_optimize_mesh_3(small, domain, GSM::parameters::sizing_field(h, params::number_of_iterations(4)));
  CGAL::gsm_optimize_mesh_3(large, domain, GSM::parameters::sizing_field([&h](const Eigen::Vector3d& x) {
    return 4 * h(x);
  }, params::number_of_iterations(4)));
  std::vector<Eigen::Vector3d> ps, pl;
  for(const auto& vp : positions(small)) ps.push_back(vp.second);
  for(const auto& vp : positions(large)) pl.push_back(vp.second);
  VVM_CHECK(ps == pl);
  VVM_CHECK(ps != p2); // and the field did change the result

  // edges near |x| = 0.5 (h = 0.025) against those near the boundary (h >= 0.105)
  auto length_ratio = [](const Implicit_c3t3& c3t3) {
    return mean_edge_length_ratio(c3t3, [](const Eigen::Vector3d& m) {
      return m.norm() > 0.35 && m.norm() < 0.65 ? 0 : m.norm() > 0.9 ? 1 : -1;
    });
  };
  Implicit_c3t3 adaptive = initial;
  CGAL::gsm_optimize_mesh_3(adaptive, domain, GSM::parameters::sizing_field(h));
  VVM_CHECK(complex_is_valid(adaptive));
  std::printf("  adaptive sphere: boundary/middle edge length ratio %.3f before, %.3f after\n",
              length_ratio(initial), length_ratio(adaptive));
  VVM_CHECK(length_ratio(adaptive) > 1.05 * length_ratio(initial));

  // the polyhedral sphere of data/sphere966.off, no features: surface vertices slide on it
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(std::string(VVM_DATA_DIR) + "/sphere966.off", surface));
  Cube_domain polyhedral(surface);
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(surface);
  const double size = 0.08 * (box.xmax() - box.xmin()); // about 2,500 vertices
  CGAL::Mesh_criteria_3<Cube_tr> criteria(params::facet_angle = 25, params::facet_size = size,
                                          params::facet_distance = size / 10, params::cell_radius_edge_ratio = 3,
                                          params::cell_size = size);
  CGAL::get_default_random() = CGAL::Random(1);
  Cube_c3t3 c3t3 = CGAL::make_mesh_3<Cube_c3t3>(polyhedral, criteria, params::no_perturb(), params::no_exude());
  const double density = 30000 / CGAL::Polygon_mesh_processing::area(surface); // sample points per area unit
  auto hausdorff = [&surface, density](const Cube_c3t3& m) {
    namespace PMP = CGAL::Polygon_mesh_processing;
    Surface_mesh boundary;
    CGAL::facets_in_complex_3_to_triangle_mesh(m, boundary);
    CGAL::get_default_random() = CGAL::Random(2);
    const double to_input = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
        boundary, surface, PMP::parameters::number_of_points_per_area_unit(density));
    const double to_boundary = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
        surface, boundary, PMP::parameters::number_of_points_per_area_unit(density));
    return (std::max)(to_input, to_boundary);
  };
  const double before = hausdorff(c3t3);
  const double min_before = GSM::mesh_quality_statistics(c3t3).min_dihedral_angle;
  CGAL::gsm_optimize_mesh_3(c3t3, polyhedral);
  const double after = hausdorff(c3t3);
  std::printf("  polyhedral sphere: Hausdorff distance to the input %.5f before, %.5f after; "
              "min dihedral %.2f -> %.2f\n", before, after, min_before,
              GSM::mesh_quality_statistics(c3t3).min_dihedral_angle);
  VVM_CHECK(complex_is_valid(c3t3));
  VVM_CHECK(before > 0 && after <= 1.1 * before);
  VVM_CHECK(GSM::mesh_quality_statistics(c3t3).min_dihedral_angle > min_before + 5);
}

// the default target size is the input mesh's: exact on a hand-made tetrahedron,
// and a graded make_mesh_3 sphere keeps its grading through GSM
void test_input_mesh_sizing()
{
  typedef CGAL::Delaunay_triangulation_3<K> Delaunay;
  // the corner tetrahedron: the origin's three edges have length 1, the others sqrt 2
  std::vector<K::Point_3> corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Delaunay tr(corners.begin(), corners.end());
  GSM::internal::Triangulation_complex<Delaunay> complex(tr);
  const GSM::internal::Input_mesh_sizing raw(complex, 0), smoothed(complex, 1);
  const double far = (1 + 2 * std::sqrt(2.)) / 3.; // mean edge length at the other corners
  VVM_CHECK_CLOSE(raw(Eigen::Vector3d(0, 0, 0)), 1., 1e-12);
  VVM_CHECK_CLOSE(raw(Eigen::Vector3d(0, 1, 0)), far, 1e-12);
  VVM_CHECK_CLOSE(raw(Eigen::Vector3d(0.25, 0.25, 0.25)), 0.25 * (1 + 3 * far), 1e-12); // linear inside
  VVM_CHECK_CLOSE(raw(Eigen::Vector3d(0.5, 0, 0)), 0.5 * (1 + far), 1e-12);
  VVM_CHECK_CLOSE(raw(Eigen::Vector3d(2, 2, 2)), far, 1e-12); // outside: the nearest hull facet's mean
  // one smoothing pass: half its own size, half its neighbours' mean
  VVM_CHECK_CLOSE(smoothed(Eigen::Vector3d(0, 0, 0)), 0.5 * (1 + far), 1e-12);
  VVM_CHECK_CLOSE(smoothed(Eigen::Vector3d(1, 0, 0)), 0.5 * far + 0.5 * (1 + 2 * far) / 3., 1e-12);

  // the sizes the vertices carry: the field where each vertex is, again when it moves; a
  // cell's map is I / (the mean of its corners' sizes), its energy that of the mapped cell
  auto field = [](const Eigen::Vector3d& x) { return 1 + x.x() + 2 * x.y(); };
  auto sizes = std::make_shared<GSM::internal::Vertex_sizes<Delaunay>>(tr, field);
  std::array<Delaunay::Vertex_handle, 4> corner;
  for(auto w : tr.finite_vertex_handles()) corner[std::size_t(w->point().x() + 2 * w->point().y() + 3 * w->point().z())] = w;
  const Delaunay::Cell_handle cell = tr.finite_cells_begin();
  VVM_CHECK_CLOSE((*sizes)(corner[1]), 2., 1e-15);
  VVM_CHECK_CLOSE(sizes->sum(cell), 1. + 2. + 3. + 1., 1e-15);
  VVM_CHECK_CLOSE(sizes->sum(cell, corner[2], 0.5), 1. + 2. + 0.5 + 1., 1e-15);
  const GSM::internal::Metric_field unit = GSM::internal::Metric_field::uniform(1.);
  const GSM::internal::Mesh_energy<GSM::internal::Triangulation_complex<Delaunay>> sized(
      complex, unit, GSM::Shape_matching_energy::GSM, sizes);
  std::array<Eigen::Vector3d, 4> mapped;
  for(int i = 0; i < 4; ++i) mapped[i] = GSM::internal::to_eigen(cell->vertex(i)->point()) / (7. / 4.);
  VVM_CHECK_CLOSE(sized.cell(cell), GSM::tetrahedron_energy(GSM::Shape_matching_energy::GSM, mapped[0], mapped[1],
                                                            mapped[2], mapped[3]), 1e-12);
  corner[3]->set_point(K::Point_3(0.1, 0.2, 1)); // moved: its size is taken again where it is
  sized.vertex_moved(corner[3]);
  VVM_CHECK_CLOSE((*sizes)(corner[3]), 1.5, 1e-15);
  VVM_CHECK_CLOSE(sizes->sum(cell), 1. + 2. + 3. + 1.5, 1e-15);
  bool refused = false;
  try { GSM::internal::Vertex_sizes<Delaunay>(tr, [](const Eigen::Vector3d&) { return -1.; }); }
  catch(const std::invalid_argument& e) { refused = std::string(e.what()).find("sizing field is -1") != std::string::npos; }
  VVM_CHECK(refused);

  // a sphere meshed with sizes from 0.06 (x = -1) to 0.18 (x = 1)
  const Implicit_domain domain = sphere_domain();
  auto h = [](const K::Point_3& p, int, const Implicit_domain::Index&) { return 0.06 * (2 + p.x()); };
  CGAL::Mesh_criteria_3<Implicit_tr> criteria(params::facet_angle = 25, params::facet_size = h,
                                              params::facet_distance = 0.01, params::cell_radius_edge_ratio = 3,
                                              params::cell_size = h);
  CGAL::get_default_random() = CGAL::Random(1);
  const Implicit_c3t3 graded =
      CGAL::make_mesh_3<Implicit_c3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  // mean edge length where x > 0.4 over that where x < -0.4
  auto grading = [](const Implicit_c3t3& c3t3) {
    return mean_edge_length_ratio(c3t3, [](const Eigen::Vector3d& m) { return m.x() < -0.4 ? 0 : m.x() > 0.4 ? 1 : -1; });
  };
  Implicit_c3t3 local = graded, uniform = graded;
  CGAL::gsm_optimize_mesh_3(local, domain);
  CGAL::gsm_optimize_mesh_3(uniform, domain, GSM::parameters::uniform_sizing(true));
  const double before = grading(graded), after = grading(local), after_uniform = grading(uniform);
  const GSM::Mesh_quality_statistics q0 = GSM::mesh_quality_statistics(graded), q = GSM::mesh_quality_statistics(local),
                                     qu = GSM::mesh_quality_statistics(uniform);
  std::printf("  graded sphere (%zu vertices): coarse/fine edge length %.3f before, %.3f after GSM, %.3f with "
              "uniform_sizing; min dihedral %.2f -> %.2f (uniform %.2f), tets under 30 deg %zu -> %zu (uniform %zu)\n",
              graded.triangulation().number_of_vertices(), before, after, after_uniform, q0.min_dihedral_angle,
              q.min_dihedral_angle, qu.min_dihedral_angle, q0.n_min_dihedral_below[2], q.n_min_dihedral_below[2],
              qu.n_min_dihedral_below[2]);
  VVM_CHECK(before > 1.8);
  VVM_CHECK(std::abs(after / before - 1) < 0.1);
  // what the default avoids: one size fights the grading (1.90 -> 1.72 when written, 1.77 since
  // the rounds stop once the cells under 30 degrees drop by less than a 20th), by at least
  // twice as much as the input's own sizes do
  VVM_CHECK(after_uniform < 0.95 * before);
  VVM_CHECK(std::abs(after / before - 1) < 0.5 * std::abs(after_uniform / before - 1));
  VVM_CHECK(complex_is_valid(local));
  VVM_CHECK(q.min_dihedral_angle > 25 && q.n_min_dihedral_below[2] < q0.n_min_dihedral_below[2] / 10);
}

// ---------------------------------------------------------------------------
// several subdomains, from CGAL's other domain kinds

// the volume of each subdomain and the number of facets between two subdomains
template <class C3T3>
std::pair<std::map<int, double>, std::size_t> subdomains_and_interface(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  std::map<int, double> volume;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = GSM::internal::to_eigen(tr.point(c, i));
    volume[int(c3t3.subdomain_index(c))] += (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) / 6.;
  }
  std::size_t interface = 0;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    const auto m = tr.mirror_facet(*f);
    interface += c3t3.is_in_complex(f->first) && c3t3.is_in_complex(m.first) &&
                 c3t3.subdomain_index(f->first) != c3t3.subdomain_index(m.first);
  }
  return {volume, interface};
}

// GSM keeps every subdomain (its volume to 2%) and the interface between them (its vertices
// slide on it), inverts nothing and lifts the worst cells
template <class C3T3, class Domain>
void check_two_subdomains(const char* name, C3T3& c3t3, const Domain& domain)
{
  const auto before = subdomains_and_interface(c3t3);
  const GSM::Mesh_quality_statistics q0 = GSM::mesh_quality_statistics(c3t3);
  CGAL::gsm_optimize_mesh_3(c3t3, domain);
  const auto after = subdomains_and_interface(c3t3);
  const GSM::Mesh_quality_statistics q = GSM::mesh_quality_statistics(c3t3);
  std::printf("  %s (%zu vertices): subdomains", name, c3t3.triangulation().number_of_vertices());
  for(const auto& d : after.first)
    std::printf(" %d: volume %.4f -> %.4f,", d.first, before.first.count(d.first) ? before.first.at(d.first) : 0.,
                d.second);
  std::printf(" interface facets %zu -> %zu; min dihedral %.2f -> %.2f, tets under 30 deg %zu -> %zu\n",
              before.second, after.second, q0.min_dihedral_angle, q.min_dihedral_angle, q0.n_min_dihedral_below[2],
              q.n_min_dihedral_below[2]);
  VVM_CHECK(complex_is_valid(c3t3));
  VVM_CHECK(before.first.size() == 2 && after.first.size() == 2);
  for(const auto& d : before.first)
    VVM_CHECK(after.first.count(d.first) && std::abs(after.first.at(d.first) / d.second - 1) < 0.02);
  VVM_CHECK(before.second > 0 && after.second > before.second / 2);
  VVM_CHECK(q.number_of_inverted_cells == 0);
  VVM_CHECK(q.min_dihedral_angle > 20 && q.min_dihedral_angle > q0.min_dihedral_angle + 5);
  VVM_CHECK(q.n_min_dihedral_below[2] < q0.n_min_dihedral_below[2] / 4);
}

// subdomain 2: a torus (radii 0.6 and 0.25) inside subdomain 1, the ball of radius 1.2
int torus_in_ball(const K::Point_3& p)
{
  const double d = std::sqrt(p.x() * p.x() + p.y() * p.y()) - 0.6;
  if(d * d + p.z() * p.z() < 0.25 * 0.25) return 2;
  return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() < 1.44 ? 1 : 0;
}

template <class C3T3, class Domain>
C3T3 mesh_two_subdomains(const Domain& domain, double size)
{
  typedef typename C3T3::Triangulation Tr;
  CGAL::Mesh_criteria_3<Tr> criteria(params::edge_size = size, params::facet_angle = 25, params::facet_size = size,
                                     params::facet_distance = size / 8, params::cell_radius_edge_ratio = 3,
                                     params::cell_size = size);
  CGAL::get_default_random() = CGAL::Random(3);
  return CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
}

// every facet between two cells of different subdomains (outside: 0) in the complex, no other
template <class C3T3>
bool surface_separates_subdomains(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  const auto label = [&](const typename C3T3::Cell_handle& c) {
    return tr.is_infinite(c) || !c3t3.is_in_complex(c) ? 0 : int(c3t3.subdomain_index(c));
  };
  for(auto f : tr.finite_facets())
    if(c3t3.is_in_complex(f) != (label(f.first) != label(f.first->neighbor(f.second)))) return false;
  return true;
}

// the convex hull is locally convex at each of its edges, hence convex: the vertex across an
// edge of a hull facet is not beyond it (an infinite cell with it for its infinite vertex is
// not positive)
bool hull_is_convex(const Implicit_tr& tr)
{
  for(auto c : tr.all_cell_handles()) {
    if(!tr.is_infinite(c)) continue;
    const int inf = c->index(tr.infinite_vertex());
    for(int j = 0; j < 4; ++j) {
      if(j == inf) continue;
      const auto n = c->neighbor(j);
      std::array<Bare_point, 4> t;
      for(int k = 0; k < 4; ++k)
        t[k] = k == inf ? n->vertex(n->index(c))->point().point() : c->vertex(k)->point().point();
      if(CGAL::orientation(t[0], t[1], t[2], t[3]) == CGAL::POSITIVE) return false;
    }
  }
  return true;
}

// surface vertex removal by edge collapse on make_mesh_3 meshes whose surface is three times
// finer than their interior, where the cells under 30 degrees are wedges between surface
// edges and the interior vertices across them: a torus, and the torus-in-ball (two
// subdomains, so interface vertices too, and the outer ball on the convex hull). Each
// collapse takes one surface vertex and two
// surface facets and moves no vertex (those left on the surface stay where they were, with
// their dimension); the surface stays closed, each facet in the complex exactly where two
// subdomains meet, both subdomains and their interface there, the complex valid, the
// counters and the running sum exact, and the mesh's smallest angle never lower
template <class Domain>
void check_surface_vertex_collapses(const char* name, const Domain& domain, double facet_size)
{
  CGAL::Mesh_criteria_3<Implicit_tr> criteria(params::facet_angle = 25, params::facet_size = facet_size,
                                              params::facet_distance = facet_size / 10,
                                              params::cell_radius_edge_ratio = 3, params::cell_size = 3 * facet_size);
  CGAL::get_default_random() = CGAL::Random(1);
  Implicit_c3t3 c3t3 = CGAL::make_mesh_3<Implicit_c3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  const GSM::internal::Metric_field metric = GSM::internal::Metric_field::uniform(GSM::internal::estimated_edge_length(c3t3));
  const GSM::internal::Mesh_energy<Implicit_c3t3> energy{c3t3, metric, GSM::Shape_matching_energy::GSM};
  auto [sum, count] = energy.total();
  const GSM::internal::Vertex_smoother<Implicit_c3t3, Domain> smoother(c3t3, &domain, energy, false);
  GSM::internal::Surface_vertex_collapse<Implicit_c3t3, Domain> collapses(
      c3t3, energy, sum, count, smoother, GSM::internal::Angle_penalty::for_bound(30));
  std::map<Vertex_handle, std::pair<Bare_point, int>> before;
  for(auto v : c3t3.triangulation().finite_vertex_handles()) before[v] = {v->point().point(), c3t3.in_dimension(v)};
  const std::size_t facets_before = c3t3.number_of_facets_in_complex();
  const auto parts_before = subdomains_and_interface(c3t3);
  const GSM::Mesh_quality_statistics q0 = GSM::mesh_quality_statistics(c3t3);
  std::vector<std::array<Vertex_handle, 4>> bad;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    if(energy.min_dihedral_angle(c) < 30) bad.push_back({{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}});
  std::set<Vertex_handle> removed;
  for(const auto& t : bad) {
    if(std::any_of(t.begin(), t.end(), [&](const Vertex_handle& v) { return removed.count(v) != 0; })) continue;
    Implicit_tr::Cell_handle c;
    int i, j, k, l;
    Vertex_handle v;
    if(!c3t3.triangulation().is_cell(t[0], t[1], t[2], t[3], c, i, j, k, l)) continue;
    std::map<Vertex_handle, double> bounds; // how far the surface may be from the boundary
    for(int m = 0; m < 4; ++m) bounds[c->vertex(m)] = smoother.boundary_bound(c->vertex(m));
    if(collapses.try_collapse_cell(c, v)) {
      VVM_CHECK_EQUAL(before.at(v).second, 2);
      removed.insert(v);
      // v, a point of the surface, is as near the boundary as the boundary may be to the surface
      VVM_CHECK(bounds.at(v) > 0);
      VVM_CHECK(distance_to_boundary(c3t3, before.at(v).first) <= bounds.at(v) * (1 + 1e-9));
    }
  }
  const std::size_t done = removed.size();
  const GSM::Mesh_quality_statistics q = GSM::mesh_quality_statistics(c3t3);
  std::cerr << "    " << name << ": " << done << " surface vertex removals for " << bad.size()
            << " cells under 30 degrees; min dihedral " << q0.min_dihedral_angle << " -> " << q.min_dihedral_angle
            << ", tets under 30 " << q0.n_min_dihedral_below[2] << " -> " << q.n_min_dihedral_below[2] << "\n";
  VVM_CHECK(done > 0);
  VVM_CHECK_EQUAL(c3t3.triangulation().number_of_vertices(), before.size() - done);
  VVM_CHECK_EQUAL(c3t3.number_of_facets_in_complex(), facets_before - 2 * done);
  VVM_CHECK(complex_is_valid(c3t3) && surface_is_closed(c3t3) && surface_separates_subdomains(c3t3));
  VVM_CHECK(hull_is_convex(c3t3.triangulation()));
  for(auto v : c3t3.triangulation().finite_vertex_handles()) {
    VVM_CHECK(before.count(v) == 1 && removed.count(v) == 0);
    VVM_CHECK(before.at(v).first == v->point().point() && before.at(v).second == c3t3.in_dimension(v));
  }
  const auto parts = subdomains_and_interface(c3t3);
  VVM_CHECK(parts.first.size() == parts_before.first.size() && (parts.second > 0) == (parts_before.second > 0));
  const auto total = energy.total();
  VVM_CHECK_EQUAL(count, total.second);
  VVM_CHECK_CLOSE(sum, total.first, 1e-9 * total.first);
  VVM_CHECK(q.min_dihedral_angle >= q0.min_dihedral_angle - 1e-9);
  VVM_CHECK_EQUAL(q.number_of_inverted_cells, std::size_t(0));
}

void test_surface_vertex_collapse()
{
  {
    // the distance to the boundary: on a hand-made complex, a tetrahedron with one facet on the surface
    Implicit_c3t3 t;
    Implicit_tr& tr = t.triangulation();
    const Vertex_handle a = insert(tr, 0, 0, 0), b = insert(tr, 1, 0, 0), c = insert(tr, 0, 1, 0), d = insert(tr, 0, 0, 1);
    Implicit_tr::Cell_handle cell;
    int i, j, k, l;
    VVM_CHECK(tr.is_cell(a, b, c, d, cell, i, j, k, l));
    t.add_to_complex(cell, l, std::make_pair(1, 0)); // the facet (a, b, c), at z = 0
    VVM_CHECK_CLOSE(distance_to_boundary(t, Bare_point(0.25, 0.25, 2)), 2., 1e-12);
    VVM_CHECK_CLOSE(distance_to_boundary(t, Bare_point(2, 0, 0)), 1., 1e-12);
  }
  check_surface_vertex_collapses("torus", implicit_domain(torus_function), 0.05);
  const Implicit_domain labelled(std::function<int(const K::Point_3&)>(torus_in_ball), K::Sphere_3(CGAL::ORIGIN, 2.),
                                 params::relative_error_bound = 1e-6);
  check_surface_vertex_collapses("torus-in-ball", labelled, 0.06);
}

void test_several_subdomains()
{
  // a labelled implicit domain
  const Implicit_domain implicit(std::function<int(const K::Point_3&)>(torus_in_ball), K::Sphere_3(CGAL::ORIGIN, 2.),
                                 params::relative_error_bound = 1e-6);
  Implicit_c3t3 labelled = mesh_two_subdomains<Implicit_c3t3>(implicit, 0.12);
  check_two_subdomains("labelled implicit domain", labelled, implicit);

  // the same on a triangulation made for the concurrent mesher
#ifdef CGAL_LINKED_WITH_TBB
  typedef CGAL::Mesh_triangulation_3<Implicit_domain, CGAL::Default, CGAL::Parallel_tag>::type Parallel_tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Parallel_tr> Parallel_c3t3;
  Parallel_c3t3 parallel = mesh_two_subdomains<Parallel_c3t3>(implicit, 0.12);
  check_two_subdomains("Parallel_tag triangulation", parallel, implicit);
#endif

  // a labelled 3D image: a ball of label 1 around a smaller ball of label 2, 0.05 voxels
  const std::size_t n = 52;
  const double voxel = 0.05, centre = 0.5 * voxel * double(n - 1);
  CGAL::Image_3 image(_createImage(n, n, n, 1, voxel, voxel, voxel, 1, WK_FIXED, SGN_UNSIGNED));
  unsigned char* label = static_cast<unsigned char*>(image.data());
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        const double r = Eigen::Vector3d(voxel * double(i) - centre, voxel * double(j) - centre,
                                         voxel * double(k) - centre).norm();
        label[(k * n + j) * n + i] = r < 0.45 ? 2 : r < 1.1 ? 1 : 0;
      }
  const Implicit_domain image_domain = Implicit_domain::create_labeled_image_mesh_domain(image);
  Implicit_c3t3 from_image = mesh_two_subdomains<Implicit_c3t3>(image_domain, 0.12);
  check_two_subdomains("labelled 3D image", from_image, image_domain);

  // a polyhedral complex: the box [-1,1]^3 (subdomain 1) around the box [-0.4,0.4]^3
  // (subdomain 2), their edges protected as features
  typedef CGAL::Polyhedral_complex_mesh_domain_3<K> Complex_domain;
  typedef Complex_domain::Polyhedron Polyhedron;
  typedef CGAL::Mesh_triangulation_3<Complex_domain>::type Complex_tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Complex_tr, Complex_domain::Corner_index,
                                                  Complex_domain::Curve_index> Complex_c3t3;
  auto box = [](double a) {
    Polyhedron p;
    CGAL::make_hexahedron(K::Point_3(-a, -a, -a), K::Point_3(a, -a, -a), K::Point_3(a, a, -a), K::Point_3(-a, a, -a),
                          K::Point_3(-a, a, a), K::Point_3(-a, -a, a), K::Point_3(a, -a, a), K::Point_3(a, a, a), p);
    CGAL::Polygon_mesh_processing::triangulate_faces(p);
    if(!CGAL::Polygon_mesh_processing::is_outward_oriented(p)) CGAL::Polygon_mesh_processing::reverse_face_orientations(p);
    return p;
  };
  const std::vector<Polyhedron> patches = {box(1.), box(0.4)};
  const std::vector<std::pair<int, int>> sides = {{1, 0}, {2, 1}}; // (inside, outside) of each
  Complex_domain boxes(patches.begin(), patches.end(), sides.begin(), sides.end());
  boxes.detect_features();
  Complex_c3t3 from_boxes = mesh_two_subdomains<Complex_c3t3>(boxes, 0.15);
  check_two_subdomains("polyhedral complex", from_boxes, boxes);
}

// gsm_optimize_triangulation_3 on a Delaunay triangulation of random points in a
// box: the hull stays as it is, no cell inverts, the slivers go.
void test_bare_triangulation()
{
  typedef CGAL::Delaunay_triangulation_3<K> Delaunay;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<K::Point_3> points;
  // the boundary: a 9 x 9 grid on each face of [-1,1]^3; inside: random points
  for(int axis = 0; axis < 3; ++axis)
    for(int side = -1; side <= 1; side += 2)
      for(int i = 0; i <= 8; ++i)
        for(int j = 0; j <= 8; ++j) {
          double c[3];
          c[axis] = side;
          c[(axis + 1) % 3] = -1 + 0.25 * i;
          c[(axis + 2) % 3] = -1 + 0.25 * j;
          points.emplace_back(c[0], c[1], c[2]);
        }
  for(int i = 0; i < 1500; ++i) points.emplace_back(0.95 * u(rng), 0.95 * u(rng), 0.95 * u(rng));
  Delaunay tr(points.begin(), points.end());
  auto hull = [&tr]() {
    std::set<std::array<K::Point_3, 3>> facets;
    for(auto c : tr.all_cell_handles()) {
      if(!tr.is_infinite(c)) continue;
      const int i = c->index(tr.infinite_vertex());
      std::array<K::Point_3, 3> f;
      for(int k = 0; k < 3; ++k) f[k] = c->vertex((i + 1 + k) & 3)->point();
      std::sort(f.begin(), f.end());
      facets.insert(f);
    }
    return facets;
  };
  const auto hull_before = hull();
  const GSM::Mesh_quality_statistics before = GSM::triangulation_quality_statistics(tr);
  const Delaunay copy = tr;
  const CGAL::Mesh_optimization_return_code code = CGAL::gsm_optimize_triangulation_3(tr);
  const GSM::Mesh_quality_statistics after = GSM::triangulation_quality_statistics(tr);
  std::printf("  bare Delaunay triangulation: min dihedral %.2f -> %.2f, tets under 20 deg %zu -> %zu\n",
              before.min_dihedral_angle, after.min_dihedral_angle, before.n_min_dihedral_below[1],
              after.n_min_dihedral_below[1]);
  VVM_CHECK(code != CGAL::TIME_LIMIT_REACHED);
  VVM_CHECK(tr.tds().is_valid());
  // splits add interior vertices only (the hull is checked below)
  VVM_CHECK(tr.number_of_vertices() >= copy.number_of_vertices() &&
            tr.number_of_vertices() < copy.number_of_vertices() * 11 / 10);
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
  VVM_CHECK(hull() == hull_before);
  VVM_CHECK(after.min_dihedral_angle > before.min_dihedral_angle + 5);
  VVM_CHECK(after.n_min_dihedral_below[1] * 10 < before.n_min_dihedral_below[1]);

  // errors leave it unchanged
  Delaunay flat;
  bool thrown = false;
  try { CGAL::gsm_optimize_triangulation_3(flat); } catch(const std::invalid_argument&) { thrown = true; }
  VVM_CHECK(thrown);
}

} // namespace

int main()
{
  test_energies();
  test_flip_2_3_and_3_2();
  test_flip_4_4();
  test_boundary_peel();
  test_boundary_cap_peel();
  test_polygon_triangulation();
  test_edge_removal();
  test_least_norm_point_of_hull();
  test_angle_penalty_and_edge_removal_for_quality();
  test_multi_face_removal();
  test_flip_pass_on_sphere();
  test_edge_split_on_sphere();
  test_vertex_collapse();
  test_surface_edge_split();
  test_surface_vertex_collapse();
  test_sphere_run();
  test_bad_input();
  test_cube_with_features();
  test_boundary_fidelity_on_a_crease();
  test_boundary_fidelity_bounds_on_sphere();
  test_threads_fields_and_boundary();
  test_input_mesh_sizing();
  test_several_subdomains();
  test_bare_triangulation();
  return vvm_test::report("test_gsm_optimizer");
}
