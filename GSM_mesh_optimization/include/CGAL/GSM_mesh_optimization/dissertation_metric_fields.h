// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sizing and metric fields of the dissertation's adaptive and anisotropic
// GSM experiments (section 3.4.4, Fig. 3.7-3.9), for the examples and the
// benchmark. Each is a callable for the `sizing_field` / `metric_field` named
// parameters of `gsm_optimize_mesh_3()`.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_DISSERTATION_METRIC_FIELDS_H
#define CGAL_GSM_MESH_OPTIMIZATION_DISSERTATION_METRIC_FIELDS_H

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace dissertation {

/*!
 * \ingroup PkgGSMMeshOptimizationRef
 * Fig. 3.7, the unit ball: target edge length `h(x) = 0.025 + 0.2 | |x| - 0.5 |`
 * (the metric `s^2 I` with `s = 1/h`): small edges on the sphere of radius 0.5.
 */
inline double adaptive_sphere_sizing(const Eigen::Vector3d& x)
{
  return 0.025 + 0.2 * std::abs(x.norm() - 0.5);
}

/*!
 * \ingroup PkgGSMMeshOptimizationRef
 * Fig. 3.8, the unit ball: `M(x) = Q diag(100, 10, 10) Q^T` where the first
 * column of the rotation `Q` is the unit vector along `(2 cos 6x, 1, 0)`; the
 * other two columns share one eigenvalue, so `M = 10 I + 90 d d^T`. Edges are
 * `sqrt(10)` times shorter along `d`, which turns with `x`.
 */
inline Eigen::Matrix3d anisotropic_sphere_metric(const Eigen::Vector3d& x)
{
  const Eigen::Vector3d d = Eigen::Vector3d(2 * std::cos(6 * x.x()), 1, 0).normalized();
  return 10 * Eigen::Matrix3d::Identity() + 90 * d * d.transpose();
}

/*!
 * \ingroup PkgGSMMeshOptimizationRef
 * Fig. 3.9, a cube: `M(x) = L^2` with `L = diag(1 / (0.025 + 0.2 (1 - e^{-u})), 5, 5)`,
 * where `u` in [0, 1] is the abscissa relative to the cube (`u = (x - x_min) / (x_max - x_min)`;
 * the default cube is [-1, 1]^3). Edges along x grow from 0.025 to 0.151, against 0.2 along y and z.
 */
inline Eigen::Matrix3d anisotropic_cube_metric(const Eigen::Vector3d& x, double x_min = -1., double x_max = 1.)
{
  const double u = std::clamp((x.x() - x_min) / (x_max - x_min), 0., 1.);
  const Eigen::Vector3d L(1. / (0.025 + 0.2 * (1. - std::exp(-u))), 5., 5.);
  return L.cwiseProduct(L).asDiagonal();
}

} // namespace dissertation
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_DISSERTATION_METRIC_FIELDS_H
