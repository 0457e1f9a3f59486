// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_optimizers on a closed triangle surface read from a file, or on the
// built-in cube: Polyhedral_mesh_domain_with_features_3, sharp features
// protected when --features-angle > 0 (the cube's by default).

#include "box_surface.h"
#include "comparison_driver.h"
#include "surface_input.h"
#include "thickness_sizing.h"

#include <cmath>

namespace vvm_benchmark {
namespace {

typedef Polyhedral_domain Domain;
typedef Polyhedral_c3t3 C3T3;
namespace PMP = CGAL::Polygon_mesh_processing;

// --sizing thickness: the sizing field of the surface's walls and gaps, and of the faces between
// its protected feature curves
Target_field input_sizing(const Options& options, const Surface_mesh& surface, double features_angle)
{
  if(options.sizing != "thickness") return Target_field("");
  const Thickness_sizing<K> sizing =
      thickness_sizing<K>(surface, options.cells_across, options.gradation, features_angle);
  const auto field = sizing.field;
  return Target_field::input_sizing(
      "thickness", [field](const Eigen::Vector3d& x) { return (*field)(K::Point_3(x.x(), x.y(), x.z())); },
      sizing.median_size);
}

} // namespace

int run_polyhedral_domain(const Options& options)
{
  const bool is_cube = options.input == "cube";
  Surface_mesh surface = is_cube ? box_surface<Surface_mesh>(-1, 1) : Surface_mesh();
  const double volume = is_cube ? std::abs(PMP::volume(surface))
                                : read_surface_input(options.input, surface,
                                                     options.refuse_self_intersecting ? nullptr : "compare_optimizers");
  Domain domain(surface);
  const double angle = options.features_angle >= 0 ? options.features_angle : (is_cube ? 60. : 0.);
  if(angle > 0) domain.detect_features(angle);
  Comparison_driver<C3T3, Domain> driver(options, is_cube ? "cube" : GSM::IO::file_stem(options.input), domain,
                                         volume, input_sizing(options, surface, angle));
  driver.set_boundary_distance(boundary_distance_to<C3T3>(surface));
  return driver.run();
}

} // namespace vvm_benchmark
