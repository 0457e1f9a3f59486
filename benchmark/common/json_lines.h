// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmarks' JSON output: one object per line (a row of a table), numbers
// to full double precision, non-finite numbers as null (JSON has no NaN).

#ifndef VVM_BENCHMARK_JSON_LINES_H
#define VVM_BENCHMARK_JSON_LINES_H

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace vvm_benchmark {

// One JSON object, built key by key in the order given.
class Json_line
{
public:
  Json_line& add(const std::string& key, const std::string& value)
  {
    std::string quoted = "\"";
    for(char c : value) {
      if(c == '"' || c == '\\') quoted += '\\', quoted += c;
      else if(static_cast<unsigned char>(c) < 0x20) {
        char escape[8];
        std::snprintf(escape, sizeof escape, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
        quoted += escape;
      } else
        quoted += c;
    }
    return raw(key, quoted + "\"");
  }
  Json_line& add(const std::string& key, const char* value) { return add(key, std::string(value)); }
  Json_line& add(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  template <class Number, class = std::enable_if_t<std::is_arithmetic<Number>::value>>
  Json_line& add(const std::string& key, Number value)
  {
    if constexpr(std::is_floating_point<Number>::value)
      if(!std::isfinite(value)) return raw(key, "null");
    std::ostringstream os;
    os.precision(17);
    os << value;
    return raw(key, os.str());
  }

  std::string str() const { return "{" + body_ + "}"; }

private:
  Json_line& raw(const std::string& key, const std::string& value)
  {
    body_ += (body_.empty() ? "\"" : ", \"") + key + "\": " + value;
    return *this;
  }

  std::string body_;
};

// A file of JSON lines; with no file name, writes nothing.
class Json_lines_file
{
public:
  enum Mode { REPLACE, APPEND };

  Json_lines_file(const std::string& name, Mode mode) : name_(name)
  {
    if(name_.empty()) return;
    os_.open(name_, mode == APPEND ? std::ios::app : std::ios::trunc);
    if(!os_) throw std::runtime_error("cannot write '" + name_ + "'");
  }

  void write(const Json_line& line)
  {
    if(name_.empty()) return;
    os_ << line.str() << "\n" << std::flush;
    if(!os_) throw std::runtime_error("cannot write '" + name_ + "'");
  }

private:
  std::string name_;
  std::ofstream os_;
};

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_JSON_LINES_H
