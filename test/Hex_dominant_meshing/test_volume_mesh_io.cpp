// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The volume mesh readers of Hex_dominant_meshing (read_MEDIT, read_MSH, read_VTU,
// read_volume_mesh) on a hand-made mixed mesh (a hexahedron, a prism, a pyramid and two
// tetrahedra in the subdomains 3 and 7, and an unused point), unit tests:
// - round trips through the writers give the mesh back;
// - hand-written inputs with extra sections, sparse node tags, skipped cells: MEDIT, MSH
//   2.2 and 4.1 in ASCII and binary (bytes built here), VTU ASCII, base64 binary,
//   zlib-compressed (compressed here), appended raw and base64;
// - files written by meshio 5, by VTK 9.1's XML writer (ParaView's) and by Gmsh 4.8
//   (data/mesh_io/, made by make_mesh_io_files.py there): the counts meshio reads;
// - bad inputs throw std::invalid_argument naming the file and the problem, and leave
//   the mesh unchanged; every truncation and many random mutations of the inputs either
//   read or throw std::invalid_argument.

#include "vvm_test.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/IO/read_volume_mesh.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Hex_dominant_mesh_3<Point> Mesh;
typedef Mesh::Cell Cell;
typedef CGAL::Hex_dominant_cell_type Cell_type;

namespace IO = CGAL::Hex_dominant_meshing::IO;

namespace {

Cell make_cell(Cell_type t, std::vector<std::size_t> v, int subdomain)
{
  Cell c;
  c.type = t;
  std::copy(v.begin(), v.end(), c.vertices.begin());
  c.subdomain_index = subdomain;
  return c;
}

// The hexahedron [0,1]^3 and the pyramid on its top (subdomain 3), the prism beside it
// and two tetrahedra on its face x = 0 (subdomain 7), and an unused point; the
// coordinates need all 17 digits. The same mesh as data/mesh_io/make_mesh_io_files.py's.
const double mixed_points[13][3] = {
  {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {2, 0, 0}, {2, 0, 1},
  {0.5, 0.5, 1.6180339887498949}, {-0.7, 1.0 / 3.0, 0.1}, {3.0000000000000004, -2.5e-7, 12345.678}};

Mesh mixed_mesh()
{
  Mesh m;
  for(const auto& p : mixed_points) m.points.push_back(Point(p[0], p[1], p[2]));
  m.cells.push_back(make_cell(Cell_type::HEXAHEDRON, {0, 1, 2, 3, 4, 5, 6, 7}, 3));
  m.cells.push_back(make_cell(Cell_type::PRISM, {1, 8, 2, 5, 9, 6}, 7));
  m.cells.push_back(make_cell(Cell_type::PYRAMID, {4, 5, 6, 7, 10}, 3));
  m.cells.push_back(make_cell(Cell_type::TETRAHEDRON, {0, 7, 3, 11}, 7));
  m.cells.push_back(make_cell(Cell_type::TETRAHEDRON, {0, 4, 7, 11}, 7));
  return m;
}

// the cells of `m` in the order write_MEDIT writes them: by section, then as in `m`
std::vector<Cell> medit_order(const Mesh& m)
{
  std::vector<Cell> res;
  for(Cell_type t : {Cell_type::TETRAHEDRON, Cell_type::HEXAHEDRON, Cell_type::PRISM, Cell_type::PYRAMID})
    for(const Cell& c : m.cells)
      if(c.type == t) res.push_back(c);
  return res;
}

bool same_cell(const Cell& a, const Cell& b)
{
  return a.type == b.type && a.subdomain_index == b.subdomain_index && std::equal(a.begin(), a.end(), b.begin());
}

// true if the points are the same to `tolerance` (0: exactly) and the cells are `cells`
bool same_mesh(const Mesh& m, const std::vector<Point>& points, const std::vector<Cell>& cells, double tolerance = 0)
{
  bool ok = m.points.size() == points.size() && m.cells.size() == cells.size();
  for(std::size_t i = 0; ok && i < points.size(); ++i)
    for(int k = 0; k < 3; ++k)
      ok = ok && std::abs(m.points[i][k] - points[i][k]) <= tolerance * (1 + std::abs(points[i][k]));
  for(std::size_t i = 0; ok && i < cells.size(); ++i) ok = same_cell(m.cells[i], cells[i]);
  if(!ok) {
    std::cerr << "    read " << m.points.size() << " points and " << m.cells.size() << " cells:\n";
    for(const Cell& c : m.cells) {
      std::cerr << "      type " << int(c.type) << " subdomain " << c.subdomain_index << ":";
      for(std::size_t v : c) std::cerr << " " << v;
      std::cerr << "\n";
    }
  }
  return ok;
}

bool same_mesh(const Mesh& m, const Mesh& expected, double tolerance = 0)
{
  return same_mesh(m, expected.points, expected.cells, tolerance);
}

// every cell cut into tetrahedra in its own vertex order has positive volumes
bool positively_oriented(const Mesh& m)
{
  static const std::vector<std::vector<int>> cuts[4] = {
    {{0, 1, 2, 3}},
    {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}},
    {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}},
    {{0, 1, 2, 4}, {0, 2, 3, 4}}};
  for(const Cell& c : m.cells) {
    const int k = c.type == Cell_type::TETRAHEDRON ? 0 : c.type == Cell_type::HEXAHEDRON ? 1 : c.type == Cell_type::PRISM ? 2 : 3;
    for(const auto& t : cuts[k])
      if(CGAL::volume(m.points[c.vertices[t[0]]], m.points[c.vertices[t[1]]], m.points[c.vertices[t[2]]],
                      m.points[c.vertices[t[3]]]) <= 0)
        return false;
  }
  return true;
}

Mesh read_MEDIT_string(const std::string& s)
{
  std::istringstream is(s);
  Mesh m;
  IO::read_MEDIT(is, m);
  return m;
}

Mesh read_MSH_string(const std::string& s)
{
  std::istringstream is(s);
  Mesh m;
  IO::read_MSH(is, m);
  return m;
}

Mesh read_VTU_string(const std::string& s,
                     const std::vector<std::string>& names = IO::default_VTU_subdomain_array_names())
{
  std::istringstream is(s);
  Mesh m;
  IO::read_VTU(is, m, names);
  return m;
}

void write_file(const std::string& name, const std::string& content)
{
  std::ofstream os(name, std::ios::binary);
  os << content;
}

std::string file_contents(const std::string& name)
{
  std::ifstream is(name, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(is), std::istreambuf_iterator<char>());
}

