// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the fuzz targets share. Each target file defines one function
// `int fuzz_<name>(const std::uint8_t* data, std::size_t size)` with VVM_FUZZ_TARGET(name).
// Built for libFuzzer (clang, -fsanitize=fuzzer; VVM_FUZZ_ENTRY defined), the macro also
// defines LLVMFuzzerTestOneInput; built without it, replay.cpp calls the functions on the
// committed corpus and regression inputs.
//
// A target accepts what the code under test documents as the refusal of bad input
// (std::invalid_argument); anything else (a crash, a sanitizer report, another exception,
// a broken round trip: fuzz_failure()) is a finding.

#ifndef VVM_FUZZ_TARGET_H
#define VVM_FUZZ_TARGET_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace vvm_fuzz {

/// a property the target checks does not hold: stop with a message (libFuzzer keeps the input)
[[noreturn]] inline void fuzz_failure(const std::string& what)
{
  std::fprintf(stderr, "fuzz target: %s\n", what.c_str());
  std::abort();
}

inline std::string as_string(const std::uint8_t* data, std::size_t size)
{
  return std::string(reinterpret_cast<const char*>(data), size);
}

} // namespace vvm_fuzz

#ifdef VVM_FUZZ_ENTRY
#define VVM_FUZZ_ENTRY_POINT(name)                                                                          \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)                          \
  {                                                                                                          \
    return fuzz_##name(data, size);                                                                          \
  }
#else
#define VVM_FUZZ_ENTRY_POINT(name)
#endif

/// declares and begins the definition of the target `name`:
/// VVM_FUZZ_TARGET(read_MEDIT) { ... use data, size ... return 0; }
#define VVM_FUZZ_TARGET(name)                                                                               \
  int fuzz_##name(const std::uint8_t* data, std::size_t size);                                              \
  VVM_FUZZ_ENTRY_POINT(name)                                                                                 \
  int fuzz_##name(const std::uint8_t* data, std::size_t size)

#endif // VVM_FUZZ_TARGET_H
