// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the .vtu reader of Hex_dominant_meshing (XML; ASCII, base64, appended and
// zlib-compressed data), and its writer's round trip.

#include "volume_mesh_round_trip.h"

#include <CGAL/Hex_dominant_meshing/IO/read_VTU.h>
#include <CGAL/Hex_dominant_meshing/IO/write_VTU.h>

VVM_FUZZ_TARGET(read_VTU)
{
  namespace IO = CGAL::Hex_dominant_meshing::IO;
  return vvm_fuzz::check_round_trip(
      data, size, [](std::istream& is, vvm_fuzz::Mesh& m) { IO::read_VTU(is, m); },
      [](std::ostream& os, const vvm_fuzz::Mesh& m) { IO::write_VTU(os, m); });
}
