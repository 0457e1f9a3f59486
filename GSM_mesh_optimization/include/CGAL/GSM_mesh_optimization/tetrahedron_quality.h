// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Element quality measures of a single tetrahedron, optionally measured in
// the "imagined" space of an anisotropic metric (the tet mapped by a 3x3
// matrix B). Used by every VVM package and by the benchmarks.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_TETRAHEDRON_QUALITY_H
#define CGAL_GSM_MESH_OPTIMIZATION_TETRAHEDRON_QUALITY_H

#include <CGAL/number_utils.h>
#include <CGAL/VVM/internal/Eigen_conversion.h>

#include <Eigen/Core>
#include <Eigen/Geometry> // cross()

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

using VVM::internal::to_eigen;

} // namespace internal

/*!
 * \ingroup PkgGSMMeshOptimizationQuality
 * Quality measures of one tetrahedron `(p0, p1, p2, p3)`.
 *
 * - `dihedral_angles[k]`: interior dihedral angle, in degrees, at the edge
 *   `edge_vertices(k)`; the edges are ordered (0,1), (0,2), (0,3), (1,2), (1,3), (2,3).
 *   Dihedral angles do not depend on orientation: an inverted tetrahedron has
 *   the angles of its mirror image.
 * - `volume`: signed volume, positive when `(p0, p1, p2, p3)` is positively oriented
 *   (CGAL's `orientation()` convention).
 * - `radius_ratio`: 3 r_in / r_circ, 1 for the regular tetrahedron, 0 for a flat one;
 *   negative for an inverted tetrahedron (the sign of `volume`).
 * - `edge_radius_ratio`: sqrt(6) e_min / (4 r_circ), 1 for the regular tetrahedron.
 * - `condition`: 3 sqrt(6) V / (2 l_rms A_rms), the mean ratio of the tetrahedron,
 *   1 for the regular one, signed like `volume`.
 */
struct Tetrahedron_quality
{
  std::array<double, 6> dihedral_angles{{0, 0, 0, 0, 0, 0}};
  double volume = 0;
  double radius_ratio = 0;
  double edge_radius_ratio = 0;
  double condition = 0;

  double min_dihedral_angle() const
  { return *std::min_element(dihedral_angles.begin(), dihedral_angles.end()); }
  double max_dihedral_angle() const
  { return *std::max_element(dihedral_angles.begin(), dihedral_angles.end()); }
  /// true if the tetrahedron is inverted or flat (non-positive signed volume)
  bool is_inverted() const { return !(volume > 0); }

  /// the two local vertex indices of the edge at which `dihedral_angles[k]` is measured
  static std::array<int, 2> edge_vertices(int k)
  {
    static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    return {{e[k][0], e[k][1]}};
  }
};

/*!
 * \ingroup PkgGSMMeshOptimizationQuality
 * computes the quality measures of the tetrahedron with vertices `p[0..3]` (in double precision).
 */
