// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The writers of Hex_dominant_meshing and the conversion to a linear cell
// complex, on hand-made 2x1x1 blocks of all four cell types. Writes
// mixed.vtu, mixed.msh, mixed.mesh and expected.txt (JSON) into argv[1], which
// check_hex_dominant_files.py reads back with meshio and Gmsh.

#include "vvm_test.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MEDIT.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MSH.h>
#include <CGAL/Hex_dominant_meshing/IO/write_VTU.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_mesh_to_linear_cell_complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
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
typedef CGAL::Linear_cell_complex_for_combinatorial_map<3> LCC;
typedef std::vector<std::pair<std::string, std::vector<double>>> Fields;

namespace IO = CGAL::Hex_dominant_meshing::IO;

// The cells cut into tetrahedra in their own vertex order (the same cuts as the
// Python check): each piece has a positive volume iff the cell is positively oriented.
const std::vector<std::vector<int>>& sub_tetrahedra(Cell_type t)
{
  static const std::map<Cell_type, std::vector<std::vector<int>>> cuts = {
    {Cell_type::TETRAHEDRON, {{0, 1, 2, 3}}},
    {Cell_type::HEXAHEDRON, {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}}},
    {Cell_type::PRISM, {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}}},
    {Cell_type::PYRAMID, {{0, 1, 2, 4}, {0, 2, 3, 4}}}};
  return cuts.at(t);
}

double cell_volume(const Mesh& mesh, const Cell& c)
{
  double volume = 0;
  for(const auto& t : sub_tetrahedra(c.type)) {
    const double v = CGAL::volume(mesh.points[c.vertices[t[0]]], mesh.points[c.vertices[t[1]]],
                                  mesh.points[c.vertices[t[2]]], mesh.points[c.vertices[t[3]]]);
    VVM_CHECK(v > 0);
    volume += v;
  }
  return volume;
}

Cell make_cell(Cell_type t, std::vector<std::size_t> v, int subdomain)
{
  Cell c;
  c.type = t;
  VVM_CHECK(v.size() == CGAL::number_of_vertices(t));
  std::copy(v.begin(), v.end(), c.vertices.begin());
  c.subdomain_index = subdomain;
  return c;
}

// The hexahedron [0,1]^3 (subdomain 1) and the cube [1,2]x[0,1]^2 cut by the plane
// x - y = 1 into the prism over (1,0) (2,1) (1,1) (subdomain 2), which shares the
// quadrilateral x = 1 with the hexahedron, and the prism over (1,0) (2,0) (2,1), cut in
// one of two ways:
// - conforming: the pyramid on the quadrilateral 1 9 11 5 of the first prism with apex
//   10 (subdomain 3), and the tetrahedron 1 8 9 10 (subdomain 2) against its triangle
//   1 9 10; every shared face is a face of both cells;
// - quad_against_triangles: the tetrahedron 1 8 9 5 (subdomain 2) and the pyramid on
//   x = 2 with apex 5 (subdomain 3), which share the triangle 8 9 5 and cover the
//   quadrilateral 1 9 11 5 of the first prism with two triangles.
Mesh make_mixed_block(bool quad_against_triangles)
{
  Mesh mesh;
  mesh.points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),  // 0-3
                 Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), Point(0, 1, 1),  // 4-7
                 Point(2, 0, 0), Point(2, 1, 0), Point(2, 0, 1), Point(2, 1, 1)}; // 8-11
  if(quad_against_triangles)
    mesh.cells = {make_cell(Cell_type::TETRAHEDRON, {1, 8, 9, 5}, 2),
                  make_cell(Cell_type::HEXAHEDRON, {0, 1, 2, 3, 4, 5, 6, 7}, 1),
                  make_cell(Cell_type::PYRAMID, {8, 10, 11, 9, 5}, 3),
                  make_cell(Cell_type::PRISM, {1, 9, 2, 5, 11, 6}, 2)};
  else
    mesh.cells = {make_cell(Cell_type::TETRAHEDRON, {1, 8, 9, 10}, 2),
                  make_cell(Cell_type::HEXAHEDRON, {0, 1, 2, 3, 4, 5, 6, 7}, 1),
                  make_cell(Cell_type::PYRAMID, {1, 9, 11, 5, 10}, 3),
                  make_cell(Cell_type::PRISM, {1, 9, 2, 5, 11, 6}, 2)};
  return mesh;
}

// the volume of the 3-cell of `d` from its faces, which turn around inner normals
double lcc_volume(LCC& lcc, LCC::Dart_handle d)
{
  const Point& origin = lcc.point(d);
  double sum = 0;
  auto faces = lcc.one_dart_per_incident_cell<2, 3>(d);
  for(auto f = faces.begin(), end = faces.end(); f != end; ++f) {
    std::vector<Point> face;
    LCC::Dart_handle e = f;
    do {
      face.push_back(lcc.point(e));
      e = lcc.next(e);
    } while(e != LCC::Dart_handle(f));
    for(std::size_t i = 1; i + 1 < face.size(); ++i) sum += CGAL::volume(origin, face[0], face[i], face[i + 1]);
  }
  return -sum; // the divergence theorem gives the volume with outer normals
}

