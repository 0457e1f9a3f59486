// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input of every VVM program that meshes a volume: a closed triangle
// surface read from a file, checked so that a mesher can rely on it.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_IO_READ_CLOSED_SURFACE_H
#define CGAL_GSM_MESH_OPTIMIZATION_IO_READ_CLOSED_SURFACE_H

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace IO {

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * reads the polygon mesh in the file `fname` into `tm` (cleared first), in any format
 * that `CGAL::IO::read_polygon_mesh()` reads (OFF, OBJ, PLY, STL, GOCAD, VTP, ...),
 * triangulates its faces if needed, and checks that it bounds a volume a mesher can
 * fill. The messages of the exceptions name `fname` and the reason:
 *
 * - the file cannot be opened (`"cannot open '...'"`) or is empty
 *   (`"'...' is an empty file"`);
 * - it is not a polygon mesh (`"cannot read '...' as a polygon mesh (OFF, OBJ, PLY, STL, ...)"`)
 *   or has no face (`"'...' contains no faces"`);
 * - a vertex has a NaN or infinite coordinate (`"'...' has a vertex with a non-finite coordinate"`);
 * - the surface has border edges (`"the surface in '...' is open (it has border edges); a closed surface is needed"`);
 * - it self-intersects (`"the surface in '...' self-intersects"`), unless `self_intersects` is given;
 * - it encloses no volume (`"the surface in '...' encloses no volume"`).
 *
 * \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point
 *   property map, e.g. `CGAL::Surface_mesh<Point_3>`
 *
 * \param fname the path of the file
 * \param tm the surface read
 * \param self_intersects if given, a self-intersecting surface is not an error: whether it
 *   self-intersects is written there instead (`make_mesh_3()` meshes such a surface, with the
 *   inside its domain's ray-parity test sees, which may not be the one intended)
 * \returns the volume enclosed by `tm`, positive
 * \throws std::invalid_argument if any of the checks above fails
 */
template <class TriangleMesh>
double read_closed_surface(const std::string& fname, TriangleMesh& tm, bool* self_intersects = nullptr)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::ifstream probe(fname, std::ios::binary | std::ios::ate);
  if(!probe) throw std::invalid_argument("cannot open '" + fname + "'");
  if(probe.tellg() <= 0) throw std::invalid_argument("'" + fname + "' is an empty file");
  probe.close();
  clear(tm);
  if(!CGAL::IO::read_polygon_mesh(fname, tm))
    throw std::invalid_argument("cannot read '" + fname + "' as a polygon mesh (OFF, OBJ, PLY, STL, ...)");
  if(num_faces(tm) == 0) throw std::invalid_argument("'" + fname + "' contains no faces");
  const auto vpm = get(CGAL::vertex_point, tm);
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      throw std::invalid_argument("'" + fname + "' has a vertex with a non-finite coordinate");
  }
  if(!CGAL::is_triangle_mesh(tm)) PMP::triangulate_faces(tm);
  if(!CGAL::is_closed(tm))
    throw std::invalid_argument("the surface in '" + fname +
                                "' is open (it has border edges); a closed surface is needed");
  const bool intersects = PMP::does_self_intersect(tm);
  if(intersects && !self_intersects) throw std::invalid_argument("the surface in '" + fname + "' self-intersects");
  if(self_intersects) *self_intersects = intersects;
  const double volume = std::abs(CGAL::to_double(PMP::volume(tm)));
  if(!(volume > 0)) throw std::invalid_argument("the surface in '" + fname + "' encloses no volume");
  return volume;
}

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * the name of the file `path` without its directory (after the last `/` or `\\`) and its
 * last extension: `"data/fandisk.off"` gives `"fandisk"`; used to name a model in reports.
 */
inline std::string file_stem(const std::string& path)
{
  const std::string name = path.substr(path.find_last_of("/\\") + 1);
  return name.substr(0, name.find_last_of('.'));
}

} // namespace IO
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_IO_READ_CLOSED_SURFACE_H
