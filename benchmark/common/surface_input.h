// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The drivers' surface inputs: the polyhedral domain types they mesh, a closed
// surface read as a user error when it is not one, and the two-sided Hausdorff
// distance between a mesh's boundary and the input surface.

#ifndef VVM_BENCHMARK_SURFACE_INPUT_H
#define VVM_BENCHMARK_SURFACE_INPUT_H

#include "command_line.h"

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
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace vvm_benchmark {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Polyhedral_domain;
typedef CGAL::Mesh_triangulation_3<Polyhedral_domain, CGAL::Default, CGAL::Sequential_tag>::type Polyhedral_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Polyhedral_tr, Polyhedral_domain::Corner_index,
                                                Polyhedral_domain::Curve_index>
    Polyhedral_c3t3;

// Reads a closed surface enclosing a volume and returns the volume; anything else is an
// Input_error. A self-intersecting surface is refused, or, with `program` given, meshed
// after a warning (make_mesh_3 meshes what its inside test sees).
inline double read_surface_input(const std::string& path, Surface_mesh& sm, const char* program = nullptr)
{
  try {
    bool self_intersects = false;
    const double volume =
        CGAL::GSM_mesh_optimization::IO::read_closed_surface(path, sm, program ? &self_intersects : nullptr);
    if(self_intersects)
      std::cerr << program << ": warning: the surface in '" << path
                << "' self-intersects; make_mesh_3 meshes the inside its ray-parity test sees, which may not "
                   "be the intended one (--refuse-self-intersecting to stop here)\n";
    return volume;
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
}

// the grid spacing that samples about 200,000 points on `surface` (deterministic sampling)
inline double distance_sampling_spacing(const Surface_mesh& surface)
{
  return std::sqrt(CGAL::Polygon_mesh_processing::area(surface) / 2e5);
}

// the Hausdorff distance from a to b, and from b to a, sampled on a grid of the given spacing
template <class TriangleMesh>
std::pair<double, double> two_sided_distance(const TriangleMesh& a, const TriangleMesh& b, double spacing)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const auto np = PMP::parameters::use_grid_sampling(true).grid_spacing(spacing);
  return {PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(a, b, np),
          PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(b, a, np)};
}

// the two-sided Hausdorff distance between a complex's boundary facets and `surface`
template <class C3T3>
std::function<double(const C3T3&)> boundary_distance_to(const Surface_mesh& surface)
{
  const double spacing = distance_sampling_spacing(surface);
  return [&surface, spacing](const C3T3& c3t3) {
    Surface_mesh boundary;
    CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, boundary);
    const std::pair<double, double> d = two_sided_distance(boundary, surface, spacing);
    return (std::max)(d.first, d.second);
  };
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_SURFACE_INPUT_H
