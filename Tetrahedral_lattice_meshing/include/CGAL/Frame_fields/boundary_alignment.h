// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How well a generated cross field follows the boundary, seen three ways: for
// each boundary facet, the angle between its normal and the nearest axis of the
// field there (what a mesher gets); for each boundary vertex, the angle between
// the direction it was constrained to and the nearest axis of its frame (the
// constraint); for each facet, the angle between its normal and the mean of its
// vertices' normals (how much the surface turns between vertices, which no field
// with one frame per vertex on the vertex normals can follow).

#ifndef CGAL_FRAME_FIELDS_BOUNDARY_ALIGNMENT_H
#define CGAL_FRAME_FIELDS_BOUNDARY_ALIGNMENT_H

#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/Frame_fields/internal/Boundary_vertex_normals.h>
#include <CGAL/Frame_fields/internal/L4_spherical_harmonics.h>
#include <CGAL/VVM/internal/Eigen_conversion.h>

#include <CGAL/number_type_config.h> // CGAL_PI

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
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

  /// the vertices of the boundary facets, in increasing order
  std::vector<std::size_t> boundary_vertices;
  /// per boundary vertex, the angle between its constrained axis
  /// (`Generated_cross_field_3::constrained_axes`) and the nearest axis of its frame;
  /// 90 for a boundary vertex left without a constrained axis (all its facets degenerate)
  std::vector<double> vertex_errors;
  double vertex_mean = 0; ///< mean of `vertex_errors`
  double vertex_p95 = 0;  ///< their 95th percentile
  double vertex_max = 0;  ///< the largest

  /// per boundary facet, the angle between its normal and the mean of its three vertices'
  /// normals (each the principal direction of the area-weighted normals of its boundary
  /// facets; the facet's own normal for a vertex of a sharp edge): the error a field
  /// aligned with the vertex normals and interpolated perfectly would still have
  std::vector<double> facet_normal_deviations;
  double normal_deviation_mean = 0; ///< area-weighted mean of `facet_normal_deviations`
  double normal_deviation_p95 = 0;  ///< their 95th percentile
};

namespace internal {

// the 95th percentile and the largest of `x` (0 if empty)
inline std::pair<double, double> p95_and_max(std::vector<double> x)
{
  if(x.empty()) return {0., 0.};
  std::sort(x.begin(), x.end());
  return {x[std::min(x.size() - 1, std::size_t(std::ceil(0.95 * double(x.size()))) - 1)], x.back()};
}

} // namespace internal

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
  auto xyz = [&](std::size_t v) { return VVM::internal::to_eigen(points[v]); };
  Boundary_alignment_statistics s;
  const std::size_t n = g.boundary_facets.size();
  s.facet_errors.resize(n);
  s.facet_areas.resize(n);
  internal::parallel_for_each_index(n, [&](std::size_t i) {
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
  std::tie(s.p95, s.max) = internal::p95_and_max(s.facet_errors);

  // the vertex view: the constraint alone
  for(const auto& f : g.boundary_facets) s.boundary_vertices.insert(s.boundary_vertices.end(), f.begin(), f.end());
  std::sort(s.boundary_vertices.begin(), s.boundary_vertices.end());
  s.boundary_vertices.erase(std::unique(s.boundary_vertices.begin(), s.boundary_vertices.end()),
                            s.boundary_vertices.end());
  for(std::size_t v : s.boundary_vertices) {
    const Eigen::Vector3d a = v < g.constrained_axes.size() ? g.constrained_axes[v] : Eigen::Vector3d::Zero();
    s.vertex_errors.push_back(a.squaredNorm() > 0 ? angle_to_nearest_axis(frames[v], a) : 90.);
  }
  for(double e : s.vertex_errors) s.vertex_mean += e;
  if(!s.vertex_errors.empty()) s.vertex_mean /= double(s.vertex_errors.size());
  std::tie(s.vertex_p95, s.vertex_max) = internal::p95_and_max(s.vertex_errors);

  // the geometry: facet normals against their vertices' normals
  const std::vector<Eigen::Matrix3d> normal_tensor = internal::boundary_normal_tensors(frames.size(), g.boundary_facets, xyz);
  std::vector<Eigen::Vector3d> vertex_normal(frames.size(), Eigen::Vector3d::Zero());
  std::vector<char> on_sharp_edge(frames.size(), 0);
  for(const auto& e : g.feature_edges) on_sharp_edge[e[0]] = on_sharp_edge[e[1]] = 1;
  for(std::size_t v : s.boundary_vertices) vertex_normal[v] = internal::principal_normal(normal_tensor[v]);
  s.facet_normal_deviations.resize(n);
  for(std::size_t i = 0; i < n; ++i) {
    const auto& f = g.boundary_facets[i];
    const Eigen::Vector3d N = (xyz(f[1]) - xyz(f[0])).cross(xyz(f[2]) - xyz(f[0]));
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for(std::size_t v : f) // a vertex of a sharp edge has no normal: it counts as the facet's
      m += on_sharp_edge[v] ? Eigen::Vector3d(N.normalized()) : (vertex_normal[v].dot(N) < 0 ? -1. : 1.) * vertex_normal[v];
    const double c = N.norm() > 0 && m.norm() > 0 ? std::abs(N.normalized().dot(m.normalized())) : 1.;
    s.facet_normal_deviations[i] = std::acos((std::min)(1., c)) * 180 / CGAL_PI;
    s.normal_deviation_mean += s.facet_normal_deviations[i] * s.facet_areas[i];
  }
  if(area > 0) s.normal_deviation_mean /= area;
  s.normal_deviation_p95 = internal::p95_and_max(s.facet_normal_deviations).first;
  return s;
}

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_BOUNDARY_ALIGNMENT_H
