// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the volume mesh readers share: the whole input in memory, messages that
// name it, and a cursor over its text and binary data that checks every read
// and every declared count against what is left of the input.

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_INTERNAL_READ_UTILITIES_H
#define CGAL_HEX_DOMINANT_MESHING_IO_INTERNAL_READ_UTILITIES_H

#include <CGAL/Hex_dominant_mesh_3.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {
namespace internal {

// The whole input and how messages name it: `'x.mesh'` for a file, `the MEDIT input`
// for a stream.
struct Read_input
{
  std::string data;
  std::string name;
};

// throws std::invalid_argument(name + text); `text` starts with ": ..." or " is ..."
[[noreturn]] inline void read_error(const std::string& name, const std::string& text)
{
  throw std::invalid_argument(name + text);
}

inline bool is_space(char ch) { return ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t' || ch == '\f' || ch == '\v'; }

inline void check_not_empty(const Read_input& in, bool is_file)
{
  if(std::all_of(in.data.begin(), in.data.end(), is_space))
    read_error(in.name, is_file ? " is an empty file" : " is empty");
}

// the file `filename`, whole
inline Read_input read_input_file(const std::string& filename)
{
  Read_input in;
  in.name = "'" + filename + "'";
  std::error_code ec;
  if(std::filesystem::is_directory(filename, ec)) throw std::invalid_argument("cannot open " + in.name + ": it is a directory");
  std::ifstream is(filename, std::ios::binary);
  if(!is) throw std::invalid_argument("cannot open " + in.name);
  is.seekg(0, std::ios::end);
  const std::streamoff size = is.tellg();
  is.seekg(0, std::ios::beg);
  if(size > 0 && is) {
    in.data.resize(static_cast<std::size_t>(size));
    is.read(&in.data[0], size);
    if(is.gcount() != size) throw std::invalid_argument("cannot read " + in.name);
  } else {
    is.clear();
    is.seekg(0, std::ios::beg);
    in.data.assign(std::istreambuf_iterator<char>(is), std::istreambuf_iterator<char>());
  }
  if(is.bad()) throw std::invalid_argument("cannot read " + in.name);
  check_not_empty(in, true);
  return in;
}

// the rest of `is`
inline Read_input read_input_stream(std::istream& is, const std::string& name)
{
  Read_input in;
  in.name = name;
  if(!is) throw std::invalid_argument(name + ": the stream is not readable");
  in.data.assign(std::istreambuf_iterator<char>(is), std::istreambuf_iterator<char>());
  if(is.bad()) throw std::invalid_argument(name + ": the stream failed");
  check_not_empty(in, false);
  return in;
}

// `token` as it may stand in a message: printable, at most 40 characters, quoted
inline std::string shown(std::string_view token)
{
  std::string res = "'";
  for(std::size_t i = 0; i < token.size() && i < 40; ++i) {
    const unsigned char ch = static_cast<unsigned char>(token[i]);
    res += (ch >= 32 && ch < 127) ? static_cast<char>(ch) : '?';
  }
  if(token.size() > 40) res += "...";
  return res + "'";
}

inline std::string lower_case(std::string_view s)
{
  std::string res(s);
  for(char& ch : res)
    if(ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
  return res;
}

// the whole of `token` as a number, locale-independent; false if it is none. A leading
// '+' is accepted. Infinities and NaN are parsed: the caller checks finiteness. A
// magnitude beyond the double range is an infinity, one below it zero.
inline bool parse_number(std::string_view token, double& value)
{
  const char* first = token.data();
  const char* last = first + token.size();
  if(first != last && *first == '+') ++first;
  if(first == last) return false;
  const auto res = std::from_chars(first, last, value);
  if(res.ptr != last) return false;
  if(res.ec == std::errc::result_out_of_range) {
    // from_chars leaves `value` as it was: tell overflow from underflow by the exponent
    const std::size_t e = token.find_first_of("eE");
    const bool negative = token.find('-') == 0 || (token.size() > 1 && token[0] == '+' && token[1] == '-');
    const bool tiny = e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-';
    value = tiny ? 0. : std::numeric_limits<double>::infinity();
    if(negative) value = -value;
    return true;
  }
  return res.ec == std::errc();
}

template <class Int>
bool parse_integer(std::string_view token, Int& value)
{
  const char* first = token.data();
  const char* last = first + token.size();
  if(first != last && *first == '+') ++first;
  if(first == last) return false;
  const auto res = std::from_chars(first, last, value);
  return res.ec == std::errc() && res.ptr == last;
}

// A cursor over the input: whitespace-separated tokens (with `#` comments to the end of
// the line if asked) and little-endian binary values; every read is checked against
// the end of the input, every error names it.
class Read_cursor
{
public:
  Read_cursor(const Read_input& in, bool hash_comments = false)
    : s_(in.data), name_(in.name), hash_comments_(hash_comments)
  {}

  const std::string& name() const { return name_; }
  const std::string& data() const { return s_; }
  std::size_t position() const { return pos_; }
  void set_position(std::size_t pos) { pos_ = (std::min)(pos, s_.size()); }
  std::size_t remaining() const { return s_.size() - pos_; }

  [[noreturn]] void fail(const std::string& what) const { read_error(name_, ": " + what); }
  [[noreturn]] void truncated(const std::string& where) const { read_error(name_, " is truncated (" + where + ")"); }

  void skip_space()
  {
    for(;;) {
      while(pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
      if(hash_comments_ && pos_ < s_.size() && s_[pos_] == '#') {
        while(pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
        continue;
      }
      return;
    }
  }

  bool at_end()
  {
    skip_space();
    return pos_ >= s_.size();
  }

  // the next token, empty at the end of the input
  std::string_view token()
  {
    skip_space();
    const std::size_t begin = pos_;
    while(pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
    return std::string_view(s_.data() + begin, pos_ - begin);
  }

  // the next token; `what` is missing if there is none
  std::string_view expect_token(const std::string& what)
  {
    const std::string_view t = token();
    if(t.empty()) truncated(what + " is missing");
    return t;
  }

  template <class Int>
  Int integer(const std::string& what)
  {
    const std::string_view t = expect_token(what);
    Int value{};
    if(!parse_integer(t, value)) fail("expected " + what + ", found " + shown(t));
    return value;
  }

  double number(const std::string& what)
  {
    const std::string_view t = expect_token(what);
    double value = 0;
    if(!parse_number(t, value)) fail("expected " + what + ", found " + shown(t));
    return value;
  }

  // A count of `n` entries of at least `bytes_each` bytes each (as text: two bytes a
  // number, one digit and one separator), checked against what is left of the input.
  std::size_t count(std::uint64_t n, std::size_t bytes_each, const std::string& what) const
  {
    if(bytes_each == 0) bytes_each = 1;
    if(n > (remaining() + 1) / bytes_each)
      read_error(name_, " is truncated or corrupt (" + what + " declares " + std::to_string(n) +
                          " entries, more than the rest of the input can hold)");
    return static_cast<std::size_t>(n);
  }

  // after the end of the current line
  void skip_line()
  {
    while(pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
    if(pos_ < s_.size()) ++pos_;
  }

  // binary values, little-endian
  void need(std::size_t n, const std::string& where) const
  {
    if(n > remaining()) truncated(where);
  }
  std::uint64_t unsigned_value(std::size_t bytes, const std::string& where)
  {
    need(bytes, where);
    std::uint64_t v = 0;
    for(std::size_t i = 0; i < bytes; ++i) v |= std::uint64_t(static_cast<unsigned char>(s_[pos_ + i])) << (8 * i);
    pos_ += bytes;
    return v;
  }
  std::int32_t int32(const std::string& where)
  {
    const std::uint32_t u = static_cast<std::uint32_t>(unsigned_value(4, where));
    std::int32_t v;
    std::memcpy(&v, &u, 4);
    return v;
  }
  std::uint64_t uint64(const std::string& where) { return unsigned_value(8, where); }
  double float64(const std::string& where)
  {
    const std::uint64_t u = unsigned_value(8, where);
    double v;
    std::memcpy(&v, &u, 8);
    return v;
  }

private:
  const std::string& s_;
  const std::string& name_;
  bool hash_comments_;
  std::size_t pos_ = 0;
};

template <class Point_3>
Point_3 checked_point(const std::string& name, double x, double y, double z)
{
  if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    read_error(name, " has a point with a non-finite coordinate");
  return Point_3(x, y, z);
}

// checks that `read` has a volume cell and hands its contents over to `mesh`
template <class Point_3>
void hand_over(Hex_dominant_mesh_3<Point_3>& read, Hex_dominant_mesh_3<Point_3>& mesh, const std::string& name)
{
  if(read.cells.empty()) read_error(name, " has no tetrahedron, hexahedron, prism or pyramid");
  std::swap(mesh.points, read.points);
  std::swap(mesh.cells, read.cells);
}

} // namespace internal
} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_INTERNAL_READ_UTILITIES_H
