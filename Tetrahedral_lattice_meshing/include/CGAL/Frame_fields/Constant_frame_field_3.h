// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The same frame everywhere.

#ifndef CGAL_FRAME_FIELDS_CONSTANT_FRAME_FIELD_3_H
#define CGAL_FRAME_FIELDS_CONSTANT_FRAME_FIELD_3_H

#include <CGAL/Frame_fields/frame_inverse.h>

#include <Eigen/Core>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * A frame field with the same frame `T` at every point.
 *
 * \tparam GeomTraits a model of `Kernel`
 * \cgalModels `FrameField_3`
 */
template <class GeomTraits>
class Constant_frame_field_3
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef Eigen::Matrix3d Matrix;

  /// the frame `T` everywhere (identity by default).
  /// \throws std::invalid_argument if `T` is degenerate
  explicit Constant_frame_field_3(const Matrix& T = Matrix::Identity())
    : T_(T), B_(frame_inverse(T, "of Constant_frame_field_3"))
  {}

  Matrix T(const Point_3&) const { return T_; }
  Matrix B(const Point_3&) const { return B_; }

private:
  Matrix T_, B_;
};

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_CONSTANT_FRAME_FIELD_3_H
