// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The start of the ASCII VTU files that the frame field and hex-dominant
// writers make.

#ifndef CGAL_VVM_INTERNAL_VTU_HEAD_H
#define CGAL_VVM_INTERNAL_VTU_HEAD_H

#include <CGAL/number_utils.h>

#include <cstddef>
#include <ostream>
#include <vector>

namespace CGAL {
namespace VVM {
namespace internal {

/// the XML header, the points and the opening of the connectivity array of a VTU file
template <class Point_3>
void write_VTU_head(std::ostream& os, const std::vector<Point_3>& points, std::size_t number_of_cells)
{
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\""
     << number_of_cells << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const auto& p : points)
    os << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " " << CGAL::to_double(p.z()) << "\n";
  os << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
}

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_VTU_HEAD_H
