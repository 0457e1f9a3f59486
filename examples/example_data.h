// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the examples find the models bundled with VVM, so that each runs with no
// argument from the build folder: the file under the environment variable
// CGAL_DATA_DIR when it is set and holds the file (directly or in its meshes/
// folder, as CGAL's own data), else under the source tree's data/ folder, whose
// path the build compiles in as VVM_DATA_DIR.

#ifndef VVM_EXAMPLE_DATA_H
#define VVM_EXAMPLE_DATA_H

#include <cstdlib>
#include <filesystem>
#include <string>

#ifndef VVM_DATA_DIR
#define VVM_DATA_DIR "data"
#endif

namespace vvm_example {

/// the path of the bundled model `name` (e.g. "fandisk.off", "thin_walled/open_box.off")
inline std::string data_file(const std::string& name)
{
  namespace fs = std::filesystem;
  if(const char* dir = std::getenv("CGAL_DATA_DIR"); dir != nullptr && *dir != '\0') {
    for(const fs::path& p : {fs::path(dir) / name, fs::path(dir) / "meshes" / name})
      if(fs::exists(p))
        return p.string();
  }
  return (fs::path(VVM_DATA_DIR) / name).string();
}

/// `path` made absolute, to tell the user where a file was written
inline std::string absolute(const std::string& path)
{
  std::error_code error;
  const std::filesystem::path p = std::filesystem::absolute(path, error);
  return error ? path : p.lexically_normal().string();
}

} // namespace vvm_example

#endif // VVM_EXAMPLE_DATA_H
