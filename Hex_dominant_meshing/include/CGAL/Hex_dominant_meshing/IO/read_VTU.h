// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh from a VTK XML unstructured grid (.vtu): ASCII, base64
// binary, zlib-compressed and appended data arrays, as this package, meshio
// and ParaView write them; the tetrahedra, hexahedra, wedges and pyramids with
// their subdomains from a cell data array.

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_READ_VTU_H
#define CGAL_HEX_DOMINANT_MESHING_IO_READ_VTU_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/IO/internal/read_utilities.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {

/// \ingroup PkgHexDominantMeshingRef
/// the names of the cell data arrays that `read_VTU()` takes the subdomain indices from,
/// the first one present: `subdomain` (what `write_VTU()` writes), `medit:ref`,
/// `gmsh:physical` (meshio's), `cell_tags`, `CellEntityIds` (VTK's and ParaView's),
/// `labels`
inline const std::vector<std::string>& default_VTU_subdomain_array_names()
{
  static const std::vector<std::string> names = {"subdomain", "medit:ref", "gmsh:physical",
                                                 "cell_tags", "CellEntityIds", "labels"};
  return names;
}

namespace internal {

// An XML element of a VTK file: its attributes, its children and the ranges of the
// input that are its own text (not its children's).
struct Xml_element
{
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<std::size_t> children;
  std::vector<std::pair<std::size_t, std::size_t>> text;

  const std::string* attribute(const std::string& key) const
  {
    for(const auto& a : attributes)
      if(a.first == key) return &a.second;
    return nullptr;
  }
};

// The elements of a VTK XML file up to <AppendedData>, whose content (raw bytes, maybe
// holding any character) is not parsed: `appended` is its first byte after the '_'.
struct Xml_document
{
  std::vector<Xml_element> elements; // elements[0] is the root
  std::size_t appended = std::string::npos;
  std::size_t appended_end = std::string::npos;
  bool appended_base64 = false;
};

inline std::string xml_unescaped(std::string_view s)
{
  std::string res;
  for(std::size_t i = 0; i < s.size(); ++i) {
    if(s[i] != '&') {
      res += s[i];
      continue;
    }
    const std::size_t semicolon = s.find(';', i);
    const std::string_view entity = semicolon == std::string_view::npos ? std::string_view() : s.substr(i + 1, semicolon - i - 1);
    char ch = 0;
    if(entity == "amp") ch = '&';
    else if(entity == "lt") ch = '<';
    else if(entity == "gt") ch = '>';
    else if(entity == "quot") ch = '"';
    else if(entity == "apos") ch = '\'';
    else if(entity.size() > 1 && entity[0] == '#') {
      unsigned int code = 0;
      const bool hex = entity[1] == 'x' || entity[1] == 'X';
      const std::string_view digits = entity.substr(hex ? 2 : 1);
      const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), code, hex ? 16 : 10);
      if(r.ec == std::errc() && r.ptr == digits.data() + digits.size() && code > 0 && code < 128) ch = static_cast<char>(code);
    }
    if(ch == 0) {
      res += s[i]; // not an entity we know: kept as it is
      continue;
    }
    res += ch;
    i = semicolon;
  }
  return res;
}