// little-endian binary data
struct Bytes
{
  std::string s;
  Bytes& text(const std::string& t) { s += t; return *this; }
  Bytes& u(std::uint64_t v, int n)
  {
    for(int i = 0; i < n; ++i) s += static_cast<char>((v >> (8 * i)) & 0xff);
    return *this;
  }
  Bytes& i32(std::int64_t v) { return u(static_cast<std::uint64_t>(v), 4); }
  Bytes& u64(std::uint64_t v) { return u(v, 8); }
  Bytes& f64(double d)
  {
    std::uint64_t v;
    std::memcpy(&v, &d, 8);
    return u64(v);
  }
  Bytes& f32(float f)
  {
    std::uint32_t v;
    std::memcpy(&v, &f, 4);
    return u(v, 4);
  }
};

std::string base64(const std::string& bytes)
{
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string res;
  for(std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = 0;
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    for(std::size_t k = 0; k < 3; ++k)
      v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for(std::size_t k = 0; k < 4; ++k) res += k <= n ? table[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return res;
}

std::string zlib_compressed(const std::string& bytes)
{
  uLongf length = compressBound(static_cast<uLong>(bytes.size()));
  std::string out(length, '\0');
  const int status = compress(reinterpret_cast<Bytef*>(&out[0]), &length,
                              reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uLong>(bytes.size()));
  if(status != Z_OK) throw std::runtime_error("compress failed");
  out.resize(length);
  return out;
}

// -1 if reading `input` throws something else than std::invalid_argument, 0 if it
// throws std::invalid_argument, 1 if it reads
int outcome(const std::function<void()>& read)
{
  try {
    read();
    return 1;
  } catch(const std::invalid_argument&) {
    return 0;
  } catch(...) {
    return -1;
  }
}

// ---------------------------------------------------------------------------------
// hand-written inputs: the mixed mesh, or parts of it, in every format

// MEDIT with comments, keywords in any case, `Dimension` and its value on two lines, and
// the sections a reader skips
const char* medit_with_extra_sections = R"(# written by hand
  MeshVersionFormatted 2
dimension
3
# the vertices of the mixed mesh
Vertices
13
0 0 0 1
1 0 0 1
1 1 0 1
0 1 0 1
0 0 1 0
1 0 1 0
1 1 1 0
0 1 1 0
2 0 0 0
2 0 1 0
0.5 0.5 1.6180339887498949 0
-0.69999999999999996 0.33333333333333331 0.10000000000000001 2
3.0000000000000004 -2.4999999999999999e-07 12345.678 -1
Identifier
"a mixed mesh"
EDGES
2
1 2 5
2 3 5
Triangles
1
1 2 3 4
Quadrilaterals 1
1 2 3 4 9
Corners
2 1 9
RequiredVertices
1
1
Ridges
1
2
RequiredEdges
1 1
Normals
1
0 0 1
NormalAtVertices
1
1 1
Tangents
2
1 0 0
0 1 0
TangentAtVertices
2
1 1
2 2
Hexahedra
1
1 2 3 4 5 6 7 8 3
Tetrahedra
2
1 8 4 12 7
1 5 8 12 7   # a comment after an entry
Prisms
1
2 9 3 6 10 7 7
pyramids
1
5 6 7 8 11 3
End
)";

// MSH 2.2 ASCII: sparse, shuffled node tags; points, lines, triangles and quadrangles to
// skip; an element without tags (subdomain 1); sections to skip
const char* msh22_ascii = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Comments
this section is skipped, even its $Nodes
$EndComments
$PhysicalNames
2
3 3 "inside"
3 7 "outside"
$EndPhysicalNames
$Nodes
13
10 0 0 0
20 1 0 0
30 1 1 0
40 0 1 0
50 0 0 1
60 1 0 1
70 1 1 1
80 0 1 1
90 2 0 0
100 2 0 1
110 0.5 0.5 1.6180339887498949
5 -0.69999999999999996 0.33333333333333331 0.10000000000000001
1000 3.0000000000000004 -2.4999999999999999e-07 12345.678
$EndNodes
$Elements
9
1 15 2 0 1 10
2 1 2 0 1 10 20
3 2 2 0 1 10 20 30
4 3 2 0 1 10 20 30 40
5 5 2 3 1 10 20 30 40 50 60 70 80
6 6 2 7 2 20 90 30 60 100 70
7 7 2 3 1 50 60 70 80 110
8 4 2 7 2 10 80 40 5
9 4 0 10 50 80 5
$EndElements
$NodeData
1
"temperature"
1
0.0
3
0
1
1
10 1.0
$EndNodeData
)";

// the mesh read from msh22_ascii: points in the order of their tags
Mesh msh22_expected()
{
  const Mesh m = mixed_mesh();
  Mesh e;
  e.points.push_back(m.points[11]); // tag 5
  for(std::size_t i = 0; i < 11; ++i) e.points.push_back(m.points[i]);
  e.points.push_back(m.points[12]);
  auto v = [](std::size_t i) { return i == 11 ? std::size_t(0) : i == 12 ? i : i + 1; };
  for(const Cell& c : m.cells) {
    Cell d = c;
    for(std::size_t i = 0; i < c.size(); ++i) d.vertices[i] = v(c.vertices[i]);
    e.cells.push_back(d);
  }
  e.cells.back().subdomain_index = 1; // no tag
  return e;
}

// MSH 4.1 ASCII: $Entities with physical tags (volume 5 has none: its tag), node blocks
// on several entities with sparse unordered tags and a parametric block, a triangle block
// to skip, element tags out of order, sections to skip
const char* msh41_ascii = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
3 30 "inside"
$EndPhysicalNames
$Entities
1 1 1 3
1 0 0 0 0
1 0 0 0 1 0 0 0 2 1 -1
1 0 0 0 1 1 0 1 12 3 1 2 -3
1 -1 0 0 1 1 2 2 30 31 1 1
2 1 0 0 2 1 1 1 70 1 1
5 -1 0 0 0 1 1 0 1 1
$EndEntities
$Nodes
4 13 1 1007
0 1 0 1
1007
0 0 0
2 1 1 3
2
3
4
1 0 0 0.1 0.2
1 1 0 0.3 0.4
0 1 0 0.5 0.6
3 1 0 8
5
6
7
8
9
10
11
12
2 0 0
2 0 1
0.5 0.5 1.6180339887498949
-0.69999999999999996 0.33333333333333331 0.10000000000000001
1 0 1
1 1 1
0 1 1
3.0000000000000004 -2.4999999999999999e-07 12345.678
3 2 0 1
13
0 0 1
$EndNodes
$Elements
5 6 1 40
2 1 2 1
40 1007 2 3
3 1 5 1
10 1007 2 3 4 13 9 10 11
3 2 6 1
20 2 5 3 9 6 10
3 1 7 1
30 13 9 10 11 7
3 5 4 2
32 1007 11 4 8
31 1007 13 11 8
$EndElements
$Periodic
0
$EndPeriodic
)";

