// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// vvm::surface_mesh: a triangle mesh of a triangle surface whose vertices form
// a hexagonal lattice aligned with a tangent frame field
// (CGAL::make_lattice_surface_mesh), measured in that field's metric.

#include "frame_fields.h"
#include "lattice_progress.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/make_lattice_surface_mesh.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace vvm {
namespace internal {
namespace {

namespace FF = CGAL::Frame_fields;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef FF::Surface_frame_field_3<Kernel> Surface_field;

/// the polygons in the file `path`, read as read_closed_surface() reads them: the header checked
/// first against what CGAL 5.5's readers would act on blindly
void read_polygons(const std::string& path, std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons)
{
  std::ifstream probe(path, std::ios::binary | std::ios::ate);
  if(!probe) throw Input_error("cannot open '" + path + "'");
  const std::streamoff size = probe.tellg();
  if(size <= 0) throw Input_error("'" + path + "' is an empty file");
  probe.seekg(0);
  bool read = false;
  try {
    CGAL::GSM_mesh_optimization::IO::internal::check_surface_file_header(path, probe, std::uintmax_t(size));
    read = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  } catch(const std::length_error&) { // a face's vector sized by a count read from the file
  } catch(const std::bad_alloc&) {
  } catch(const CGAL::Failure_exception&) { // a reader's assertion on a header it did not expect
  }
  if(!read) throw Input_error("cannot read '" + path + "' as a polygon mesh (OFF, OBJ, PLY, STL, ...)");
}

/// the triangle surface of `source`, open or closed; Input_error on no face, a face that is no
/// triangle, a non-finite coordinate, or faces that no orientation makes a surface
Surface_mesh triangle_surface(const Surface_source& source)
{
  const std::string what = source.is_file() ? "the surface in '" + source.path + "'" : "the surface";
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(source.is_file()) {
    read_polygons(source.path, points, polygons);
  } else {
    for(const auto& p : source.points) points.emplace_back(p[0], p[1], p[2]);
    polygons = source.polygons;
  }
  if(polygons.empty()) throw Input_error(what + " has no face");
  for(const Point& p : points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(what + " has a vertex with a non-finite coordinate");
  for(std::size_t i = 0; i < polygons.size(); ++i) {
    const std::vector<std::size_t>& f = polygons[i];
    const std::string face = "face " + std::to_string(i) + " of " + what;
    if(f.size() != 3)
      throw Input_error(face + " has " + std::to_string(f.size()) + " vertices: a triangle surface is needed");
    for(std::size_t v : f)
      if(v >= points.size())
        throw Input_error(face + " has the vertex index " + std::to_string(v) + ", out of range (" +
                          std::to_string(points.size()) + " vertices)");
    if(f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) throw Input_error(face + " has a repeated vertex");
  }
  // as CGAL::IO::read_polygon_mesh(): faces turned to agree, non-manifold vertices split
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) PMP::orient_polygon_soup(points, polygons);
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Input_error("the faces of " + what + " do not form a surface, whatever their orientation");
  Surface_mesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
  // the field fits a jet at every vertex: one in no face has none
  std::vector<Surface_mesh::Vertex_index> isolated;
  for(auto v : surface.vertices())
    if(surface.is_isolated(v)) isolated.push_back(v);
  for(auto v : isolated) surface.remove_vertex(v);
  surface.collect_garbage();
  return surface;
}

/// the field `o.field` names on `surface`
Surface_field surface_field(const Surface_mesh& surface, const Surface_options& o, const Progress& progress,
                            Run_report& r)
{
  const Stage stage(progress, "field");
  stage.report(o.field == "identity"             ? "the x axis on the tangent planes"
               : is_surface_field_name(o.field) ? o.field + " frames at " + std::to_string(surface.number_of_vertices()) + " vertices"
                                                : "the field of '" + o.field + "' on the tangent planes");
  std::vector<Point> points(surface.points().begin(), surface.points().end());
  std::vector<std::array<std::size_t, 3>> faces;
  for(auto f : surface.faces()) {
    const auto h = surface.halfedge(f);
    faces.push_back({std::size_t(surface.source(h)), std::size_t(surface.target(h)),
                     std::size_t(surface.target(surface.next(h)))});
  }
  const Surface_field field =
      surface_frame_field(points, faces, o.field, o.maximum_anisotropy, o.maximum_size_ratio, o.features_angle);
  r.mesh_time = stage.time();
  return field;
}

} // namespace
} // namespace internal

Surface_mesh_result surface_mesh(const Surface_source& input, const Surface_options& o, const Progress& progress,
                                 Run_report* report)
{
  Run_report local;
  Run_report& r = report ? *report : local;
  const internal::Run_timer run_timer(r);
  r.input = input.name();
  r.method = "lattice";
  r.field = o.field;
  internal::check_mesh_size(o.size);
  internal::check_surface_field(o.field);
  if(!(o.features_angle >= 0 && o.features_angle <= 180)) throw Input_error("the features angle must be in [0, 180] degrees");
  const auto threads = internal::thread_limit(o.threads);
  const internal::Surface_mesh surface = internal::triangle_surface(input);
  const internal::Surface_field field = internal::surface_field(surface, o, progress, r);

  const internal::Stage stage(progress, "lattice surface");
  internal::TLM::Lattice_surface_mesh_report lattice;
  internal::Surface_mesh mesh;
  try {
    namespace TLM = internal::TLM;
    auto np = TLM::parameters::report(
        &lattice, TLM::parameters::number_of_threads(
                      o.threads, internal::FF::parameters::features_angle(
                                     o.features_angle, CGAL::parameters::random_seed(o.seed)
                                                           .maximum_running_time(o.time_limit)
                                                           .visitor(internal::progress_visitor(stage)))));
    mesh = o.size.size > 0 ? CGAL::make_lattice_surface_mesh(surface, field, TLM::parameters::edge_length(o.size.size, np))
                           : CGAL::make_lattice_surface_mesh(surface, field, TLM::parameters::number_of_particles(o.size.vertices, np));
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
  if(mesh.has_garbage()) mesh.collect_garbage();
  r.optimize_time = stage.time();
  r.time_limit_reached = lattice.time_limit_reached;
  stage.report(std::to_string(mesh.number_of_faces()) + " triangles, " + std::to_string(lattice.number_of_flips) +
               " flips, " + std::to_string(lattice.number_of_filled_holes) + " holes filled, " +
               std::to_string(lattice.number_of_smoothing_moves) + " smoothing moves");

  Surface_mesh_result result;
  result.quality = internal::TLM::surface_mesh_quality(mesh, field, o.features_angle);
  result.points.assign(mesh.points().begin(), mesh.points().end());
  for(auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    result.triangles.push_back(
        {std::size_t(mesh.source(h)), std::size_t(mesh.target(h)), std::size_t(mesh.target(mesh.next(h)))});
  }
  return result;
}

} // namespace vvm
