// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL_VVM_ADD_NAMED_PARAMETER(NAME): a named parameter that CGAL's central
// list does not have (CGAL 5.5.1 offers no hook to add names to
// CGAL::parameters). Expanded in a namespace `X::parameters` whose sibling
// `X::internal_np` declares `enum NAME_t { NAME };`, it defines `NAME(t)` and
// `NAME(t, np)`, the latter appending the parameter to an existing pack.
// Shared by every VVM package that has parameters of its own.
// CGAL_VVM_ADD_DEPRECATED_NAMED_PARAMETER(OLD, NEW): `OLD(t)` and `OLD(t, np)` give
// the parameter `NEW` (a name kept for one release), with a deprecation warning.

#ifndef CGAL_VVM_INTERNAL_ADD_NAMED_PARAMETER_H
#define CGAL_VVM_INTERNAL_ADD_NAMED_PARAMETER_H

#include <CGAL/Named_function_parameters.h>

#define CGAL_VVM_ADD_NAMED_PARAMETER(NAME)                                                       \
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

#define CGAL_VVM_ADD_DEPRECATED_NAMED_PARAMETER(OLD, NEW)                                       \
  template <class T>                                                                             \
  [[deprecated("use the named parameter " #NEW)]] auto OLD(const T& t)                           \
  {                                                                                              \
    return NEW(t);                                                                               \
  }                                                                                              \
  template <class T, class NP_T, class NP_Tag, class NP_Base>                                    \
  [[deprecated("use the named parameter " #NEW)]] auto                                           \
  OLD(const T& t, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np)              \
  {                                                                                              \
    return NEW(t, np);                                                                           \
  }

#endif // CGAL_VVM_INTERNAL_ADD_NAMED_PARAMETER_H
