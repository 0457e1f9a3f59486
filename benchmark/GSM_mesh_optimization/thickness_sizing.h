// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// --sizing thickness of the benchmark drivers: the thickness sizing field of the
// input surface, and its median over the surface (the size a scale factor of 1
// gives, typically).

#ifndef VVM_BENCHMARK_THICKNESS_SIZING_H
#define VVM_BENCHMARK_THICKNESS_SIZING_H

#include <CGAL/Local_thickness_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Thickness_sizing_field_3.h>

#include <iostream>
#include <memory>

namespace vvm_benchmark {

template <class K>
struct Thickness_sizing
{
  std::shared_ptr<const CGAL::Thickness_sizing_field_3<K>> field;
  double median_size = 0; // over the surface samples
};

/// the thickness sizing of `surface`, `cells_across` cells across, graded by `gradation`; one
/// line on std::cerr (samples, median size, grid, time)
template <class K, class TriangleMesh>
Thickness_sizing<K> thickness_sizing(const TriangleMesh& surface, double cells_across, double gradation)
{
  CGAL::Real_timer timer;
  timer.start();
  const CGAL::Local_thickness_3<K> thickness(surface);
  Thickness_sizing<K> r;
  r.field = std::make_shared<const CGAL::Thickness_sizing_field_3<K>>(
      thickness, CGAL::VVM::parameters::cells_across(cells_across, CGAL::VVM::parameters::gradation(gradation)));
  timer.stop();
  r.median_size = r.field->typical_size();
  std::cerr << "thickness sizing: " << thickness.samples().size() << " samples, median size " << r.median_size
            << ", grid spacing " << r.field->grid_spacing() << " (" << timer.time() << " s)\n";
  return r;
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_THICKNESS_SIZING_H
