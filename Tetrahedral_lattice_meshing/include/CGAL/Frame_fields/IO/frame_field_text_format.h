// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small text format for discrete frame fields: the mesh as in a MEDIT .mesh
// file (vertices, 1-based tetrahedra) and one 3x3 matrix T per vertex or cell.

#ifndef CGAL_FRAME_FIELDS_IO_FRAME_FIELD_TEXT_FORMAT_H
#define CGAL_FRAME_FIELDS_IO_FRAME_FIELD_TEXT_FORMAT_H

#include <CGAL/Frame_fields/Discrete_frame_field_3.h>

#include <boost/io/ios_state.hpp>

#include <array>
#include <cstddef>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace IO {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFieldsIO
 * writes `field` in the VVM frame field text format:
 *
 * \code
 * VVMFrameField 1
 * Location Vertices          # or Cells
 * Vertices
 * 3                          # count, then one "x y z" per line
 * 0 0 0
 * ...
 * Tetrahedra
 * 1                          # count, then four 1-based vertex indices per line (as in .mesh)
 * 1 2 3 4
 * Frames
 * 3                          # one per vertex or per tetrahedron, as Location says:
 * 1 0 0 0 1 0 0 0 1          # T row by row (T00 T01 T02 T10 ... T22); the columns of T are the axes
 * ...
 * End
 * \endcode
 *
 * Keywords are case-sensitive; everything after `#` on a line is a comment. The vertices
 * and tetrahedra are those of the `.mesh` file the field belongs to, so a reader can
 * check that they match. Numbers are written with 17 significant digits; the precision
 * of `os` is restored afterwards.
 * \throws std::runtime_error if the stream fails
 */
template <class GeomTraits>
void write_frame_field(std::ostream& os, const Discrete_frame_field_3<GeomTraits>& field)
{
  boost::io::ios_precision_saver saved_precision(os);
  os.precision(17);
  os << "VVMFrameField 1\nLocation "
     << (field.location() == Frame_location::VERTICES ? "Vertices" : "Cells") << "\nVertices\n"
     << field.points().size() << "\n";
  for(const auto& p : field.points())
    os << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " " << CGAL::to_double(p.z()) << "\n";
  os << "Tetrahedra\n" << field.cells().size() << "\n";
  for(const auto& c : field.cells()) os << c[0] + 1 << " " << c[1] + 1 << " " << c[2] + 1 << " " << c[3] + 1 << "\n";
  os << "Frames\n" << field.frames().size() << "\n";
  for(const auto& T : field.frames()) {
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c) os << T(r, c) << (r == 2 && c == 2 ? "\n" : " ");
  }
  os << "End\n";
  if(!os) throw std::runtime_error("write_frame_field: the stream failed");
}

namespace internal {

// whitespace-separated tokens with '#' comments removed
class Token_reader
{
public:
  explicit Token_reader(std::istream& is)
  {
    std::string line;
    std::ostringstream all;
    while(std::getline(is, line)) all << line.substr(0, line.find('#')) << "\n";
    in_.str(all.str());
  }

  std::string word(const char* what)
  {
    std::string w;
    if(!(in_ >> w)) fail(std::string("unexpected end of file, expected ") + what);
    return w;
  }
  void expect(const char* keyword)
  {
    const std::string w = word(keyword);
    if(w != keyword) fail(std::string("expected '") + keyword + "', found '" + w + "'");
  }
  std::size_t count(const char* what)
  {
    const std::string w = word(what);
    std::size_t used = 0;
    unsigned long long n = 0;
    try { n = std::stoull(w, &used); } catch(...) { used = 0; }
    if(used != w.size() || w[0] == '-') fail(std::string("bad ") + what + " '" + w + "'");
    return std::size_t(n);
  }
  double number(const char* what)
  {
    const std::string w = word(what);
    std::size_t used = 0;
    double x = 0;
    try { x = std::stod(w, &used); } catch(...) { used = 0; }
    if(used != w.size()) fail(std::string("bad ") + what + " '" + w + "'");
    return x;
  }
  [[noreturn]] static void fail(const std::string& message)
  {
    throw std::invalid_argument("read_frame_field: " + message);
  }

private:
  std::istringstream in_;
};

} // namespace internal

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFieldsIO
 * reads a field written by `write_frame_field()`.
 * \throws std::invalid_argument with the reason (a missing keyword, a bad number, an index
 *   out of range, a count that does not match, a degenerate frame, ...)
 */
template <class GeomTraits>
Discrete_frame_field_3<GeomTraits> read_frame_field(std::istream& is)
{
  typedef typename GeomTraits::Point_3 Point_3;
  internal::Token_reader in(is);
  in.expect("VVMFrameField");
  if(in.count("version") != 1) internal::Token_reader::fail("unsupported version (1 expected)");
  in.expect("Location");
  const std::string where = in.word("Vertices or Cells");
  if(where != "Vertices" && where != "Cells")
    internal::Token_reader::fail("Location must be Vertices or Cells, not '" + where + "'");
  in.expect("Vertices");
  const std::size_t n = in.count("number of vertices");
  std::vector<Point_3> points;
  points.reserve((std::min)(n, std::size_t(1) << 24));
  for(std::size_t i = 0; i < n; ++i) {
    const double x = in.number("coordinate"), y = in.number("coordinate"), z = in.number("coordinate");
    points.emplace_back(x, y, z);
  }
  in.expect("Tetrahedra");
  const std::size_t m = in.count("number of tetrahedra");
  std::vector<std::array<std::size_t, 4>> cells;
  cells.reserve((std::min)(m, std::size_t(1) << 24));
  for(std::size_t i = 0; i < m; ++i) {
    std::array<std::size_t, 4> c;
    for(std::size_t& v : c) {
      v = in.count("vertex index");
      if(v < 1 || v > n)
        internal::Token_reader::fail("tetrahedron " + std::to_string(i + 1) + " has vertex index " +
                                     std::to_string(v) + " out of 1.." + std::to_string(n));
      --v;
    }
    cells.push_back(c);
  }
  in.expect("Frames");
  const std::size_t k = in.count("number of frames");
  std::vector<Eigen::Matrix3d> frames;
  frames.reserve((std::min)(k, std::size_t(1) << 24));
  for(std::size_t i = 0; i < k; ++i) {
    Eigen::Matrix3d T;
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c) T(r, c) = in.number("matrix entry");
    frames.push_back(T);
  }
  in.expect("End");
  return Discrete_frame_field_3<GeomTraits>(std::move(points), std::move(cells), std::move(frames),
                                            where == "Vertices" ? Frame_location::VERTICES
                                                                : Frame_location::CELLS);
}

} // namespace IO
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_IO_FRAME_FIELD_TEXT_FORMAT_H
