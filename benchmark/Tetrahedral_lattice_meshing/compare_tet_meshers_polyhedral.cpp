// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_tet_meshers on a closed triangle surface read from a file, or on the
// built-in cube ([-1,1]^3; [0.1,1.1]^3 with --field fig4.8, [1,11]^3 with
// fig4.9): Polyhedral_mesh_domain_with_features_3, sharp edges by angle.

#include "tet_mesher_comparison.h"

#include "box_surface.h"
#include "surface_input.h"
#include "thickness_sizing.h"

#include <cmath>

namespace vvm_tet_benchmark {
namespace {

typedef vvm_benchmark::K K;
typedef vvm_benchmark::Surface_mesh Surface_mesh;
typedef vvm_benchmark::Polyhedral_domain Domain;
typedef vvm_benchmark::Polyhedral_c3t3 C3T3;
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
    volume = vvm_benchmark::read_surface_input(options.input, surface);
  }
  Domain domain(surface);
  const double angle = options.features_angle >= 0 ? options.features_angle : (is_cube ? 60. : 0.);
  if(angle > 0) domain.detect_features(angle);
  const auto distance = vvm_benchmark::boundary_distance_to<C3T3>(surface);
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
