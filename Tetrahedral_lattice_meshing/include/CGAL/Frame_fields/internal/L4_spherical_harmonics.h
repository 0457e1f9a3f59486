// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cross frames as band-4 spherical harmonics (Huang et al. 2011, Ray et al.
// 2016): a frame R is the function F_R(p) = F_0(R^T p), F_0 = x^4 + y^4 + z^4
// minus its mean, written in the 9 real orthonormal SH of band 4 (order
// m = -4..4, so e4 is Y_4^0 and e0, e8 are Y_4^-4, Y_4^4). F_0 is
// sqrt(7/12) e4 + sqrt(5/12) e8, and the 24 rotations of the cube leave it
// unchanged, which is why SH vectors compare frames without matching axes.
//
// The band is rotation invariant, so the 9x9 matrix D(R) of a rotation follows
// exactly from sampling: Y(R^T s) = D(R)^T Y(s) at any 9+ directions s.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_L4_SPHERICAL_HARMONICS_H
#define CGAL_FRAME_FIELDS_INTERNAL_L4_SPHERICAL_HARMONICS_H

#include <CGAL/number_type_config.h> // CGAL_PI

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <random>

namespace CGAL {
namespace Frame_fields {
namespace internal {

typedef Eigen::Matrix<double, 9, 1> SH_vector;
typedef Eigen::Matrix<double, 9, 9> SH_matrix;

// the normalization constants of the band-4 real spherical harmonics
struct SH4_constants
{
  const double k1 = 0.75 * std::sqrt(35 / CGAL_PI), k2 = 0.75 * std::sqrt(35 / (2 * CGAL_PI)),
               k3 = 0.75 * std::sqrt(5 / CGAL_PI), k4 = 0.75 * std::sqrt(5 / (2 * CGAL_PI)),
               k5 = 3. / 16 * std::sqrt(1 / CGAL_PI), k6 = 3. / 8 * std::sqrt(5 / CGAL_PI),
               k7 = 3. / 16 * std::sqrt(35 / CGAL_PI);
};

/// the 9 band-4 real SH at `p` (homogeneous quartics: exact for unit `p`)
inline SH_vector sh4(const Eigen::Vector3d& p)
{
  const SH4_constants k;
  const double x = p.x(), y = p.y(), z = p.z();
  const double x2 = x * x, y2 = y * y, z2 = z * z;
  SH_vector Y;
  Y << k.k1 * x * y * (x2 - y2),
       k.k2 * y * z * (3 * x2 - y2),
       k.k3 * x * y * (6 * z2 - x2 - y2),
       k.k4 * y * z * (4 * z2 - 3 * x2 - 3 * y2),
       k.k5 * (3 * x2 * x2 + 3 * y2 * y2 + 8 * z2 * z2 + 6 * x2 * y2 - 24 * x2 * z2 - 24 * y2 * z2),
       k.k4 * x * z * (4 * z2 - 3 * x2 - 3 * y2),
       k.k6 * (6 * x2 * z2 - 6 * y2 * z2 - x2 * x2 + y2 * y2),
       k.k2 * x * z * (x2 - 3 * y2),
       k.k7 * (x2 * x2 - 6 * x2 * y2 + y2 * y2);
  return Y;
}

/// d/dp of sh4: row i is the gradient of Y_i
inline Eigen::Matrix<double, 9, 3> sh4_gradient(const Eigen::Vector3d& p)
{
  const SH4_constants k;
  const double x = p.x(), y = p.y(), z = p.z();
  const double x2 = x * x, y2 = y * y, z2 = z * z;
  Eigen::Matrix<double, 9, 3> G;
  G << k.k1 * (3 * x2 * y - y2 * y), k.k1 * (x2 * x - 3 * x * y2), 0,
       k.k2 * 6 * x * y * z, k.k2 * (3 * x2 * z - 3 * y2 * z), k.k2 * (3 * x2 * y - y2 * y),
       k.k3 * (6 * y * z2 - 3 * x2 * y - y2 * y), k.k3 * (6 * x * z2 - x2 * x - 3 * x * y2), k.k3 * 12 * x * y * z,
       -k.k4 * 6 * x * y * z, k.k4 * (4 * z2 * z - 3 * x2 * z - 9 * y2 * z), k.k4 * (12 * y * z2 - 3 * x2 * y - 3 * y2 * y),
       k.k5 * (12 * x2 * x + 12 * x * y2 - 48 * x * z2), k.k5 * (12 * y2 * y + 12 * x2 * y - 48 * y * z2),
           k.k5 * (32 * z2 * z - 48 * x2 * z - 48 * y2 * z),
       k.k4 * (4 * z2 * z - 9 * x2 * z - 3 * y2 * z), -k.k4 * 6 * x * y * z, k.k4 * (12 * x * z2 - 3 * x2 * x - 3 * x * y2),
       k.k6 * (12 * x * z2 - 4 * x2 * x), k.k6 * (4 * y2 * y - 12 * y * z2), k.k6 * (12 * x2 * z - 12 * y2 * z),
       k.k2 * (3 * x2 * z - 3 * y2 * z), -k.k2 * 6 * x * y * z, k.k2 * (x2 * x - 3 * x * y2),
       k.k7 * (4 * x2 * x - 12 * x * y2), k.k7 * (4 * y2 * y - 12 * x2 * y), 0;
  return G;
}

/// Rotations of band-4 SH, frames as SH vectors, and the projection of any
/// SH vector onto the nearest frame. One shared, immutable instance.
class L4_frames
{
public:
  static const L4_frames& instance()
  {
    static const L4_frames frames;
    return frames;
  }

