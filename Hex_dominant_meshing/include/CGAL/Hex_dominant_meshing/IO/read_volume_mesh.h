// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading and writing a hex-dominant mesh in the format its file name's
// extension says: .mesh (MEDIT), .msh (Gmsh) or .vtu (VTK XML).

#ifndef CGAL_HEX_DOMINANT_MESHING_IO_READ_VOLUME_MESH_H
#define CGAL_HEX_DOMINANT_MESHING_IO_READ_VOLUME_MESH_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/IO/read_MEDIT.h>
#include <CGAL/Hex_dominant_meshing/IO/read_MSH.h>
#include <CGAL/Hex_dominant_meshing/IO/read_VTU.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MEDIT.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MSH.h>
#include <CGAL/Hex_dominant_meshing/IO/write_VTU.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace IO {
namespace internal {

enum class Volume_mesh_format { MEDIT, MSH, VTU };

// the format of `filename` by its extension, in any case
inline Volume_mesh_format volume_mesh_format(const std::string& filename)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  const std::string extension =
    dot == std::string::npos || (slash != std::string::npos && dot < slash) ? std::string() : lower_case(filename.substr(dot));
  if(extension == ".mesh") return Volume_mesh_format::MEDIT;
  if(extension == ".msh") return Volume_mesh_format::MSH;
  if(extension == ".vtu") return Volume_mesh_format::VTU;
  throw std::invalid_argument("'" + filename + "': unknown volume mesh extension " +
                              (extension.empty() ? std::string("(none)") : "'" + extension + "'") +
                              "; the known ones are .mesh (MEDIT), .msh (Gmsh) and .vtu (VTK XML)");
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * reads the volume mesh in the file `filename` into `mesh` with `read_MEDIT()`,
 * `read_MSH()` or `read_VTU()` (with its default subdomain arrays), as its extension
 * `.mesh`, `.msh` or `.vtu` says (in any case). `mesh` is left unchanged if an exception
 * is thrown.
 * \throws std::invalid_argument for another extension (nothing is read then), or as
 * the reader does
 */
template <class Point_3>
void read_volume_mesh(const std::string& filename, Hex_dominant_mesh_3<Point_3>& mesh)
{
  switch(internal::volume_mesh_format(filename)) {
    case internal::Volume_mesh_format::MEDIT: read_MEDIT(filename, mesh); break;
    case internal::Volume_mesh_format::MSH: read_MSH(filename, mesh); break;
    default: read_VTU(filename, mesh); break;
  }
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * writes `mesh` to the file `filename` with `write_MEDIT()`, `write_MSH()` or
 * `write_VTU()` (without cell fields), as its extension `.mesh`, `.msh` or `.vtu` says
 * (in any case).
 * \throws std::invalid_argument for another extension (nothing is written then), or as
 * the writer does
 * \throws std::runtime_error as the writer does
 */
template <class Point_3>
void write_volume_mesh(const std::string& filename, const Hex_dominant_mesh_3<Point_3>& mesh)
{
  switch(internal::volume_mesh_format(filename)) {
    case internal::Volume_mesh_format::MEDIT: write_MEDIT(filename, mesh); break;
    case internal::Volume_mesh_format::MSH: write_MSH(filename, mesh); break;
    default: write_VTU(filename, mesh); break;
  }
}

} // namespace IO
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_IO_READ_VOLUME_MESH_H