inline Xml_document parse_vtk_xml(const Read_input& in)
{
  const std::string& s = in.data;
  const std::size_t npos = std::string::npos;
  const std::size_t max_elements = 1000000, max_depth = 256;
  Xml_document doc;
  std::vector<std::size_t> open;
  std::size_t pos = 0;
  auto skip_space = [&] {
    while(pos < s.size() && is_space(s[pos])) ++pos;
  };
  auto name_at = [&]() -> std::string {
    const std::size_t begin = pos;
    while(pos < s.size() && !is_space(s[pos]) && s[pos] != '>' && s[pos] != '/' && s[pos] != '=' && s[pos] != '<')
      ++pos;
    return s.substr(begin, pos - begin);
  };
  auto skip_past = [&](const char* end, const char* what) {
    const std::size_t e = s.find(end, pos);
    if(e == npos) read_error(in.name, std::string(" is truncated (") + what + " is not closed)");
    pos = e + std::strlen(end);
  };
  while(pos < s.size()) {
    if(s[pos] != '<') {
      const std::size_t end = (std::min)(s.find('<', pos), s.size());
      if(!open.empty()) doc.elements[open.back()].text.emplace_back(pos, end);
      else if(!std::all_of(s.begin() + static_cast<std::ptrdiff_t>(pos), s.begin() + static_cast<std::ptrdiff_t>(end), is_space))
        read_error(in.name, ": not a VTK XML file (text outside its elements)");
      pos = end;
      continue;
    }
    if(s.compare(pos, 4, "<!--") == 0) {
      pos += 4;
      skip_past("-->", "a comment");
      continue;
    }
    if(s.compare(pos, 9, "<![CDATA[") == 0) read_error(in.name, ": CDATA sections are not supported");
    if(s.compare(pos, 2, "<?") == 0) {
      skip_past("?>", "a processing instruction");
      continue;
    }
    if(s.compare(pos, 2, "<!") == 0) {
      skip_past(">", "a declaration");
      continue;
    }
    if(s.compare(pos, 2, "</") == 0) {
      pos += 2;
      const std::string name = name_at();
      skip_space();
      if(pos >= s.size()) read_error(in.name, " is truncated (in the tag </" + name + ">)");
      if(s[pos] != '>' || open.empty() || doc.elements[open.back()].name != name)
        read_error(in.name, ": not a well-formed VTK XML file (the closing tag " + shown("</" + name + ">") +
                              (open.empty() ? std::string(" closes nothing") : " does not close <" + doc.elements[open.back()].name + ">") + ")");
      open.pop_back();
      ++pos;
      continue;
    }
    // a start tag
    ++pos;
    Xml_element e;
    e.name = name_at();
    if(e.name.empty()) read_error(in.name, ": not a well-formed VTK XML file (a '<' starts no tag)");
    bool self_closing = false;
    for(;;) {
      skip_space();
      if(pos >= s.size()) read_error(in.name, " is truncated (in the tag <" + e.name + ">)");
      if(s[pos] == '>') {
        ++pos;
        break;
      }
      if(s[pos] == '/') {
        if(pos + 1 < s.size() && s[pos + 1] == '>') {
          pos += 2;
          self_closing = true;
          break;
        }
        read_error(in.name, ": not a well-formed VTK XML file (a stray '/' in the tag <" + e.name + ">)");
      }
      const std::string key = name_at();
      skip_space();
      if(key.empty() || pos >= s.size() || s[pos] != '=')
        read_error(in.name, ": not a well-formed VTK XML file (a malformed attribute in the tag <" + e.name + ">)");
      ++pos;
      skip_space();
      if(pos >= s.size() || (s[pos] != '"' && s[pos] != '\''))
        read_error(in.name, ": not a well-formed VTK XML file (the attribute " + key + " of <" + e.name + "> is not quoted)");
      const std::size_t close = s.find(s[pos], pos + 1);
      if(close == npos) read_error(in.name, " is truncated (in the tag <" + e.name + ">)");
      e.attributes.emplace_back(key, xml_unescaped(std::string_view(s).substr(pos + 1, close - pos - 1)));
      pos = close + 1;
    }
    const std::size_t index = doc.elements.size();
    if(index == max_elements) read_error(in.name, ": more than a million XML elements");
    if(open.empty()) {
      if(index > 0) read_error(in.name, ": not a well-formed VTK XML file (two root elements)");
    } else {
      doc.elements[open.back()].children.push_back(index);
    }
    const bool appended = e.name == "AppendedData";
    doc.elements.push_back(std::move(e));
    if(appended) {
      const std::string* encoding = doc.elements.back().attribute("encoding");
      if(encoding == nullptr || (*encoding != "raw" && *encoding != "base64"))
        read_error(in.name, ": the <AppendedData> encoding " + (encoding ? shown(*encoding) : std::string("(none)")) +
                              " is neither 'raw' nor 'base64'");
      doc.appended_base64 = *encoding == "base64";
      skip_space();
      if(self_closing || pos >= s.size() || s[pos] != '_')
        read_error(in.name, ": the appended data does not start with '_'");
      doc.appended = pos + 1;
      // base64 data ends at the closing tag; raw data, which may hold any byte, at the end
      doc.appended_end = doc.appended_base64 ? (std::min)(s.find('<', doc.appended), s.size()) : s.size();
      return doc; // what follows is </AppendedData></VTKFile>
    }
    if(!self_closing) {
      if(open.size() == max_depth) read_error(in.name, ": XML elements nested too deeply");
      open.push_back(index);
    }
  }
  if(doc.elements.empty()) read_error(in.name, ": not a VTK XML file (no XML element)");
  if(!open.empty()) read_error(in.name, " is truncated (<" + doc.elements[open.back()].name + "> is not closed)");
  return doc;
}