  /// D(R): the SH coefficients of F(R^T p) are D(R) times those of F(p)
  SH_matrix rotation(const Eigen::Matrix3d& R) const
  {
    Eigen::Matrix<double, n_samples, 9> Yr;
    for(int k = 0; k < n_samples; ++k) Yr.row(k) = sh4(R.transpose() * samples_.col(k)).transpose();
    return fit_ * Yr;
  }

  /// the SH vector of the frame whose axes are the columns of the rotation `R`
  /// (F_0(R^T p) = sum_i (r_i . p)^4 - 3/5: its 15 quartic coefficients times a
  /// fixed matrix, a quarter of the work of sampling it)
  SH_vector frame(const Eigen::Matrix3d& R) const
  {
    return monomials_to_frame_ * quartic_coefficients(R) + constant_to_frame_;
  }

  /// the reference frame (identity rotation)
  const SH_vector& reference() const { return reference_; }

  /// generator of the rotations about `axis` (0, 1, 2): D(exp(t [e_axis]x)) = exp(t L)
  const SH_matrix& generator(int axis) const { return L_[axis]; }

  /// the rotation R maximizing <frame(R), q>, that is the frame nearest to q
  /// after scaling; the identity for q = 0. A coarse search over fixed
  /// rotations, then Newton steps on SO(3) from the best.
  Eigen::Matrix3d nearest_frame(const SH_vector& q) const
  {
    const double norm = q.norm();
    if(!(norm > 0) || !q.allFinite()) return Eigen::Matrix3d::Identity();
    Eigen::Index best;
    (candidate_frames_.transpose() * q).maxCoeff(&best);
    return refine(q / norm, candidate_rotations_[std::size_t(best)]);
  }

