// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The map B(x) into the isotropic space where the GSM template is the regular
// tetrahedron of edge 1: I / a for a uniform edge length a, M(x)^{1/2} for an
// anisotropic metric M. (An isotropic sizing field is sampled at the vertices:
// Vertex_sizes.h.)

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_METRIC_FIELD_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_METRIC_FIELD_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

class Metric_field
{
public:
  /// uniform edge length `a`
  static Metric_field uniform(double a)
  {
    if(!(a > 0) || !std::isfinite(a))
      throw std::invalid_argument("GSM: the template edge length must be positive and finite");
    Metric_field m;
    m.constant_B_ = Eigen::Matrix3d::Identity() / a;
    m.isotropic_ = true;
    return m;
  }

  /// metric `M(x)`, symmetric positive definite
  static Metric_field anisotropic(std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> M)
  {
    Metric_field m;
    m.B_ = [M](const Eigen::Vector3d& x) -> Eigen::Matrix3d { return square_root(M(x), x); };
    return m;
  }

  bool is_constant() const { return !B_; }
  /// B is a multiple of the identity everywhere: angles are those of the mesh itself
  bool is_isotropic() const { return isotropic_; }
  Eigen::Matrix3d operator()(const Eigen::Vector3d& x) const
  {
    return B_ ? Eigen::Matrix3d(scale_ * B_(x)) : constant_B_;
  }

  /// the same field with target edges `factor` times shorter
  Metric_field scaled(double factor) const
  {
    if(!(factor > 0) || !std::isfinite(factor))
      throw std::invalid_argument("GSM: the metric cannot be scaled to the mesh (degenerate mesh or field)");
    Metric_field m = *this;
    m.constant_B_ *= factor;
    m.scale_ *= factor;
    return m;
  }

  /// M^{1/2} of a symmetric positive definite M; anything else is an error
  static Eigen::Matrix3d square_root(const Eigen::Matrix3d& M, const Eigen::Vector3d& x)
  {
    const bool finite = M.allFinite();
    const bool symmetric = finite && (M - M.transpose()).norm() <= 1e-9 * M.norm();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    if(symmetric) eig.computeDirect(M); // closed form: this runs for every energy evaluation
    // relative to the largest eigenvalue: a singular M's zero eigenvalue comes out of the
    // closed form as a rounding error of either sign
    if(!symmetric || eig.info() != Eigen::Success ||
       !(eig.eigenvalues().minCoeff() > 1e-12 * eig.eigenvalues().maxCoeff())) {
      std::ostringstream os;
      os << "GSM: the metric at (" << x.transpose()
         << ") is not a finite symmetric positive definite matrix (singular, indefinite or not finite):\n" << M;
      throw std::invalid_argument(os.str());
    }
    return eig.eigenvectors() * eig.eigenvalues().cwiseSqrt().asDiagonal() *
           eig.eigenvectors().transpose();
  }

private:
  Eigen::Matrix3d constant_B_ = Eigen::Matrix3d::Identity();
  double scale_ = 1;
  bool isotropic_ = false;
  std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> B_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_METRIC_FIELD_H