// The bytes of a data array: raw, or base64 (possibly several encoded blocks one after
// the other, as VTK writes a header and its data, each padded).
class Vtk_bytes
{
public:
  Vtk_bytes(const std::string& s, std::size_t begin, std::size_t end, bool base64, const std::string& name)
    : s_(s), pos_(begin), end_((std::min)(end, s.size())), base64_(base64), name_(name)
  {}

  // an upper bound on the number of bytes left
  std::size_t available() const
  {
    const std::size_t chars = pos_ < end_ ? end_ - pos_ : 0;
    return base64_ ? chars / 4 * 3 + 3 + (buffered_ - used_) : chars;
  }

  // false if the data ends first
  bool read(unsigned char* out, std::size_t n)
  {
    if(!base64_) {
      if(n > available()) return false;
      if(n > 0) std::memcpy(out, s_.data() + pos_, n);
      pos_ += n;
      return true;
    }
    for(std::size_t i = 0; i < n; ++i) {
      if(used_ == buffered_ && !next_quantum()) return false;
      out[i] = buffer_[used_++];
    }
    return true;
  }

private:
  static int value_of(char ch)
  {
    if(ch >= 'A' && ch <= 'Z') return ch - 'A';
    if(ch >= 'a' && ch <= 'z') return ch - 'a' + 26;
    if(ch >= '0' && ch <= '9') return ch - '0' + 52;
    if(ch == '+') return 62;
    if(ch == '/') return 63;
    return -1;
  }

  // decodes the next four characters (or the last two or three, unpadded)
  bool next_quantum()
  {
    int values[4];
    std::size_t n = 0, padding = 0;
    while(n < 4 && pos_ < end_) {
      const char ch = s_[pos_++];
      if(is_space(ch)) continue;
      if(ch == '=') {
        if(n < 2) read_error(name_, ": invalid base64 data (misplaced '=')");
        values[n++] = 0;
        ++padding;
        continue;
      }
      const int v = value_of(ch);
      if(v < 0 || padding > 0) read_error(name_, ": invalid base64 data (the character " + shown(std::string(1, ch)) + ")");
      values[n++] = v;
    }
    if(n == 0) return false;
    if(n == 1) read_error(name_, ": invalid base64 data (a lone character at its end)");
    for(std::size_t i = n; i < 4; ++i) values[i] = 0, ++padding;
    const std::uint32_t bits = (std::uint32_t(values[0]) << 18) | (std::uint32_t(values[1]) << 12) |
                               (std::uint32_t(values[2]) << 6) | std::uint32_t(values[3]);
    buffer_[0] = static_cast<unsigned char>(bits >> 16);
    buffer_[1] = static_cast<unsigned char>((bits >> 8) & 0xff);
    buffer_[2] = static_cast<unsigned char>(bits & 0xff);
    buffered_ = 3 - padding;
    used_ = 0;
    return buffered_ > 0;
  }

  const std::string& s_;
  std::size_t pos_, end_;
  bool base64_;
  const std::string& name_;
  unsigned char buffer_[3] = {0, 0, 0};
  std::size_t buffered_ = 0, used_ = 0;
};

// a VTK scalar type
struct Vtk_scalar_type
{
  std::size_t size = 0;
  bool is_float = false, is_signed = false;
};

