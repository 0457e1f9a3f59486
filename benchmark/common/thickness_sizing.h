// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// --sizing thickness of the benchmark drivers: the thickness sizing field of the
// input surface, and its median over the surface (the size a scale factor of 1
// gives, typically).

#ifndef VVM_BENCHMARK_THICKNESS_SIZING_H
#define VVM_BENCHMARK_THICKNESS_SIZING_H

#include <CGAL/Local_thickness_3.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Thickness_sizing_field_3.h>

#include <iostream>
#include <memory>
#include <unordered_map>

namespace vvm_benchmark {

template <class K>
struct Thickness_sizing
{
  std::shared_ptr<const CGAL::Thickness_sizing_field_3<K>> field;
  double median_size = 0; // over the surface samples
};

/// the thickness sizing of `surface`, `cells_across` cells across, graded by `gradation`, with
/// the faces between the edges sharper than `features_angle` (if positive: the domain's
/// protected features) as narrow as they are; one line on std::cerr (samples, median size,
/// grid, time)
template <class K, class TriangleMesh>
Thickness_sizing<K> thickness_sizing(const TriangleMesh& surface, double cells_across, double gradation,
                                     double features_angle = 0)
{
  CGAL::Real_timer timer;
  timer.start();
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  std::unordered_map<edge_descriptor, bool> is_feature;
  if(features_angle > 0)
    CGAL::Polygon_mesh_processing::detect_sharp_edges(surface, features_angle,
                                                      boost::make_assoc_property_map(is_feature));
  const CGAL::Local_thickness_3<K> thickness(
      surface, CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(is_feature)));
  Thickness_sizing<K> r;
  r.field = std::make_shared<const CGAL::Thickness_sizing_field_3<K>>(
      thickness, CGAL::VVM::parameters::cells_across(cells_across, CGAL::VVM::parameters::gradation(gradation)));
  timer.stop();
  r.median_size = r.field->typical_size();
  std::cerr << "thickness sizing: " << thickness.samples().size() << " samples, "
            << thickness.feature_samples().size() << " on feature curves, median size " << r.median_size
            << ", grid spacing " << r.field->grid_spacing() << " (" << timer.time() << " s)\n";
  return r;
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_THICKNESS_SIZING_H
