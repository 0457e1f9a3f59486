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

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Frame_fields {
namespace internal_np {

enum edge_length_t { edge_length };
enum features_angle_t { features_angle };

} // namespace internal_np

namespace parameters {

#define CGAL_FRAME_FIELDS_ADD_NAMED_PARAMETER(NAME)                                              \
  template <class T>                                                                             \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& t)                     \
  {                                                                                              \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(t);                         \
  }                                                                                              \
  template <class T, class NP_T, class NP_Tag, class NP_Base>                                    \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t,                                      \
                                  CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>>        \
  NAME(const T& t, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np)             \
  {                                                                                              \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t,                             \
                                           CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>>(t, np); \
  }

/// `double`: the length of the three axes of every generated frame (default 1)
CGAL_FRAME_FIELDS_ADD_NAMED_PARAMETER(edge_length)
/// `double`, degrees: on a `Triangulation_3`, the convex hull's edges whose two facet
/// normals differ by more than this are sharp features (default 60; 0 for none)
CGAL_FRAME_FIELDS_ADD_NAMED_PARAMETER(features_angle)

#undef CGAL_FRAME_FIELDS_ADD_NAMED_PARAMETER

} // namespace parameters
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_PARAMETERS_H