inline bool vtk_scalar_type(const std::string& name, Vtk_scalar_type& t)
{
  static const std::pair<const char*, Vtk_scalar_type> types[] = {
    {"Int8", {1, false, true}},    {"UInt8", {1, false, false}},  {"Int16", {2, false, true}},
    {"UInt16", {2, false, false}}, {"Int32", {4, false, true}},   {"UInt32", {4, false, false}},
    {"Int64", {8, false, true}},   {"UInt64", {8, false, false}}, {"Float32", {4, true, true}},
    {"Float64", {8, true, true}}};
  for(const auto& p : types)
    if(name == p.first) {
      t = p.second;
      return true;
    }
  return false;
}

struct Vtu_context
{
  const Read_input& in;
  const Xml_document& doc;
  bool big_endian = false;
  std::size_t header_size = 4;
  bool zlib = false;

  [[noreturn]] void fail(const std::string& what) const { read_error(in.name, ": " + what); }
  [[noreturn]] void truncated(const std::string& where) const { read_error(in.name, " is truncated (" + where + ")"); }

  std::uint64_t word(const unsigned char* b, std::size_t size) const
  {
    std::uint64_t v = 0;
    for(std::size_t i = 0; i < size; ++i) v |= std::uint64_t(b[big_endian ? size - 1 - i : i]) << (8 * i);
    return v;
  }

  std::uint64_t header_word(Vtk_bytes& src, const std::string& what) const
  {
    unsigned char b[8];
    if(!src.read(b, header_size)) truncated("the header of " + what);
    return word(b, header_size);
  }

  // the bytes of a binary or appended data array, decompressed
  std::vector<unsigned char> binary_data(Vtk_bytes& src, const std::string& what) const
  {
    std::vector<unsigned char> out;
    if(!zlib) {
      const std::uint64_t n = header_word(src, what);
      if(n > src.available())
        read_error(in.name, " is truncated or corrupt (" + what + " declares " + std::to_string(n) +
                              " bytes, more than the input holds)");
      out.resize(static_cast<std::size_t>(n));
      if(!src.read(out.data(), out.size())) truncated("the data of " + what);
      return out;
    }
    // zlib: [number of blocks, block size, last block size, compressed size of each block]
    const std::uint64_t n_blocks = header_word(src, what);
    if(n_blocks > src.available() / header_size)
      read_error(in.name, " is truncated or corrupt (" + what + " declares " + std::to_string(n_blocks) +
                            " compressed blocks, more than the input holds)");
    const std::uint64_t block_size = header_word(src, what);
    const std::uint64_t last_size_read = header_word(src, what);
    std::vector<std::uint64_t> compressed(static_cast<std::size_t>(n_blocks));
    std::uint64_t total_compressed = 0;
    for(std::uint64_t& size : compressed) {
      size = header_word(src, what);
      if(size > src.available() || total_compressed + size > src.available())
        read_error(in.name, " is truncated or corrupt (the compressed blocks of " + what + " are larger than the input)");
      total_compressed += size;
    }
    const std::uint64_t last_size = last_size_read == 0 ? block_size : last_size_read;
    if(n_blocks > 0 && (block_size == 0 || last_size > block_size))
      fail("the compression header of " + what + " is invalid");
    std::uint64_t total = 0;
    std::vector<std::uint64_t> sizes(compressed.size());
    for(std::size_t k = 0; k < sizes.size(); ++k) {
      sizes[k] = k + 1 == sizes.size() ? last_size : block_size;
      // zlib compresses at most 1032:1: a larger size is a lie that would allocate absurdly
      if(sizes[k] > 1032 * compressed[k] + 64 || sizes[k] > (std::numeric_limits<uLong>::max)() ||
         compressed[k] > (std::numeric_limits<uLong>::max)())
        fail("the compression header of " + what + " declares a block of " + std::to_string(sizes[k]) +
             " bytes compressed into " + std::to_string(compressed[k]));
      total += sizes[k];
    }
    out.resize(static_cast<std::size_t>(total));
    std::vector<unsigned char> block;
    std::size_t offset = 0;
    for(std::size_t k = 0; k < sizes.size(); ++k) {
      block.resize(static_cast<std::size_t>(compressed[k]));
      if(!src.read(block.data(), block.size())) truncated("the compressed data of " + what);
      uLongf length = static_cast<uLongf>(sizes[k]);
      const int status = uncompress(out.data() + offset, &length, block.data(), static_cast<uLong>(block.size()));
      if(status != Z_OK || length != sizes[k]) fail("the zlib data of " + what + " is corrupt");
      offset += static_cast<std::size_t>(sizes[k]);
    }
    return out;
  }