inline Tetrahedron_quality
tetrahedron_quality(const std::array<Eigen::Vector3d, 4>& p)
{
  constexpr double rad_to_deg = 57.295779513082320876798154814105;
  Tetrahedron_quality q;

  const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double det = a.dot(b.cross(c)); // 6 V
  q.volume = det / 6.;

  // Area vectors of the faces opposite each vertex, all pointing outwards for a
  // positively oriented tet (all inwards otherwise, which leaves angles unchanged).
  std::array<Eigen::Vector3d, 4> n;
  n[0] = (p[2] - p[1]).cross(p[3] - p[1]);
  n[1] = c.cross(b);
  n[2] = a.cross(c);
  n[3] = b.cross(a);
  std::array<double, 4> area;
  double area_sum = 0, sq_area_sum = 0;
  for(int i = 0; i < 4; ++i) {
    area[i] = 0.5 * n[i].norm();
    area_sum += area[i];
    sq_area_sum += area[i] * area[i];
  }

  // The dihedral angle at edge (i,j) is the angle between the two faces that
  // contain the edge, i.e. the faces opposite the two other vertices k and l:
  // theta = pi - angle(n_k, n_l).
  for(int e = 0; e < 6; ++e) {
    const std::array<int, 2> ij = Tetrahedron_quality::edge_vertices(e);
    int kl[2], m = 0;
    for(int v = 0; v < 4; ++v)
      if(v != ij[0] && v != ij[1]) kl[m++] = v;
    const double denom = 4. * area[kl[0]] * area[kl[1]];
    if(denom > 0) {
      const double cos_theta = std::clamp(-n[kl[0]].dot(n[kl[1]]) / denom, -1., 1.);
      q.dihedral_angles[e] = std::acos(cos_theta) * rad_to_deg;
    } // a face of zero area: the angle is taken as 0 (the tet is degenerate)
  }

  std::array<Eigen::Vector3d, 6> edges{{a, b, c, p[2] - p[1], p[3] - p[1], p[3] - p[2]}};
  double min_sq_edge = edges[0].squaredNorm(), sq_edge_sum = 0;
  for(const Eigen::Vector3d& e : edges) {
    min_sq_edge = (std::min)(min_sq_edge, e.squaredNorm());
    sq_edge_sum += e.squaredNorm();
  }

  if(det == 0 || area_sum == 0)
    return q; // flat tetrahedron: all ratios stay 0

  // circumcenter offset from p0: (|a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b)) / (2 det)
  const Eigen::Vector3d num = a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a)
                            + c.squaredNorm() * a.cross(b);
  const double r_circ = num.norm() / (2. * std::abs(det));
  const double r_in = 3. * std::abs(q.volume) / area_sum;
  const double sign = det > 0 ? 1. : -1.;

  q.radius_ratio = sign * 3. * r_in / r_circ;
  q.edge_radius_ratio = std::sqrt(6. * min_sq_edge) / (4. * r_circ);
  const double l_rms = std::sqrt(sq_edge_sum / 6.);
  const double a_rms = std::sqrt(sq_area_sum / 4.);
  q.condition = 3. * std::sqrt(6.) * q.volume / (2. * l_rms * a_rms);
  return q;
}

/*!
 * \ingroup PkgGSMMeshOptimizationQuality
 * the smallest dihedral angle, in degrees, of the tetrahedron with vertices `p[0..3]`:
 * `tetrahedron_quality(p).min_dihedral_angle()` with one arc cosine in place of six and
 * none of the other measures (the optimizers evaluate it millions of times).
 */
inline double tetrahedron_min_dihedral_angle(const std::array<Eigen::Vector3d, 4>& p)
{
  constexpr double rad_to_deg = 57.295779513082320876798154814105;
  const Eigen::Vector3d a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  // the faces' area vectors, as in tetrahedron_quality(): the angle at edge (i, j) is
  // pi minus the angle between those of the faces opposite the two other vertices
  const std::array<Eigen::Vector3d, 4> n{{(p[2] - p[1]).cross(p[3] - p[1]), c.cross(b), a.cross(c), b.cross(a)}};
  std::array<double, 4> length;
  for(int i = 0; i < 4; ++i) length[i] = n[i].norm();
  double largest_cos = -1;
  for(int e = 0; e < 6; ++e) {
    const std::array<int, 2> ij = Tetrahedron_quality::edge_vertices(e);
    int kl[2], m = 0;
    for(int v = 0; v < 4; ++v)
      if(v != ij[0] && v != ij[1]) kl[m++] = v;
    // the same products as tetrahedron_quality()'s (4 * half lengths): the same angles
    const double denom = 4. * (0.5 * length[kl[0]]) * (0.5 * length[kl[1]]);
    if(!(denom > 0)) return 0; // a face of zero area: the angle is taken as 0
    largest_cos = (std::max)(largest_cos, std::clamp(-n[kl[0]].dot(n[kl[1]]) / denom, -1., 1.));
  }
  return std::acos(largest_cos) * rad_to_deg;
}

/*!
 * \ingroup PkgGSMMeshOptimizationQuality
 * computes the quality measures of the tetrahedron `(p0, p1, p2, p3)` mapped
 * by the matrix `B` (anisotropic quality: the tetrahedron as seen in the
 * isotropic "imagined" space of the metric `B^T B`).
 * `Point_3` is any CGAL point type with `x()`, `y()`, `z()`.
 */
template <class Point_3>
Tetrahedron_quality
tetrahedron_quality(const Point_3& p0, const Point_3& p1, const Point_3& p2, const Point_3& p3,
                    const Eigen::Matrix3d& B = Eigen::Matrix3d::Identity())
{
  using internal::to_eigen;
  return tetrahedron_quality({{B * to_eigen(p0), B * to_eigen(p1), B * to_eigen(p2), B * to_eigen(p3)}});
}

} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_TETRAHEDRON_QUALITY_H
