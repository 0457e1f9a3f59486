// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A frame field given by a formula T(x), checked at every evaluation.

#ifndef CGAL_FRAME_FIELDS_CLOSED_FORM_FRAME_FIELD_3_H
#define CGAL_FRAME_FIELDS_CLOSED_FORM_FRAME_FIELD_3_H

#include <CGAL/Frame_fields/frame_inverse.h>

#include <Eigen/Core>

#include <functional>
#include <sstream>
#include <string>
#include <utility>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * A frame field given by any callable `Eigen::Matrix3d(const Point_3&)` returning
 * \f$ T(x) \f$; \f$ B(x) \f$ is its inverse.
 *
 * \tparam GeomTraits a model of `Kernel`
 * \tparam Function a callable `Eigen::Matrix3d(const GeomTraits::Point_3&)`;
 *   `std::function` by default, so that fields of different formulas share one type.
 * \cgalModels `FrameField_3`
 */
template <class GeomTraits,
          class Function = std::function<Eigen::Matrix3d(const typename GeomTraits::Point_3&)>>
class Closed_form_frame_field_3
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef Eigen::Matrix3d Matrix;

  explicit Closed_form_frame_field_3(Function T) : T_(std::move(T)) {}

  /// \throws std::invalid_argument if the frame at `p` is degenerate
  Matrix T(const Point_3& p) const
  {
    const Matrix t = T_(p);
    if(is_degenerate_frame(t)) frame_inverse(t, at(p)); // throws with the message
    return t;
  }

  /// \throws std::invalid_argument if the frame at `p` is degenerate
  Matrix B(const Point_3& p) const
  {
    const Matrix t = T_(p);
    if(!is_degenerate_frame(t)) {
      const Matrix b = t.inverse();
      if(b.allFinite()) return b;
    }
    return frame_inverse(t, at(p)); // throws; the message (the point printed) only then
  }

  const Function& function() const { return T_; }

private:
  static std::string at(const Point_3& p)
  {
    std::ostringstream os;
    os.precision(17);
    os << "at (" << p << ")";
    return os.str();
  }

  Function T_;
};

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * returns a `Closed_form_frame_field_3` of the callable `T`, keeping its type.
 */
template <class GeomTraits, class Function>
Closed_form_frame_field_3<GeomTraits, Function> make_closed_form_frame_field_3(Function T)
{
  return Closed_form_frame_field_3<GeomTraits, Function>(std::move(T));
}

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_CLOSED_FORM_FRAME_FIELD_3_H
