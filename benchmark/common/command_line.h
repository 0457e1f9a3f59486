// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmark drivers' command lines share: the user error they report
// with exit code 2, strict parsing of the numbers given to options, the options
// every driver has (INPUT, --threads, --json, --out-dir, --seed,
// --features-angle, --verbose, --help), and the main() around a driver's run
// (thread limit, output folder, exit codes).

#ifndef VVM_BENCHMARK_COMMAND_LINE_H
#define VVM_BENCHMARK_COMMAND_LINE_H

#include <tbb/global_control.h>

#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

// "a+b+c" -> {"a", "b", "c"} (chains of steps), "a,b" -> {"a", "b"} (lists); empty items dropped
inline std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> items;
  std::stringstream ss(text);
  for(std::string item; std::getline(ss, item, separator);)
    if(!item.empty()) items.push_back(item);
  return items;
}

// The options every driver has.
struct Common_options
{
  std::string input;         // INPUT: a surface file or a built-in domain's name
  std::string json_file;     // --json
  std::string out_dir;       // --out-dir
  int threads = 0;           // --threads; 0: all cores
  unsigned int seed = 0;     // --seed
  double features_angle = -1; // --features-angle; < 0: not given
  bool verbose = false;      // --verbose
};

// Walks the arguments: a driver tests its own options with is() and reads their values,
// and hands the others to common(), which knows the shared ones and refuses the rest.
class Command_line
{
public:
  Command_line(int argc, char** argv, const std::string& usage) : argc_(argc), argv_(argv), usage_(usage) {}

  // moves to the next argument; false after the last one
  bool next()
  {
    if(++i_ >= argc_) return false;
    arg_ = argv_[i_];
    return true;
  }
  const std::string& argument() const { return arg_; }
  bool is(const char* option) const { return arg_ == option; }

  // the value after the current option
  std::string value()
  {
    if(i_ + 1 >= argc_) throw Input_error("option " + arg_ + " expects a value");
    return argv_[++i_];
  }
  template <class T>
  T number() { return parse_number<T>(arg_, value()); }
  // a number in [lo, hi]
  template <class T>
  T number_in(T lo, T hi)
  {
    const std::string option = arg_;
    const T x = number<T>();
    if(!(x >= lo && x <= hi)) {
      std::ostringstream os;
      os << option << " must be in [" << lo << ", " << hi << "]";
      throw Input_error(os.str());
    }
    return x;
  }
  // a comma-separated list
  std::vector<std::string> list() { return split(value(), ','); }
  // the value, one of `known`
  std::string one_of(const std::vector<std::string>& known)
  {
    const std::string option = arg_, v = value();
    std::string names;
    for(const std::string& k : known) {
      if(v == k) return v;
      names += (names.empty() ? "" : ", ") + k;
    }
    throw Input_error("unknown " + option + " '" + v + "' (known: " + names + ")");
  }

  // handles the current argument if it is a shared option or INPUT; an unknown option is an error
  void common(Common_options& o)
  {
    if(is("--threads")) o.threads = number_in<int>(0, 1 << 16);
    else if(is("--json")) o.json_file = value();
    else if(is("--out-dir")) o.out_dir = value();
    else if(is("--seed")) o.seed = number<unsigned int>();
    else if(is("--features-angle")) {
      o.features_angle = number<double>();
      if(!(o.features_angle >= 0 && o.features_angle < 180)) throw Input_error("--features-angle must be in [0, 180)");
    } else if(is("--verbose")) o.verbose = true;
    else if(is("--help") || is("-h")) {
      std::cout << usage_;
      std::exit(0);
    } else if(!arg_.empty() && arg_[0] == '-') throw Input_error("unknown option " + arg_);
    else if(o.input.empty()) o.input = arg_;
    else throw Input_error("more than one INPUT given ('" + o.input + "', '" + arg_ + "')");
  }

  // after the walk: INPUT is required
  static void require_input(const Common_options& o)
  {
    if(o.input.empty()) throw Input_error("no INPUT given");
  }

private:
  int argc_;
  char** argv_;
  std::string usage_;
  int i_ = 0;
  std::string arg_;
};

// The main() of a driver: parses the command line (`parse(argc, argv)` returns options
// deriving from Common_options), limits the threads, creates the output folder and runs
// `run(options)`. Exit codes: run's, 2 for a user error (an Input_error, or an input a
// mesher refuses with std::invalid_argument), 1 for a run that fails midway.
template <class Parse, class Run>
int benchmark_main(const char* name, const std::string& usage, int argc, char** argv, Parse parse, Run run)
{
  try {
    const auto options = parse(argc, argv);
    const Common_options& common = options;
    std::unique_ptr<tbb::global_control> threads;
    if(common.threads > 0)
      threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      std::size_t(common.threads));
    if(!common.out_dir.empty()) {
      std::error_code error;
      std::filesystem::create_directories(common.out_dir, error);
      if(error) throw Input_error("cannot create '" + common.out_dir + "': " + error.message());
    }
    return run(options);
  } catch(const Input_error& e) {
    std::cerr << name << ": error: " << e.what() << "\n" << usage;
    return 2;
  } catch(const std::invalid_argument& e) {
    std::cerr << name << ": error: " << e.what() << "\n";
    return 2;
  } catch(const std::exception& e) {
    std::cerr << name << ": failed: " << e.what() << "\n";
    return 1;
  }
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_COMMAND_LINE_H