// converts `mesh` to a linear cell complex and checks its volumes (their orientation
// too), its sewn darts and its vertex attributes
void check_linear_cell_complex(const Mesh& mesh, const std::vector<double>& volumes, std::size_t expected_sewn_darts,
                               std::size_t expected_vertex_attributes)
{
  LCC lcc;
  lcc.make_tetrahedron(Point(5, 5, 5), Point(6, 5, 5), Point(5, 6, 5), Point(5, 5, 6)); // replaced
  CGAL::Hex_dominant_meshing::hex_dominant_mesh_to_linear_cell_complex(mesh, lcc);
  VVM_CHECK(lcc.is_valid());
  VVM_CHECK(lcc.one_dart_per_cell<3>().size() == mesh.number_of_cells());
  VVM_CHECK(lcc.number_of_vertex_attributes() == expected_vertex_attributes);
  VVM_CHECK(lcc.number_of_darts() == 12 + 24 + 16 + 18);
  std::size_t sewn_darts = 0;
  for(auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) sewn_darts += !lcc.is_free<3>(d);
  VVM_CHECK(sewn_darts == expected_sewn_darts);
  std::vector<double> lcc_volumes;
  auto lcc_cells = lcc.one_dart_per_cell<3>();
  for(auto d = lcc_cells.begin(), end = lcc_cells.end(); d != end; ++d) lcc_volumes.push_back(lcc_volume(lcc, d));
  std::vector<double> sorted_volumes = volumes;
  std::sort(sorted_volumes.begin(), sorted_volumes.end());
  std::sort(lcc_volumes.begin(), lcc_volumes.end());
  for(std::size_t i = 0; i < lcc_volumes.size(); ++i)
    VVM_CHECK(std::abs(lcc_volumes[i] - sorted_volumes[i]) < 1e-14); // all alike oriented, inner normals
  std::cout << "linear cell complex: " << lcc.number_of_darts() << " darts, " << sewn_darts << " 3-sewn, "
            << lcc.one_dart_per_cell<3>().size() << " volumes, " << lcc.number_of_vertex_attributes()
            << " vertex attributes for " << mesh.number_of_points() << " points, valid" << std::endl;
}

template <class F>
bool throws_invalid_argument(F f)
{
  try {
    f();
  } catch(const std::invalid_argument&) {
    return true;
  }
  return false;
}

template <class F>
bool throws_runtime_error(F f)
{
  try {
    f();
  } catch(const std::runtime_error&) {
    return true;
  }
  return false;
}

