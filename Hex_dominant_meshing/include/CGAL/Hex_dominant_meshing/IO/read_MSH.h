// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh from Gmsh's MSH format, versions 2.2 and 4.1, ASCII and
// binary: all the nodes, and the linear volume elements with their subdomains.

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_READ_MSH_H
#define CGAL_HEX_DOMINANT_MESHING_IO_READ_MSH_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/IO/internal/read_utilities.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {
namespace internal {

// The number of nodes of an element of Gmsh's type `t` (GmshDefines.h), 0 if unknown
// or variable (polygons, polyhedra).
inline std::size_t gmsh_nodes_per_element(std::int64_t t)
{
  static const std::pair<int, int> types[] = {
    {1, 2}, {2, 3}, {3, 4}, {4, 4}, {5, 8}, {6, 6}, {7, 5}, {8, 3}, {9, 6}, {10, 9}, {11, 10}, {12, 27},
    {13, 18}, {14, 14}, {15, 1}, {16, 8}, {17, 20}, {18, 15}, {19, 13}, {20, 9}, {21, 10}, {22, 12},
    {23, 15}, {24, 15}, {25, 21}, {26, 4}, {27, 5}, {28, 6}, {29, 20}, {30, 35}, {31, 56}, {32, 22},
    {33, 28}, {36, 16}, {37, 25}, {38, 36}, {39, 12}, {40, 16}, {41, 20}, {42, 28}, {43, 36}, {44, 45},
    {45, 55}, {46, 66}, {47, 49}, {48, 64}, {49, 81}, {50, 100}, {51, 121}, {52, 18}, {53, 21},
    {54, 24}, {55, 27}, {56, 30}, {57, 24}, {58, 28}, {59, 32}, {60, 36}, {61, 40}, {62, 7}, {63, 8},
    {64, 9}, {65, 10}, {66, 11}, {71, 84}, {72, 120}, {73, 165}, {74, 220}, {75, 286}, {90, 40},
    {91, 75}, {92, 64}, {93, 125}, {94, 216}, {95, 343}, {96, 512}, {97, 729}, {98, 1000},
    {106, 126}, {107, 196}, {108, 288}, {109, 405}, {110, 550}};
  for(const auto& p : types)
    if(p.first == t) return static_cast<std::size_t>(p.second);
  return 0;
}

// the cell type of Gmsh's linear volume element type `t`; false for any other type
inline bool gmsh_cell_type(std::int64_t t, Hex_dominant_cell_type& type)
{
  switch(t) {
    case 4: type = Hex_dominant_cell_type::TETRAHEDRON; return true;
    case 5: type = Hex_dominant_cell_type::HEXAHEDRON; return true;
    case 6: type = Hex_dominant_cell_type::PRISM; return true;
    case 7: type = Hex_dominant_cell_type::PYRAMID; return true;
    default: return false;
  }
}

// an element kept, its nodes as tags, its subdomain as read (2.2) or to be found from
// its entity (4.1)
struct Gmsh_element
{
  Hex_dominant_cell_type type;
  std::array<std::uint64_t, 8> nodes;
  std::uint64_t tag;
  int entity_tag;
  int subdomain;
};

struct Gmsh_reader
{
  Read_cursor& c;
  bool version_4 = false, binary = false;
  bool have_nodes = false, have_elements = false, have_entities = false;
  std::vector<std::uint64_t> node_tags;
  std::vector<std::array<double, 3>> coordinates;
  std::vector<Gmsh_element> elements;
  std::map<int, int> volume_subdomains; // volume entity tag -> physical tag (4.1)

  explicit Gmsh_reader(Read_cursor& cursor) : c(cursor) {}

  int to_int(std::int64_t v, const std::string& what) const
  {
    if(v < (std::numeric_limits<int>::min)() || v > (std::numeric_limits<int>::max)())
      c.fail(what + " " + std::to_string(v) + " is out of the range of int");
    return static_cast<int>(v);
  }

  // the binary data of a section starts after the line of its header
  void end_of_line()
  {
    while(c.position() < c.data().size() && (c.data()[c.position()] == ' ' || c.data()[c.position()] == '\r' ||
                                              c.data()[c.position()] == '\t'))
      c.set_position(c.position() + 1);
    if(c.position() >= c.data().size() || c.data()[c.position()] != '\n') c.fail("expected the end of a line");
    c.set_position(c.position() + 1);
  }

