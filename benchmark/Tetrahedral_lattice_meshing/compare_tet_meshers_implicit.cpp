// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_tet_meshers on the built-in implicit domains, through
// Labeled_mesh_domain_3: the unit sphere, and the torus of Table 4.3 about the
// y axis (radii 1 and 0.4), the axis of the rotation field rotation-y.

#include "tet_mesher_comparison.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace vvm_tet_benchmark {
namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

const double torus_R = 1.0, torus_r = 0.4;

double sphere_function(const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

double torus_function(const K::Point_3& p)
{
  const double d = std::hypot(p.x(), p.z()) - torus_R;
  return d * d + p.y() * p.y() - torus_r * torus_r;
}

// the exact distances to the surfaces, and the surfaces sampled at about `n` points
double distance_to_surface(bool sphere, const K::Point_3& p)
{
  if(sphere) return std::abs(std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()) - 1.);
  return std::abs(std::hypot(std::hypot(p.x(), p.z()) - torus_R, p.y()) - torus_r);
}

std::vector<K::Point_3> surface_samples(bool sphere, int n)
{
  std::vector<K::Point_3> samples;
  const int m = int(std::sqrt(double(n)));
  for(int i = 0; i < m; ++i)
    for(int j = 0; j < m; ++j) {
      const double u = 2 * CGAL_PI * (i + 0.5) / m, v = (j + 0.5) / m;
      if(sphere) { // uniform on the sphere: z uniform in [-1, 1]
        const double z = 2 * v - 1, r = std::sqrt(1 - z * z);
        samples.emplace_back(r * std::cos(u), r * std::sin(u), z);
      } else {
        const double w = 2 * CGAL_PI * v, rho = torus_R + torus_r * std::cos(w);
        samples.emplace_back(rho * std::sin(u), torus_r * std::sin(w), rho * std::cos(u));
      }
    }
  return samples;
}

} // namespace

bool is_implicit_domain_name(const std::string& name) { return name == "sphere" || name == "torus"; }

int run_implicit_domain(const Options& options)
{
  namespace P = CGAL::parameters;
  const bool sphere = options.input == "sphere";
  std::function<double(const K::Point_3&)> f = sphere ? sphere_function : torus_function;
  const double volume = sphere ? 4. / 3. * CGAL_PI : 2. * CGAL_PI * CGAL_PI * torus_R * torus_r * torus_r;
  Domain domain = Domain::create_implicit_mesh_domain(f, K::Sphere_3(CGAL::ORIGIN, 4.), P::relative_error_bound = 1e-6);
  const std::vector<K::Point_3> samples = surface_samples(sphere, 200000);
  // two-sided: the complex's boundary grid-sampled against the exact surface, and the
  // exact surface's samples against the boundary
  auto distance = [sphere, &samples](const C3T3& c3t3) {
    Surface_mesh boundary;
    CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, boundary);
    std::vector<K::Point_3> points;
    PMP::sample_triangle_mesh(boundary, std::back_inserter(points),
                              PMP::parameters::use_grid_sampling(true).grid_spacing(0.005));
    double d = 0;
    for(const K::Point_3& p : points) d = (std::max)(d, distance_to_surface(sphere, p));
    return (std::max)(d, PMP::max_distance_to_triangle_mesh<CGAL::Parallel_if_available_tag>(samples, boundary));
  };
  Tet_mesher_comparison<C3T3, Domain> comparison(options, options.input, domain, volume, distance);
  return comparison.run();
}

} // namespace vvm_tet_benchmark
