// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A frame field whose frames are scaled by a sizing field: the lattice keeps
// the field's directions and takes the sizing's spacing, e.g. a cross field
// with the size of CGAL::Thickness_sizing_field_3.

#ifndef CGAL_FRAME_FIELDS_SCALED_FRAME_FIELD_3_H
#define CGAL_FRAME_FIELDS_SCALED_FRAME_FIELD_3_H


#include <Eigen/Core>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * The frame field \f$ T'(x) = \frac{h(x)}{h_0} T(x) \f$ of a frame field \f$ T \f$ and a sizing
 * field \f$ h \f$: where \f$ h \f$ is half of \f$ h_0 \f$, the lattice is twice as fine. Only
 * the ratios of \f$ h \f$ matter to the lattice meshers given a number of particles, since
 * they scale the whole field to the count; \f$ h_0 \f$ sets the spacing given an edge length.
 *
 * \tparam FrameField a model of `FrameField_3`
 * \tparam SizingField a callable `double(const FrameField::Point_3&)`, positive, e.g.
 *   `CGAL::Thickness_sizing_field_3`
 * \cgalModels `FrameField_3`
 */
template <class FrameField, class SizingField>
class Scaled_frame_field_3
{
public:
  typedef typename FrameField::Point_3 Point_3;
  typedef Eigen::Matrix3d Matrix;

  /// \throws std::invalid_argument if `reference_size` is not positive and finite
  Scaled_frame_field_3(FrameField field, SizingField size, double reference_size)
    : field_(std::move(field)), size_(std::move(size)), reference_(reference_size)
  {
    if(!(reference_ > 0) || !std::isfinite(reference_))
      throw std::invalid_argument("Scaled_frame_field_3: the reference size must be positive and finite");
  }

  /// \throws std::invalid_argument if the size at `p` is not positive and finite, or if the frame is degenerate
  Matrix T(const Point_3& p) const { return field_.T(p) * scale(p); }
  /// \throws std::invalid_argument if the size at `p` is not positive and finite, or if the frame is degenerate
  Matrix B(const Point_3& p) const { return field_.B(p) / scale(p); }

  const FrameField& frame_field() const { return field_; }
  const SizingField& sizing_field() const { return size_; }
  double reference_size() const { return reference_; }

private:
  double scale(const Point_3& p) const
  {
    const double h = size_(p);
    if(!(h > 0) || !std::isfinite(h)) {
      std::ostringstream os;
      os.precision(17);
      os << "Scaled_frame_field_3: the size at (" << p << ") is " << h << ", not positive and finite";
      throw std::invalid_argument(os.str());
    }
    return h / reference_;
  }

  FrameField field_;
  SizingField size_;
  double reference_;
};

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_SCALED_FRAME_FIELD_3_H
