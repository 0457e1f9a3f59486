// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How well a generated cross field follows the boundary: for each boundary
// facet, the angle between its normal and the nearest axis of the field there.

#ifndef CGAL_FRAME_FIELDS_BOUNDARY_ALIGNMENT_H
#define CGAL_FRAME_FIELDS_BOUNDARY_ALIGNMENT_H

#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/Frame_fields/internal/L4_spherical_harmonics.h>
#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h> // internal::to_eigen

#include <CGAL/number_type_config.h> // CGAL_PI

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * Boundary alignment errors of a cross field, in degrees.
 */
struct Boundary_alignment_statistics
{
  /// per boundary facet (in the order of `Generated_cross_field_3::boundary_facets`)
  std::vector<double> facet_errors;
  /// per boundary facet, its area
  std::vector<double> facet_areas;
  double mean = 0;  ///< area-weighted mean
  double p95 = 0;   ///< 95th percentile over facets (each facet counted once)
  double max = 0;   ///< largest
};

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// the angle (degrees, in [0, 54.7]) between the direction `n` and the nearest of the
/// three axes (columns, any length) of `T`
inline double angle_to_nearest_axis(const Eigen::Matrix3d& T, const Eigen::Vector3d& n)
{
  double best = 0;
  for(int a = 0; a < 3; ++a)
    best = (std::max)(best, std::abs(T.col(a).normalized().dot(n.normalized())));
  return std::acos((std::min)(1., best)) * 180 / CGAL_PI;
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * measures the alignment error of each boundary facet of `g`: the angle between the
 * facet's normal and the nearest axis of the field at the facet, the field there being
 * the frame nearest to the mean of the spherical-harmonic vectors of its three vertices
 * (the field interpolated linearly in SH, as the generator smooths it).
 */
template <class GeomTraits>
Boundary_alignment_statistics boundary_alignment_statistics(const Generated_cross_field_3<GeomTraits>& g)
{
  const internal::L4_frames& sh = internal::L4_frames::instance();
  const auto& points = g.field.points();
  const auto& frames = g.field.frames();
  std::vector<internal::SH_vector> c(frames.size());
  for(std::size_t v = 0; v < frames.size(); ++v) {
    Eigen::Matrix3d R = frames[v];
    R.colwise().normalize();
    c[v] = sh.frame(R);
  }
  auto xyz = [&](std::size_t v) { return GSM_mesh_optimization::internal::to_eigen(points[v]); };
  Boundary_alignment_statistics s;
  const std::size_t n = g.boundary_facets.size();
  s.facet_errors.resize(n);
  s.facet_areas.resize(n);
  internal::for_each_index(n, [&](std::size_t i) {
    const auto& f = g.boundary_facets[i];
    const Eigen::Vector3d N = (xyz(f[1]) - xyz(f[0])).cross(xyz(f[2]) - xyz(f[0]));
    s.facet_areas[i] = 0.5 * N.norm();
    s.facet_errors[i] =
        N.norm() > 0 ? angle_to_nearest_axis(sh.nearest_frame(c[f[0]] + c[f[1]] + c[f[2]]), N) : 0.;
  });
  double area = 0;
  for(std::size_t i = 0; i < n; ++i) {
    s.mean += s.facet_errors[i] * s.facet_areas[i];
    area += s.facet_areas[i];
  }
  if(area > 0) s.mean /= area;
  if(n > 0) {
    std::vector<double> sorted = s.facet_errors;
    std::sort(sorted.begin(), sorted.end());
    s.p95 = sorted[std::min(n - 1, std::size_t(std::ceil(0.95 * double(n))) - 1)];
    s.max = sorted.back();
  }
  return s;
}

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_BOUNDARY_ALIGNMENT_H