// the mesh read from msh41_ascii: the node tags 2..13 and 1007 are the points
// 1 2 3 8 9 10 11 5 6 7 12 4 and 0 of the mixed mesh
Mesh msh41_expected()
{
  const Mesh m = mixed_mesh();
  const std::size_t tag_order[13] = {1, 2, 3, 8, 9, 10, 11, 5, 6, 7, 12, 4, 0}; // mixed index of each point
  Mesh e;
  std::vector<std::size_t> index(13);
  for(std::size_t i = 0; i < 13; ++i) {
    e.points.push_back(m.points[tag_order[i]]);
    index[tag_order[i]] = i;
  }
  // the element tags 10 (hex), 20 (prism), 30 (pyramid), 31, 32 (tets, in tag order)
  const std::size_t order[5] = {0, 1, 2, 4, 3};
  const int subdomains[5] = {30, 70, 30, 5, 5};
  for(std::size_t k = 0; k < 5; ++k) {
    Cell d = m.cells[order[k]];
    for(std::size_t i = 0; i < d.size(); ++i) d.vertices[i] = index[d.vertices[i]];
    d.subdomain_index = subdomains[k];
    e.cells.push_back(d);
  }
  return e;
}

// the mixed mesh in binary MSH 2.2: node tags 1..13, element tags k + 1, a line to skip
std::string msh22_binary()
{
  const Mesh m = mixed_mesh();
  Bytes b;
  b.text("$MeshFormat\n2.2 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n13\n");
  for(std::size_t i = 0; i < m.points.size(); ++i)
    b.i32(std::int64_t(i) + 1).f64(m.points[i].x()).f64(m.points[i].y()).f64(m.points[i].z());
  b.text("\n$EndNodes\n$Elements\n6\n");
  b.i32(1).i32(1).i32(2).i32(100).i32(3).i32(7).i32(1).i32(2); // a line, two tags
  const int gmsh_type[15] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4, 0, 5, 6, 7};
  for(std::size_t k = 0; k < m.cells.size(); ++k) {
    const Cell& c = m.cells[k];
    b.i32(gmsh_type[int(c.type)]).i32(1).i32(2);
    b.i32(std::int64_t(k) + 1).i32(c.subdomain_index).i32(99);
    for(std::size_t v : c) b.i32(std::int64_t(v) + 1);
  }
  b.text("\n$EndElements\n");
  return b.s;
}

// the mixed mesh in binary MSH 4.1: $Entities (volumes 1 and 2, physical tags 3 and 7),
// node tags 2i + 2 in two blocks, a triangle block to skip
std::string msh41_binary()
{
  const Mesh m = mixed_mesh();
  Bytes b;
  b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n$Entities\n");
  b.u64(0).u64(0).u64(1).u64(2);
  b.i32(4).f64(0).f64(0).f64(0).f64(1).f64(1).f64(1).u64(0).u64(0); // a surface
  b.i32(1).f64(0).f64(0).f64(0).f64(1).f64(1).f64(1).u64(1).i32(3).u64(1).i32(4);
  b.i32(2).f64(0).f64(0).f64(0).f64(1).f64(1).f64(1).u64(2).i32(7).i32(8).u64(1).i32(-4);
  b.text("\n$EndEntities\n$Nodes\n");
  b.u64(2).u64(13).u64(2).u64(26);
  b.i32(3).i32(1).i32(0).u64(5);
  for(std::uint64_t i = 0; i < 5; ++i) b.u64(2 * i + 2);
  for(std::size_t i = 0; i < 5; ++i) b.f64(m.points[i].x()).f64(m.points[i].y()).f64(m.points[i].z());
  b.i32(3).i32(2).i32(0).u64(8);
  for(std::uint64_t i = 5; i < 13; ++i) b.u64(2 * i + 2);
  for(std::size_t i = 5; i < 13; ++i) b.f64(m.points[i].x()).f64(m.points[i].y()).f64(m.points[i].z());
  b.text("\n$EndNodes\n$Elements\n");
  b.u64(5).u64(6).u64(1).u64(100);
  b.i32(2).i32(4).i32(2).u64(1).u64(100).u64(2).u64(4).u64(6); // a triangle
  const int gmsh_type[15] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4, 0, 5, 6, 7};
  for(std::size_t k = 0; k < 3; ++k) {
    const Cell& c = m.cells[k];
    b.i32(3).i32(c.subdomain_index == 3 ? 1 : 2).i32(gmsh_type[int(c.type)]).u64(1);
    b.u64(k + 1);
    for(std::size_t v : c) b.u64(2 * v + 2);
  }
  b.i32(3).i32(2).i32(4).u64(2);
  for(std::size_t k = 3; k < 5; ++k) {
    b.u64(k + 1);
    for(std::size_t v : m.cells[k]) b.u64(2 * v + 2);
  }
  b.text("\n$EndElements\n");
  return b.s;
}

// VTU ASCII as ParaView writes it (an InformationKey in the Points array, point data),
// with a vertex and a triangle to skip, the wedge in VTK's order, Float32 points,
// `subdomain` preferred to `medit:ref`
const char* vtu_ascii = R"(<?xml version="1.0"?>
<!-- a comment -->
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <UnstructuredGrid>
    <Piece NumberOfPoints="6" NumberOfCells="4">
      <PointData Scalars="t">
        <DataArray type="Float64" Name="t" format="ascii">1 2 3 4 5 6</DataArray>
      </PointData>
      <CellData>
        <DataArray type="Int32" Name="medit:ref" format="ascii">9 9 9 9</DataArray>
        <DataArray type="Int16" Name="subdomain" format="ascii">
          1 -4 5 1
        </DataArray>
      </CellData>
      <Points>
        <DataArray type="Float32" Name="Points" NumberOfComponents="3" format="ascii" RangeMin="0" RangeMax="1.4142135624">
          <InformationKey name="L2_NORM_RANGE" location="vtkDataArray" length="2">
            <Value index="0">
              0
            </Value>
            <Value index="1">
              1.4142135624
            </Value>
          </InformationKey>
          0 0 0   1 0 0   0 1 0
          0 0 1   1 0 1   0 1 1
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int64" Name="connectivity" format="ascii">
          0   0 1 2 3   0 2 1 3 5 4   0 1 2
        </DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">1 5 11 14</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">1 10 13 5</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)";

