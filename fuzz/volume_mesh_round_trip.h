// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reader targets' shared check: what a reader accepts, its writer writes and the
// reader reads back; from then on the mesh is a fixed point (write, read: the same points,
// cells and labels, exactly: the writers write 17 significant digits).

#ifndef VVM_FUZZ_VOLUME_MESH_ROUND_TRIP_H
#define VVM_FUZZ_VOLUME_MESH_ROUND_TRIP_H

#include "fuzz_target.h"

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Simple_cartesian.h>

#include <sstream>
#include <stdexcept>

namespace vvm_fuzz {

typedef CGAL::Simple_cartesian<double>::Point_3 Point;
typedef CGAL::Hex_dominant_mesh_3<Point> Mesh;

inline bool same(const Mesh& a, const Mesh& b)
{
  if(a.points.size() != b.points.size() || a.cells.size() != b.cells.size()) return false;
  for(std::size_t i = 0; i < a.points.size(); ++i)
    if(a.points[i] != b.points[i]) return false;
  for(std::size_t i = 0; i < a.cells.size(); ++i) {
    const Mesh::Cell &c = a.cells[i], &d = b.cells[i];
    if(c.type != d.type || c.subdomain_index != d.subdomain_index) return false;
    for(std::size_t k = 0; k < c.size(); ++k)
      if(c.vertices[k] != d.vertices[k]) return false;
  }
  return true;
}

/// reads `data` with `read(istream&, Mesh&)`; if it is accepted, checks that
/// `write(ostream&, const Mesh&)` then `read` reach a fixed point. A writer may refuse a mesh
/// its format cannot hold (std::invalid_argument, e.g. Gmsh's non-positive tags).
template <class Read, class Write>
int check_round_trip(const std::uint8_t* data, std::size_t size, const Read& read, const Write& write)
{
  Mesh mesh;
  try {
    std::istringstream is(as_string(data, size));
    read(is, mesh);
  } catch(const std::invalid_argument&) {
    return 0; // refused, with a message: what bad input must get
  }
  Mesh once, twice;
  std::string first;
  try {
    std::ostringstream os;
    write(os, mesh);
    first = os.str();
  } catch(const std::invalid_argument&) {
    return 0;
  }
  std::istringstream is1(first);
  read(is1, once); // a file the writer wrote must be read: no catch
  std::ostringstream os2;
  write(os2, once);
  std::istringstream is2(os2.str());
  read(is2, twice);
  if(!same(once, twice)) fuzz_failure("write then read is not a fixed point");
  if(once.cells.size() != mesh.cells.size()) fuzz_failure("the round trip lost or added cells");
  return 0;
}

} // namespace vvm_fuzz

#endif // VVM_FUZZ_VOLUME_MESH_ROUND_TRIP_H