  void expect_end(const char* section)
  {
    const std::string end = std::string("$End") + section;
    const std::string_view t = c.token();
    if(t.empty()) c.truncated(end + " is missing");
    if(t != end) c.fail("expected " + end + ", found " + shown(t));
  }

  // binary counts: `n` entries of `bytes_each` bytes must fit in what is left
  std::size_t binary_count(std::uint64_t n, std::size_t bytes_each, const std::string& what) const
  {
    if(n > c.remaining() / bytes_each)
      read_error(c.name(), " is truncated or corrupt (" + what + " declares " + std::to_string(n) +
                             " entries, more than the rest of the input can hold)");
    return static_cast<std::size_t>(n);
  }

  void add_node(std::uint64_t tag, double x, double y, double z)
  {
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      read_error(c.name(), " has a point with a non-finite coordinate");
    node_tags.push_back(tag);
    coordinates.push_back({x, y, z});
  }

  std::size_t nodes_of(std::int64_t type) const
  {
    const std::size_t n = gmsh_nodes_per_element(type);
    if(n == 0) c.fail("unsupported Gmsh element type " + std::to_string(type));
    return n;
  }

  void read_format()
  {
    const std::string_view version = c.expect_token("the MSH version");
    if(version == "4.1") version_4 = true;
    else if(version == "2.2" || version == "2" || version == "2.0" || version == "2.1") version_4 = false;
    else c.fail("MSH version " + shown(version) + " is not supported (2.2 and 4.1 are)");
    const int file_type = c.integer<int>("the MSH file type");
    if(file_type != 0 && file_type != 1) c.fail("the MSH file type " + std::to_string(file_type) + " is neither 0 (ASCII) nor 1 (binary)");
    binary = file_type == 1;
    const int data_size = c.integer<int>("the MSH data size");
    if(binary) {
      if(data_size != 8) c.fail("the binary data size " + std::to_string(data_size) + " is not supported (8 is)");
      end_of_line();
      const std::uint32_t one = static_cast<std::uint32_t>(c.unsigned_value(4, "the binary one of $MeshFormat"));
      if(one == 0x01000000u) c.fail("big-endian binary MSH files are not supported");
      if(one != 1) c.fail("the binary one of $MeshFormat is " + std::to_string(one) + ", not 1");
    }
    expect_end("MeshFormat");
  }

  void read_entities()
  {
    if(!version_4) { // MSH 2 has no $Entities: skipped as unknown
      skip_section("Entities");
      return;
    }
    if(have_entities) c.fail("two $Entities sections");
    have_entities = true;
    if(binary) end_of_line();
    std::uint64_t counts[4];
    for(int d = 0; d < 4; ++d)
      counts[d] = binary ? c.uint64("the $Entities counts") : c.integer<std::uint64_t>("the number of entities");
    for(int d = 0; d < 4; ++d) {
      const std::string what = "the entities of dimension " + std::to_string(d);
      // a point: its tag, 3 coordinates, a count; any other entity: its tag, 6 coordinates, 2 counts
      const std::size_t n = binary ? binary_count(counts[d], d == 0 ? 4 + 24 + 8 : 4 + 48 + 16, what)
                                   : c.count(counts[d], d == 0 ? 2 * 5 : 2 * 9, what);
      for(std::size_t k = 0; k < n; ++k) {
        std::int64_t tag;
        if(binary) {
          tag = c.int32("an entity tag");
          for(int i = 0; i < (d == 0 ? 3 : 6); ++i) c.float64("the bounding box of an entity");
        } else {
          tag = c.integer<std::int64_t>("an entity tag");
          for(int i = 0; i < (d == 0 ? 3 : 6); ++i) c.number("the bounding box of an entity");
        }
        const std::uint64_t n_physicals_read =
          binary ? c.uint64("the number of physical tags") : c.integer<std::uint64_t>("the number of physical tags");
        const std::size_t n_physicals = binary ? binary_count(n_physicals_read, 4, "an entity's physical tags")
                                               : c.count(n_physicals_read, 2, "an entity's physical tags");
        std::int64_t physical = tag;
        for(std::size_t i = 0; i < n_physicals; ++i) {
          const std::int64_t p = binary ? c.int32("a physical tag") : c.integer<std::int64_t>("a physical tag");
          if(i == 0) physical = p;
        }
        if(d > 0) {
          const std::uint64_t n_bounding_read =
            binary ? c.uint64("the number of bounding entities") : c.integer<std::uint64_t>("the number of bounding entities");
          const std::size_t n_bounding = binary ? binary_count(n_bounding_read, 4, "an entity's bounding entities")
                                                : c.count(n_bounding_read, 2, "an entity's bounding entities");
          for(std::size_t i = 0; i < n_bounding; ++i)
            binary ? static_cast<std::int64_t>(c.int32("a bounding entity")) : c.integer<std::int64_t>("a bounding entity");
        }
        if(d == 3) volume_subdomains[to_int(tag, "the volume entity tag")] = to_int(physical, "the physical tag");
      }
    }
    expect_end("Entities");
  }

