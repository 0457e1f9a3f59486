// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmarks' command lines share: the user error they report with exit
// code 2, and the strict parsing of a number given to an option.

#ifndef VVM_BENCHMARK_COMMAND_LINE_H
#define VVM_BENCHMARK_COMMAND_LINE_H

#include <sstream>
#include <stdexcept>
#include <string>

namespace vvm_benchmark {

// A user error (bad command line, unreadable or invalid input): printed and exit code 2.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// `text` as a number of type T, all of it, or an Input_error naming `option`
template <class T>
T parse_number(const std::string& option, const std::string& text)
{
  std::istringstream is(text);
  T value;
  if(!(is >> value) || !is.eof())
    throw Input_error("option " + option + " expects a number, got '" + text + "'");
  return value;
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_COMMAND_LINE_H
