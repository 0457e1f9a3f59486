// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Replays inputs through the fuzz targets without libFuzzer: the committed seed corpus and
// every input a fuzzer found a defect with (fuzz/regressions/<target>/), as a CTest test.
//   fuzz_replay TARGET FILE_OR_FOLDER...
// A target aborts on a finding; an exception other than std::invalid_argument escaping a
// target is one too (exit code 1).

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

int fuzz_read_MEDIT(const std::uint8_t*, std::size_t);
int fuzz_read_MSH(const std::uint8_t*, std::size_t);
int fuzz_read_VTU(const std::uint8_t*, std::size_t);
int fuzz_frame_field(const std::uint8_t*, std::size_t);
int fuzz_closed_surface(const std::uint8_t*, std::size_t);
int fuzz_vvm_mesh_arguments(const std::uint8_t*, std::size_t);

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  const std::map<std::string, int (*)(const std::uint8_t*, std::size_t)> targets{
      {"read_MEDIT", fuzz_read_MEDIT},     {"read_MSH", fuzz_read_MSH},
      {"read_VTU", fuzz_read_VTU},         {"frame_field", fuzz_frame_field},
      {"closed_surface", fuzz_closed_surface}, {"vvm_mesh_arguments", fuzz_vvm_mesh_arguments}};
  if(argc < 3 || !targets.count(argv[1])) {
    std::fprintf(stderr, "usage: fuzz_replay TARGET FILE_OR_FOLDER...\ntargets:");
    for(const auto& t : targets) std::fprintf(stderr, " %s", t.first.c_str());
    std::fprintf(stderr, "\n");
    return 2;
  }
  std::vector<fs::path> files;
  for(int i = 2; i < argc; ++i) {
    const fs::path p(argv[i]);
    if(fs::is_directory(p)) {
      for(const auto& e : fs::directory_iterator(p))
        if(e.is_regular_file()) files.push_back(e.path());
    } else if(fs::exists(p)) {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  if(files.empty()) {
    std::fprintf(stderr, "fuzz_replay: no input\n");
    return 2;
  }
  const auto target = targets.at(argv[1]);
  for(const fs::path& file : files) {
    std::ifstream is(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
    try {
      target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch(const std::exception& e) {
      std::fprintf(stderr, "fuzz_replay: %s: %s escaped the target: %s\n", argv[1], file.string().c_str(), e.what());
      return 1;
    }
  }
  std::printf("fuzz_replay: %s: %zu inputs replayed, no finding\n", argv[1], files.size());
  return 0;
}
