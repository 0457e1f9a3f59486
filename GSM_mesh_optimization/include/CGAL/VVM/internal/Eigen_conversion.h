// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points between CGAL and Eigen, and a frame field as the function of an Eigen
// point that the particle and mesh code evaluate: one spelling for the three
// packages.

#ifndef CGAL_VVM_INTERNAL_EIGEN_CONVERSION_H
#define CGAL_VVM_INTERNAL_EIGEN_CONVERSION_H

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <functional>

namespace CGAL {
namespace VVM {
namespace internal {

/// a CGAL point (bare or weighted) as an Eigen vector of doubles
template <class Point_3>
Eigen::Vector3d to_eigen(const Point_3& p)
{
  return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

/// an Eigen vector as a CGAL point
template <class Point_3>
Point_3 to_point(const Eigen::Vector3d& x)
{
  return Point_3(x[0], x[1], x[2]);
}

/// the inverse frame \f$ B(x) = T(x)^{-1} \f$ of a frame field, as a function of an Eigen point
typedef std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> Frame_inverse_function;

/// `field.B` as a `Frame_inverse_function`; `field` must outlive it
template <class FrameField>
Frame_inverse_function frame_inverse_function(const FrameField& field)
{
  return [&field](const Eigen::Vector3d& x) {
    return Eigen::Matrix3d(field.B(to_point<typename FrameField::Point_3>(x)));
  };
}

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_EIGEN_CONVERSION_H
