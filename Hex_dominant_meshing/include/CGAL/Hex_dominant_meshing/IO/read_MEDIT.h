// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh from the MEDIT ASCII format (.mesh): the vertices and the
// tetrahedra, hexahedra, prisms and pyramids, the reference of each cell as
// its subdomain index; the other sections are skipped.

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_READ_MEDIT_H
#define CGAL_HEX_DOMINANT_MESHING_IO_READ_MEDIT_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/IO/internal/read_utilities.h>

#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <string>
#include <string_view>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {
namespace internal {

// The number of values of an entry of the MEDIT section `keyword` (lower case) that
// the reader skips, for Dimension 3 (libMeshb's keyword table, and the older names
// meshio reads); 0 for a keyword it does not know.
inline std::size_t medit_skipped_entry_size(const std::string& keyword)
{
  static const std::pair<const char*, std::size_t> sections[] = {
    {"edges", 3}, {"triangles", 4}, {"quadrilaterals", 5},
    {"edgesp2", 4}, {"trianglesp2", 7}, {"quadrilateralsq2", 10},
    {"corners", 1}, {"ridges", 1}, {"requiredvertices", 1}, {"requirededges", 1},
    {"requiredtriangles", 1}, {"requiredquadrilaterals", 1},
    {"normals", 3}, {"tangents", 3},
    {"normalatvertices", 2}, {"tangentatvertices", 2}, {"tangentatedgevertices", 3},
    {"normalattrianglevertices", 3}, {"normalatquadrilateralvertices", 4},
    {"subdomainfromgeom", 3}, {"subdomainfrommesh", 4},
    {"verticesongeometricvertices", 2}, {"verticesongeometricedges", 4},
    {"verticesongeometrictriangles", 5}, {"verticesongeometricquadrilaterals", 5},
    {"edgesongeometricedges", 2},
    {"trianglesongeometrictriangles", 2}, {"trianglesongeometricquadrilaterals", 2},
    {"quadrilateralsongeometrictriangles", 2}, {"quadrilateralsongeometricquadrilaterals", 2},
    {"vertexongeometricvertex", 2}, {"vertexongeometricedge", 3}, {"edgeongeometricedge", 2},
    {"periodicvertices", 2}, {"periodicedges", 2}, {"periodictriangles", 2}, {"periodicquadrilaterals", 2},
    {"coarsehexahedra", 1}};
  for(const auto& s : sections)
    if(keyword == s.first) return s.second;
  return 0;
}

template <class Point_3>
void read_MEDIT(const Read_input& in, Hex_dominant_mesh_3<Point_3>& mesh)
{
  typedef Hex_dominant_mesh_3<Point_3> Mesh;
  typedef Hex_dominant_cell_type Cell_type;
  Read_cursor c(in, true);
  Mesh read;

  const std::string_view first = c.token();
  if(lower_case(first) != "meshversionformatted")
    c.fail("not a MEDIT ASCII file: it does not start with MeshVersionFormatted");
  const int version = c.integer<int>("the version after MeshVersionFormatted");
  if(version < 1 || version > 4) c.fail("MeshVersionFormatted " + std::to_string(version) + " is not a MEDIT version (1 to 4)");

  bool have_dimension = false, have_vertices = false;
  for(;;) {
    const std::string_view token = c.token();
    if(token.empty()) break; // the end of the input: `End` is optional
    const std::string keyword = lower_case(token);
    if(keyword == "end") break;
    if(keyword == "dimension") {
      const int d = c.integer<int>("the dimension");
      if(d != 3) c.fail("Dimension " + std::to_string(d) + ": only volume meshes (Dimension 3) are read");
      have_dimension = true;
      continue;
    }
    if(keyword == "vertices") {
      if(!have_dimension) c.fail("Vertices come before Dimension");
      if(have_vertices) c.fail("two Vertices sections");
      have_vertices = true;
      const std::size_t n = c.count(c.integer<std::uint64_t>("the number of Vertices"), 8, "the Vertices section");
      read.points.reserve(n);
      for(std::size_t i = 0; i < n; ++i) {
        const double x = c.number("a vertex coordinate");
        const double y = c.number("a vertex coordinate");
        const double z = c.number("a vertex coordinate");
        c.number("the reference of a vertex");
        read.points.push_back(checked_point<Point_3>(c.name(), x, y, z));
      }
      continue;
    }
    const std::pair<const char*, Cell_type> cell_sections[] = {
      {"tetrahedra", Cell_type::TETRAHEDRON}, {"hexahedra", Cell_type::HEXAHEDRON},
      {"hexaedra", Cell_type::HEXAHEDRON}, {"prisms", Cell_type::PRISM}, {"pyramids", Cell_type::PYRAMID}};
    bool is_cell_section = false;
    for(const auto& section : cell_sections) {
      if(keyword != section.first) continue;
      is_cell_section = true;
      const std::string what = "the " + std::string(token) + " section";
      if(!have_vertices) c.fail(what + " comes before Vertices");
      const std::size_t size = number_of_vertices(section.second);
      const std::size_t n = c.count(c.integer<std::uint64_t>("the number of " + std::string(token)), 2 * (size + 1), what);
      read.cells.reserve(read.cells.size() + n);
      for(std::size_t k = 0; k < n; ++k) {
        typename Mesh::Cell cell;
        cell.type = section.second;
        for(std::size_t i = 0; i < size; ++i) {
          const std::uint64_t v = c.integer<std::uint64_t>("a vertex index in " + what);
          if(v == 0 || v > read.points.size())
            c.fail(std::string(token) + " entry " + std::to_string(k + 1) + " refers to vertex " + std::to_string(v) +
                   ", which does not exist (the vertices are numbered 1 to " + std::to_string(read.points.size()) + ")");
          cell.vertices[i] = static_cast<std::size_t>(v - 1);
        }
        cell.subdomain_index = c.integer<int>("the reference of an entry of " + what);
        read.cells.push_back(cell);
      }
      break;
    }
    if(is_cell_section) continue;
    if(keyword == "identifier" || keyword == "geometry") { // one string, maybe quoted
      const std::string_view s = c.expect_token("the string after " + std::string(token));
      if(s.front() == '"' && (s.size() == 1 || s.back() != '"')) {
        const std::size_t close = c.data().find('"', c.position());
        if(close == std::string::npos) c.truncated("the string after " + std::string(token) + " is not closed");
        c.set_position(close + 1);
      }
      continue;
    }
    if(keyword == "angleofcornerbound" || keyword == "iterations" || keyword == "time") { // one value, no count
      c.number("the value after " + std::string(token));
      continue;
    }
    const std::size_t entry_size = medit_skipped_entry_size(keyword);
    if(entry_size == 0) {
      if((token[0] >= 'a' && token[0] <= 'z') || (token[0] >= 'A' && token[0] <= 'Z'))
        c.fail("unknown keyword " + shown(token) + " (the size of its entries is unknown, so what follows cannot be read)");
      c.fail("expected a keyword, found " + shown(token));
    }
    const std::string what = "the " + std::string(token) + " section";
    const std::size_t n = c.count(c.integer<std::uint64_t>("the number of " + std::string(token)), 2 * entry_size, what);
    for(std::size_t k = 0; k < n * entry_size; ++k) {
      double ignored;
      const std::string_view t = c.expect_token("an entry of " + what);
      if(!parse_number(t, ignored)) c.fail("expected a number in " + what + ", found " + shown(t));
    }
  }
  if(!have_vertices) c.fail("no Vertices section");
  hand_over(read, mesh, in.name);
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * reads a volume mesh in the MEDIT ASCII format (`.mesh`) from `is` into `mesh`, the
 * counterpart of `write_MEDIT()`: `MeshVersionFormatted` 1 to 4, `Dimension 3`, and
 * keywords in any case, as MEDIT, meshio, CGAL, TetGen and Gmsh write them; `#` starts a
 * comment to the end of the line. The points are the `Vertices` in their order (their
 * references are ignored); the cells are the entries of the sections `Tetrahedra`,
 * `Hexahedra` (or `Hexaedra`), `Prisms` and `Pyramids` in the order of the file, their
 * 1-based vertex indices made 0-based and kept in the order of the file (MEDIT's order is
 * Gmsh's, the mesh's: nothing is reordered or reoriented), the reference of each entry
 * as its subdomain index. The sections whose entries have a known number of values
 * (`Edges`, `Triangles`, `Quadrilaterals`, `Corners`, `Ridges`, `RequiredVertices`,
 * `RequiredEdges`, `Normals`, `NormalAtVertices`, `Tangents`, `TangentAtVertices`, ...)
 * are skipped; `End` ends the mesh (it may be missing). Binary MEDIT (`.meshb`) and the
 * higher-order sections (`TetrahedraP2`, ...) are not read.
 *
 * `mesh` is left unchanged if an exception is thrown.
 * \throws std::invalid_argument naming `name` and the problem if the input is empty, is
 * not MEDIT, is truncated, has a keyword whose entries' size is unknown, a count larger
 * than the input can hold, a vertex index out of range, a non-finite coordinate, or no
 * tetrahedron, hexahedron, prism or pyramid
 */
template <class Point_3>
void read_MEDIT(std::istream& is, Hex_dominant_mesh_3<Point_3>& mesh, const std::string& name = "the MEDIT input")
{
  internal::read_MEDIT(internal::read_input_stream(is, name), mesh);
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * reads the file `filename` into `mesh` as `read_MEDIT(std::istream&, mesh)` does; the
 * messages of the exceptions name the file.
 * \throws std::invalid_argument if the file cannot be opened or read, or as
 * `read_MEDIT(std::istream&, mesh)` does
 */
template <class Point_3>
void read_MEDIT(const std::string& filename, Hex_dominant_mesh_3<Point_3>& mesh)
{
  internal::read_MEDIT(internal::read_input_file(filename), mesh);
}

} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_READ_MEDIT_H
