// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh files for the front end: volume meshes read by extension, volume and
// surface meshes written through a temporary file in the target folder that is
// renamed at the end, so that a failed run leaves no partial file and an
// existing one untouched.

#include "vvm_front_end.h"

#include <CGAL/Hex_dominant_meshing/IO/read_volume_mesh.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MEDIT.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MSH.h>
#include <CGAL/Hex_dominant_meshing/IO/write_VTU.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <system_error>

namespace vvm {
namespace {

std::string lower_extension(const std::string& path)
{
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// writes with `write` into a temporary file next to `path`, then renames it to `path`
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  if(!fs::is_directory(folder, error)) throw Input_error("cannot write '" + path + "': no folder '" + folder.string() + "'");
  if(fs::is_directory(target, error)) throw Input_error("cannot write '" + path + "': it is a folder");
  std::random_device seed;
  const fs::path temporary =
      folder / ("." + target.filename().string() + ".vvm-" + std::to_string(seed() % 1000000000u) + ".tmp");
  try {
    {
      std::ofstream os(temporary, std::ios::binary);
      if(!os) throw Input_error("cannot write into the folder of '" + path + "'");
      write(os);
      os.flush();
      if(!os) throw std::runtime_error("cannot write '" + path + "' (disk full?)");
    }
    fs::rename(temporary, target, error);
    if(error) throw std::runtime_error("cannot rename the temporary file to '" + path + "': " + error.message());
  } catch(...) {
    fs::remove(temporary, error);
    throw;
  }
}

} // namespace

bool is_volume_mesh_file(const std::string& path)
{
  const std::string e = lower_extension(path);
  return e == ".mesh" || e == ".msh" || e == ".vtu";
}

Volume_mesh read_volume_mesh(const std::string& path)
{
  Volume_mesh mesh;
  try {
    CGAL::Hex_dominant_meshing::IO::read_volume_mesh(path, mesh);
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
  return mesh;
}

void write_volume_mesh(const Volume_mesh& mesh, const std::string& path)
{
  namespace IO = CGAL::Hex_dominant_meshing::IO;
  const std::string e = lower_extension(path);
  if(!is_volume_mesh_file(path))
    throw Input_error("unknown output extension in '" + path + "' (known: .mesh, .msh, .vtu)");
  if(e == ".msh")
    for(const Volume_mesh::Cell& c : mesh.cells)
      if(c.subdomain_index <= 0)
        throw Input_error("cannot write '" + path + "': Gmsh needs positive subdomain labels, and a cell has label " +
                          std::to_string(c.subdomain_index) + " (write .mesh or .vtu)");
  write_atomically(path, [&](std::ostream& os) {
    if(e == ".mesh")
      IO::write_MEDIT(os, mesh);
    else if(e == ".msh")
      IO::write_MSH(os, mesh);
    else
      IO::write_VTU(os, mesh, cell_quality_arrays(mesh));
  });
}

bool is_surface_mesh_file(const std::string& path)
{
  const std::string e = lower_extension(path);
  return e == ".off" || e == ".obj" || e == ".ply" || e == ".stl";
}

void write_surface_mesh(const Surface_mesh_result& mesh, const std::string& path)
{
  const std::string e = lower_extension(path);
  if(!is_surface_mesh_file(path))
    throw Input_error("unknown output extension in '" + path + "' (known: .off, .obj, .ply, .stl)");
  write_atomically(path, [&](std::ostream& os) {
    // CGAL::IO::write_polygon_mesh()'s choices: PLY and STL binary, text with every digit
    const auto np = CGAL::parameters::stream_precision(17);
    if(e == ".ply" || e == ".stl") CGAL::IO::set_binary_mode(os);
    const bool written = e == ".off"   ? CGAL::IO::write_OFF(os, mesh.points, mesh.triangles, np)
                         : e == ".obj" ? CGAL::IO::write_OBJ(os, mesh.points, mesh.triangles, np)
                         : e == ".ply" ? CGAL::IO::write_PLY(os, mesh.points, mesh.triangles, np)
                                       : CGAL::IO::write_STL(os, mesh.points, mesh.triangles, np);
    if(!written) throw std::runtime_error("cannot write '" + path + "'");
  });
}

void write_text_file(const std::string& text, const std::string& path)
{
  write_atomically(path, [&](std::ostream& os) { os << text; });
}

} // namespace vvm
