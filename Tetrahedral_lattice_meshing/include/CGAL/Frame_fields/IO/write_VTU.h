// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A discrete frame field as a VTK unstructured grid, its three axes as
// vector arrays, for ParaView glyphs; and its singular edges as lines.

#ifndef CGAL_FRAME_FIELDS_IO_WRITE_VTU_H
#define CGAL_FRAME_FIELDS_IO_WRITE_VTU_H

#include <CGAL/Frame_fields/Discrete_frame_field_3.h>
#include <CGAL/Frame_fields/Singular_curve.h>
#include <CGAL/VVM/internal/VTU_head.h>

#include <CGAL/number_utils.h>

#include <boost/io/ios_state.hpp>

#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace IO {
namespace internal {

// the end of the connectivity, the offsets (cells of `size` vertices) and the types
inline void write_VTU_cell_types(std::ostream& os, std::size_t number_of_cells, std::size_t size, int vtk_type)
{
  os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for(std::size_t i = 1; i <= number_of_cells; ++i) os << size * i << "\n";
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t i = 0; i < number_of_cells; ++i) os << vtk_type << "\n";
  os << "</DataArray>\n</Cells>\n";
}

} // namespace internal

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFieldsIO
 * writes `field` to `os` as an ASCII VTK XML unstructured grid (`.vtu`): its points, its
 * tetrahedra (or, if it has none, one vertex cell per point), and the three axes of the
 * frames (the columns of \f$ T \f$) as the vector arrays `axis_1`, `axis_2`, `axis_3`,
 * point data for a field on vertices, cell data for a field on cells. In ParaView, a
 * Glyph filter per array shows the frames. Numbers are written with 17 significant
 * digits; the precision of `os` is restored afterwards.
 * \throws std::runtime_error if the stream fails
 */
template <class GeomTraits>
void write_VTU(std::ostream& os, const Discrete_frame_field_3<GeomTraits>& field)
{
  const auto& points = field.points();
  const auto& cells = field.cells();
  const bool have_cells = !cells.empty();
  const std::size_t n_cells = have_cells ? cells.size() : points.size();
  boost::io::ios_precision_saver saved_precision(os);
  os.precision(17);
  VVM::internal::write_VTU_head(os, points, n_cells);
  if(have_cells)
    for(const auto& c : cells) os << c[0] << " " << c[1] << " " << c[2] << " " << c[3] << "\n";
  else
    for(std::size_t i = 0; i < points.size(); ++i) os << i << "\n";
  internal::write_VTU_cell_types(os, n_cells, have_cells ? 4 : 1, have_cells ? 10 : 1); // VTK_TETRA, VTK_VERTEX
  // a field on cells with no tets cannot exist (the constructor refuses it)
  const char* section = field.location() == Frame_location::VERTICES ? "PointData" : "CellData";
  os << "<" << section << " Vectors=\"axis_1\">\n";
  for(int a = 0; a < 3; ++a) {
    os << "<DataArray type=\"Float64\" Name=\"axis_" << a + 1
       << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for(const auto& T : field.frames()) os << T(0, a) << " " << T(1, a) << " " << T(2, a) << "\n";
    os << "</DataArray>\n";
  }
  os << "</" << section << ">\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if(!os) throw std::runtime_error("write_VTU: the stream failed");
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFieldsIO
 * writes the segments `edges` (pairs of indices into `points`) to `os` as an ASCII VTK
 * XML unstructured grid of lines, e.g. the singular edges of a generated cross field:
 * `write_edges_VTU(os, g.field.points(), g.singular_edges)`. Numbers are written with 17
 * significant digits; the precision of `os` is restored afterwards.
 * \throws std::runtime_error if the stream fails
 */
template <class Point_3, class Edge>
void write_edges_VTU(std::ostream& os, const std::vector<Point_3>& points, const std::vector<Edge>& edges)
{
  boost::io::ios_precision_saver saved_precision(os);
  os.precision(17);
  VVM::internal::write_VTU_head(os, points, edges.size());
  for(const auto& e : edges) os << e[0] << " " << e[1] << "\n";
  internal::write_VTU_cell_types(os, edges.size(), 2, 3); // VTK_LINE
  os << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if(!os) throw std::runtime_error("write_edges_VTU: the stream failed");
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFieldsIO
 * writes `curves` (e.g. `Generated_cross_field_3::singular_curves`, indices into `points`)
 * to `os` as an ASCII VTK XML unstructured grid of polylines, with the cell data `length`
 * and `closed` (1 for a loop). Numbers are written with 17 significant digits; the
 * precision of `os` is restored afterwards.
 * \throws std::runtime_error if the stream fails
 */
template <class Point_3>
void write_polylines_VTU(std::ostream& os, const std::vector<Point_3>& points,
                         const std::vector<Singular_curve>& curves)
{
  boost::io::ios_precision_saver saved_precision(os);
  os.precision(17);
  VVM::internal::write_VTU_head(os, points, curves.size());
  for(const Singular_curve& c : curves) {
    for(std::size_t v : c.vertices) os << v << " ";
    os << "\n";
  }
  os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for(const Singular_curve& c : curves) os << (offset += c.vertices.size()) << "\n";
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t i = 0; i < curves.size(); ++i) os << "4\n"; // VTK_POLY_LINE
  os << "</DataArray>\n</Cells>\n<CellData>\n<DataArray type=\"Float64\" Name=\"length\" format=\"ascii\">\n";
  for(const Singular_curve& c : curves) os << c.length << "\n";
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"closed\" format=\"ascii\">\n";
  for(const Singular_curve& c : curves) os << (c.is_closed() ? 1 : 0) << "\n";
  os << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if(!os) throw std::runtime_error("write_polylines_VTU: the stream failed");
}

} // namespace IO
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_IO_WRITE_VTU_H
