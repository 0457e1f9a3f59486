// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh in the MEDIT ASCII format (.mesh), the subdomain index
// of each cell as its reference.

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_WRITE_MEDIT_H
#define CGAL_HEX_DOMINANT_MESHING_IO_WRITE_MEDIT_H

#include <CGAL/Hex_dominant_mesh_3.h>

#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <boost/io/ios_state.hpp>

#include <cstddef>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {

/*!
 * \ingroup PkgHexDominantMeshingRef
 * writes `mesh` to `os` in the MEDIT ASCII format (`.mesh`, `MeshVersionFormatted 1`
 * as CGAL's own MEDIT writers): the `Vertices` in the order of `mesh.points` with the
 * reference 0, then the sections `Tetrahedra`, `Hexahedra`, `Prisms` and `Pyramids` of
 * the cells present, each cell with 1-based vertex indices and its subdomain index as
 * its reference; within a section the cells keep their order in `mesh.cells`. The
 * vertices of each cell are written in the mesh's order, which is Gmsh's: Gmsh's own
 * MEDIT reader and writer (tetrahedra and hexahedra only) and MMG (which reorients
 * negative tetrahedra) use it as it is. The format itself fixes no orientation for
 * prisms and pyramids; meshio reads them in Gmsh's order as well. Numbers are written
 * with 17 significant digits; the precision of `os` is restored afterwards.
 * \throws std::runtime_error if the stream fails
 */
template <class Point_3>
void write_MEDIT(std::ostream& os, const Hex_dominant_mesh_3<Point_3>& mesh)
{
  typedef Hex_dominant_cell_type Cell_type;
  boost::io::ios_precision_saver saved_precision(os);
  os.precision(17);
  os << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << mesh.number_of_points() << "\n";
  for(const auto& p : mesh.points)
    os << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " " << CGAL::to_double(p.z()) << " 0\n";
  const std::pair<Cell_type, const char*> sections[] = {{Cell_type::TETRAHEDRON, "Tetrahedra"},
                                                        {Cell_type::HEXAHEDRON, "Hexahedra"},
                                                        {Cell_type::PRISM, "Prisms"},
                                                        {Cell_type::PYRAMID, "Pyramids"}};
  for(const auto& section : sections) {
    const std::size_t n = mesh.number_of_cells(section.first);
    if(n == 0) continue;
    os << section.second << "\n" << n << "\n";
    for(const auto& c : mesh.cells) {
      if(c.type != section.first) continue;
      for(std::size_t v : c) {
        CGAL_precondition(v < mesh.number_of_points());
        os << v + 1 << " ";
      }
      os << c.subdomain_index << "\n";
    }
  }
  os << "End\n";
  if(!os) throw std::runtime_error("write_MEDIT: the stream failed");
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * writes `mesh` to the file `filename` as `write_MEDIT(std::ostream&, mesh)` does.
 * \throws std::runtime_error if the file cannot be opened or written
 */
template <class Point_3>
void write_MEDIT(const std::string& filename, const Hex_dominant_mesh_3<Point_3>& mesh)
{
  std::ofstream os(filename);
  if(!os) throw std::runtime_error("write_MEDIT: cannot open " + filename);
  write_MEDIT(os, mesh);
}

} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_WRITE_MEDIT_H
