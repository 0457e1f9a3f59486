// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh in Gmsh's MSH 4.1 ASCII format: one volume entity per
// subdomain, the cells in blocks per (subdomain, element type).

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_WRITE_MSH_H
#define CGAL_HEX_DOMINANT_MESHING_IO_WRITE_MSH_H

#include <CGAL/Hex_dominant_mesh_3.h>

#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <boost/io/ios_state.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {
namespace internal {

// Gmsh's element type numbers: MSH_TET_4, MSH_HEX_8, MSH_PRI_6, MSH_PYR_5
inline int gmsh_element_type(Hex_dominant_cell_type t)
{
  switch(t) {
    case Hex_dominant_cell_type::TETRAHEDRON: return 4;
    case Hex_dominant_cell_type::HEXAHEDRON: return 5;
    case Hex_dominant_cell_type::PRISM: return 6;
    default: return 7;
  }
}

template <class Point_3>
void check_entity_tags(const Hex_dominant_mesh_3<Point_3>& mesh)
{
  for(std::size_t k = 0; k < mesh.number_of_cells(); ++k)
    if(mesh.cells[k].subdomain_index <= 0)
      throw std::invalid_argument("write_MSH: the subdomain index " + std::to_string(mesh.cells[k].subdomain_index) +
                                  " of cell " + std::to_string(k) + " is not a valid Gmsh entity tag");
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * writes `mesh` to `os` in Gmsh's MSH 4.1 ASCII format. Each subdomain index `i` of the
 * cells becomes the volume entity `i`, with the physical tag `i`; the nodes are
 * `1 ... mesh.number_of_points()` in the order of `mesh.points`, each in the block of
 * the first entity whose cells use it (unused points in the first entity's, or in the
 * entity 1 if there are no cells), and the
 * element of `mesh.cells[k]` has the tag `k + 1`, in the block of its subdomain and
 * type (Gmsh types 4 tetrahedron, 5 hexahedron, 6 prism, 7 pyramid). Gmsh's node
 * orders and orientations are those of `Hex_dominant_mesh_3`, so the vertices are
 * written as they are. Numbers are written with 17 significant digits; the precision
 * of `os` is restored afterwards.
 * \throws std::invalid_argument if a subdomain index is not positive (Gmsh's entity tags
 * are; nothing is written then)
 * \throws std::runtime_error if the stream fails
 */
template <class Point_3>
void write_MSH(std::ostream& os, const Hex_dominant_mesh_3<Point_3>& mesh)
{
  internal::check_entity_tags(mesh);
  const std::size_t n_points = mesh.number_of_points();
  const std::size_t n_cells = mesh.number_of_cells();

  // entity tag -> (element type -> cell indices); std::map keeps the tags sorted
  std::map<int, std::map<int, std::vector<std::size_t>>> blocks;
  for(std::size_t k = 0; k < n_cells; ++k)
    blocks[mesh.cells[k].subdomain_index][internal::gmsh_element_type(mesh.cells[k].type)].push_back(k);
  // points but no cells: one entity still holds the nodes
  if(blocks.empty() && n_points > 0) blocks[1];

  // the entity of each node, and the bounding box of each entity
  const std::size_t unassigned = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> node_entity(n_points, unassigned);
  std::vector<int> tags;
  std::vector<std::array<double, 6>> boxes;
  const double inf = std::numeric_limits<double>::infinity();
  for(const auto& entity : blocks) {
    const std::size_t e = tags.size();
    tags.push_back(entity.first);
    boxes.push_back({inf, inf, inf, -inf, -inf, -inf});
    for(const auto& type_block : entity.second)
      for(std::size_t k : type_block.second)
        for(std::size_t v : mesh.cells[k]) {
          CGAL_precondition(v < n_points);
          if(node_entity[v] == unassigned) node_entity[v] = e;
        }
  }
  std::vector<std::vector<std::size_t>> entity_nodes(tags.size());
  for(std::size_t v = 0; v < n_points; ++v) {
    if(node_entity[v] == unassigned) node_entity[v] = 0;
    entity_nodes[node_entity[v]].push_back(v);
  }
  auto add_to_box = [&](std::size_t e, std::size_t v) {
    const auto& p = mesh.points[v];
    const double xyz[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int i = 0; i < 3; ++i) {
      boxes[e][i] = (std::min)(boxes[e][i], xyz[i]);
      boxes[e][i + 3] = (std::max)(boxes[e][i + 3], xyz[i]);
    }
  };
  for(std::size_t e = 0; e < tags.size(); ++e) {
    for(const auto& type_block : blocks[tags[e]])
      for(std::size_t k : type_block.second)
        for(std::size_t v : mesh.cells[k]) add_to_box(e, v);
    for(std::size_t v : entity_nodes[e]) add_to_box(e, v);
  }

  boost::io::ios_precision_saver saved_precision(os);
  os.precision(17);
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

  os << "$Entities\n0 0 0 " << tags.size() << "\n";
  for(std::size_t e = 0; e < tags.size(); ++e) {
    os << tags[e];
    for(double b : boxes[e]) os << " " << b;
    os << " 1 " << tags[e] << " 0\n"; // one physical tag, no bounding surface
  }
  os << "$EndEntities\n";

  std::size_t n_node_blocks = 0;
  for(const auto& nodes : entity_nodes) n_node_blocks += !nodes.empty();
  os << "$Nodes\n" << n_node_blocks << " " << n_points << " " << (n_points > 0 ? 1 : 0) << " " << n_points << "\n";
  for(std::size_t e = 0; e < tags.size(); ++e) {
    if(entity_nodes[e].empty()) continue;
    os << "3 " << tags[e] << " 0 " << entity_nodes[e].size() << "\n";
    for(std::size_t v : entity_nodes[e]) os << v + 1 << "\n";
    for(std::size_t v : entity_nodes[e]) {
      const auto& p = mesh.points[v];
      os << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " " << CGAL::to_double(p.z()) << "\n";
    }
  }
  os << "$EndNodes\n";

  std::size_t n_blocks = 0;
  for(const auto& entity : blocks) n_blocks += entity.second.size();
  os << "$Elements\n" << n_blocks << " " << n_cells << " " << (n_cells > 0 ? 1 : 0) << " " << n_cells << "\n";
  for(const auto& entity : blocks)
    for(const auto& type_block : entity.second) {
      os << "3 " << entity.first << " " << type_block.first << " " << type_block.second.size() << "\n";
      for(std::size_t k : type_block.second) {
        os << k + 1;
        for(std::size_t v : mesh.cells[k]) os << " " << v + 1;
        os << "\n";
      }
    }
  os << "$EndElements\n";
  if(!os) throw std::runtime_error("write_MSH: the stream failed");
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * writes `mesh` to the file `filename` as `write_MSH(std::ostream&, mesh)` does.
 * \throws std::invalid_argument if a subdomain index is not positive (the file is not
 * created then)
 * \throws std::runtime_error if the file cannot be opened or written
 */
template <class Point_3>
void write_MSH(const std::string& filename, const Hex_dominant_mesh_3<Point_3>& mesh)
{
  internal::check_entity_tags(mesh);
  std::ofstream os(filename);
  if(!os) throw std::runtime_error("write_MSH: cannot open " + filename);
  write_MSH(os, mesh);
}

} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_WRITE_MSH_H
