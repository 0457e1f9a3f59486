// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_optimizers on a closed triangle surface read from a file, or on the
// built-in cube: Polyhedral_mesh_domain_with_features_3, sharp features
// protected when --features-angle > 0 (the cube's by default).

#include "box_surface.h"
#include "comparison_driver.h"
#include "thickness_sizing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vvm_benchmark {
namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
namespace PMP = CGAL::Polygon_mesh_processing;

// a closed surface enclosing a volume; anything else is an Input_error. A self-intersecting
// one (which make_mesh_3 meshes) gets a warning, or is refused if asked
double read_closed_surface(const std::string& path, Surface_mesh& sm, bool refuse_self_intersecting)
{
  try {
    bool self_intersects = false;
    const double volume = GSM::IO::read_closed_surface(path, sm, refuse_self_intersecting ? nullptr : &self_intersects);
    if(self_intersects)
      std::cerr << "compare_optimizers: warning: the surface in '" << path
                << "' self-intersects; make_mesh_3 meshes the inside its ray-parity test sees, which may not "
                   "be the intended one (--refuse-self-intersecting to stop here)\n";
    return volume;
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
}

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
  const double volume = is_cube ? std::abs(PMP::volume(surface)) : read_closed_surface(options.input, surface, options.refuse_self_intersecting);
  Domain domain(surface);
  const double angle = options.features_angle >= 0 ? options.features_angle : (is_cube ? 60. : 0.);
  if(angle > 0) domain.detect_features(angle);
  Comparison_driver<C3T3, Domain> driver(options, is_cube ? "cube" : GSM::IO::file_stem(options.input), domain,
                                         volume, input_sizing(options, surface, angle));
  // two-sided, sampled on a grid of about 200,000 points on each surface (deterministic)
  const double spacing = std::sqrt(PMP::area(surface) / 2e5);
  driver.set_boundary_distance([&surface, spacing](const C3T3& c3t3) {
    Surface_mesh boundary;
    CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, boundary);
    const auto np = PMP::parameters::use_grid_sampling(true).grid_spacing(spacing);
    return (std::max)(PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(boundary, surface, np),
                      PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(surface, boundary, np));
  });
  return driver.run();
}

} // namespace vvm_benchmark