int main(int argc, char** argv)
{
  if(argc != 2) {
    std::cerr << "usage: " << argv[0] << " <output directory>\n";
    return 2;
  }
  const std::filesystem::path out_dir = argv[1];
  std::filesystem::create_directories(out_dir);

  const Mesh mesh = make_mixed_block(false);
  VVM_CHECK(mesh.number_of_points() == 12 && mesh.number_of_cells() == 4);
  for(Cell_type t : {Cell_type::TETRAHEDRON, Cell_type::HEXAHEDRON, Cell_type::PRISM, Cell_type::PYRAMID})
    VVM_CHECK(mesh.number_of_cells(t) == 1);
  std::vector<double> volumes, indices;
  double total_volume = 0;
  for(std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    volumes.push_back(cell_volume(mesh, mesh.cells[k])); // asserts the orientation
    indices.push_back(double(k));
    total_volume += volumes.back();
  }
  const double expected_total_volume = 2;
  VVM_CHECK(std::abs(total_volume - expected_total_volume) < 1e-14);
  const double expected_volumes[] = {1. / 6, 1, 1. / 3, 0.5};
  for(std::size_t k = 0; k < 4; ++k) VVM_CHECK(std::abs(volumes[k] - expected_volumes[k]) < 1e-15);

  check_linear_cell_complex(mesh, volumes, 2 * 4 + 2 * 4 + 2 * 3, mesh.number_of_points());
  // The quadrilateral against two triangles stays 3-free on both sides, so the points
  // 1, 5, 9 and 11 on it have two groups of volumes, and two vertex attributes each.
  const Mesh quad_against_triangles = make_mixed_block(true);
  std::vector<double> qat_volumes;
  for(const Cell& c : quad_against_triangles.cells) qat_volumes.push_back(cell_volume(quad_against_triangles, c));
  check_linear_cell_complex(quad_against_triangles, qat_volumes, 2 * 4 + 2 * 3, 12 + 4);

  // the files
  const Fields fields = {{"volume", volumes}, {"cell_index", indices}};
  IO::write_VTU((out_dir / "mixed.vtu").string(), mesh, fields);
  IO::write_MSH((out_dir / "mixed.msh").string(), mesh);
  IO::write_MEDIT((out_dir / "mixed.mesh").string(), mesh);

  // the vertex orders in the files: the VTU's wedge mirrored into VTK's order, all the
  // other cells as in the mesh
  {
    std::ostringstream vtu;
    IO::write_VTU(vtu, mesh);
    VVM_CHECK(vtu.str().find("\n1 2 9 5 6 11\n") != std::string::npos);
    VVM_CHECK(vtu.str().find("\n1 9 11 5 10\n") != std::string::npos);
    std::ostringstream msh;
    IO::write_MSH(msh, mesh);
    VVM_CHECK(msh.str().find("\n4 2 10 3 6 12 7\n") != std::string::npos); // element 4, the prism
    VVM_CHECK(msh.str().find("$Entities\n0 0 0 3\n") != std::string::npos);
    std::ostringstream medit;
    IO::write_MEDIT(medit, mesh);
    VVM_CHECK(medit.str().find("Prisms\n1\n2 10 3 6 12 7 2\n") != std::string::npos);
  }

  // errors
  {
    Fields short_field = {{"volume", volumes}, {"short", std::vector<double>(3, 1.)}};
    std::ostringstream os;
    VVM_CHECK(throws_invalid_argument([&] { IO::write_VTU(os, mesh, short_field); }));
    VVM_CHECK(os.str().empty()); // checked before anything is written
    const std::filesystem::path not_written = out_dir / "not_written.vtu";
    std::filesystem::remove(not_written);
    VVM_CHECK(throws_invalid_argument([&] { IO::write_VTU(not_written.string(), mesh, short_field); }));
    VVM_CHECK(!std::filesystem::exists(not_written));

    Mesh bad_subdomain = mesh;
    bad_subdomain.cells[2].subdomain_index = 0;
    VVM_CHECK(throws_invalid_argument([&] { IO::write_MSH(os, bad_subdomain); }));
    VVM_CHECK(os.str().empty());

    const std::string no_dir = (out_dir / "no_such_directory" / "mixed").string();
    VVM_CHECK(throws_runtime_error([&] { IO::write_VTU(no_dir + ".vtu", mesh); }));
    VVM_CHECK(throws_runtime_error([&] { IO::write_MSH(no_dir + ".msh", mesh); }));
    VVM_CHECK(throws_runtime_error([&] { IO::write_MEDIT(no_dir + ".mesh", mesh); }));

    std::ostringstream failed;
    failed.setstate(std::ios::badbit);
    VVM_CHECK(throws_runtime_error([&] { IO::write_VTU(failed, mesh); }));
    VVM_CHECK(throws_runtime_error([&] { IO::write_MSH(failed, mesh); }));
    VVM_CHECK(throws_runtime_error([&] { IO::write_MEDIT(failed, mesh); }));

    std::ostringstream precision;
    precision.precision(3);
    IO::write_MEDIT(precision, mesh);
    IO::write_MSH(precision, mesh);
    IO::write_VTU(precision, mesh, fields);
    VVM_CHECK(precision.precision() == 3);
  }

  // what the files must hold, for the Python check
  {
    std::ofstream expected(out_dir / "expected.txt");
    expected.precision(17);
    expected << "{\n  \"points\": " << mesh.number_of_points() << ",\n  \"volume\": " << expected_total_volume
             << ",\n  \"cell_fields\": [\"volume\", \"cell_index\"],\n  \"cells\": {";
    // meshio's names of the cell types, each with its number of cells, then with the
    // subdomains of its cells
    const std::pair<Cell_type, const char*> names[] = {{Cell_type::TETRAHEDRON, "tetra"},
                                                       {Cell_type::HEXAHEDRON, "hexahedron"},
                                                       {Cell_type::PRISM, "wedge"},
                                                       {Cell_type::PYRAMID, "pyramid"}};
    bool first_type = true;
    for(const auto& name : names) {
      expected << (first_type ? "" : ", ") << "\"" << name.second << "\": " << mesh.number_of_cells(name.first);
      first_type = false;
    }
    expected << "},\n  \"subdomains\": {";
    first_type = true;
    for(const auto& name : names) {
      expected << (first_type ? "\n" : ",\n") << "    \"" << name.second << "\": [";
      bool first_cell = true;
      for(const Cell& c : mesh.cells)
        if(c.type == name.first) {
          expected << (first_cell ? "" : ", ") << c.subdomain_index;
          first_cell = false;
        }
      expected << "]";
      first_type = false;
    }
    expected << "\n  }\n}\n";
    VVM_CHECK(expected);
  }
  std::cout << "wrote mixed.vtu, mixed.msh, mixed.mesh and expected.txt to " << out_dir.string() << std::endl;
  return vvm_test::report("test_hex_dominant_io");
}
