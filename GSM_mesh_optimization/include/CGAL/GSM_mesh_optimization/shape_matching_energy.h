// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shape matching energies of simplices (dissertation ch. 3.2) and their
// analytic gradient and Hessian with respect to one vertex (eq. 3.17-3.19).
//
// All energies are measured against a regular template simplex of edge
// length 1: the caller maps the simplex into the isotropic space of its
// metric first (by B = M^{1/2}, or by I / h for a sizing h), which is also how
// the template edge length enters.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_SHAPE_MATCHING_ENERGY_H
#define CGAL_GSM_MESH_OPTIMIZATION_SHAPE_MATCHING_ENERGY_H

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <limits>

namespace CGAL {
namespace GSM_mesh_optimization {

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * The energy that `gsm_optimize_mesh_3()` minimizes.
 */
enum class Shape_matching_energy
{
  GSM, ///< Gradient-based Shape Matching, trace(D^T D) (eq. 3.8): punishes every small height
  ESM  ///< Edge-based Shape Matching, trace(J^T J) (eq. 3.3): blind to slivers, for comparison
};

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * The value, gradient and Hessian of an energy with respect to one vertex.
 */
struct Energy_derivatives
{
  double value = 0;
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();

  Energy_derivatives& operator+=(const Energy_derivatives& o)
  {
    value += o.value;
    gradient += o.gradient;
    hessian += o.hessian;
    return *this;
  }
  /// the derivatives of `E(B x)` from those of `E(y)` at `y = B x`, for a constant `B`
  Energy_derivatives mapped_back(const Eigen::Matrix3d& B) const
  {
    Energy_derivatives d;
    d.value = value;
    d.gradient = B.transpose() * gradient;
    d.hessian = B.transpose() * hessian * B;
    return d;
  }
};

namespace internal {

// E = c p / q, from p, q and their derivatives (eq. 3.17-3.19)
inline Energy_derivatives quotient_derivatives(double c, double p, const Eigen::Vector3d& dp,
                                               const Eigen::Matrix3d& hp, double q,
                                               const Eigen::Vector3d& dq, const Eigen::Matrix3d& hq)
{
  Energy_derivatives d;
  if(!(q > 0)) {
    d.value = std::numeric_limits<double>::infinity();
    return d;
  }
  const double iq = 1. / q;
  d.value = c * p * iq;
  d.gradient = c * (dp * iq - p * iq * iq * dq);
  d.hessian = c * (hp * iq - iq * iq * (dp * dq.transpose() + dq * dp.transpose()) - p * iq * iq * hq +
                   2. * p * iq * iq * iq * dq * dq.transpose());
  return d;
}

// |n|^2 / 4 for the triangle (v, x, y) with v moving: n = (x - v) x (y - v)
// is affine in v, d|n|^2/dv = 2 (x - y) x n, d2|n|^2/dv2 = 2 (|x-y|^2 I - (x-y)(x-y)^T).
inline void squared_area_derivatives(const Eigen::Vector3d& v, const Eigen::Vector3d& x,
                                     const Eigen::Vector3d& y, double& a2, Eigen::Vector3d& da2,
                                     Eigen::Matrix3d& ha2)
{
  const Eigen::Vector3d n = (x - v).cross(y - v);
  const Eigen::Vector3d d = x - y;
  a2 = 0.25 * n.squaredNorm();
  da2 = 0.5 * d.cross(n);
  ha2 = 0.5 * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

} // namespace internal

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * GSM energy of the tetrahedron `(v0, v1, v2, v3)` against the regular
 * tetrahedron of edge 1: `(1/18) sum_i |S_i|^2 / V^2` (eq. 3.8); 3 for the
 * regular tetrahedron of edge 1, infinite for a flat one. Orientation-free.
 */
inline double gsm_tetrahedron_energy(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                     const Eigen::Vector3d& v2, const Eigen::Vector3d& v3)
{
  const Eigen::Vector3d a = v1 - v0, b = v2 - v0, c = v3 - v0;
  const double six_v = a.dot(b.cross(c));
  if(six_v == 0) return std::numeric_limits<double>::infinity();
  const double sum_s2 = 0.25 * (b.cross(c).squaredNorm() + c.cross(a).squaredNorm() +
                                a.cross(b).squaredNorm() + (v2 - v1).cross(v3 - v1).squaredNorm());
  return 2. * sum_s2 / (six_v * six_v); // (1/18) * sum / (six_v / 6)^2
}

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * GSM energy of the tetrahedron `(v, a, b, c)` and its derivatives with respect to `v`.
 */
inline Energy_derivatives gsm_tetrahedron_energy_derivatives(const Eigen::Vector3d& v,
                                                             const Eigen::Vector3d& a,
                                                             const Eigen::Vector3d& b,
                                                             const Eigen::Vector3d& c)
{
  // p = sum of squared face areas; the face (a, b, c) does not move
  double p = 0.25 * (b - a).cross(c - a).squaredNorm();
  Eigen::Vector3d dp = Eigen::Vector3d::Zero();
  Eigen::Matrix3d hp = Eigen::Matrix3d::Zero();
  const Eigen::Vector3d* faces[3][2] = {{&a, &b}, {&b, &c}, {&c, &a}};
  for(const auto& f : faces) {
    double s2;
    Eigen::Vector3d ds2;
    Eigen::Matrix3d hs2;
    internal::squared_area_derivatives(v, *f[0], *f[1], s2, ds2, hs2);
    p += s2;
    dp += ds2;
    hp += hs2;
  }
  // q = V^2 with 6V = m . (v - a), m = -(b - a) x (c - a)
  const Eigen::Vector3d m = -(b - a).cross(c - a);
  const double six_v = m.dot(v - a);
  const double q = six_v * six_v / 36.;
  const Eigen::Vector3d dq = six_v * m / 18.;
  const Eigen::Matrix3d hq = m * m.transpose() / 18.;
  return internal::quotient_derivatives(1. / 18., p, dp, hp, q, dq, hq);
}

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * GSM energy of the triangle `(v, a, b)` (2-simplex, eq. 3.6):
 * `(1/8) sum |e|^2 / A^2`, 2 for the equilateral triangle of edge 1, and its derivatives
 * with respect to `v`.
 */
inline Energy_derivatives gsm_triangle_energy_derivatives(const Eigen::Vector3d& v,
                                                          const Eigen::Vector3d& a,
                                                          const Eigen::Vector3d& b)
{
  const double p = (v - a).squaredNorm() + (v - b).squaredNorm() + (a - b).squaredNorm();
  const Eigen::Vector3d dp = 2. * (v - a) + 2. * (v - b);
  const Eigen::Matrix3d hp = 4. * Eigen::Matrix3d::Identity();
  double q;
  Eigen::Vector3d dq;
  Eigen::Matrix3d hq;
  internal::squared_area_derivatives(v, a, b, q, dq, hq);
  return internal::quotient_derivatives(1. / 8., p, dp, hp, q, dq, hq);
}

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * GSM energy of the segment `(v, a)` (1-simplex, eq. 3.10): `1 / |v - a|^2`, and its
 * derivatives with respect to `v`.
 */
inline Energy_derivatives gsm_segment_energy_derivatives(const Eigen::Vector3d& v,
                                                         const Eigen::Vector3d& a)
{
  return internal::quotient_derivatives(1., 1., Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(),
                                        (v - a).squaredNorm(), 2. * (v - a),
                                        2. * Eigen::Matrix3d::Identity());
}

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * ESM energy of the tetrahedron `(v, a, b, c)` against the regular tetrahedron
 * of edge 1: `(1/2) sum |e_ij|^2` (eq. 3.3), and its derivatives with respect to `v`.
 */
inline Energy_derivatives esm_tetrahedron_energy_derivatives(const Eigen::Vector3d& v,
                                                             const Eigen::Vector3d& a,
                                                             const Eigen::Vector3d& b,
                                                             const Eigen::Vector3d& c)
{
  Energy_derivatives d;
  d.value = 0.5 * ((v - a).squaredNorm() + (v - b).squaredNorm() + (v - c).squaredNorm() +
                   (a - b).squaredNorm() + (b - c).squaredNorm() + (c - a).squaredNorm());
  d.gradient = (v - a) + (v - b) + (v - c);
  d.hessian = 3. * Eigen::Matrix3d::Identity();
  return d;
}

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * The energy of the tetrahedron `(v0, v1, v2, v3)`; infinite for a flat one with GSM.
 */
inline double tetrahedron_energy(Shape_matching_energy energy, const Eigen::Vector3d& v0,
                                 const Eigen::Vector3d& v1, const Eigen::Vector3d& v2,
                                 const Eigen::Vector3d& v3)
{
  if(energy == Shape_matching_energy::GSM) return gsm_tetrahedron_energy(v0, v1, v2, v3);
  return esm_tetrahedron_energy_derivatives(v0, v1, v2, v3).value;
}

/*!
 * \ingroup PkgGSMMeshOptimizationEnergy
 * The energy of the tetrahedron `(v, a, b, c)` and its derivatives with respect to `v`.
 */
inline Energy_derivatives tetrahedron_energy_derivatives(Shape_matching_energy energy,
                                                         const Eigen::Vector3d& v,
                                                         const Eigen::Vector3d& a,
                                                         const Eigen::Vector3d& b,
                                                         const Eigen::Vector3d& c)
{
  if(energy == Shape_matching_energy::GSM) return gsm_tetrahedron_energy_derivatives(v, a, b, c);
  return esm_tetrahedron_energy_derivatives(v, a, b, c);
}

} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_SHAPE_MATCHING_ENERGY_H