  /// Newton ascent of <frame(R), q> over R, from R0 (q of unit norm)
  Eigen::Matrix3d refine(const SH_vector& q, Eigen::Matrix3d R) const
  {
    for(int iteration = 0; iteration < 50; ++iteration) {
      const SH_vector f = frame(R);
      std::array<SH_vector, 3> Lf;
      for(int a = 0; a < 3; ++a) Lf[a] = L_[a] * f;
      Eigen::Vector3d g;
      Eigen::Matrix3d H;
      for(int a = 0; a < 3; ++a) {
        g[a] = Lf[a].dot(q);
        for(int b = 0; b <= a; ++b)
          H(a, b) = H(b, a) = 0.5 * ((L_[a] * Lf[b]).dot(q) + (L_[b] * Lf[a]).dot(q));
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(H);
      Eigen::Vector3d omega;
      if(eig.eigenvalues().maxCoeff() < -1e-9) // concave here: Newton
        omega = -eig.eigenvectors() * eig.eigenvalues().cwiseInverse().asDiagonal() *
                eig.eigenvectors().transpose() * g;
      else
        omega = 0.1 * g; // gradient ascent until the maximum's basin
      const double step = omega.norm();
      if(step > 0.3) omega *= 0.3 / step;
      if(step < 1e-14) break;
      R = Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix() * R;
      if(step < 1e-10) break; // quadratic convergence: this step reached the precision
    }
    // re-orthonormalize the product of rotations
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return svd.matrixU() * svd.matrixV().transpose();
  }

private:
  static constexpr int n_samples = 32;
  static constexpr int n_candidates = 512;
  typedef Eigen::Matrix<double, 15, 1> Quartic;

  // x^a y^b z^c, a + b + c = 4, in the order of quartic_coefficients()
  static Quartic quartic_monomials(const Eigen::Vector3d& p)
  {
    const double x = p.x(), y = p.y(), z = p.z();
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    Quartic m;
    m << x2 * x2, y2 * y2, z2 * z2, x2 * x * y, x2 * x * z, y2 * y * x, y2 * y * z, z2 * z * x, z2 * z * y,
         x2 * y2, x2 * z2, y2 * z2, x2 * y * z, y2 * x * z, z2 * x * y;
    return m;
  }

  // the coefficients of sum_i (r_i . p)^4 over the columns r_i of R (multinomial weights 1, 4, 6, 12)
  static Quartic quartic_coefficients(const Eigen::Matrix3d& R)
  {
    Quartic q = Quartic::Zero();
    for(int i = 0; i < 3; ++i) {
      const double u = R(0, i), v = R(1, i), w = R(2, i);
      const double u2 = u * u, v2 = v * v, w2 = w * w;
      q[0] += u2 * u2, q[1] += v2 * v2, q[2] += w2 * w2;
      q[3] += 4 * u2 * u * v, q[4] += 4 * u2 * u * w, q[5] += 4 * v2 * v * u;
      q[6] += 4 * v2 * v * w, q[7] += 4 * w2 * w * u, q[8] += 4 * w2 * w * v;
      q[9] += 6 * u2 * v2, q[10] += 6 * u2 * w2, q[11] += 6 * v2 * w2;
      q[12] += 12 * u2 * v * w, q[13] += 12 * v2 * u * w, q[14] += 12 * w2 * u * v;
    }
    return q;
  }

  L4_frames()
  {
    // Fibonacci directions: well spread, so the least-squares fit is well conditioned
    const double golden = CGAL_PI * (3 - std::sqrt(5.));
    Eigen::Matrix<double, 9, n_samples> Ys;
    for(int k = 0; k < n_samples; ++k) {
      const double z = 1 - (2 * k + 1) / double(n_samples), r = std::sqrt(1 - z * z);
      samples_.col(k) = Eigen::Vector3d(r * std::cos(golden * k), r * std::sin(golden * k), z);
      Ys.col(k) = sh4(samples_.col(k));
    }
    fit_ = (Ys * Ys.transpose()).ldlt().solve(Ys);
    // F_0 = x^4 + y^4 + z^4 - 3/5 lies in band 4 on the sphere
    Eigen::Matrix<double, n_samples, 1> values;
    for(int k = 0; k < n_samples; ++k) values[k] = samples_.col(k).array().square().square().sum() - 0.6;
    reference_ = fit_ * values;
    const double reference_norm = reference_.norm();
    reference_ /= reference_norm;
    // frame(R) = fit_ (values of F_0(R^T s_k)) / |reference|, linear in R's quartic coefficients
    Eigen::Matrix<double, n_samples, 15> monomials;
    for(int k = 0; k < n_samples; ++k) monomials.row(k) = quartic_monomials(samples_.col(k)).transpose();
    monomials_to_frame_ = fit_ * monomials / reference_norm;
    constant_to_frame_ = -0.6 * fit_ * Eigen::Matrix<double, n_samples, 1>::Ones() / reference_norm;
    // d/dt Y(exp(t [a]x)^T s) = grad Y(s) . (s x a)
    for(int a = 0; a < 3; ++a) {
      Eigen::Matrix<double, n_samples, 9> dY;
      for(int k = 0; k < n_samples; ++k) {
        const Eigen::Vector3d s = samples_.col(k);
        dY.row(k) = (sh4_gradient(s) * s.cross(Eigen::Vector3d::Unit(a))).transpose();
      }
      L_[a] = fit_ * dY;
    }
    // fixed, uniformly random starting rotations: about 11 deg apart modulo the cube's symmetry
    std::mt19937 rng(20160401);
    std::normal_distribution<double> normal;
    candidate_rotations_.resize(n_candidates);
    for(int i = 0; i < n_candidates; ++i) {
      Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
      candidate_rotations_[std::size_t(i)] = q.normalized().toRotationMatrix();
      candidate_frames_.col(i) = frame(candidate_rotations_[std::size_t(i)]);
    }
  }

  Eigen::Matrix<double, 3, n_samples> samples_;
  Eigen::Matrix<double, 9, n_samples> fit_; // least-squares SH coefficients of sampled values
  SH_vector reference_;
  Eigen::Matrix<double, 9, 15> monomials_to_frame_;
  SH_vector constant_to_frame_;
  std::array<SH_matrix, 3> L_;
  std::vector<Eigen::Matrix3d> candidate_rotations_;
  Eigen::Matrix<double, 9, n_candidates> candidate_frames_;
};

/// The frames with one axis along the unit vector `n`: R_n R_z(t), where R_n
/// takes z to n; their SH vectors are
/// sqrt(7/12) D(R_n) e4 + sqrt(5/12) (cos 4t D(R_n) e8 + sin 4t D(R_n) e0).
struct Axis_constrained_frames
{
  explicit Axis_constrained_frames(const Eigen::Vector3d& n)
  {
    R_n = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), n).toRotationMatrix();
    const SH_matrix D = L4_frames::instance().rotation(R_n);
    offset = std::sqrt(7. / 12) * D.col(4);
    basis.col(0) = std::sqrt(5. / 12) * D.col(8);
    basis.col(1) = std::sqrt(5. / 12) * D.col(0);
  }

  /// the rotation of the constrained frame whose SH vector is nearest to q
  Eigen::Matrix3d nearest_frame(const SH_vector& q) const
  {
    const double t = 0.25 * std::atan2(basis.col(1).dot(q), basis.col(0).dot(q));
    return R_n * Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }

  Eigen::Matrix3d R_n;
  SH_vector offset;                 // the part that does not depend on t
  Eigen::Matrix<double, 9, 2> basis; // times (cos 4t, sin 4t)
};

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_L4_SPHERICAL_HARMONICS_H
