// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the closed-surface input of every program that meshes a volume
// (CGAL/GSM_mesh_optimization/IO/read_closed_surface.h). The first byte chooses the way in:
// 0-3 a file of that format (.off, .obj, .ply, .stl) read through CGAL's readers with
// read_closed_surface(); 4 a polygon soup made of the bytes (closed_surface_from_polygon_soup(),
// the Python module's way in). What is accepted must be a closed triangle mesh with a volume.

#include "fuzz_target.h"

#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

/// a soup from the bytes: a count of points (one byte), points (three int8 coordinates
/// each), then triangles (three bytes, indices modulo the count + 1: some out of range)
void soup_of(const std::uint8_t* data, std::size_t size, std::vector<K::Point_3>& points,
             std::vector<std::vector<std::size_t>>& triangles)
{
  if(size == 0) return;
  const std::size_t n = data[0];
  std::size_t i = 1;
  for(; points.size() < n && i + 3 <= size; i += 3)
    points.emplace_back(double(std::int8_t(data[i])), double(std::int8_t(data[i + 1])), double(std::int8_t(data[i + 2])));
  for(; i + 3 <= size; i += 3)
    triangles.push_back({data[i] % (n + 1), data[i + 1] % (n + 1), data[i + 2] % (n + 1)});
}

} // namespace

VVM_FUZZ_TARGET(closed_surface)
{
  namespace IO = CGAL::GSM_mesh_optimization::IO;
  if(size == 0) return 0;
  Mesh mesh;
  double volume = 0;
  try {
    if(data[0] % 5 == 4) {
      std::vector<K::Point_3> points;
      std::vector<std::vector<std::size_t>> triangles;
      soup_of(data + 1, size - 1, points, triangles);
      volume = IO::closed_surface_from_polygon_soup(points, triangles, mesh);
    } else {
      static const char* extensions[4] = {".off", ".obj", ".ply", ".stl"};
      const std::string path = "/tmp/vvm_fuzz_surface_" + std::to_string(getpid()) + extensions[data[0] % 5];
      {
        std::ofstream os(path, std::ios::binary);
        os.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
      }
      try {
        volume = IO::read_closed_surface(path, mesh);
      } catch(...) {
        std::remove(path.c_str());
        throw;
      }
      std::remove(path.c_str());
    }
  } catch(const std::invalid_argument&) {
    return 0;
  }
  if(!(volume > 0) || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh) || !mesh.is_valid(false))
    vvm_fuzz::fuzz_failure("read_closed_surface accepted a surface that is not closed, triangulated and valid");
  return 0;
}
