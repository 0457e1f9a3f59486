// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The test programs' harness:
// - checks that stay on in every build type (a failed check never aborts, so a run
//   reports every failure), counted;
// - named tests: a program runs the tests named on its command line, or all of them,
//   and closes with "N passed, N failed"; CTest runs each named test as its own entry
//   (vvm_add_test_program in test/CMakeLists.txt), so a failure names what failed;
// - the bundled models, found through the VVM_DATA_DIR environment variable that CTest
//   sets (no path compiled in: a second clone hits the compiler cache).

#ifndef VVM_TEST_H
#define VVM_TEST_H

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <initializer_list>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

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

// a < b, printing both on failure (false for NaN)
inline bool check_less(double a, double b, const char* what, const char* file, int line)
{
  const bool ok = a < b;
  if(!check(ok, what, file, line)) std::cerr.precision(15), std::cerr << "    got " << a << ", bound " << b << "\n";
  return ok;
}

inline bool check_close(double a, double b, double tol, const char* what, const char* file, int line)
{
  const bool ok = std::abs(a - b) <= tol; // false for NaN
  if(!check(ok, what, file, line))
    std::cerr.precision(15), std::cerr << "    got " << a << ", expected " << b << " +- " << tol << "\n";
  return ok;
}

// prints the closing line and returns the process exit code
inline int report(const std::string& name)
{
  std::cout << name << ": " << passed() << " passed, " << failed() << " failed" << std::endl;
  return failed() == 0 ? 0 : 1;
}

// The path of a bundled model: $VVM_DATA_DIR/name.
inline std::string data_file(const std::string& name)
{
  const char* dir = std::getenv("VVM_DATA_DIR");
  if(dir == nullptr || *dir == '\0')
    throw std::runtime_error("VVM_DATA_DIR is not set: run the tests with ctest, or set it to the "
                             "repository's data/ folder");
  return std::string(dir) + "/" + name;
}

// true if `f` throws std::invalid_argument whose message holds `expected_words`; says why not
template <class F>
bool throws_invalid_argument(F f, const char* expected_words = "")
{
  try {
    f();
  } catch(const std::invalid_argument& e) {
    if(std::string(e.what()).find(expected_words) != std::string::npos) return true;
    std::cerr << "    message '" << e.what() << "' lacks '" << expected_words << "'\n";
    return false;
  } catch(const std::exception& e) {
    std::cerr << "    not std::invalid_argument: '" << e.what() << "'\n";
    return false;
  } catch(...) {
    return false;
  }
  std::cerr << "    no exception (expected one mentioning '" << expected_words << "')\n";
  return false;
}

struct Test
{
  const char* name;
  void (*run)();
};

// Runs a test program's named tests. Arguments:
//   (none)                   every test, in order
//   NAME...                  these tests, in the order given
//   --list                   prints the names, one a line
//   --registered NAME...     fails unless NAME... are exactly the program's tests (CTest
//                            runs this, so that no test is left out of CTest)
// A named test that runs no check fails: a test that cannot fail is a defect.
// Exit code: 0 if every check passed, 1 if one failed, 2 on an unknown name.
inline int run(int argc, char** argv, const char* program, std::initializer_list<Test> tests)
{
  std::cout << std::unitbuf;
  std::vector<std::string> args(argv + 1, argv + argc);
  std::set<std::string> names;
  for(const Test& t : tests) names.insert(t.name);

  if(!args.empty() && args[0] == "--list") {
    for(const Test& t : tests) std::cout << t.name << "\n";
    return 0;
  }
  if(!args.empty() && args[0] == "--registered") {
    const std::set<std::string> registered(args.begin() + 1, args.end());
    int code = 0;
    for(const std::string& n : names)
      if(registered.count(n) == 0) std::cerr << program << ": test '" << n << "' is not registered with CTest\n", code = 1;
    for(const std::string& n : registered)
      if(names.count(n) == 0) std::cerr << program << ": CTest names '" << n << "', which is no test of it\n", code = 1;
    if(code == 0) std::cout << program << ": " << names.size() << " tests, all registered with CTest\n";
    return code;
  }

  std::vector<const Test*> selected;
  if(args.empty())
    for(const Test& t : tests) selected.push_back(&t);
  for(const std::string& a : args) {
    const Test* found = nullptr;
    for(const Test& t : tests)
      if(a == t.name) found = &t;
    if(found == nullptr) {
      std::cerr << program << ": no test named '" << a << "' (--list lists them)\n";
      return 2;
    }
    selected.push_back(found);
  }

  for(const Test* t : selected) {
    const std::size_t checks_before = passed() + failed();
    const auto start = std::chrono::steady_clock::now();
    try {
      t->run();
    } catch(const std::exception& e) {
      check(false, (std::string("no exception escapes; got: ") + e.what()).c_str(), t->name, 0);
    } catch(...) {
      check(false, "no exception escapes; got one that is no std::exception", t->name, 0);
    }
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    const std::size_t checks = passed() + failed() - checks_before;
    if(checks == 0) ++failed(), std::cerr << t->name << ": ran no check\n";
    std::cout << "  (" << t->name << ": " << checks << " checks, " << seconds.count() << " s)\n";
  }
  std::string closing = program;
  if(!args.empty())
    for(const std::string& a : args) closing += " " + a;
  return report(closing);
}

} // namespace vvm_test

#define VVM_CHECK(cond) vvm_test::check(bool(cond), #cond, __FILE__, __LINE__)
#define VVM_CHECK_EQUAL(a, b) vvm_test::check_equal((a), (b), #a " == " #b, __FILE__, __LINE__)
#define VVM_CHECK_CLOSE(a, b, tol) vvm_test::check_close((a), (b), (tol), #a " ~ " #b, __FILE__, __LINE__)
#define VVM_CHECK_LESS(a, b) vvm_test::check_less((a), (b), #a " < " #b, __FILE__, __LINE__)

#endif // VVM_TEST_H
