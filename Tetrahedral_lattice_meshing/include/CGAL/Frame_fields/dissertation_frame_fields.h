// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The closed-form frame fields of the dissertation's experiments (ch. 4.3.3
// and 4.4.3), ready to use. Each returns T(x), the lattice axes with their
// lengths as columns; B = T^-1.

#ifndef CGAL_FRAME_FIELDS_DISSERTATION_FRAME_FIELDS_H
#define CGAL_FRAME_FIELDS_DISSERTATION_FRAME_FIELDS_H

#include <CGAL/Frame_fields/Closed_form_frame_field_3.h>
#include <CGAL/Frame_fields/Constant_frame_field_3.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>

namespace CGAL {
namespace Frame_fields {
namespace internal {

// radial, tangential and axial unit vectors about the z axis; on the axis,
// where they are undefined, x, y and z
inline void cylindrical_axes(double x, double y, Eigen::Vector3d& e_r, Eigen::Vector3d& e_t)
{
  const double r = std::hypot(x, y);
  e_r = r > 0 ? Eigen::Vector3d(x / r, y / r, 0) : Eigen::Vector3d::UnitX();
  e_t = Eigen::Vector3d(-e_r.y(), e_r.x(), 0);
}

} // namespace internal

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// \f$ T = I \f$ (Fig. 4.15a, and the field \f$ I \f$ of Tables 4.1-4.3).
template <class GeomTraits>
Constant_frame_field_3<GeomTraits> identity_frame_field()
{
  return Constant_frame_field_3<GeomTraits>();
}

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// the constant stretch along x, \f$ T = \mathrm{diag}(4, 1, 1) \f$ (Fig. 4.15b).
template <class GeomTraits>
Constant_frame_field_3<GeomTraits> constant_stretch_frame_field()
{
  return Constant_frame_field_3<GeomTraits>(Eigen::Vector3d(4, 1, 1).asDiagonal());
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * the linear scale along x on \f$ [-1,1]^3 \f$, \f$ T = \mathrm{diag}(8x, 1, 1) \f$
 * (Fig. 4.15c).
 *
 * \warning The field is degenerate on the plane \f$ x = 0 \f$, which cuts its own
 * domain \f$ [-1,1]^3 \f$ in half: `T()` and `B()` **throw** `std::invalid_argument`
 * at every point with \f$ x = 0 \f$ (and the frames near it are tiny, their inverses
 * huge). Sample it only where \f$ x \neq 0 \f$, or use it on a domain that does not
 * meet that plane; for \f$ x < 0 \f$ the first axis points along \f$ -x \f$.
 */
template <class GeomTraits>
Closed_form_frame_field_3<GeomTraits> linear_scale_frame_field()
{
  return Closed_form_frame_field_3<GeomTraits>([](const typename GeomTraits::Point_3& p) {
    return Eigen::Matrix3d(Eigen::Vector3d(8 * CGAL::to_double(p.x()), 1, 1).asDiagonal());
  });
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * the anisotropy along a single direction on \f$ [0.1, 1.1]^3 \f$, as Fig. 4.8 gives it:
 * \f$ B = \mathrm{diag}((1.0125 - e^{-|x - 0.6|})^{-1}, 1, 1) \f$, so
 * \f$ T = \mathrm{diag}(1.0125 - e^{-|x - 0.6|}, 1, 1) \f$: the axis along x has length
 * 0.0125 at \f$ x = 0.6 \f$ and grows to about 0.62 at the ends, the lattice is densest
 * at \f$ x = 0.6 \f$.
 *
 * \note The text of Fig. 4.15d, the same experiment, gives instead
 * \f$ T = \mathrm{diag}((1.0125 - e^{-|x - 0.6|})^{-1}, 1, 1) \f$, the inverse of this
 * \f$ T \f$ (i.e. Fig. 4.8's \f$ B \f$ used as \f$ T \f$): axes 80 times longer at
 * \f$ x = 0.6 \f$, the lattice sparsest there. This function follows Fig. 4.8; for the
 * field as printed in Fig. 4.15d, swap the roles: use `B()` of this field as \f$ T \f$,
 * e.g. `Closed_form_frame_field_3<GeomTraits>([f](const auto& p) { return f.B(p); })`.
 */
template <class GeomTraits>
Closed_form_frame_field_3<GeomTraits> single_direction_anisotropy_frame_field()
{
  return Closed_form_frame_field_3<GeomTraits>([](const typename GeomTraits::Point_3& p) {
    const double s = 1.0125 - std::exp(-std::abs(CGAL::to_double(p.x()) - 0.6));
    return Eigen::Matrix3d(Eigen::Vector3d(s, 1, 1).asDiagonal());
  });
}

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// the shear on y (Fig. 4.15e): the columns of \f$ T \f$ are
/// \f$ (1,0,0), (1,2,0), (0,0,1) \f$.
template <class GeomTraits>
Constant_frame_field_3<GeomTraits> shear_y_frame_field()
{
  Eigen::Matrix3d T;
  T << 1, 1, 0,
       0, 2, 0,
       0, 0, 1;
  return Constant_frame_field_3<GeomTraits>(T);
}

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// the shear on y and z (Fig. 4.15f): the columns of \f$ T \f$ are
/// \f$ (1,0,0), (1,2,0), (1,1,1) \f$.
template <class GeomTraits>
Constant_frame_field_3<GeomTraits> shear_yz_frame_field()
{
  Eigen::Matrix3d T;
  T << 1, 1, 1,
       0, 2, 1,
       0, 0, 1;
  return Constant_frame_field_3<GeomTraits>(T);
}

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// the cylindrical anisotropy on \f$ [1, 11]^3 \f$ (Fig. 4.9): \f$ B = S R \f$ with
/// \f$ S = \mathrm{diag}((1.05 - e^{-0.01 |x^2 + y^2 - 49|})^{-1}, 1, 1) \f$ and \f$ R \f$
/// the rotation whose rows are the radial, tangential and axial (z) unit vectors.
/// (The figure prints the columns of \f$ R \f$ as \f$ (-x, y, 0)/r \f$ and
/// \f$ (-y, x, 0)/r \f$, which are not orthogonal; we read them as this rotation.)
/// So \f$ T = R^T S^{-1} \f$: the radial axis has length \f$ 1.05 - e^{-0.01 |r^2 - 49|} \f$,
/// the other two length 1. On the z axis the radial direction is taken as x.
template <class GeomTraits>
Closed_form_frame_field_3<GeomTraits> cylindrical_anisotropy_frame_field()
{
  return Closed_form_frame_field_3<GeomTraits>([](const typename GeomTraits::Point_3& p) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    Eigen::Vector3d e_r, e_t;
    internal::cylindrical_axes(x, y, e_r, e_t);
    Eigen::Matrix3d T;
    T.col(0) = (1.05 - std::exp(-0.01 * std::abs(x * x + y * y - 49))) * e_r;
    T.col(1) = e_t;
    T.col(2) = Eigen::Vector3d::UnitZ();
    return T;
  });
}

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// the rotation about the y axis used on the torus (Table 4.3, Fig. 4.6, field
/// \f$ R_y \f$; the torus's axis is y): \f$ T = R_y(\varphi) \f$ with
/// \f$ \varphi = \mathrm{atan2}(x, z) \f$, so the columns are the tangential direction
/// \f$ (\cos\varphi, 0, -\sin\varphi) \f$, y, and the radial direction
/// \f$ (\sin\varphi, 0, \cos\varphi) \f$.
template <class GeomTraits>
Closed_form_frame_field_3<GeomTraits> rotation_about_y_frame_field()
{
  return Closed_form_frame_field_3<GeomTraits>([](const typename GeomTraits::Point_3& p) {
    const double phi = std::atan2(CGAL::to_double(p.x()), CGAL::to_double(p.z()));
    const double c = std::cos(phi), s = std::sin(phi);
    Eigen::Matrix3d T;
    T << c, 0, s,
         0, 1, 0,
        -s, 0, c;
    return T;
  });
}

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// the cross field of a cylinder about the z axis (Fig. 4.16): the columns of
/// \f$ T \f$ are the radial, tangential and axial unit vectors. With
/// `scale_correction`, the tangential axis has length \f$ r / r_0 \f$
/// (`reference_radius` \f$ r_0 \f$), so that every ring around the axis holds the same
/// number of lattice cells and the field is the Jacobian inverse of the map
/// \f$ (r, r_0\theta, z) \f$: a lattice aligned with it has no gap to fill between
/// rings (the all-hex result of Fig. 4.16a); it is degenerate on the axis. Without,
/// the field is a unit cross field (Fig. 4.16b); on the axis the radial direction
/// is taken as x.
/// \throws std::invalid_argument if `reference_radius` is not positive and finite
template <class GeomTraits>
Closed_form_frame_field_3<GeomTraits> cylinder_frame_field(double reference_radius,
                                                           bool scale_correction)
{
  if(!(reference_radius > 0) || !std::isfinite(reference_radius))
    throw std::invalid_argument("cylinder_frame_field: the reference radius must be positive and finite");
  return Closed_form_frame_field_3<GeomTraits>(
      [reference_radius, scale_correction](const typename GeomTraits::Point_3& p) {
        const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
        Eigen::Vector3d e_r, e_t;
        internal::cylindrical_axes(x, y, e_r, e_t);
        Eigen::Matrix3d T;
        T.col(0) = e_r;
        T.col(1) = scale_correction ? (std::hypot(x, y) / reference_radius) * e_t : e_t;
        T.col(2) = Eigen::Vector3d::UnitZ();
        return T;
      });
}

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_DISSERTATION_FRAME_FIELDS_H