Mesh small_expected(int tet_subdomain = -4, int prism_subdomain = 5)
{
  Mesh e;
  const double p[6][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  for(const auto& q : p) e.points.push_back(Point(q[0], q[1], q[2]));
  e.cells.push_back(make_cell(Cell_type::TETRAHEDRON, {0, 1, 2, 3}, tet_subdomain));
  e.cells.push_back(make_cell(Cell_type::PRISM, {0, 1, 2, 3, 4, 5}, prism_subdomain));
  return e;
}

// the arrays of the mixed mesh as VTU writes them: points, connectivity (wedges in VTK's
// order), offsets, types, subdomains; as raw little-endian bytes
struct Vtu_arrays
{
  std::string points, connectivity, offsets, types, subdomains;
};

Vtu_arrays mixed_arrays()
{
  const Mesh m = mixed_mesh();
  Bytes points, connectivity, offsets, types, subdomains;
  for(const Point& p : m.points) points.f64(p.x()).f64(p.y()).f64(p.z());
  std::size_t offset = 0;
  for(const Cell& c : m.cells) {
    static const std::size_t wedge[6] = {0, 2, 1, 3, 5, 4};
    for(std::size_t i = 0; i < c.size(); ++i)
      connectivity.u64(c.vertices[c.type == Cell_type::PRISM ? wedge[i] : i]);
    offsets.u64(offset += c.size());
    types.u(static_cast<std::uint64_t>(c.type), 1);
    subdomains.i32(c.subdomain_index);
  }
  return {points.s, connectivity.s, offsets.s, types.s, subdomains.s};
}

// a VTU file of the mixed mesh whose five arrays are `data` (each given as the text of
// its DataArray) or appended (then `data` holds the offset attributes)
std::string vtu_file(const std::string& root_attributes, const std::vector<std::string>& data,
                     const std::string& format, const std::string& appended = "")
{
  const bool is_appended = format == "appended";
  auto array = [&](const char* type, const char* name, const char* extra, const std::string& d) {
    return std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" " + extra + " format=\"" + format +
           "\"" + (is_appended ? " offset=\"" + d + "\"/>\n" : ">" + d + "</DataArray>\n");
  };
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" " + root_attributes +
                  ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"13\" NumberOfCells=\"5\">\n<Points>\n" +
                  array("Float64", "Points", "NumberOfComponents=\"3\"", data[0]) + "</Points>\n<Cells>\n" +
                  array("Int64", "connectivity", "", data[1]) + array("Int64", "offsets", "", data[2]) +
                  array("UInt8", "types", "", data[3]) + "</Cells>\n<CellData>\n" +
                  array("Int32", "gmsh:physical", "", data[4]) + "</CellData>\n</Piece>\n</UnstructuredGrid>\n";
  if(is_appended) s += appended;
  return s + "</VTKFile>\n";
}

std::vector<std::string> arrays_as_list(const Vtu_arrays& a)
{
  return {a.points, a.connectivity, a.offsets, a.types, a.subdomains};
}

// inline base64 with a UInt32 header: header and data encoded together (meshio's way) for
// the points and the offsets, apart (VTK's way, each padded) for the others
std::string vtu_base64()
{
  std::vector<std::string> data;
  int k = 0;
  for(const std::string& a : arrays_as_list(mixed_arrays())) {
    const std::string header = Bytes().u(a.size(), 4).s;
    data.push_back(k % 2 == 0 ? base64(header + a) : base64(header) + "\n   " + base64(a));
    ++k;
  }
  return vtu_file("byte_order=\"LittleEndian\"", data, "binary");
}

// zlib-compressed inline binary with UInt32 headers, blocks of 64 bytes (the points and
// connectivity take several), the last block partial
std::string vtu_zlib(std::size_t block_size = 64)
{
  std::vector<std::string> data;
  for(const std::string& a : arrays_as_list(mixed_arrays())) {
    std::vector<std::string> blocks;
    for(std::size_t i = 0; i < a.size(); i += block_size) blocks.push_back(zlib_compressed(a.substr(i, block_size)));
    Bytes header;
    header.u(blocks.size(), 4).u(block_size, 4).u(a.size() - (blocks.size() - 1) * block_size, 4);
    std::string all;
    for(const std::string& b : blocks) header.u(b.size(), 4), all += b;
    data.push_back(base64(header.s) + base64(all));
  }
  return vtu_file("byte_order=\"LittleEndian\" compressor=\"vtkZLibDataCompressor\"", data, "binary");
}

// appended raw data with UInt64 headers (bytes of all values, '<' and '_' among them)
std::string vtu_appended_raw()
{
  std::vector<std::string> offsets;
  std::string raw;
  for(const std::string& a : arrays_as_list(mixed_arrays())) {
    offsets.push_back(std::to_string(raw.size()));
    raw += Bytes().u64(a.size()).s + a;
  }
  return vtu_file("byte_order=\"LittleEndian\" header_type=\"UInt64\"", offsets, "appended",
                  "<AppendedData encoding=\"raw\">\n   _" + raw + "\n</AppendedData>\n");
}

// appended base64 data, header and data encoded apart (offsets in characters)
std::string vtu_appended_base64()
{
  std::vector<std::string> offsets;
  std::string text;
  for(const std::string& a : arrays_as_list(mixed_arrays())) {
    offsets.push_back(std::to_string(text.size()));
    text += base64(Bytes().u(a.size(), 4).s) + base64(a);
  }
  return vtu_file("byte_order=\"LittleEndian\"", offsets, "appended",
                  "<AppendedData encoding=\"base64\">_" + text + "</AppendedData>\n");
}

// ---------------------------------------------------------------------------------

void test_round_trip_MEDIT()
{
  const Mesh m = mixed_mesh();
  VVM_CHECK(positively_oriented(m));
  std::ostringstream os;
  IO::write_MEDIT(os, m);
  VVM_CHECK(same_mesh(read_MEDIT_string(os.str()), m.points, medit_order(m)));
  IO::write_MEDIT("round_trip.mesh", m);
  Mesh r;
  IO::read_MEDIT("round_trip.mesh", r);
  VVM_CHECK(same_mesh(r, m.points, medit_order(m)));
}

void test_round_trip_MSH()
{
  // write_MSH groups nodes and cells by subdomain; their tags bring the order back
  const Mesh m = mixed_mesh();
  std::ostringstream os;
  IO::write_MSH(os, m);
  VVM_CHECK(same_mesh(read_MSH_string(os.str()), m));
  IO::write_MSH("round_trip.msh", m);
  Mesh r;
  IO::read_MSH("round_trip.msh", r);
  VVM_CHECK(same_mesh(r, m));
}

void test_round_trip_VTU()
{
  const Mesh m = mixed_mesh();
  std::ostringstream os;
  IO::write_VTU(os, m, {{"quality", {0.5, 0.25, 1, 2, 3}}});
  VVM_CHECK(same_mesh(read_VTU_string(os.str()), m));
  IO::write_VTU("round_trip.vtu", m);
  Mesh r;
  IO::read_VTU("round_trip.vtu", r);
  VVM_CHECK(same_mesh(r, m));
}

void test_round_trip_by_extension()
{
  const Mesh m = mixed_mesh();
  for(const char* name : {"by_extension.MESH", "by_extension.Msh", "by_extension.vtu"}) {
    IO::write_volume_mesh(name, m);
    Mesh r;
    IO::read_volume_mesh(name, r);
    const bool medit = std::string(name).find(".MESH") != std::string::npos;
    VVM_CHECK(same_mesh(r, m.points, medit ? medit_order(m) : m.cells));
  }
  // the extension chooses the reader: MEDIT text in a .msh file is no MSH
  write_file("medit_content.msh", file_contents("by_extension.MESH"));
  Mesh r;
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { IO::read_volume_mesh("medit_content.msh", r); },
                                              "'medit_content.msh': not a Gmsh MSH file"));
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { IO::read_volume_mesh("mesh.obj", r); },
                                              "'mesh.obj': unknown volume mesh extension '.obj'; the known ones are .mesh"));
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { IO::write_volume_mesh("mesh.vtk", m); }, "unknown volume mesh extension"));
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { IO::read_volume_mesh("dir.d/mesh", r); }, "extension (none)"));
  VVM_CHECK(r.points.empty() && r.cells.empty());
}

