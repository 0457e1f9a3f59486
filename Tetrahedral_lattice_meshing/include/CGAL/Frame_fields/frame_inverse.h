// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The check every frame passes: T finite and invertible, so that B = T^-1
// (the map into the imagined isotropic space) exists.

#ifndef CGAL_FRAME_FIELDS_FRAME_INVERSE_H
#define CGAL_FRAME_FIELDS_FRAME_INVERSE_H

#include <Eigen/Core>
#include <Eigen/LU>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * returns `true` if the frame `T` (columns: the three lattice axes with their lengths)
 * cannot be inverted reliably: a non-finite entry, a zero axis, or axes so close to
 * coplanar that \f$ |\det T| < 10^{-12} |t_1| |t_2| |t_3| \f$.
 */
inline bool is_degenerate_frame(const Eigen::Matrix3d& T)
{
  if(!T.allFinite()) return true;
  const double volume_bound = T.col(0).norm() * T.col(1).norm() * T.col(2).norm();
  // relative to the axis lengths, so that uniformly tiny or huge frames stay valid
  return !(volume_bound > 0) || !(std::abs(T.determinant()) >= 1e-12 * volume_bound);
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * returns \f$ B = T^{-1} \f$.
 * \throws std::invalid_argument if `T` is degenerate (see `is_degenerate_frame()`);
 *   the message names `where` (a point or an index) and shows `T`.
 */
inline Eigen::Matrix3d frame_inverse(const Eigen::Matrix3d& T, const std::string& where = std::string())
{
  if(is_degenerate_frame(T)) {
    std::ostringstream os;
    os << "degenerate frame" << (where.empty() ? "" : " " + where)
       << " (non-finite, a zero axis, or |det T| ~ 0): T =\n" << T;
    throw std::invalid_argument(os.str());
  }
  const Eigen::Matrix3d B = T.inverse();
  if(!B.allFinite()) // overflow of the inverse of a valid but extreme frame
    throw std::invalid_argument("frame" + (where.empty() ? std::string() : " " + where) +
                                ": T^-1 overflows");
  return B;
}

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_FRAME_INVERSE_H
