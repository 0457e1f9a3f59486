// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Gaussian Hole Kernel (dissertation eq. 4.1, 4.2, 4.6): one positive
// Gaussian at a particle and a negative one at each hole of its lattice
// one-ring, so that neighbours settle in the holes.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_GAUSSIAN_HOLE_KERNEL_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_GAUSSIAN_HOLE_KERNEL_H

#include <CGAL/Tetrahedral_lattice_meshing/Lattice.h>

#include <Eigen/Core>

#include <cmath>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * returns the Gaussian Hole Kernel of `lattice` at the offset `u` between two particles in
 * the imagined space, in units of \f$ l^* \f$:
 * \f[ e(u) = w\, e^{-|u|^2 / 2\sigma^2} - \frac{1}{N_{or}} \sum_{k=1}^{N_{or}} e^{-|u - h_k|^2 / 2\sigma^2}, \f]
 * \f$ h_k \f$ the one-ring offsets, \f$ w \f$ the positive weight (1 for BCC and FCC).
 * Gaussians further than \f$ 6\sigma \f$ from `u` (under \f$ 1.6\cdot 10^{-8} \f$) are skipped.
 * If `de_du` is not null, it receives the gradient \f$ \partial e / \partial u \f$.
 *
 * \param lattice the lattice, whose one-ring gives the holes
 * \param u the offset between the two particles
 * \param sigma the kernel width in units of \f$ l^* \f$ (`lattice.sigma` by default)
 * \param de_du if not null, receives the gradient
 */
inline double gaussian_hole_kernel(const Lattice& lattice, const Eigen::Vector3d& u, double sigma,
                                   Eigen::Vector3d* de_du = nullptr)
{
  const double inv_s2 = 1. / (sigma * sigma), cutoff = 36. * sigma * sigma;
  double e = 0;
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  const double u2 = u.squaredNorm();
  if(u2 < cutoff) {
    const double k = lattice.positive_weight * std::exp(-0.5 * u2 * inv_s2);
    e += k;
    g -= k * inv_s2 * u;
  }
  const double hole_weight = 1. / double(lattice.number_of_holes());
  for(const Eigen::Vector3d& h : lattice.one_ring) {
    const Eigen::Vector3d d = u - h;
    const double d2 = d.squaredNorm();
    if(d2 >= cutoff) continue;
    const double k = hole_weight * std::exp(-0.5 * d2 * inv_s2);
    e -= k;
    g += k * inv_s2 * d;
  }
  if(de_du) *de_du = g;
  return e;
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * returns the energy \f$ E_{ij} \f$ of eq. 4.2 between particles at \f$ p_i \f$ and
 * \f$ p_j \f$ (`v` \f$ = p_i - p_j \f$) under the frame \f$ T_{ij} \f$ of their midpoint,
 * given by its inverse `B`, and with `grad_i` not null, its gradient with respect to
 * \f$ p_i \f$: \f$ B^T \nabla e(u) / l^* \f$ with \f$ u = B v / l^* \f$ (the gradient with respect
 * to \f$ p_j \f$ is its opposite; \f$ E_{ij} = E_{ji} \f$). This is the exact gradient for a
 * frozen \f$ B \f$; the force of eq. 4.3 maps the isotropic force by \f$ T \f$ instead of
 * \f$ B^T \f$, which agrees with it for orthonormal frames (cross fields).
 *
 * \param lattice the lattice, whose one-ring gives the holes
 * \param B the inverse of the frame at the midpoint
 * \param v the vector \f$ p_i - p_j \f$
 * \param l_star the target edge length \f$ l^* \f$
 * \param sigma the kernel width in units of \f$ l^* \f$
 * \param grad_i if not null, receives the gradient with respect to \f$ p_i \f$
 */
inline double gaussian_hole_pair_energy(const Lattice& lattice, const Eigen::Matrix3d& B, const Eigen::Vector3d& v,
                                        double l_star, double sigma, Eigen::Vector3d* grad_i = nullptr)
{
  const Eigen::Vector3d u = B * v / l_star;
  if(!grad_i) return gaussian_hole_kernel(lattice, u, sigma);
  Eigen::Vector3d g;
  const double e = gaussian_hole_kernel(lattice, u, sigma, &g);
  *grad_i = B.transpose() * g / l_star;
  return e;
}

} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_GAUSSIAN_HOLE_KERNEL_H
