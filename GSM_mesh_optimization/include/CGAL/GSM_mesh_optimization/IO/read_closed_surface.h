// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input of every VVM program that meshes a volume: a closed triangle
// surface read from a file, checked so that a mesher can rely on it.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_IO_READ_CLOSED_SURFACE_H
#define CGAL_GSM_MESH_OPTIMIZATION_IO_READ_CLOSED_SURFACE_H

#include <CGAL/IO/OFF/File_header_OFF.h>
#include <CGAL/IO/io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/exceptions.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace IO {

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * triangulates the faces of `tm` if needed and checks that it bounds a volume a mesher can
 * fill. The messages of the exceptions start with `what`, which names the surface (e.g.
 * `"the surface in 'fandisk.off'"`), and give the reason:
 *
 * - it has no face (`"... has no face"`);
 * - a vertex has a NaN or infinite coordinate (`"... has a vertex with a non-finite coordinate"`);
 * - it has border edges (`"... is open (it has border edges); a closed surface is needed"`);
 * - it self-intersects (`"... self-intersects"`), unless `self_intersects` is given;
 * - it encloses no volume (`"... encloses no volume"`);
 * - a predicate of an inexact kernel (e.g. `Simple_cartesian<double>`) fails on degenerate
 *   faces (`"... is too degenerate for the kernel's predicates ..."`).
 *
 * \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point
 *   property map, e.g. `CGAL::Surface_mesh<Point_3>`
 *
 * \param tm the surface
 * \param what the surface's name in the messages
 * \param self_intersects if given, a self-intersecting surface is not an error: whether it
 *   self-intersects is written there instead (`make_mesh_3()` meshes such a surface, with the
 *   inside its domain's ray-parity test sees, which may not be the one intended)
 * \returns the volume enclosed by `tm`, positive
 * \throws std::invalid_argument if any of the checks above fails
 */
template <class TriangleMesh>
double check_closed_surface(TriangleMesh& tm, const std::string& what, bool* self_intersects = nullptr)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(num_faces(tm) == 0) throw std::invalid_argument(what + " has no face");
  const auto vpm = get(CGAL::vertex_point, tm);
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      throw std::invalid_argument(what + " has a vertex with a non-finite coordinate");
  }
  bool intersects = false;
  double volume = 0;
  try {
    if(!CGAL::is_triangle_mesh(tm)) PMP::triangulate_faces(tm);
    if(!CGAL::is_closed(tm)) throw std::invalid_argument(what + " is open (it has border edges); a closed surface is needed");
    intersects = PMP::does_self_intersect(tm);
    volume = std::abs(CGAL::to_double(PMP::volume(tm)));
  } catch(const CGAL::Failure_exception& e) { // an inexact kernel's predicate on degenerate faces
    throw std::invalid_argument(what + " is too degenerate for the kernel's predicates (" + e.expression() +
                                " failed in CGAL)");
  }
  if(intersects && !self_intersects) throw std::invalid_argument(what + " self-intersects");
  if(self_intersects) *self_intersects = intersects;
  if(!(volume > 0)) throw std::invalid_argument(what + " encloses no volume");
  return volume;
}

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * reads the polygon mesh in the file `fname` into `tm` (cleared first), in any format
 * that `CGAL::IO::read_polygon_mesh()` reads (OFF, OBJ, PLY, STL, GOCAD, VTP, ...),
 * and checks it with `check_closed_surface()` (the messages name `"the surface in '...'"`).
 * Besides those checks, the messages of the exceptions say when:
 *
 * - the file cannot be opened (`"cannot open '...'"`) or is empty
 *   (`"'...' is an empty file"`);
 * - its header declares more vertices, faces or elements than the file can hold (OFF, PLY),
 *   a PLY property before any element, or PLY vertex coordinates that are not float or
 *   double (CGAL 5.5's PLY reader does not survive either);
 * - it is not a polygon mesh (`"cannot read '...' as a polygon mesh (OFF, OBJ, PLY, STL, ...)"`).
 *
 * \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point
 *   property map, e.g. `CGAL::Surface_mesh<Point_3>`
 *
 * \param fname the path of the file
 * \param tm the surface read
 * \param self_intersects as in `check_closed_surface()`
 * \returns the volume enclosed by `tm`, positive
 * \throws std::invalid_argument if the file cannot be read or a check fails
 */
namespace internal {

/// the lowercase extension of `fname`, with its dot
inline std::string lowercase_extension(const std::string& fname)
{
  const std::size_t dot = fname.find_last_of('.'), slash = fname.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = fname.substr(dot);
  for(char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

/// a PLY element of the header: its count and properties (a list's size and item types)
struct Ply_property
{
  bool is_list = false;
  std::string size_type, item_type;
};
struct Ply_element
{
  double count;
  std::vector<Ply_property> properties;
};

/// the bytes of a PLY scalar type (0: unknown)
inline std::size_t ply_type_size(const std::string& t)
{
  if(t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if(t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if(t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
  if(t == "double" || t == "float64") return 8;
  return 0;
}

/// the next number of an ASCII PLY body as CGAL 5.5's reader reads a `T`: extracted as a
/// `Read` from the stream (floating point through `CGAL::IO::iformat()`), then cast to `T`
template <class T, class Read>
bool read_ply_ascii(std::istream& is, double& value)
{
  Read r;
  if constexpr(std::is_floating_point<Read>::value) {
    if(!(is >> CGAL::IO::iformat(r))) return false;
  } else if(!(is >> r))
    return false;
  value = double(static_cast<T>(r));
  return true;
}

/// walks the body of a PLY file after its header and refuses a list (a face's vertex indices)
/// whose size is larger than the file can hold: CGAL 5.5's reader resizes a vector to the
/// size it reads before reading the items, so 4294967295 in a `uint` size would allocate
/// 32 GB; and a body that ends before the elements the header declares.
inline void check_ply_list_sizes(const std::string& fname, std::istream& is, const std::string& format,
                                 const std::vector<Ply_element>& elements, std::uintmax_t size_of_file)
{
  auto refuse = [&](double n) {
    std::ostringstream count; // a double: a binary size may be far beyond any integer type
    count << std::setprecision(12) << n;
    throw std::invalid_argument("'" + fname + "' has a list of " + count.str() + " items: a list size is a whole " +
                                "number no larger than the file (" + std::to_string(size_of_file) + " bytes)");
  };
  const bool ascii = format == "ascii";
  const bool big_endian = format == "binary_big_endian";
  if(!ascii && !big_endian && format != "binary_little_endian") return; // CGAL's reader refuses it
  // the next scalar of type `type`, as a double; false at the end of the file or on a bad item
  auto read = [&](const std::string& type, double& value) -> bool {
    if(ascii) {
      // as CGAL's reader: one stream, each number read as its C++ type ("0-1" is two uint
      // numbers, 0 and 4294967295); chars through shorts, then cast
      if(type == "char" || type == "int8") return read_ply_ascii<signed char, short>(is, value);
      if(type == "uchar" || type == "uint8") return read_ply_ascii<unsigned char, unsigned short>(is, value);
      if(type == "short" || type == "int16") return read_ply_ascii<short, short>(is, value);
      if(type == "ushort" || type == "uint16") return read_ply_ascii<unsigned short, unsigned short>(is, value);
      if(type == "int" || type == "int32") return read_ply_ascii<int, int>(is, value);
      if(type == "uint" || type == "uint32") return read_ply_ascii<unsigned int, unsigned int>(is, value);
      if(type == "float" || type == "float32") return read_ply_ascii<float, float>(is, value);
      if(type == "double" || type == "float64") return read_ply_ascii<double, double>(is, value);
      return false;
    }
    const std::size_t bytes = ply_type_size(type);
    unsigned char b[8];
    if(bytes == 0 || !is.read(reinterpret_cast<char*>(b), std::streamsize(bytes))) return false;
    if(big_endian) std::reverse(b, b + bytes);
    const bool is_signed = type == "char" || type == "int8" || type == "short" || type == "int16" ||
                           type == "int" || type == "int32";
    if(type == "float" || type == "float32") {
      float f;
      std::memcpy(&f, b, 4);
      value = f;
    } else if(bytes == 8) {
      std::memcpy(&value, b, 8);
    } else {
      std::uint64_t u = 0;
      for(std::size_t k = 0; k < bytes; ++k) u |= std::uint64_t(b[k]) << (8 * k);
      if(is_signed && (u >> (8 * bytes - 1))) value = double(std::int64_t(u) - (std::int64_t(1) << (8 * bytes)));
      else value = double(u);
    }
    return true;
  };
  // CGAL's reader reads a list's size into an uninitialized variable: at the end of the
  // file it resizes the list to whatever that held
  auto truncated = [&]() {
    throw std::invalid_argument("'" + fname + "' ends before the elements its PLY header declares (or holds an "
                                "item that is not a number)");
  };
  double value, item;
  for(const Ply_element& e : elements)
    for(double row = 0; row < e.count; ++row)
      for(const Ply_property& p : e.properties) {
        if(!p.is_list) {
          if(!read(p.item_type, value)) truncated();
          continue;
        }
        if(!read(p.size_type, value)) truncated();
        // a negative size too: CGAL reads "-1" into an unsigned size as 4294967295
        if(!(value >= 0 && value <= double(size_of_file))) refuse(value);
        for(double k = 0; k < value; ++k)
          if(!read(p.item_type, item)) truncated();
      }
}

/// the faces of a binary OFF body after its vertices, as CGAL 5.5's reader reads them: each
/// a big-endian int32 size, by which the reader resizes a vector, then that many indices; a
/// size that is negative, larger than the rest of the file can hold, or cut by its end is
/// refused
inline void check_binary_off_faces(const std::string& fname, std::istream& is, const CGAL::File_header_OFF& header,
                                   std::uintmax_t size)
{
  const std::uintmax_t w = header.is_homogeneous() ? 1 : 0;
  const std::uintmax_t vertex_bytes =
      4 * ((3 + w) + (header.has_normals() ? 3 + w : 0) + (header.has_textures() ? 2 + w : 0));
  const std::streamoff start = is.tellg();
  if(start < 0) return;
  // the counts are at most the file's size (checked): no overflow
  const std::uintmax_t faces = std::uintmax_t(start) + header.size_of_vertices() * vertex_bytes;
  if(faces > size) return; // the reader fails in the vertices
  is.seekg(std::streamoff(faces));
  for(std::size_t f = 0; f < header.size_of_facets(); ++f) {
    // at the end of the file, CGAL's reader takes the size from an uninitialized int32
    unsigned char b[4];
    if(!is.read(reinterpret_cast<char*>(b), 4))
      throw std::invalid_argument("'" + fname + "' ends before the faces its OFF header declares");
    const std::int32_t n = std::int32_t(std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 |
                                        std::uint32_t(b[2]) << 8 | std::uint32_t(b[3]));
    const std::uintmax_t left = size - std::uintmax_t(is.tellg());
    if(n < 0 || std::uintmax_t(n) > left / 4)
      throw std::invalid_argument("'" + fname + "' has a face of " + std::to_string(n) + " vertices");
    is.seekg(4 * std::streamoff(n), std::ios::cur);
  }
}

/// refuses the headers CGAL 5.5's readers would act on blindly: a PLY "property" before
/// any "element" (CGAL's PLY reader writes through an empty vector's back()), vertex
/// coordinates of another type than float or double (it casts them to either), and element
/// or OFF counts larger than a file of `size` bytes can hold (each item takes a byte at
/// least; CGAL reserves memory for the counts it reads)
inline void check_surface_file_header(const std::string& fname, std::istream& is, std::uintmax_t size)
{
  const std::uintmax_t size_of_file = size;
  const std::string extension = lowercase_extension(fname);
  auto too_many = [&](const std::string& what, double count) {
    if(count > double(size))
      throw std::invalid_argument("'" + fname + "' declares " + what + " than its " + std::to_string(size) +
                                  " bytes can hold");
  };
  if(extension == ".ply") {
    std::string line, element, format;
    std::vector<Ply_element> elements;
    for(int n = 0; n < 100000 && std::getline(is, line); ++n) {
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      // as CGAL's reader: the second line is the format line, whatever its first word, and the
      // format is its second word
      if(n == 1) {
        words >> format;
        continue;
      }
      if(keyword == "end_header") {
        check_ply_list_sizes(fname, is, format, elements, size_of_file);
        return;
      }
      if(keyword == "property") {
        if(element.empty())
          throw std::invalid_argument("the PLY header of '" + fname + "' has a property before any element");
        // "property TYPE NAME" or "property list SIZE_TYPE ITEM_TYPE NAME"
        std::string type, name;
        Ply_property property;
        words >> type;
        if(type == "list") {
          property.is_list = true;
          words >> property.size_type >> property.item_type;
        } else property.item_type = type;
        words >> name;
        // CGAL reads a vertex's x, y, z as float or double, whatever their declared type (a
        // list of them fails its assertion, or without assertions reads through a null pointer)
        if((element == "vertex" || element == "vertices") && (name == "x" || name == "y" || name == "z") &&
           type != "float" && type != "float32" && type != "double" && type != "float64")
          throw std::invalid_argument("the PLY header of '" + fname + "' declares the vertex coordinate " + name +
                                      " as " + type + "; float or double is needed");
        // CGAL's reader skips a property of a type it does not know (and a list of a size type
        // that is not an integer)
        const bool known = ply_type_size(property.item_type) != 0 &&
                           (!property.is_list || (ply_type_size(property.size_type) != 0 &&
                                                  property.size_type.find("float") == std::string::npos &&
                                                  property.size_type != "double"));
        if(known && !elements.empty()) elements.back().properties.push_back(property);
      }
      if(keyword == "element") {
        // CGAL reads the count into a std::size_t: a negative one would wrap around
        std::string count;
        if(!(words >> element >> count)) element = "?";
        else if(!std::isdigit(static_cast<unsigned char>(count[0])))
          throw std::invalid_argument("the PLY header of '" + fname + "' declares " + count + " " + element +
                                      " elements; a count is a whole number");
        else {
          too_many("more " + element + " elements", std::stod(count));
          elements.push_back(Ply_element{std::stod(count), {}});
        }
      }
    }
    // CGAL's reader, given no end of header, reads on into the data as header lines
    throw std::invalid_argument("the PLY header of '" + fname + "' has no end_header line");
  } else if(extension == ".off") {
    // the header as CGAL's reader reads it (keyword, comments, counts; binary or text): the
    // reader resizes its vectors to the counts
    CGAL::File_header_OFF header(false);
    is >> header;
    if(!is) return; // CGAL's reader refuses it
    too_many("more vertices", double(header.size_of_vertices()));
    too_many("more faces", double(header.size_of_facets()));
    if(header.binary()) {
      check_binary_off_faces(fname, is, header, size_of_file);
      return;
    }
    // each face line starts with its number of vertices, by which CGAL sizes a vector: after
    // the rest of the counts line and the vertex lines (blank and comment lines skipped)
    std::string line;
    std::getline(is, line);
    const double vertices = double(header.size_of_vertices()), lines = vertices + double(header.size_of_facets());
    for(double n = 0; n < lines && std::getline(is, line);) {
      std::istringstream words(line);
      std::string token;
      if(!(words >> token) || token[0] == '#') continue;
      if(n++ < vertices) continue;
      std::istringstream number(token);
      double size;
      if(number >> size && !(size >= 0 && size <= double(size_of_file)))
        throw std::invalid_argument("'" + fname + "' has a face of " + token + " vertices");
    }
  }
}

/// closed_surface_from_polygon_soup(), its messages naming the surface `what`
template <class PointRange, class PolygonRange, class TriangleMesh>
double closed_surface_from_polygon_soup(const PointRange& points, const PolygonRange& polygons, TriangleMesh& tm,
                                        const std::string& what, bool* self_intersects)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  clear(tm);
  if(polygons.empty()) throw std::invalid_argument(what + " has no face");
  std::size_t i = 0;
  for(const auto& polygon : polygons) {
    if(polygon.size() < 3)
      throw std::invalid_argument("face " + std::to_string(i) + " of " + what + " has fewer than 3 vertices");
    for(const auto v : polygon)
      if(v >= points.size())
        throw std::invalid_argument("face " + std::to_string(i) + " of " + what + " has the vertex index " +
                                    std::to_string(v) + ", out of range (" + std::to_string(points.size()) +
                                    " vertices)");
    ++i;
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw std::invalid_argument("the faces of " + what + " do not form a polygon mesh (a non-manifold edge or vertex, a repeated "
                                "vertex in a face, or neighbouring faces oriented the opposite way)");
  PMP::polygon_soup_to_polygon_mesh(points, polygons, tm);
  return check_closed_surface(tm, what, self_intersects);
}

} // namespace internal

template <class TriangleMesh>
double read_closed_surface(const std::string& fname, TriangleMesh& tm, bool* self_intersects = nullptr)
{
  std::ifstream probe(fname, std::ios::binary | std::ios::ate);
  if(!probe) throw std::invalid_argument("cannot open '" + fname + "'");
  const std::streamoff size = probe.tellg();
  if(size <= 0) throw std::invalid_argument("'" + fname + "' is an empty file");
  probe.seekg(0);
  internal::check_surface_file_header(fname, probe, std::uintmax_t(size));
  probe.close();
  // a soup first: CGAL 5.5's face graph builders index the points with the file's face
  // indices unchecked; the soup's are checked before the mesh is built
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  clear(tm);
  bool read = false;
  try {
    read = CGAL::IO::read_polygon_soup(fname, points, polygons, CGAL::parameters::verbose(false));
  } catch(const std::length_error&) { // CGAL sizes a face's vector by a count read from the file
  } catch(const std::bad_alloc&) {
  } catch(const CGAL::Failure_exception&) { // a reader's own assertion on a header it did not expect
  }
  if(!read)
    throw std::invalid_argument("cannot read '" + fname + "' as a polygon mesh (OFF, OBJ, PLY, STL, ...)");
  return internal::closed_surface_from_polygon_soup(points, polygons, tm, "the surface in '" + fname + "'",
                                                    self_intersects);
}

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * builds `tm` (cleared first) from the polygon soup `points`, `polygons` (each polygon a
 * range of indices into `points`, three or more) and checks it with
 * `check_closed_surface()` (the messages name `"the surface"`). Besides those checks, the
 * messages of the exceptions say when a polygon has fewer than three vertices or an index
 * out of range, or when the polygons do not form a polygon mesh (a non-manifold edge or
 * vertex, or inconsistent orientations).
 *
 * \tparam PointRange a random access range of points convertible to `tm`'s points
 * \tparam PolygonRange a random access range of ranges of `std::size_t`
 * \throws std::invalid_argument if a check fails
 */
template <class PointRange, class PolygonRange, class TriangleMesh>
double closed_surface_from_polygon_soup(const PointRange& points, const PolygonRange& polygons, TriangleMesh& tm,
                                        bool* self_intersects = nullptr)
{
  return internal::closed_surface_from_polygon_soup(points, polygons, tm, "the surface", self_intersects);
}

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * the name of the file `path` without its directory (after the last `/` or `\\`) and its
 * last extension: `"data/fandisk.off"` gives `"fandisk"`; used to name a model in reports.
 */
inline std::string file_stem(const std::string& path)
{
  const std::string name = path.substr(path.find_last_of("/\\") + 1);
  return name.substr(0, name.find_last_of('.'));
}

} // namespace IO
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_IO_READ_CLOSED_SURFACE_H
