// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks that stay on in every build type (a failed check never aborts, so a
// run reports every failure) and the closing "N passed, N failed" line.

#ifndef VVM_TEST_UTILITIES_H
#define VVM_TEST_UTILITIES_H

#include <cmath>
#include <cstddef>
#include <iostream>

namespace vvm_test {

inline std::size_t& passed() { static std::size_t n = 0; return n; }
inline std::size_t& failed() { static std::size_t n = 0; return n; }

inline bool check(bool ok, const char* what, const char* file, int line)
{
  if(ok) ++passed();
  else {
    ++failed();
    std::cerr << file << ":" << line << ": check failed: " << what << "\n";
  }
  return ok;
}

template <class A, class B>
bool check_equal(const A& a, const B& b, const char* what, const char* file, int line)
{
  if(!check(a == b, what, file, line)) std::cerr << "    got " << a << " and " << b << "\n";
  return a == b;
}

inline bool check_close(double a, double b, double tol, const char* what, const char* file, int line)
{
  const bool ok = std::abs(a - b) <= tol; // false for NaN
  if(!check(ok, what, file, line))
    std::cerr.precision(15), std::cerr << "    got " << a << ", expected " << b << " +- " << tol << "\n";
  return ok;
}

// prints the closing line and returns the process exit code
inline int report(const char* name)
{
  std::cout << name << ": " << passed() << " passed, " << failed() << " failed" << std::endl;
  return failed() == 0 ? 0 : 1;
}

} // namespace vvm_test

#define VVM_CHECK(cond) vvm_test::check(bool(cond), #cond, __FILE__, __LINE__)
#define VVM_CHECK_EQUAL(a, b) vvm_test::check_equal((a), (b), #a " == " #b, __FILE__, __LINE__)
#define VVM_CHECK_CLOSE(a, b, tol) vvm_test::check_close((a), (b), (tol), #a " ~ " #b, __FILE__, __LINE__)

#endif // VVM_TEST_UTILITIES_H
