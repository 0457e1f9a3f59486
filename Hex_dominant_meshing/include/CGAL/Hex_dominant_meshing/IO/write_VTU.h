// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh as a VTK unstructured grid of mixed cells (tetrahedra,
// hexahedra, wedges, pyramids), with its cell types, subdomains and any
// per-cell fields as cell data, for ParaView.

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_WRITE_VTU_H
#define CGAL_HEX_DOMINANT_MESHING_IO_WRITE_VTU_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/VVM/internal/VTU_head.h>

#include <CGAL/assertions.h>

#include <boost/io/ios_state.hpp>

#include <cstddef>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {
namespace internal {

// The vertex of a cell that VTK puts at position `i`. VTK's wedge is the one cell whose
// order differs from `Hex_dominant_mesh_3`'s: the normal of its triangle 0 1 2 points
// away from 3 4 5 (vtkWedge's documentation and face table; Gmsh's own VTK export and
// meshio both swap 1<->2 and 4<->5), so it is mirrored to stay positively oriented.
template <class Cell>
std::size_t vtk_vertex(const Cell& c, std::size_t i)
{
  static const std::size_t wedge[6] = {0, 2, 1, 3, 5, 4};
  return c.type == Hex_dominant_cell_type::PRISM ? c.vertices[wedge[i]] : c.vertices[i];
}

// `name` with the characters that would end an XML attribute escaped
inline std::string xml_escaped(const std::string& name)
{
  std::string res;
  for(char ch : name) {
    switch(ch) {
      case '&': res += "&amp;"; break;
      case '<': res += "&lt;"; break;
      case '>': res += "&gt;"; break;
      case '"': res += "&quot;"; break;
      default: res += ch;
    }
  }
  return res;
}

template <class Point_3>
void check_cell_fields(const Hex_dominant_mesh_3<Point_3>& mesh,
                       const std::vector<std::pair<std::string, std::vector<double>>>& cell_fields)
{
  for(const auto& f : cell_fields)
    if(f.second.size() != mesh.number_of_cells())
      throw std::invalid_argument("write_VTU: the cell field '" + f.first + "' has " +
                                  std::to_string(f.second.size()) + " values for " +
                                  std::to_string(mesh.number_of_cells()) + " cells");
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * writes `mesh` to `os` as an ASCII VTK XML unstructured grid (`.vtu`): its points, its
 * cells in their order as VTK tetrahedra (10), hexahedra (12), wedges (13) and pyramids
 * (14), and as cell data the `Int32` arrays `cell_type` (the VTK type) and `subdomain`
 * (the subdomain index), then each of `cell_fields` as a `Float64` array of its name.
 * Prisms are written in VTK's wedge order (`0 2 1 3 5 4` of the mesh's), the other cells
 * as they are, so that every cell keeps a positive volume in VTK. Numbers are written
 * with 17 significant digits; the precision of `os` is restored afterwards.
 * \throws std::invalid_argument if a field does not have one value per cell (nothing is
 * written then)
 * \throws std::runtime_error if the stream fails
 */
template <class Point_3>
void write_VTU(std::ostream& os, const Hex_dominant_mesh_3<Point_3>& mesh,
               const std::vector<std::pair<std::string, std::vector<double>>>& cell_fields = {})
{
  internal::check_cell_fields(mesh, cell_fields);
  boost::io::ios_precision_saver saved_precision(os);
  os.precision(17);
  CGAL::VVM::internal::write_VTU_head(os, mesh.points, mesh.number_of_cells());
  for(const auto& c : mesh.cells) {
    for(std::size_t i = 0; i < c.size(); ++i) {
      CGAL_precondition(c.vertices[i] < mesh.number_of_points());
      os << (i == 0 ? "" : " ") << internal::vtk_vertex(c, i);
    }
    os << "\n";
  }
  os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for(const auto& c : mesh.cells) os << (offset += c.size()) << "\n";
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(const auto& c : mesh.cells) os << static_cast<int>(c.type) << "\n";
  os << "</DataArray>\n</Cells>\n<CellData Scalars=\"subdomain\">\n"
     << "<DataArray type=\"Int32\" Name=\"cell_type\" format=\"ascii\">\n";
  for(const auto& c : mesh.cells) os << static_cast<int>(c.type) << "\n";
  os << "</DataArray>\n<DataArray type=\"Int32\" Name=\"subdomain\" format=\"ascii\">\n";
  for(const auto& c : mesh.cells) os << c.subdomain_index << "\n";
  os << "</DataArray>\n";
  for(const auto& f : cell_fields) {
    os << "<DataArray type=\"Float64\" Name=\"" << internal::xml_escaped(f.first) << "\" format=\"ascii\">\n";
    for(double v : f.second) os << v << "\n";
    os << "</DataArray>\n";
  }
  os << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if(!os) throw std::runtime_error("write_VTU: the stream failed");
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * writes `mesh` to the file `filename` as `write_VTU(std::ostream&, mesh, cell_fields)` does.
 * \throws std::invalid_argument if a field does not have one value per cell (the file is
 * not created then)
 * \throws std::runtime_error if the file cannot be opened or written
 */
template <class Point_3>
void write_VTU(const std::string& filename, const Hex_dominant_mesh_3<Point_3>& mesh,
               const std::vector<std::pair<std::string, std::vector<double>>>& cell_fields = {})
{
  internal::check_cell_fields(mesh, cell_fields);
  std::ofstream os(filename);
  if(!os) throw std::runtime_error("write_VTU: cannot open " + filename);
  write_VTU(os, mesh, cell_fields);
}

} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_WRITE_VTU_H
