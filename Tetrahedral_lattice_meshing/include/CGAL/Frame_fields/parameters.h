// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of the frame fields that CGAL's central list does not
// have (CGAL 5.5.1 offers no hook to add names to CGAL::parameters); each has
// an overload that appends it to an existing pack:
//
//   namespace FF = CGAL::Frame_fields;
//   FF::generate_cross_field_3(tr, FF::parameters::features_angle(45,
//       CGAL::parameters::number_of_iterations(5)));

#ifndef CGAL_FRAME_FIELDS_PARAMETERS_H
#define CGAL_FRAME_FIELDS_PARAMETERS_H

#include <CGAL/VVM/internal/add_named_parameter.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Frame_fields {
namespace internal_np {

enum axis_length_t { axis_length };
enum features_angle_t { features_angle };
enum smoothing_tolerance_t { smoothing_tolerance };
enum maximum_anisotropy_t { maximum_anisotropy };
enum maximum_size_ratio_t { maximum_size_ratio };

} // namespace internal_np

namespace parameters {

/// `double`: the length of the three axes of every generated frame (default 1)
CGAL_VVM_ADD_NAMED_PARAMETER(axis_length)
/// the former name of `axis_length` (not the lattice's `Tetrahedral_lattice_meshing::parameters::edge_length`)
template <class... Args>
[[deprecated("use axis_length")]] auto edge_length(const Args&... args)
{
  return axis_length(args...);
}
/// `double`, degrees: on a `Triangulation_3`, the convex hull's edges whose two facet
/// normals differ by more than this are sharp features (default 60; 0 for none)
CGAL_VVM_ADD_NAMED_PARAMETER(features_angle)
/// `double`: the smoothing of a generated cross field stops after the first round that
/// lowers its energy by less than this fraction (default 1e-4)
CGAL_VVM_ADD_NAMED_PARAMETER(smoothing_tolerance)
/// `double`: the largest ratio of a frame's two tangent lengths in a curvature field (default 3)
CGAL_VVM_ADD_NAMED_PARAMETER(maximum_anisotropy)
/// `double`: the largest ratio of two lengths over a field, for the functions that choose
/// lengths (curvature fields, the scale correction; each documents its default)
CGAL_VVM_ADD_NAMED_PARAMETER(maximum_size_ratio)

} // namespace parameters
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_PARAMETERS_H
