// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_tet_meshers on a closed triangle surface read from a file, or on the
// built-in cube ([-1,1]^3; [0.1,1.1]^3 with --field fig4.8, [1,11]^3 with
// fig4.9): Polyhedral_mesh_domain_with_features_3, sharp edges by angle.

#include "tet_mesher_comparison.h"

#include "box_surface.h"
#include "thickness_sizing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>

#include <algorithm>
#include <cmath>

namespace vvm_tet_benchmark {
namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
namespace PMP = CGAL::Polygon_mesh_processing;

} // namespace

int run_polyhedral_domain(const Options& options)
{
  const bool is_cube = options.input == "cube";
  Surface_mesh surface;
  double volume = 0;
  if(is_cube) {
    const double lo = options.field == "fig4.8" ? 0.1 : options.field == "fig4.9" ? 1. : -1.;
    const double hi = options.field == "fig4.8" ? 1.1 : options.field == "fig4.9" ? 11. : 1.;
    surface = vvm_benchmark::box_surface<Surface_mesh>(lo, hi);
    volume = std::abs(PMP::volume(surface));
  } else {
    try {
      volume = GSM::IO::read_closed_surface(options.input, surface);
    } catch(const std::invalid_argument& e) {
      throw Input_error(e.what());
    }
  }
  Domain domain(surface);
  const double angle = options.features_angle >= 0 ? options.features_angle : (is_cube ? 60. : 0.);
  if(angle > 0) domain.detect_features(angle);
  // two-sided, sampled on a grid of about 200,000 points on each surface (deterministic)
  const double spacing = std::sqrt(PMP::area(surface) / 2e5);
  auto distance = [&surface, spacing](const C3T3& c3t3) {
    Surface_mesh boundary;
    CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, boundary);
    const auto np = PMP::parameters::use_grid_sampling(true).grid_spacing(spacing);
    return (std::max)(PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(boundary, surface, np),
                      PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(surface, boundary, np));
  };
  std::function<double(const K::Point_3&)> size;
  if(options.sizing == "thickness") {
    const auto sizing = vvm_benchmark::thickness_sizing<K>(surface, 3., 0.3, angle);
    const auto field = sizing.field;
    const double median = sizing.median_size;
    size = [field, median](const K::Point_3& p) { return (*field)(p) / median; };
  }
  Tet_mesher_comparison<C3T3, Domain> comparison(options, is_cube ? "cube" : GSM::IO::file_stem(options.input),
                                                 domain, volume, distance, size);
  return comparison.run();
}

} // namespace vvm_tet_benchmark