  void read_nodes()
  {
    if(have_nodes) c.fail("two $Nodes sections");
    have_nodes = true;
    if(!version_4) {
      const std::uint64_t n_read = c.integer<std::uint64_t>("the number of nodes");
      if(binary) {
        end_of_line();
        const std::size_t n = binary_count(n_read, 28, "$Nodes");
        node_tags.reserve(n), coordinates.reserve(n);
        for(std::size_t i = 0; i < n; ++i) {
          const std::int32_t tag = c.int32("a node tag");
          if(tag < 0) c.fail("the node tag " + std::to_string(tag) + " is negative");
          const double x = c.float64("a node coordinate"), y = c.float64("a node coordinate"), z = c.float64("a node coordinate");
          add_node(static_cast<std::uint64_t>(tag), x, y, z);
        }
      } else {
        const std::size_t n = c.count(n_read, 8, "$Nodes");
        node_tags.reserve(n), coordinates.reserve(n);
        for(std::size_t i = 0; i < n; ++i) {
          const std::uint64_t tag = c.integer<std::uint64_t>("a node tag");
          const double x = c.number("a node coordinate"), y = c.number("a node coordinate"), z = c.number("a node coordinate");
          add_node(tag, x, y, z);
        }
      }
      expect_end("Nodes");
      return;
    }
    if(binary) end_of_line();
    std::uint64_t header[4]; // blocks, nodes, min tag, max tag
    for(std::uint64_t& h : header) h = binary ? c.uint64("the $Nodes header") : c.integer<std::uint64_t>("the $Nodes header");
    const std::size_t n_nodes = binary ? binary_count(header[1], 32, "$Nodes") : c.count(header[1], 8, "$Nodes");
    const std::size_t n_blocks = binary ? binary_count(header[0], 20, "$Nodes") : c.count(header[0], 8, "$Nodes");
    node_tags.reserve(n_nodes), coordinates.reserve(n_nodes);
    for(std::size_t b = 0; b < n_blocks; ++b) {
      std::int64_t dim, parametric;
      std::uint64_t n_read;
      if(binary) {
        dim = c.int32("a node block header");
        c.int32("a node block header");
        parametric = c.int32("a node block header");
        n_read = c.uint64("a node block header");
      } else {
        dim = c.integer<std::int64_t>("the dimension of a node block");
        c.integer<std::int64_t>("the entity of a node block");
        parametric = c.integer<std::int64_t>("the parametric flag of a node block");
        n_read = c.integer<std::uint64_t>("the number of nodes of a block");
      }
      if(dim < 0 || dim > 3) c.fail("a node block has the dimension " + std::to_string(dim));
      if(parametric != 0 && parametric != 1) c.fail("a node block has the parametric flag " + std::to_string(parametric));
      const std::size_t values = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
      const std::size_t n = binary ? binary_count(n_read, 8 * (1 + values), "a node block")
                                   : c.count(n_read, 2 * (1 + values), "a node block");
      if(n > n_nodes - node_tags.size()) c.fail("the node blocks hold more nodes than the " + std::to_string(n_nodes) + " of the $Nodes header");
      for(std::size_t i = 0; i < n; ++i)
        node_tags.push_back(binary ? c.uint64("a node tag") : c.integer<std::uint64_t>("a node tag"));
      for(std::size_t i = 0; i < n; ++i) {
        double xyz[3] = {0, 0, 0};
        for(std::size_t j = 0; j < values; ++j) {
          const double v = binary ? c.float64("a node coordinate") : c.number("a node coordinate");
          if(j < 3) xyz[j] = v;
        }
        if(!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
          read_error(c.name(), " has a point with a non-finite coordinate");
        coordinates.push_back({xyz[0], xyz[1], xyz[2]});
      }
    }
    if(node_tags.size() != n_nodes)
      c.fail("the $Nodes header declares " + std::to_string(n_nodes) + " nodes, its blocks hold " + std::to_string(node_tags.size()));
    expect_end("Nodes");
  }

  void keep(std::int64_t type, const std::vector<std::uint64_t>& nodes, std::uint64_t tag, int entity, int subdomain)
  {
    Gmsh_element e;
    if(!gmsh_cell_type(type, e.type)) return;
    std::copy(nodes.begin(), nodes.end(), e.nodes.begin());
    e.tag = tag;
    e.entity_tag = entity;
    e.subdomain = subdomain;
    elements.push_back(e);
  }

  void read_elements()
  {
    if(have_elements) c.fail("two $Elements sections");
    have_elements = true;
    std::vector<std::uint64_t> nodes;
    if(!version_4) {
      const std::uint64_t n_read = c.integer<std::uint64_t>("the number of elements");
      if(binary) {
        end_of_line();
        const std::size_t n = binary_count(n_read, 8, "$Elements");
        std::size_t done = 0;
        while(done < n) {
          const std::int32_t type = c.int32("an element block header");
          const std::int32_t n_follow = c.int32("an element block header");
          const std::int32_t n_tags = c.int32("an element block header");
          if(n_follow <= 0 || static_cast<std::size_t>(n_follow) > n - done)
            c.fail("an element block of " + std::to_string(n_follow) + " elements, with " + std::to_string(n - done) + " left to read");
          if(n_tags < 0) c.fail("an element block with " + std::to_string(n_tags) + " tags");
          const std::size_t size = nodes_of(type);
          binary_count(static_cast<std::uint64_t>(n_follow), 4 * (1 + static_cast<std::size_t>(n_tags) + size), "an element block");
          for(std::int32_t k = 0; k < n_follow; ++k) {
            const std::int32_t tag = c.int32("an element");
            int physical = 1;
            for(std::int32_t i = 0; i < n_tags; ++i) {
              const std::int32_t t = c.int32("an element tag");
              if(i == 0) physical = t;
            }
            nodes.clear();
            for(std::size_t i = 0; i < size; ++i) {
              const std::int32_t v = c.int32("an element's node");
              nodes.push_back(v < 0 ? (std::numeric_limits<std::uint64_t>::max)() : static_cast<std::uint64_t>(v));
            }
            keep(type, nodes, static_cast<std::uint64_t>(tag < 0 ? 0 : tag), 0, physical);
          }
          done += static_cast<std::size_t>(n_follow);
        }
      } else {
        const std::size_t n = c.count(n_read, 8, "$Elements");
        for(std::size_t k = 0; k < n; ++k) {
          const std::uint64_t tag = c.integer<std::uint64_t>("an element tag");
          const std::int64_t type = c.integer<std::int64_t>("an element type");
          const std::size_t n_tags = c.count(c.integer<std::uint64_t>("the number of tags of an element"), 2, "an element's tags");
          std::int64_t physical = 1;
          for(std::size_t i = 0; i < n_tags; ++i) {
            const std::int64_t t = c.integer<std::int64_t>("a tag of an element");
            if(i == 0) physical = t;
          }
          const std::size_t size = nodes_of(type);
          nodes.clear();
          for(std::size_t i = 0; i < size; ++i) nodes.push_back(c.integer<std::uint64_t>("a node of an element"));
          keep(type, nodes, tag, 0, to_int(physical, "the physical tag"));
        }
      }
      expect_end("Elements");
      return;
    }
    if(binary) end_of_line();
    std::uint64_t header[4]; // blocks, elements, min tag, max tag
    for(std::uint64_t& h : header) h = binary ? c.uint64("the $Elements header") : c.integer<std::uint64_t>("the $Elements header");
    const std::size_t n_elements = binary ? binary_count(header[1], 16, "$Elements") : c.count(header[1], 4, "$Elements");
    const std::size_t n_blocks = binary ? binary_count(header[0], 20, "$Elements") : c.count(header[0], 8, "$Elements");
    std::size_t done = 0;
    for(std::size_t b = 0; b < n_blocks; ++b) {
      std::int64_t entity, type;
      std::uint64_t n_read;
      if(binary) {
        c.int32("an element block header");
        entity = c.int32("an element block header");
        type = c.int32("an element block header");
        n_read = c.uint64("an element block header");
      } else {
        c.integer<std::int64_t>("the dimension of an element block");
        entity = c.integer<std::int64_t>("the entity of an element block");
        type = c.integer<std::int64_t>("the element type of a block");
        n_read = c.integer<std::uint64_t>("the number of elements of a block");
      }
      const std::size_t size = nodes_of(type);
      const std::size_t n = binary ? binary_count(n_read, 8 * (1 + size), "an element block")
                                   : c.count(n_read, 2 * (1 + size), "an element block");
      if(n > n_elements - done)
        c.fail("the element blocks hold more elements than the " + std::to_string(n_elements) + " of the $Elements header");
      const int entity_tag = to_int(entity, "the entity tag");
      for(std::size_t k = 0; k < n; ++k) {
        const std::uint64_t tag = binary ? c.uint64("an element tag") : c.integer<std::uint64_t>("an element tag");
        nodes.clear();
        for(std::size_t i = 0; i < size; ++i)
          nodes.push_back(binary ? c.uint64("a node of an element") : c.integer<std::uint64_t>("a node of an element"));
        keep(type, nodes, tag, entity_tag, entity_tag);
      }
      done += n;
    }
    if(done != n_elements)
      c.fail("the $Elements header declares " + std::to_string(n_elements) + " elements, its blocks hold " + std::to_string(done));
    expect_end("Elements");
  }

  // skips the section `name` up to its $End line
  void skip_section(const std::string& name)
  {
    const std::string end = "$End" + name;
    std::size_t from = c.position();
    for(;;) {
      const std::size_t found = c.data().find(end, from);
      if(found == std::string::npos) c.truncated("the section $" + name + " has no " + end);
      const std::size_t after = found + end.size();
      if(after == c.data().size() || is_space(c.data()[after])) {
        c.set_position(after);
        return;
      }
      from = found + 1;
    }
  }

  template <class Point_3>
  void build(Hex_dominant_mesh_3<Point_3>& read)
  {
    // the nodes in the order of their tags, each tag once
    const std::size_t n = node_tags.size();
    std::vector<std::pair<std::uint64_t, std::size_t>> sorted; // (tag, index in the file)
    sorted.reserve(n);
    for(std::size_t i = 0; i < n; ++i) sorted.emplace_back(node_tags[i], i);
    std::sort(sorted.begin(), sorted.end());
    for(std::size_t i = 1; i < n; ++i)
      if(sorted[i].first == sorted[i - 1].first) c.fail("the node tag " + std::to_string(sorted[i].first) + " appears twice");
    read.points.reserve(n);
    for(const auto& s : sorted) {
      const auto& p = coordinates[s.second];
      read.points.push_back(Point_3(p[0], p[1], p[2]));
    }

    // the elements in the order of their tags (the order of the file among equal tags)
    std::stable_sort(elements.begin(), elements.end(),
                     [](const Gmsh_element& a, const Gmsh_element& b) { return a.tag < b.tag; });
    read.cells.reserve(elements.size());
    for(const Gmsh_element& e : elements) {
      typename Hex_dominant_mesh_3<Point_3>::Cell cell;
      cell.type = e.type;
      for(std::size_t i = 0; i < number_of_vertices(e.type); ++i) {
        const auto it = std::lower_bound(sorted.begin(), sorted.end(), std::make_pair(e.nodes[i], std::size_t(0)));
        if(it == sorted.end() || it->first != e.nodes[i])
          c.fail("element " + std::to_string(e.tag) + " refers to node " +
                 (e.nodes[i] == (std::numeric_limits<std::uint64_t>::max)() ? std::string("with a negative tag")
                                                                            : std::to_string(e.nodes[i])) +
                 ", which does not exist");
        cell.vertices[i] = static_cast<std::size_t>(it - sorted.begin());
      }
      cell.subdomain_index = e.subdomain;
      if(version_4) {
        const auto it = volume_subdomains.find(e.entity_tag);
        if(it != volume_subdomains.end()) cell.subdomain_index = it->second;
      }
      read.cells.push_back(cell);
    }
  }
};

template <class Point_3>
void read_MSH(const Read_input& in, Hex_dominant_mesh_3<Point_3>& mesh)
{
  Read_cursor c(in);
  Gmsh_reader r(c);
  const std::string_view first = c.token();
  if(first != "$MeshFormat") c.fail("not a Gmsh MSH file: it does not start with $MeshFormat");
  r.read_format();
  for(;;) {
    const std::string_view t = c.token();
    if(t.empty()) break;
    if(t[0] != '$' || t.size() < 2) c.fail("expected a section such as $Nodes, found " + shown(t));
    const std::string section(t.substr(1));
    if(section == "Nodes") r.read_nodes();
    else if(section == "Elements") r.read_elements();
    else if(section == "Entities") r.read_entities();
    else if(section == "MeshFormat") c.fail("two $MeshFormat sections");
    else r.skip_section(section);
  }
  Hex_dominant_mesh_3<Point_3> read;
  r.build(read);
  hand_over(read, mesh, in.name);
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * reads a volume mesh in Gmsh's MSH format from `is` into `mesh`, the counterpart of
 * `write_MSH()`: versions 2.2 (2.0 and 2.1 alike) and 4.1, ASCII and binary
 * (little-endian, data size 8).
 * - The points are all the nodes of `$Nodes` (nodes no cell uses are kept, so the counts
 *   are those of Gmsh and meshio), in the order of their tags, which may be sparse and
 *   need not increase through the file; where they do, as in Gmsh's files, this is the
 *   order of the file. (`write_MSH()` groups the nodes by entity, their tags giving
 *   their indices: reading its file gives back the points in their order.)
 * - The cells are the linear volume elements (Gmsh types 4 tetrahedron, 5 hexahedron,
 *   6 prism, 7 pyramid), in the order of their element tags (then of the file), as
 *   `write_MSH()` numbers them; each cell's nodes keep the order of the file (Gmsh's
 *   order is the mesh's: nothing is reordered or reoriented). All other
 *   elements (points, lines, triangles, quadrangles, and higher-order elements, which
 *   are not linearized) are skipped; an element type of unknown size is an error.
 * - The subdomain index of a cell: in version 2, its first tag (the physical one), or 1
 *   if it has none; in version 4.1, the first physical tag of its volume entity in
 *   `$Entities`, or the entity tag if that entity has no physical tag, is not listed
 *   there or if there is no `$Entities`.
 *
 * The other sections (`$PhysicalNames`, `$NodeData`, `$Periodic`, ...) are skipped up to
 * their `$End` line. `mesh` is left unchanged if an exception is thrown.
 * \throws std::invalid_argument naming `name` and the problem if the input is empty, is
 * not MSH 2 or 4.1, is truncated, has a count larger than the input can hold, a
 * duplicate node tag, an element referring to a node that does not exist, a non-finite
 * coordinate, or no tetrahedron, hexahedron, prism or pyramid
 */
template <class Point_3>
void read_MSH(std::istream& is, Hex_dominant_mesh_3<Point_3>& mesh, const std::string& name = "the MSH input")
{
  internal::read_MSH(internal::read_input_stream(is, name), mesh);
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * reads the file `filename` into `mesh` as `read_MSH(std::istream&, mesh)` does; the
 * messages of the exceptions name the file.
 * \throws std::invalid_argument if the file cannot be opened or read, or as
 * `read_MSH(std::istream&, mesh)` does
 */
template <class Point_3>
void read_MSH(const std::string& filename, Hex_dominant_mesh_3<Point_3>& mesh)
{
  internal::read_MSH(internal::read_input_file(filename), mesh);
}

} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_READ_MSH_H