void test_MEDIT_extra_sections()
{
  const Mesh m = mixed_mesh();
  const Mesh r = read_MEDIT_string(medit_with_extra_sections);
  // the sections in the order of the file: hexahedra, tetrahedra, prisms, pyramids
  VVM_CHECK(same_mesh(r, m.points, {m.cells[0], m.cells[3], m.cells[4], m.cells[1], m.cells[2]}));
  VVM_CHECK(positively_oriented(r));
  // MeshVersionFormatted 1, no End, Hexaedra (Dobrzynski's spelling), CRLF line ends
  const Mesh s = read_MEDIT_string("MeshVersionFormatted 1\r\nDimension 3\r\nVertices\r\n8\r\n"
                                   "0 0 0 0\r\n1 0 0 0\r\n1 1 0 0\r\n0 1 0 0\r\n0 0 1 0\r\n1 0 1 0\r\n1 1 1 0\r\n0 1 1 0\r\n"
                                   "Hexaedra\r\n1\r\n1 2 3 4 5 6 7 8 -2\r\n");
  VVM_CHECK_EQUAL(s.number_of_cells(Cell_type::HEXAHEDRON), 1u);
  VVM_CHECK_EQUAL(s.cells.at(0).subdomain_index, -2);
}

void test_MSH22_ascii()
{
  const Mesh r = read_MSH_string(msh22_ascii);
  VVM_CHECK(same_mesh(r, msh22_expected()));
  VVM_CHECK(positively_oriented(r));
}

void test_MSH22_binary()
{
  const Mesh r = read_MSH_string(msh22_binary());
  VVM_CHECK(same_mesh(r, mixed_mesh()));
}

void test_MSH41_ascii()
{
  const Mesh r = read_MSH_string(msh41_ascii);
  VVM_CHECK(same_mesh(r, msh41_expected()));
  VVM_CHECK(positively_oriented(r));
  // without $Entities, the subdomain is the entity tag
  std::string no_entities = msh41_ascii;
  const std::size_t a = no_entities.find("$Entities"), b = no_entities.find("$Nodes");
  no_entities.erase(a, b - a);
  const Mesh s = read_MSH_string(no_entities);
  VVM_CHECK_EQUAL(s.cells.size(), 5u);
  const int subdomains[5] = {1, 2, 1, 5, 5};
  for(std::size_t k = 0; k < s.cells.size() && k < 5; ++k) VVM_CHECK_EQUAL(s.cells[k].subdomain_index, subdomains[k]);
}

void test_MSH41_binary()
{
  const Mesh r = read_MSH_string(msh41_binary());
  VVM_CHECK(same_mesh(r, mixed_mesh()));
}

void test_VTU_ascii()
{
  VVM_CHECK(same_mesh(read_VTU_string(vtu_ascii), small_expected()));
  // the preferred array: a name of the caller's, then none (subdomain 1)
  VVM_CHECK(same_mesh(read_VTU_string(vtu_ascii, {"no such array", "medit:ref"}), small_expected(9, 9)));
  VVM_CHECK(same_mesh(read_VTU_string(vtu_ascii, {"other"}), small_expected(1, 1)));
  // a subdomain array of floats is read if its values are integers
  std::string floats = vtu_ascii;
  floats.replace(floats.find("Int16"), 5, "Float64");
  floats.replace(floats.find("1 -4 5 1"), 8, "1 -4.0 5e0 1");
  VVM_CHECK(same_mesh(read_VTU_string(floats), small_expected()));
  floats.replace(floats.find("5e0"), 3, "5.5");
  VVM_CHECK(vvm_test::throws_invalid_argument([&] { read_VTU_string(floats); },
                                              "the VTU input: the cell data array 'subdomain' holds '5.5', not"));
}

void test_VTU_base64()
{
  VVM_CHECK(same_mesh(read_VTU_string(vtu_base64()), mixed_mesh()));
}

void test_VTU_zlib()
{
  VVM_CHECK(same_mesh(read_VTU_string(vtu_zlib()), mixed_mesh()));
  VVM_CHECK(same_mesh(read_VTU_string(vtu_zlib(1 << 15)), mixed_mesh())); // one block per array
}

void test_VTU_appended()
{
  VVM_CHECK(same_mesh(read_VTU_string(vtu_appended_raw()), mixed_mesh()));
  VVM_CHECK(same_mesh(read_VTU_string(vtu_appended_base64()), mixed_mesh()));
  // big-endian data
  std::vector<std::string> offsets;
  std::string raw;
  const auto arrays = arrays_as_list(mixed_arrays());
  const std::size_t sizes[5] = {8, 8, 8, 1, 4};
  for(std::size_t k = 0; k < 5; ++k) {
    offsets.push_back(std::to_string(raw.size()));
    std::string a = arrays[k];
    for(std::size_t i = 0; i < a.size(); i += sizes[k]) std::reverse(a.begin() + long(i), a.begin() + long(i + sizes[k]));
    std::string header = Bytes().u(a.size(), 4).s;
    std::reverse(header.begin(), header.end());
    raw += header + a;
  }
  const std::string big = vtu_file("byte_order=\"BigEndian\"", offsets, "appended",
                                   "<AppendedData encoding=\"raw\">_" + raw + "</AppendedData>\n");
  VVM_CHECK(same_mesh(read_VTU_string(big), mixed_mesh()));
}

