// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tests of gsm_optimize_mesh_3 share: the complexes they build (hand-made
// and make_mesh_3 ones on implicit, polyhedral and labelled domains) and the checks
// of a complex. Each test program includes it once.

#ifndef VVM_GSM_TEST_SUPPORT_H
#define VVM_GSM_TEST_SUPPORT_H

#include "vvm_test.h"

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

// the polyhedral cube [-1,1]^3 with its 12 edges and 8 corners protected
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Cube_domain;
typedef CGAL::Mesh_triangulation_3<Cube_domain>::type Cube_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Cube_tr, Cube_domain::Corner_index, Cube_domain::Curve_index> Cube_c3t3;

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

} // namespace

#endif // VVM_GSM_TEST_SUPPORT_H
