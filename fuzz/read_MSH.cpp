// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the Gmsh .msh reader (2.2 and 4.1, ASCII and binary) of Hex_dominant_meshing,
// and its writer's round trip.

#include "volume_mesh_round_trip.h"

#include <CGAL/Hex_dominant_meshing/IO/read_MSH.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MSH.h>

VVM_FUZZ_TARGET(read_MSH)
{
  namespace IO = CGAL::Hex_dominant_meshing::IO;
  return vvm_fuzz::check_round_trip(
      data, size, [](std::istream& is, vvm_fuzz::Mesh& m) { IO::read_MSH(is, m); },
      [](std::ostream& os, const vvm_fuzz::Mesh& m) { IO::write_MSH(os, m); });
}