// bad inputs: each throws std::invalid_argument naming the input and the problem
void test_bad_inputs()
{
  Mesh r;
  auto throws = [&](const std::function<void()>& f, const char* words) {
    return vvm_test::throws_invalid_argument(f, words);
  };
  // missing and empty files
  VVM_CHECK(throws([&] { IO::read_MEDIT("no_such_file.mesh", r); }, "cannot open 'no_such_file.mesh'"));
  VVM_CHECK(throws([&] { IO::read_MSH("no_such_file.msh", r); }, "cannot open 'no_such_file.msh'"));
  VVM_CHECK(throws([&] { IO::read_VTU("no_such_file.vtu", r); }, "cannot open 'no_such_file.vtu'"));
  VVM_CHECK(throws([&] { IO::read_volume_mesh(".", r); }, "unknown volume mesh extension"));
  for(const char* name : {"empty.mesh", "empty.msh", "empty.vtu"}) {
    write_file(name, "");
    VVM_CHECK(throws([&] { IO::read_volume_mesh(name, r); }, (std::string("'") + name + "' is an empty file").c_str()));
  }
  write_file("blank.mesh", " \n\t\n");
  VVM_CHECK(throws([&] { IO::read_volume_mesh("blank.mesh", r); }, "'blank.mesh' is an empty file"));
  VVM_CHECK(throws([&] { read_MEDIT_string(""); }, "the MEDIT input is empty"));

  // truncated files
  const std::string medit = medit_with_extra_sections;
  write_file("truncated.mesh", medit.substr(0, medit.find("1 1 1 0")));
  VVM_CHECK(throws([&] { IO::read_MEDIT("truncated.mesh", r); }, "'truncated.mesh' is truncated or corrupt (the Vertices section declares 13 entries"));
  write_file("truncated.mesh", medit.substr(0, medit.find("12 7   #")));
  VVM_CHECK(throws([&] { IO::read_MEDIT("truncated.mesh", r); }, "'truncated.mesh' is truncated"));
  const std::string msh = msh22_binary();
  write_file("truncated.msh", msh.substr(0, msh.size() - 40));
  VVM_CHECK(throws([&] { IO::read_MSH("truncated.msh", r); }, "'truncated.msh' is truncated"));
  const std::string msh41 = msh41_binary();
  write_file("truncated.msh", msh41.substr(0, msh41.find("$EndNodes") - 10));
  VVM_CHECK(throws([&] { IO::read_MSH("truncated.msh", r); }, "'truncated.msh' is truncated"));
  const std::string vtu = vtu_appended_raw();
  write_file("truncated.vtu", vtu.substr(0, vtu.size() - 60));
  VVM_CHECK(throws([&] { IO::read_VTU("truncated.vtu", r); }, "'truncated.vtu' is truncated"));
  write_file("truncated.vtu", std::string(vtu_ascii).substr(0, std::strlen(vtu_ascii) * 2 / 3));
  VVM_CHECK(throws([&] { IO::read_VTU("truncated.vtu", r); }, "'truncated.vtu' is truncated"));
  VVM_CHECK(throws([&] { read_VTU_string(vtu_base64().substr(0, 900)); }, "the VTU input is truncated"));

  // indices out of range
  std::string s = medit;
  s.replace(s.find("1 8 4 12 7"), 10, "1 8 4 99 7");
  VVM_CHECK(throws([&] { read_MEDIT_string(s); },
                   "the MEDIT input: Tetrahedra entry 1 refers to vertex 99, which does not exist (the vertices are numbered 1 to 13)"));
  s = msh22_ascii;
  s.replace(s.find("9 4 0 10 50 80 5"), 16, "12 4 0 10 50 99 5");
  write_file("bad_index.msh", s);
  VVM_CHECK(throws([&] { IO::read_MSH("bad_index.msh", r); }, "'bad_index.msh': element 12 refers to node 99, which does not exist"));
  s = vtu_ascii;
  s.replace(s.find("0 2 1 3 5 4"), 11, "0 2 1 3 5 6");
  VVM_CHECK(throws([&] { read_VTU_string(s); }, "cell 2 refers to point 6, which does not exist (6 points)"));
  s = vtu_ascii;
  s.replace(s.find("1 5 11 14"), 9, "1 5 12 14");
  VVM_CHECK(throws([&] { read_VTU_string(s); }, "cell 2 of VTK type 13 has 7 vertices, not 6"));

  // non-finite coordinates
  s = medit;
  s.replace(s.find("2 0 1 0"), 7, "2 nan 1 0");
  write_file("nan.mesh", s);
  VVM_CHECK(throws([&] { IO::read_MEDIT("nan.mesh", r); }, "'nan.mesh' has a point with a non-finite coordinate"));
  s = msh22_ascii;
  s.replace(s.find("100 2 0 1"), 9, "100 2 1e999 1");
  VVM_CHECK(throws([&] { read_MSH_string(s); }, "the MSH input has a point with a non-finite coordinate"));
  Bytes b;
  b.text("$MeshFormat\n2.2 1 8\n").i32(1).text("\n$EndMeshFormat\n$Nodes\n1\n").i32(1).f64(0).f64(std::nan("")).f64(0);
  VVM_CHECK(throws([&] { read_MSH_string(b.s); }, "non-finite coordinate"));
  s = vtu_ascii;
  s.replace(s.find("0 1 1\n"), 5, "0 inf 1");
  write_file("nan.vtu", s);
  VVM_CHECK(throws([&] { IO::read_VTU("nan.vtu", r); }, "'nan.vtu' has a point with a non-finite coordinate"));

  // absurd counts and sizes
  VVM_CHECK(throws([&] { read_MEDIT_string("MeshVersionFormatted 2\nDimension 3\nVertices\n999999999999\n0 0 0 0\n"); },
                   "the MEDIT input is truncated or corrupt (the Vertices section declares 999999999999 entries, more than the rest of the input can hold)"));
  VVM_CHECK(throws([&] { read_MEDIT_string("MeshVersionFormatted 2\nDimension 3\nVertices\n99999999999999999999999\n"); },
                   "expected the number of Vertices, found '99999999999999999999999'"));
  VVM_CHECK(throws([&] { read_MSH_string("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 999999999999 1 999999999999\n"); },
                   "$Nodes declares 999999999999 entries"));
  b = Bytes();
  b.text("$MeshFormat\n4.1 1 8\n").i32(1).text("\n$EndMeshFormat\n$Elements\n").u64(1).u64(1).u64(1).u64(1);
  b.i32(3).i32(1).i32(4).u64(std::uint64_t(1) << 62);
  VVM_CHECK(throws([&] { read_MSH_string(b.s); }, "an element block declares 4611686018427387904 entries"));
  std::vector<std::string> offsets = {"0", "0", "0", "0", "0"};
  const std::string huge = vtu_file("header_type=\"UInt64\"", offsets, "appended",
                                    "<AppendedData encoding=\"raw\">_" + Bytes().u64(std::uint64_t(1) << 40).s + "</AppendedData>");
  VVM_CHECK(throws([&] { read_VTU_string(huge); }, "the VTU input is truncated or corrupt (the <Points> array declares 1099511627776 bytes, more than the input holds)"));
  const std::string bomb = vtu_file("compressor=\"vtkZLibDataCompressor\"", offsets, "appended",
                                    "<AppendedData encoding=\"raw\">_" + Bytes().i32(1).i32(-1).i32(0).i32(10).s +
                                      std::string(10, 'x') + "</AppendedData>");
  VVM_CHECK(throws([&] { read_VTU_string(bomb); }, "declares a block of 4294967295 bytes compressed into 10"));
  s = vtu_zlib();
  const std::size_t at = s.find('>', s.find("Name=\"offsets\"")) + 30; // in the compressed data, after the header
  s[at] = s[at] == 'A' ? 'B' : 'A';
  VVM_CHECK(throws([&] { read_VTU_string(s); }, "the VTU input: the zlib data of the offsets array is corrupt"));

  // no volume cell
  VVM_CHECK(throws([&] { read_MEDIT_string("MeshVersionFormatted 1\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
                                           "Triangles\n1\n1 2 3 0\nEnd\n"); },
                   "the MEDIT input has no tetrahedron, hexahedron, prism or pyramid"));
  write_file("flat.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                         "$Elements\n1\n1 2 0 1 2 3\n$EndElements\n");
  VVM_CHECK(throws([&] { IO::read_MSH("flat.msh", r); }, "'flat.msh' has no tetrahedron, hexahedron, prism or pyramid"));
  s = vtu_ascii;
  s.replace(s.find("1 10 13 5"), 9, "1 9 33 5");
  VVM_CHECK(throws([&] { read_VTU_string(s); }, "has no tetrahedron"));

  // not the format, unknown parts
  VVM_CHECK(throws([&] { read_MEDIT_string("MeshVersionFormatted 1\nDimension 3\nVertices 0\nFoo\n3\n"); },
                   "unknown keyword 'Foo'"));
  VVM_CHECK(throws([&] { read_MEDIT_string("MeshVersionFormatted 1\nDimension 2\n"); }, "Dimension 2"));
  VVM_CHECK(throws([&] { read_MEDIT_string("solid cube\nfacet normal 0 0 1\n"); }, "not a MEDIT ASCII file"));
  VVM_CHECK(throws([&] { read_MSH_string("$MeshFormat\n4.0 0 8\n$EndMeshFormat\n"); }, "MSH version '4.0' is not supported"));
  VVM_CHECK(throws([&] { read_MSH_string("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n"); }, "$EndNodes is missing"));
  VVM_CHECK(throws([&] { read_MSH_string("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Foo\n1 2 3\n"); },
                   "the section $Foo has no $EndFoo"));
  VVM_CHECK(throws([&] { read_MSH_string("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n1 1 0 0\n$EndNodes\n"); },
                   "the node tag 1 appears twice"));
  VVM_CHECK(throws([&] { read_VTU_string("<VTKFile type=\"PolyData\"><PolyData/></VTKFile>"); },
                   "a VTK XML file of type 'PolyData', not UnstructuredGrid"));
  VVM_CHECK(throws([&] { read_VTU_string(vtu_file("compressor=\"vtkLZ4DataCompressor\"", offsets, "binary")); },
                   "the compressor 'vtkLZ4DataCompressor' is not supported"));
  VVM_CHECK(throws([&] { read_VTU_string("<VTKFile><a></b></VTKFile>"); }, "the closing tag '</b>' does not close <a>"));
  s = vtu_base64();
  s.replace(s.find("format=\"binary\">") + 16, 1, "*");
  VVM_CHECK(throws([&] { read_VTU_string(s); }, "invalid base64 data"));

  // the mesh is left as it was
  Mesh m = mixed_mesh();
  VVM_CHECK(throws([&] { IO::read_MEDIT("nan.mesh", m); }, "non-finite"));
  VVM_CHECK(throws([&] { IO::read_MSH("bad_index.msh", m); }, "does not exist"));
  VVM_CHECK(throws([&] { IO::read_VTU("truncated.vtu", m); }, "truncated"));
  VVM_CHECK(same_mesh(m, mixed_mesh()));
}

// Every truncation of the inputs, and random changes of their bytes, either read or throw
// std::invalid_argument (and, under the sanitizers, do not touch memory they should not).
void test_truncated_and_mutated_inputs()
{
  std::mt19937 random(1234);
  struct Input
  {
    std::string text;
    int format; // 0 MEDIT, 1 MSH, 2 VTU
  };
  std::vector<Input> inputs = {{medit_with_extra_sections, 0}, {msh22_ascii, 1}, {msh41_ascii, 1},
                               {msh22_binary(), 1},           {msh41_binary(), 1}, {vtu_ascii, 2},
                               {vtu_base64(), 2},             {vtu_zlib(), 2},    {vtu_appended_raw(), 2},
                               {vtu_appended_base64(), 2}};
  std::ostringstream os;
  IO::write_MSH(os, mixed_mesh());
  inputs.push_back({os.str(), 1});
  const char special[] = {'0', '9', '-', '.', ' ', '\n', '<', '>', '/', '"', '$', '_', '=', 'e', '\0', '\xff', '\x80'};
  for(const Input& in : inputs) {
    auto read = [&](const std::string& s) {
      return outcome([&] {
        Mesh m;
        std::istringstream is(s);
        if(in.format == 0) IO::read_MEDIT(is, m);
        else if(in.format == 1) IO::read_MSH(is, m);
        else IO::read_VTU(is, m);
      });
    };
    int wrong = 0, read_ok = 0;
    for(std::size_t n = 0; n < in.text.size(); ++n) {
      const int o = read(in.text.substr(0, n));
      wrong += o < 0;
    }
    for(int trial = 0; trial < 4000; ++trial) {
      std::string s = in.text;
      const int changes = 1 + int(random() % 3);
      for(int k = 0; k < changes; ++k) {
        const std::size_t at = random() % s.size();
        const unsigned what = random() % 4;
        if(what == 0) s[at] = static_cast<char>(random() % 256);
        else if(what == 1) s[at] = special[random() % sizeof(special)];
        else if(what == 2) s.insert(at, std::string(1 + random() % 12, '9'));
        else s.erase(at, 1 + random() % 8);
      }
      const int o = read(s);
      wrong += o < 0;
      read_ok += o > 0;
    }
    if(!VVM_CHECK_EQUAL(wrong, 0)) std::cerr << "    input " << (&in - inputs.data()) << "\n";
    (void)read_ok;
  }
}

// ---------------------------------------------------------------------------------
// files of other writers, with the counts meshio reads in them (make_mesh_io_files.py)

void test_meshio_files()
{
  const Mesh m = mixed_mesh();
  // meshio writes MEDIT's sections in the order of its cell blocks: the mesh's order
  for(const char* name : {"meshio_mixed.vtu", "meshio_mixed_22.msh", "meshio_mixed_22_binary.msh", "meshio_mixed_41.msh",
                          "meshio_mixed_41_binary.msh", "meshio_mixed.mesh"}) {
    Mesh r;
    IO::read_volume_mesh(vvm_test::data_file(std::string("mesh_io/") + name), r);
    if(!VVM_CHECK(same_mesh(r, m))) std::cerr << "    " << name << "\n";
  }
  // meshio's ASCII VTU has 12 significant digits
  Mesh r;
  IO::read_VTU(vvm_test::data_file("mesh_io/meshio_mixed_ascii.vtu"), r);
  VVM_CHECK(same_mesh(r, m, 1e-11));
}

void test_vtk_files()
{
  for(const char* name : {"vtk_mixed_appended_zlib.vtu", "vtk_mixed_appended_base64.vtu", "vtk_mixed_binary.vtu",
                          "vtk_mixed_binary_zlib.vtu", "vtk_mixed_ascii.vtu"}) {
    Mesh r;
    IO::read_VTU(vvm_test::data_file(std::string("mesh_io/") + name), r);
    // VTK writes Float64 points in ASCII with 17 digits: exact
    if(!VVM_CHECK(same_mesh(r, mixed_mesh()))) std::cerr << "    " << name << "\n";
  }
}

void test_gmsh_files()
{
  // meshio reads 12 points, 1 hexahedron (physical 3), 1 prism, 5 tetrahedra, 1 pyramid
  // (physical 7) in the MSH files; the element tags are numbered differently in 2.2 and 4.1
  for(const char* name : {"gmsh_tiny_22.msh", "gmsh_tiny_22_binary.msh", "gmsh_tiny_41.msh", "gmsh_tiny_41_binary.msh"}) {
    Mesh r;
    IO::read_MSH(vvm_test::data_file(std::string("mesh_io/") + name), r);
    VVM_CHECK_EQUAL(r.number_of_points(), 12u);
    VVM_CHECK_EQUAL(r.number_of_cells(Cell_type::HEXAHEDRON), 1u);
    VVM_CHECK_EQUAL(r.number_of_cells(Cell_type::PRISM), 1u);
    VVM_CHECK_EQUAL(r.number_of_cells(Cell_type::TETRAHEDRON), 5u);
    VVM_CHECK_EQUAL(r.number_of_cells(Cell_type::PYRAMID), 1u);
    bool subdomains = true;
    for(const Cell& c : r.cells) subdomains = subdomains && c.subdomain_index == (c.type == Cell_type::HEXAHEDRON ? 3 : 7);
    VVM_CHECK(subdomains);
    VVM_CHECK(positively_oriented(r));
    const int first_type = std::string(name).find("_22") != std::string::npos ? 10 : 12;
    VVM_CHECK_EQUAL(int(r.cells.at(0).type), first_type); // 2.2: tags 1-5 the tets; 4.1: tag 1 the hexahedron
  }
  Mesh a, b;
  IO::read_MSH(vvm_test::data_file("mesh_io/gmsh_tiny_41.msh"), a);
  IO::read_MSH(vvm_test::data_file("mesh_io/gmsh_tiny_41_binary.msh"), b);
  VVM_CHECK(same_mesh(a, b));
  // Gmsh's MEDIT writer keeps tetrahedra and hexahedra, their references the entity tags
  Mesh r;
  IO::read_MEDIT(vvm_test::data_file("mesh_io/gmsh_tiny.mesh"), r);
  VVM_CHECK_EQUAL(r.number_of_points(), 12u);
  VVM_CHECK_EQUAL(r.number_of_cells(Cell_type::TETRAHEDRON), 5u);
  VVM_CHECK_EQUAL(r.number_of_cells(Cell_type::HEXAHEDRON), 1u);
  VVM_CHECK_EQUAL(r.number_of_cells(), 6u);
  VVM_CHECK_EQUAL(r.cells.at(0).subdomain_index, 121);
  VVM_CHECK_EQUAL(r.cells.at(5).subdomain_index, 1);
  VVM_CHECK(positively_oriented(r));
}

} // namespace

int main(int argc, char** argv)
{
  return vvm_test::run(argc, argv, "test_volume_mesh_io", {
      {"round_trip_MEDIT", test_round_trip_MEDIT},
      {"round_trip_MSH", test_round_trip_MSH},
      {"round_trip_VTU", test_round_trip_VTU},
      {"round_trip_by_extension", test_round_trip_by_extension},
      {"MEDIT_extra_sections", test_MEDIT_extra_sections},
      {"MSH22_ascii", test_MSH22_ascii},
      {"MSH22_binary", test_MSH22_binary},
      {"MSH41_ascii", test_MSH41_ascii},
      {"MSH41_binary", test_MSH41_binary},
      {"VTU_ascii", test_VTU_ascii},
      {"VTU_base64", test_VTU_base64},
      {"VTU_zlib", test_VTU_zlib},
      {"VTU_appended", test_VTU_appended},
      {"bad_inputs", test_bad_inputs},
      {"truncated_and_mutated_inputs", test_truncated_and_mutated_inputs},
      {"meshio_files", test_meshio_files},
      {"vtk_files", test_vtk_files},
      {"gmsh_files", test_gmsh_files}});
}
