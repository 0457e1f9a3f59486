// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parallel parts of the three packages on small inputs, with several threads: what the
// sanitizer stage (test/sanitizers/) runs under AddressSanitizer and UndefinedBehaviorSanitizer,
// and a VVM_SANITIZE=thread build under ThreadSanitizer, besides the unit tests. Each check also
// asserts what the part must give: CGAL's concurrent make_mesh_3 followed by GSM's parallel
// sweeps (a valid complex, no inverted cell, the smallest angle raised); the particle engine
// (particles inside the domain, the count near the one asked for); the cross-field smoothing
// (unit frames, orthogonal); the hex-dominant candidates (cells of the tets' volume, no inverted
// cell).

// first: Mesh_3 includes TBB headers the others rely on
#include <CGAL/make_mesh_3.h>

#include "vvm_test.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/Constant_frame_field_3.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/gsm_optimize_mesh_3.h>
#include <CGAL/lattice_particles_3.h>
#include <CGAL/tets_to_hex_dominant.h>

#include <cmath>
#include <functional>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
namespace GSM = CGAL::GSM_mesh_optimization;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace params = CGAL::parameters;

double sphere_function(const Point& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

Domain sphere_domain()
{
  return Domain::create_implicit_mesh_domain(std::function<double(const Point&)>(sphere_function),
                                             K::Sphere_3(CGAL::ORIGIN, 1.21), params::relative_error_bound = 1e-6);
}

template <class Triangulation>
CGAL::Mesh_criteria_3<Triangulation> criteria(double size)
{
  return CGAL::Mesh_criteria_3<Triangulation>(params::facet_angle = 25, params::facet_size = size,
                                              params::facet_distance = size / 10,
                                              params::cell_radius_edge_ratio = 3, params::cell_size = size);
}

template <class Complex>
bool positively_oriented(const Complex& c3t3)
{
  const auto& tr = c3t3.triangulation();
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    if(CGAL::orientation(tr.point(c, 0).point(), tr.point(c, 1).point(), tr.point(c, 2).point(),
                         tr.point(c, 3).point()) != CGAL::POSITIVE)
      return false;
  return tr.tds().is_valid(); // (GSM's moves leave it no longer regular)
}

// a torus (label 2) inside a ball (label 1)
int torus_in_ball(const Point& p)
{
  const double d = std::sqrt(p.x() * p.x() + p.y() * p.y()) - 0.6;
  if(d * d + p.z() * p.z() < 0.25 * 0.25) return 2;
  return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() < 1.44 ? 1 : 0;
}

// CGAL's concurrent refinement (Parallel_tag) of a labelled domain with two subdomains, then
// GSM's parallel sweeps with two threads
void test_concurrent_mesh_3_and_gsm()
{
#ifdef CGAL_LINKED_WITH_TBB
  typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Parallel_tag>::type Parallel_tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Parallel_tr> Parallel_c3t3;
  const Domain domain(std::function<int(const Point&)>(torus_in_ball), K::Sphere_3(CGAL::ORIGIN, 2.),
                      params::relative_error_bound = 1e-6);
  CGAL::get_default_random() = CGAL::Random(3);
  Parallel_c3t3 c3t3 = CGAL::make_mesh_3<Parallel_c3t3>(domain, criteria<Parallel_tr>(0.15), params::no_perturb(),
                                                        params::no_exude());
  const double before = GSM::mesh_quality_statistics(c3t3).min_dihedral_angle;
  CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::number_of_threads(2));
  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  std::cout << "Parallel_tag make_mesh_3 of a torus in a ball + GSM, 2 threads: " << c3t3.number_of_cells_in_complex()
            << " cells, min dihedral " << before << " -> " << after.min_dihedral_angle << "\n";
  VVM_CHECK(c3t3.number_of_cells_in_complex() > 100);
  VVM_CHECK(positively_oriented(c3t3));
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
  VVM_CHECK(after.min_dihedral_angle > before + 5);
#else
  VVM_CHECK(!"built without TBB");
#endif
}

// the particle engine's parallel energy and gradient with two threads
void test_particles()
{
  const Domain domain = sphere_domain();
  const auto particles = CGAL::lattice_particles_3(domain, CGAL::Frame_fields::Constant_frame_field_3<K>(),
      TLM::parameters::number_of_particles(std::size_t(800), TLM::parameters::number_of_threads(2)));
  std::size_t outside = 0;
  for(const Point& p : particles.points) outside += sphere_function(p) > 1e-6 ? 1 : 0;
  std::cout << "lattice_particles_3, 2 threads: " << particles.size() << " particles, energy " << particles.energy
            << "\n";
  VVM_CHECK(particles.size() > 600 && particles.size() < 1000);
  VVM_CHECK_EQUAL(outside, std::size_t(0));
  VVM_CHECK(std::isfinite(particles.energy));
}

// the cross field's parallel smoothing, with TBB's threads
void test_cross_field()
{
  const Domain domain = sphere_domain();
  CGAL::get_default_random() = CGAL::Random(1);
  const C3T3 c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria<Tr>(0.3), params::no_perturb(), params::no_exude());
  const auto generated = CGAL::Frame_fields::generate_cross_field_3(c3t3);
  double worst = 0;
  for(const auto& T : generated.field.frames())
    worst = (std::max)(worst, (T.transpose() * T - Eigen::Matrix3d::Identity()).norm());
  std::cout << "generate_cross_field_3: " << generated.field.frames().size() << " frames, |T^T T - I| <= " << worst
            << "\n";
  VVM_CHECK(!generated.field.frames().empty());
  VVM_CHECK(worst < 1e-9);
}

// the hex-dominant candidates' parallel search and scoring with two threads
void test_hex_candidates()
{
  CGAL::Random random(7);
  std::vector<Point> points;
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j)
      for(int k = 0; k < 6; ++k)
        points.emplace_back(i + random.get_double(-0.05, 0.05), j + random.get_double(-0.05, 0.05),
                            k + random.get_double(-0.05, 0.05));
  const CGAL::Delaunay_triangulation_3<K> tr(points.begin(), points.end());
  double tets_volume = 0;
  for(auto c : tr.finite_cell_handles()) tets_volume += tr.tetrahedron(c).volume();
  const auto mesh = CGAL::tets_to_hex_dominant(tr, TLM::parameters::number_of_threads(2));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh);
  std::cout << "tets_to_hex_dominant, 2 threads: " << s.number_of_hexahedra << " hexahedra of " << mesh.cells.size()
            << " cells, volume " << s.total_volume << " of " << tets_volume << "\n";
  VVM_CHECK(s.number_of_hexahedra > 0);
  VVM_CHECK_EQUAL(s.number_of_inverted_cells, std::size_t(0));
  // hexahedra and prisms with slightly non-planar faces: their volume is not exactly their tets'
  VVM_CHECK(std::abs(s.total_volume - tets_volume) < 0.01 * tets_volume);
}

} // namespace

int main(int argc, char** argv)
{
  return vvm_test::run(argc, argv, "test_parallel_parts", {
      {"concurrent_mesh_3_and_gsm", test_concurrent_mesh_3_and_gsm},
      {"particles", test_particles},
      {"cross_field", test_cross_field},
      {"hex_candidates", test_hex_candidates}});
}
