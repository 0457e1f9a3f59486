// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the frame-field text reader (CGAL/Frame_fields/IO/frame_field_text_format.h),
// the field's construction (frame inverses, the point location grid), a lookup at the
// field's first point, and the writer's round trip.

#include "fuzz_target.h"

#include <CGAL/Frame_fields/IO/frame_field_text_format.h>
#include <CGAL/Simple_cartesian.h>

#include <sstream>
#include <stdexcept>

VVM_FUZZ_TARGET(frame_field)
{
  typedef CGAL::Simple_cartesian<double> K;
  namespace FF = CGAL::Frame_fields;
  FF::Discrete_frame_field_3<K> field;
  try {
    std::istringstream is(vvm_fuzz::as_string(data, size));
    field = FF::IO::read_frame_field<K>(is);
    (void)field.B(field.points().front());
  } catch(const std::invalid_argument&) {
    return 0;
  }
  std::ostringstream os;
  FF::IO::write_frame_field(os, field);
  std::istringstream back(os.str());
  const FF::Discrete_frame_field_3<K> copy = FF::IO::read_frame_field<K>(back);
  if(copy.points() != field.points() || copy.cells() != field.cells() || copy.frames() != field.frames() ||
     copy.location() != field.location())
    vvm_fuzz::fuzz_failure("write then read changed the field");
  return 0;
}