  // the values of the data array `e` as `T` (double, or std::int64_t: then each value
  // must be an integer)
  template <class T>
  std::vector<T> values(const Xml_element& e, const std::string& what) const
  {
    static_assert(std::is_same<T, double>::value || std::is_same<T, std::int64_t>::value, "double or int64");
    const bool want_integers = std::is_same<T, std::int64_t>::value;
    const std::string* type_name = e.attribute("type");
    Vtk_scalar_type type;
    if(type_name == nullptr) fail(what + " has no type");
    if(!vtk_scalar_type(*type_name, type)) fail(what + " has the type " + shown(*type_name) + ", which is not read");
    const std::string* format = e.attribute("format");
    const std::string fmt = format ? *format : "ascii";
    std::vector<T> res;
    auto not_integer = [&] { fail(what + " holds a value that is not an integer in the range of Int64"); };

    if(fmt == "ascii") {
      const std::string& s = in.data;
      for(const auto& range : e.text) {
        std::size_t pos = range.first;
        for(;;) {
          while(pos < range.second && is_space(s[pos])) ++pos;
          if(pos >= range.second) break;
          const std::size_t begin = pos;
          while(pos < range.second && !is_space(s[pos])) ++pos;
          const std::string_view token(s.data() + begin, pos - begin);
          if(want_integers && !type.is_float) {
            std::int64_t v;
            if(!parse_integer(token, v)) fail(what + " holds " + shown(token) + ", not an integer in the range of Int64");
            res.push_back(static_cast<T>(v));
          } else {
            double v;
            if(!parse_number(token, v)) fail(what + " holds " + shown(token) + ", not a number");
            if(want_integers && !(std::isfinite(v) && v == std::floor(v) && std::abs(v) < 9.2e18))
              fail(what + " holds " + shown(token) + ", not an integer in the range of Int64");
            res.push_back(static_cast<T>(v));
          }
        }
      }
      return res;
    }

    std::vector<unsigned char> bytes;
    if(fmt == "binary") {
      std::string text;
      for(const auto& range : e.text) text.append(in.data, range.first, range.second - range.first);
      Vtk_bytes src(text, 0, text.size(), true, in.name);
      bytes = binary_data(src, what);
    } else if(fmt == "appended") {
      if(doc.appended == std::string::npos) fail(what + " is appended, but there is no <AppendedData>");
      const std::string* offset_attribute = e.attribute("offset");
      std::uint64_t offset = 0;
      if(offset_attribute == nullptr || !parse_integer(std::string_view(*offset_attribute), offset))
        fail(what + " is appended, without a valid offset");
      if(offset > doc.appended_end - doc.appended) truncated("the offset of " + what + " is past the end of the input");
      Vtk_bytes src(in.data, doc.appended + static_cast<std::size_t>(offset), doc.appended_end, doc.appended_base64, in.name);
      bytes = binary_data(src, what);
    } else {
      fail(what + " has the format " + shown(fmt) + ", not ascii, binary or appended");
    }
    if(bytes.size() % type.size != 0)
      fail(what + " has " + std::to_string(bytes.size()) + " bytes, not a whole number of " + *type_name + " values");
    res.reserve(bytes.size() / type.size);
    for(std::size_t i = 0; i < bytes.size(); i += type.size) {
      const std::uint64_t bits = word(bytes.data() + i, type.size);
      if(type.is_float) {
        double v;
        if(type.size == 4) {
          const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
          float f;
          std::memcpy(&f, &b32, 4);
          v = f;
        } else {
          std::memcpy(&v, &bits, 8);
        }
        if(want_integers && !(std::isfinite(v) && v == std::floor(v) && std::abs(v) < 9.2e18)) not_integer();
        res.push_back(static_cast<T>(v));
      } else if(type.is_signed) {
        std::int64_t v;
        if(type.size == 8) {
          std::memcpy(&v, &bits, 8);
        } else { // sign extension
          const std::uint64_t sign = std::uint64_t(1) << (8 * type.size - 1);
          v = static_cast<std::int64_t>(bits ^ sign) - static_cast<std::int64_t>(sign);
        }
        res.push_back(static_cast<T>(v));
      } else {
        if(want_integers && bits > std::uint64_t((std::numeric_limits<std::int64_t>::max)())) not_integer();
        res.push_back(static_cast<T>(bits));
      }
    }
    return res;
  }
};

