// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_surface_meshers: field-aligned lattice triangle meshes of a surface
// (make_lattice_surface_mesh) against CGAL's isotropic remeshing at the same
// vertex count, measured in the field's metric (dissertation section 4.3.4).

#include <command_line.h>
#include <frame_fields.h>
#include <json_lines.h>
#include <table.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Real_timer.h>
#include <CGAL/make_lattice_surface_mesh.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Frame_fields::Surface_frame_field_3<K> Field;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace PMP = CGAL::Polygon_mesh_processing;
using namespace vvm_benchmark;

const char* usage =
    "usage: compare_surface_meshers INPUT [--vertices N] [--field curvature|isotropic|identity|FILE]\n"
    "         [--maximum-anisotropy A] [--maximum-size-ratio R] [--features-angle DEG] [--methods lattice,isotropic_remeshing]\n"
    "         [--threads N] [--seed N] [--json FILE] [--out-dir DIR] [--verbose]\n"
    "  INPUT: a triangle mesh file (OFF, OBJ, PLY, STL...), e.g. data/surfaces/torus.off\n"
    "  --field curvature: principal curvature directions, lengths 1/sqrt|k| (default);\n"
    "          isotropic: the same directions, one length; identity: x projected, unit lengths;\n"
    "          FILE: a frame-field text file (a frame per vertex, or a volume field) on the tangent planes\n"
    "  One JSON line per method: model, method, field, n_vertices, n_faces, r6, xi_mean, xi_min,\n"
    "  min_angle_metric_deg, mean_min_angle_metric_deg, alignment_error_mean_deg, hausdorff,\n"
    "  is_closed_manifold, time_s; <model>_<method>.off in the out dir.\n";

struct Options : Common_options
{
  std::size_t vertices = 10000;
  std::string field = "curvature";
  double maximum_anisotropy = 3;
  double maximum_size_ratio = 4;
  std::vector<std::string> methods = {"lattice", "isotropic_remeshing"};
};

Options parse(int argc, char** argv)
{
  Options o;
  Command_line c(argc, argv, usage);
  while(c.next()) {
    if(c.is("--vertices")) o.vertices = c.number_in<std::size_t>(10, 10000000);
    else if(c.is("--field")) {
      o.field = c.value();
      vvm::internal::check_surface_field(o.field);
    }
    else if(c.is("--maximum-anisotropy")) o.maximum_anisotropy = c.number_in<double>(1, 100);
    else if(c.is("--maximum-size-ratio")) o.maximum_size_ratio = c.number_in<double>(1, 1000);
    else if(c.is("--methods")) {
      o.methods = c.list();
      for(const std::string& m : o.methods)
        if(m != "lattice" && m != "isotropic_remeshing") throw Input_error("unknown method '" + m + "'");
    } else
      c.common(o);
  }
  Command_line::require_input(o);
  if(o.features_angle < 0) o.features_angle = 60;
  return o;
}

Surface_mesh read_input(const std::string& input)
{
  Surface_mesh m;
  if(!CGAL::IO::read_polygon_mesh(input, m) || m.number_of_faces() == 0)
    throw Input_error("cannot read a surface mesh from '" + input + "'");
  if(!CGAL::is_triangle_mesh(m)) PMP::triangulate_faces(m);
  return m;
}

Field make_field(const Surface_mesh& m, const Options& o)
{
  std::vector<Point> points(m.points().begin(), m.points().end());
  std::vector<std::array<std::size_t, 3>> faces;
  for(auto f : m.faces()) {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[std::size_t(k++)] = std::size_t(v);
    faces.push_back(t);
  }
  return vvm::internal::surface_frame_field(points, faces, o.field, o.maximum_anisotropy, o.maximum_size_ratio,
                                            o.features_angle);
}

// isotropic remeshing at about `n` vertices: the target length of equilateral triangles of that
// count, corrected once by the count reached; sharp edges kept (split, never collapsed or flipped)
Surface_mesh isotropic_remeshing(const Surface_mesh& input, std::size_t n, double features_angle)
{
  const double area = PMP::area(input);
  double h = std::sqrt(2 * area / (std::sqrt(3.) * double(n)));
  Surface_mesh m;
  for(int attempt = 0; attempt < 2; ++attempt) {
    m = input;
    auto constrained = m.add_property_map<Surface_mesh::Edge_index, bool>("e:constrained", false).first;
    PMP::detect_sharp_edges(m, features_angle, constrained);
    for(auto e : m.edges()) if(m.is_border(e)) constrained[e] = true;
    PMP::isotropic_remeshing(faces(m), h, m, PMP::parameters::number_of_iterations(5).edge_is_constrained_map(constrained));
    m.collect_garbage();
    const double ratio = double(m.number_of_vertices()) / double(n);
    if(std::abs(ratio - 1) < 0.05) break;
    h *= std::sqrt(ratio);
  }
  return m;
}

