// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hex_dominant_mesh_3: the output of the hex-dominant mesher, a mixed volume
// mesh of hexahedra, prisms, pyramids and tetrahedra given as points and cells
// (vertex lists in VTK order), each cell with its subdomain index.

#ifndef CGAL_HEX_DOMINANT_MESH_3_H
#define CGAL_HEX_DOMINANT_MESH_3_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {

/// \ingroup PkgHexDominantMeshingRef
/// the kinds of cells of a `Hex_dominant_mesh_3`; the values are VTK's cell type numbers
enum class Hex_dominant_cell_type
{
  TETRAHEDRON = 10, ///< 4 vertices
  HEXAHEDRON = 12,  ///< 8 vertices
  PRISM = 13,       ///< 6 vertices (VTK's wedge)
  PYRAMID = 14      ///< 5 vertices
};

/// \ingroup PkgHexDominantMeshingRef
/// the number of vertices of a cell of type `t`
inline std::size_t number_of_vertices(Hex_dominant_cell_type t)
{
  switch(t) {
    case Hex_dominant_cell_type::TETRAHEDRON: return 4;
    case Hex_dominant_cell_type::HEXAHEDRON: return 8;
    case Hex_dominant_cell_type::PRISM: return 6;
    default: return 5;
  }
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 *
 * A hex-dominant volume mesh: points and cells. The vertices of a cell are listed in VTK's
 * order, every cell positively oriented (the first face's normal, by the right-hand rule,
 * points into the cell):
 * - tetrahedron `0 1 2 3`: `3` on the side of `0 1 2` its normal points to;
 * - hexahedron `0 1 2 3 4 5 6 7`: the quad `0 1 2 3`, then `4 5 6 7` above `0 1 2 3` in
 *   that order (edges `0-4`, `1-5`, `2-6`, `3-7`);
 * - prism `0 1 2 3 4 5`: the triangle `0 1 2`, then `3 4 5` above it (edges `0-3`, `1-4`, `2-5`);
 * - pyramid `0 1 2 3 4`: the quad `0 1 2 3`, then the apex `4`.
 *
 * These are the orders of Gmsh and MEDIT (as meshio reads them); VTK's wedge lists its first
 * triangle the other way round (its normal points away from `3 4 5`), so the VTU writer in
 * `CGAL/Hex_dominant_meshing/IO/` writes prisms as `0 2 1 3 5 4`.
 *
 * \tparam Point_3 a point type with `x()`, `y()`, `z()`
 */
template <class Point_3>
struct Hex_dominant_mesh_3
{
  typedef Point_3 Point;
  typedef Hex_dominant_cell_type Cell_type;

  struct Cell
  {
    Cell_type type = Cell_type::TETRAHEDRON;
    std::array<std::size_t, 8> vertices{}; ///< the first `number_of_vertices(type)` are used
    int subdomain_index = 1;               ///< the subdomain the cell lies in

    std::size_t size() const { return CGAL::number_of_vertices(type); }
    const std::size_t* begin() const { return vertices.data(); }
    const std::size_t* end() const { return vertices.data() + size(); }
  };

  std::vector<Point_3> points;
  std::vector<Cell> cells;

  std::size_t number_of_points() const { return points.size(); }
  std::size_t number_of_cells() const { return cells.size(); }
  /// the number of cells of type `t`
  std::size_t number_of_cells(Cell_type t) const
  {
    std::size_t n = 0;
    for(const Cell& c : cells) n += (c.type == t);
    return n;
  }
  void clear()
  {
    points.clear();
    cells.clear();
  }
};

} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESH_3_H