inline const Xml_element* xml_child(const Xml_document& doc, const Xml_element& e, const char* name)
{
  for(std::size_t c : e.children)
    if(doc.elements[c].name == name) return &doc.elements[c];
  return nullptr;
}

inline const Xml_element* vtu_data_array(const Xml_document& doc, const Xml_element* e, const std::string& name)
{
  if(e == nullptr) return nullptr;
  for(std::size_t c : e->children) {
    const Xml_element& a = doc.elements[c];
    const std::string* n = a.attribute("Name");
    if(a.name == "DataArray" && n != nullptr && *n == name) return &a;
  }
  return nullptr;
}

inline std::uint64_t vtu_unsigned_attribute(const Vtu_context& ctx, const Xml_element& e, const char* key)
{
  const std::string* v = e.attribute(key);
  std::uint64_t n = 0;
  if(v == nullptr || !parse_integer(std::string_view(*v), n))
    ctx.fail("the <" + e.name + "> attribute " + key + (v ? " is " + shown(*v) + ", not a count" : std::string(" is missing")));
  return n;
}

inline std::uint64_t vtu_number_of_components(const Vtu_context& ctx, const Xml_element& e)
{
  return e.attribute("NumberOfComponents") ? vtu_unsigned_attribute(ctx, e, "NumberOfComponents") : 1;
}

