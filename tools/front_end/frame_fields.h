// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The frame fields a front end names: a frame-field file, and on a triangle
// surface the principal curvature field, its isotropic variant, the x axis
// projected or a file's field on the tangent planes. Shared by vvm-mesh, the
// Python module and compare_surface_meshers.

#ifndef VVM_FRONT_END_FRAME_FIELDS_H
#define VVM_FRONT_END_FRAME_FIELDS_H

#include "vvm_front_end.h"

#include <CGAL/Frame_fields/IO/frame_field_text_format.h>
#include <CGAL/Frame_fields/Surface_frame_field_3.h>
#include <CGAL/Frame_fields/principal_curvature_frame_field.h>

#include <array>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vvm {
namespace internal {

/// the frame field in the file `path` (text format); Input_error if it cannot be read
inline CGAL::Frame_fields::Discrete_frame_field_3<Kernel> read_frame_field_file(const std::string& path)
{
  std::ifstream is(path);
  if(!is) throw Input_error("cannot open the frame-field file '" + path + "'");
  try {
    return CGAL::Frame_fields::IO::read_frame_field<Kernel>(is);
  } catch(const std::invalid_argument& e) {
    throw Input_error("'" + path + "': " + e.what());
  }
}

/// `true` if `field` names a field that surface_frame_field() builds, not a file
inline bool is_surface_field_name(const std::string& field)
{
  return field == "curvature" || field == "isotropic" || field == "identity";
}

/// Input_error unless `field` is a name surface_frame_field() knows or a file that opens: before
/// any work
inline void check_surface_field(const std::string& field)
{
  if(!is_surface_field_name(field) && !std::ifstream(field))
    throw Input_error("unknown field '" + field +
                      "': neither curvature, isotropic, identity nor a frame-field file that can be opened");
}

/// the tangent frame field `field` names on the surface of `points` and `faces`: "curvature"
/// (principal directions, lengths from the curvatures within `maximum_anisotropy` and
/// `maximum_size_ratio`), "isotropic" (the same, one length per frame), "identity" (the x axis
/// projected, unit lengths) or a frame-field file (a frame per vertex of the surface, or a volume
/// field; `Surface_frame_field_3::from_frame_field()`). Input_error on a file that cannot be read
/// or a field the surface refuses.
inline CGAL::Frame_fields::Surface_frame_field_3<Kernel>
surface_frame_field(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3>>& faces,
                    const std::string& field, double maximum_anisotropy, double maximum_size_ratio,
                    double features_angle)
{
  namespace FF = CGAL::Frame_fields;
  typedef FF::Surface_frame_field_3<Kernel> Surface_field;
  try {
    if(field == "identity")
      return Surface_field::from_tangent_frames(
          points, faces, [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return FF::Tangent_frame(); },
          features_angle);
    if(field == "curvature" || field == "isotropic")
      return FF::principal_curvature_frame_field<Kernel>(
          points, faces,
          FF::parameters::maximum_anisotropy(
              field == "isotropic" ? 1. : maximum_anisotropy,
              FF::parameters::maximum_size_ratio(maximum_size_ratio, FF::parameters::features_angle(features_angle))));
    return Surface_field::from_frame_field(points, faces, read_frame_field_file(field), features_angle);
  } catch(const Input_error&) {
    throw;
  } catch(const std::invalid_argument& e) {
    throw Input_error(is_surface_field_name(field) ? std::string(e.what()) : "'" + field + "': " + e.what());
  }
}

} // namespace internal
} // namespace vvm

#endif // VVM_FRONT_END_FRAME_FIELDS_H
