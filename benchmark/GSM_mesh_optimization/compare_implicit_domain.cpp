// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_optimizers on the built-in implicit domains: the unit sphere, a torus
// (radii 1 and 0.4) and the torus inside a ball of radius 2 (two subdomains, an
// interface), meshed through Labeled_mesh_domain_3.

#include "comparison_driver.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <cmath>
#include <functional>

namespace vvm_benchmark {
namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;

const double torus_R = 1.0, torus_r = 0.4;

double sphere_function(const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

double torus_function(const K::Point_3& p)
{
  const double d = std::sqrt(p.x() * p.x() + p.y() * p.y()) - torus_R;
  return d * d + p.z() * p.z() - torus_r * torus_r;
}

// subdomain 1: the ball of radius 2 around the torus; subdomain 2: the torus
int torus_in_ball_label(const K::Point_3& p)
{
  if(torus_function(p) < 0) return 2;
  return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() < 4. ? 1 : 0;
}

} // namespace

bool is_implicit_domain_name(const std::string& name)
{
  return name == "sphere" || name == "torus" || name == "torus-in-ball";
}

int run_implicit_domain(const Options& options)
{
  namespace params = CGAL::parameters;
  if(options.input == "torus-in-ball") {
    Domain domain(std::function<int(const K::Point_3&)>(torus_in_ball_label), K::Sphere_3(CGAL::ORIGIN, 9.),
                  params::relative_error_bound = 1e-6);
    Comparison_driver<C3T3, Domain> driver(options, options.input, domain, 4. / 3. * CGAL_PI * 8.);
    return driver.run();
  }
  const bool sphere = options.input == "sphere";
  std::function<double(const K::Point_3&)> f = sphere ? sphere_function : torus_function;
  const double volume = sphere ? 4. / 3. * CGAL_PI : 2. * CGAL_PI * CGAL_PI * torus_R * torus_r * torus_r;
  Domain domain = Domain::create_implicit_mesh_domain(f, K::Sphere_3(CGAL::ORIGIN, 4.),
                                                      params::relative_error_bound = 1e-6);
  Comparison_driver<C3T3, Domain> driver(options, options.input, domain, volume);
  return driver.run();
}

} // namespace vvm_benchmark