template <class Point_3>
void read_VTU(const Read_input& in, Hex_dominant_mesh_3<Point_3>& mesh, const std::vector<std::string>& subdomain_names)
{
  typedef Hex_dominant_mesh_3<Point_3> Mesh;
  typedef Hex_dominant_cell_type Cell_type;
  const Xml_document doc = parse_vtk_xml(in);
  Vtu_context ctx{in, doc};
  const Xml_element& root = doc.elements[0];
  if(root.name != "VTKFile") ctx.fail("not a VTK XML file (its root element is " + shown("<" + root.name + ">") + ")");
  const std::string* type = root.attribute("type");
  if(type == nullptr || *type != "UnstructuredGrid")
    ctx.fail("a VTK XML file of type " + (type ? shown(*type) : std::string("(none)")) + ", not UnstructuredGrid");
  if(const std::string* order = root.attribute("byte_order")) {
    if(*order == "BigEndian") ctx.big_endian = true;
    else if(*order != "LittleEndian") ctx.fail("the byte order " + shown(*order) + " is neither LittleEndian nor BigEndian");
  }
  if(const std::string* header = root.attribute("header_type")) {
    if(*header == "UInt64") ctx.header_size = 8;
    else if(*header != "UInt32") ctx.fail("the header type " + shown(*header) + " is neither UInt32 nor UInt64");
  }
  if(const std::string* compressor = root.attribute("compressor")) {
    if(*compressor == "vtkZLibDataCompressor") ctx.zlib = true;
    else if(!compressor->empty())
      ctx.fail("the compressor " + shown(*compressor) + " is not supported (vtkZLibDataCompressor is)");
  }
  const Xml_element* grid = xml_child(doc, root, "UnstructuredGrid");
  if(grid == nullptr) ctx.fail("no <UnstructuredGrid>");

  Mesh read;
  bool have_piece = false;
  for(std::size_t p : grid->children) {
    const Xml_element& piece = doc.elements[p];
    if(piece.name != "Piece") continue;
    have_piece = true;
    const std::uint64_t n_points = vtu_unsigned_attribute(ctx, piece, "NumberOfPoints");
    const std::uint64_t n_cells = vtu_unsigned_attribute(ctx, piece, "NumberOfCells");
    const std::size_t first_point = read.points.size();

    // the points
    const Xml_element* points = xml_child(doc, piece, "Points");
    const Xml_element* point_array = nullptr;
    if(points != nullptr)
      for(std::size_t c : points->children)
        if(doc.elements[c].name == "DataArray") {
          point_array = &doc.elements[c];
          break;
        }
    if(n_points > 0) {
      if(point_array == nullptr) ctx.fail("a <Piece> of " + std::to_string(n_points) + " points has no <Points> array");
      if(vtu_number_of_components(ctx, *point_array) != 3) ctx.fail("the <Points> array does not have 3 components");
      const std::vector<double> xyz = ctx.values<double>(*point_array, "the <Points> array");
      if(xyz.size() / 3 != n_points || xyz.size() % 3 != 0)
        ctx.fail("the <Points> array has " + std::to_string(xyz.size()) + " values for " + std::to_string(n_points) + " points");
      read.points.reserve(read.points.size() + xyz.size() / 3);
      for(std::size_t i = 0; i < xyz.size(); i += 3)
        read.points.push_back(checked_point<Point_3>(in.name, xyz[i], xyz[i + 1], xyz[i + 2]));
    }
    if(n_cells == 0) continue;

    // the cells
    const Xml_element* cells = xml_child(doc, piece, "Cells");
    const Xml_element* connectivity_array = vtu_data_array(doc, cells, "connectivity");
    const Xml_element* offsets_array = vtu_data_array(doc, cells, "offsets");
    const Xml_element* types_array = vtu_data_array(doc, cells, "types");
    if(connectivity_array == nullptr || offsets_array == nullptr || types_array == nullptr)
      ctx.fail("a <Piece> of " + std::to_string(n_cells) + " cells lacks the <Cells> array connectivity, offsets or types");
    const std::vector<std::int64_t> offsets = ctx.values<std::int64_t>(*offsets_array, "the offsets array");
    const std::vector<std::int64_t> types = ctx.values<std::int64_t>(*types_array, "the types array");
    if(offsets.size() != n_cells || types.size() != n_cells)
      ctx.fail("the offsets and types arrays have " + std::to_string(offsets.size()) + " and " +
               std::to_string(types.size()) + " values for " + std::to_string(n_cells) + " cells");
    const std::vector<std::int64_t> connectivity = ctx.values<std::int64_t>(*connectivity_array, "the connectivity array");

    // the subdomains: the first array of the names given
    std::vector<std::int64_t> subdomains;
    const Xml_element* cell_data = xml_child(doc, piece, "CellData");
    for(const std::string& name : subdomain_names) {
      const Xml_element* a = vtu_data_array(doc, cell_data, name);
      if(a == nullptr) continue;
      const std::string what = "the cell data array " + shown(name);
      if(vtu_number_of_components(ctx, *a) != 1) ctx.fail(what + " has more than one component");
      subdomains = ctx.values<std::int64_t>(*a, what);
      if(subdomains.size() != n_cells)
        ctx.fail(what + " has " + std::to_string(subdomains.size()) + " values for " + std::to_string(n_cells) + " cells");
      break;
    }

    std::int64_t begin = 0;
    for(std::size_t k = 0; k < n_cells; ++k) {
      const std::int64_t end = offsets[k];
      if(end < begin || static_cast<std::uint64_t>(end) > connectivity.size())
        ctx.fail("the offset of cell " + std::to_string(k) + " is " + std::to_string(end) + ", out of order or past the " +
                 std::to_string(connectivity.size()) + " values of the connectivity");
      typename Mesh::Cell cell;
      bool kept = true;
      switch(types[k]) {
        case 10: cell.type = Cell_type::TETRAHEDRON; break;
        case 12: cell.type = Cell_type::HEXAHEDRON; break;
        case 13: cell.type = Cell_type::PRISM; break;
        case 14: cell.type = Cell_type::PYRAMID; break;
        default: kept = false;
      }
      if(kept) {
        const std::size_t size = cell.size();
        if(static_cast<std::uint64_t>(end - begin) != size)
          ctx.fail("cell " + std::to_string(k) + " of VTK type " + std::to_string(types[k]) + " has " +
                   std::to_string(end - begin) + " vertices, not " + std::to_string(size));
        // VTK's wedge lists its first triangle the other way round (see write_VTU)
        static const std::size_t wedge[6] = {0, 2, 1, 3, 5, 4};
        for(std::size_t i = 0; i < size; ++i) {
          const std::int64_t v = connectivity[static_cast<std::size_t>(begin) + (cell.type == Cell_type::PRISM ? wedge[i] : i)];
          if(v < 0 || static_cast<std::uint64_t>(v) >= n_points)
            ctx.fail("cell " + std::to_string(k) + " refers to point " + std::to_string(v) + ", which does not exist (" +
                     std::to_string(n_points) + " points)");
          cell.vertices[i] = first_point + static_cast<std::size_t>(v);
        }
        if(!subdomains.empty()) {
          if(subdomains[k] < (std::numeric_limits<int>::min)() || subdomains[k] > (std::numeric_limits<int>::max)())
            ctx.fail("the subdomain index " + std::to_string(subdomains[k]) + " of cell " + std::to_string(k) +
                     " is out of the range of int");
          cell.subdomain_index = static_cast<int>(subdomains[k]);
        } else {
          cell.subdomain_index = 1;
        }
        read.cells.push_back(cell);
      }
      begin = end;
    }
  }
  if(!have_piece) ctx.fail("no <Piece>");
  hand_over(read, mesh, in.name);
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * reads a VTK XML unstructured grid (`.vtu`) from `is` into `mesh`, the counterpart of
 * `write_VTU()`, as this package, meshio (compressed or not, or ASCII) and ParaView
 * write it:
 * - data arrays in the formats `ascii`, `binary` (base64, with a `UInt32` or `UInt64`
 *   header as `header_type` says) and `appended` (`raw` or `base64` encoding), compressed
 *   by `vtkZLibDataCompressor` or not, of the types `Int8` to `UInt64`, `Float32` and
 *   `Float64`, little- or big-endian;
 * - the points of every `Piece` in their order (all of them, used or not);
 * - the cells of VTK types 10 (tetrahedron), 12 (hexahedron), 13 (wedge) and 14
 *   (pyramid) in their order; the cells of other types (vertices, lines, triangles,
 *   quadrilaterals, polyhedra, higher-order cells, ...) are skipped. Wedges are turned
 *   from VTK's order into the mesh's (`0 2 1 3 5 4`, the order `write_VTU()` undoes), the
 *   other cells keep their vertex order: nothing is reoriented;
 * - the subdomain index of each cell from the first cell data array of `subdomain_array_names`
 *   that the piece has (by default `default_VTU_subdomain_array_names()`, `subdomain`
 *   first: what `write_VTU()` writes), which must have one integer component; 1 if there
 *   is none.
 *
 * The header includes `<zlib.h>`: a program that uses it must link zlib (CMake:
 * `find_package(ZLIB)`, `ZLIB::ZLIB`, which `VVM::Hex_dominant_meshing` links).
 * Compressors other than zlib (LZ4, LZMA) are not supported.
 * `mesh` is left unchanged if an exception is thrown.
 * \throws std::invalid_argument naming `name` and the problem if the input is empty, is
 * not a VTK XML unstructured grid, is truncated, declares more data than it holds, has
 * corrupt compressed or base64 data, an array whose size does not match the counts of
 * its piece, a vertex index out of range, a non-finite coordinate, or no tetrahedron,
 * hexahedron, wedge or pyramid
 */
template <class Point_3>
void read_VTU(std::istream& is, Hex_dominant_mesh_3<Point_3>& mesh,
              const std::vector<std::string>& subdomain_array_names = default_VTU_subdomain_array_names(),
              const std::string& name = "the VTU input")
{
  internal::read_VTU(internal::read_input_stream(is, name), mesh, subdomain_array_names);
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * reads the file `filename` into `mesh` as `read_VTU(std::istream&, mesh, subdomain_array_names)`
 * does; the messages of the exceptions name the file.
 * \throws std::invalid_argument if the file cannot be opened or read, or as
 * `read_VTU(std::istream&, mesh, subdomain_array_names)` does
 */
template <class Point_3>
void read_VTU(const std::string& filename, Hex_dominant_mesh_3<Point_3>& mesh,
              const std::vector<std::string>& subdomain_array_names = default_VTU_subdomain_array_names())
{
  internal::read_VTU(internal::read_input_file(filename), mesh, subdomain_array_names);
}

} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_READ_VTU_H