int run(const Options& o)
{
  const Surface_mesh input = read_input(o.input);
  const std::string model = std::filesystem::path(o.input).stem().string();
  CGAL::Real_timer field_timer;
  field_timer.start();
  const Field field = make_field(input, o);
  const double field_time = field_timer.time();
  const double spacing = std::sqrt(PMP::area(input) / 2e5);
  Json_lines_file json(o.json_file, Json_lines_file::APPEND);
  Table table({{"method", 20, -1, true}, {"verts", 7}, {"r6", 6, 3}, {"xi mean", 8, 3}, {"xi min", 7, 3},
               {"min ang", 8, 2}, {"mean ang", 9, 2}, {"align", 6, 2}, {"hausdorff", 10, 5}, {"closed", 7}, {"time s", 7, 2}});
  std::cout << model << ": " << input.number_of_vertices() << " vertices, field '" << o.field << "' in " << field_time << " s\n";
  table.print_header();
  for(const std::string& method : o.methods) {
    CGAL::Real_timer timer;
    timer.start();
    Surface_mesh mesh;
    TLM::Lattice_surface_mesh_report report;
    if(method == "lattice") {
      mesh = CGAL::make_lattice_surface_mesh(
          input, field,
          TLM::parameters::report(&report, TLM::parameters::number_of_particles(o.vertices, CGAL::Frame_fields::parameters::features_angle(
                                                            o.features_angle, CGAL::parameters::random_seed(o.seed).verbose(o.verbose)))));
    } else
      mesh = isotropic_remeshing(input, o.vertices, o.features_angle);
    const double time = timer.time();
    if(o.verbose && method == "lattice")
      std::cerr << "  lattice: particles " << report.particle_time << " s, triangles " << report.triangle_time << " s, "
                << report.number_of_flips << " flips, " << report.number_of_non_manifold_triangles
                << " non-manifold triangles removed, " << report.number_of_filled_holes << " holes filled, "
                << report.number_of_smoothing_moves << " smoothing moves\n";
    const TLM::Surface_mesh_quality q = TLM::surface_mesh_quality(mesh, field, o.features_angle);
    const double hausdorff = (std::max)(PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(
                                            mesh, input, PMP::parameters::use_grid_sampling(true).grid_spacing(spacing)),
                                        PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(
                                            input, mesh, PMP::parameters::use_grid_sampling(true).grid_spacing(spacing)));
    table.print_row({method, q.number_of_vertices, q.r6, q.xi_mean, q.xi_min, q.min_angle, q.mean_min_angle,
                     q.alignment_error_mean, hausdorff, q.is_closed_manifold ? "yes" : "no", time});
    json.write(Json_line()
                   .add("model", model)
                   .add("method", method)
                   .add("field", o.field)
                   .add("n_vertices", q.number_of_vertices)
                   .add("n_faces", q.number_of_faces)
                   .add("r6", q.r6)
                   .add("xi_mean", q.xi_mean)
                   .add("xi_min", q.xi_min)
                   .add("min_angle_metric_deg", q.min_angle)
                   .add("mean_min_angle_metric_deg", q.mean_min_angle)
                   .add("alignment_error_mean_deg", q.alignment_error_mean)
                   .add("hausdorff", hausdorff)
                   .add("is_closed_manifold", q.is_closed_manifold)
                   .add("time_s", time)
                   .add("particle_time_s", method == "lattice" ? report.particle_time : 0.)
                   .add("triangle_time_s", method == "lattice" ? report.triangle_time : 0.)
                   .add("filled_holes", report.number_of_filled_holes)
                   .add("non_manifold_triangles", report.number_of_non_manifold_triangles)
                   .add("smoothing_moves", report.number_of_smoothing_moves)
                   .add("field_time_s", field_time));
    if(!o.out_dir.empty()) {
      const std::string out = o.out_dir + "/" + model + "_" + method + ".off";
      if(!CGAL::IO::write_polygon_mesh(out, mesh, CGAL::parameters::stream_precision(17)))
        throw std::runtime_error("cannot write '" + out + "'");
    }
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return benchmark_main("compare_surface_meshers", usage, argc, argv, parse, run);
}
