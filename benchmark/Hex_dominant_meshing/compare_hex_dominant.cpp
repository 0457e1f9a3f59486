// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_hex_dominant INPUT [--particles N] [--features-angle DEG]
//                      [--field cross|identity|fig4.15a..f|cylinder|cylinder-scaled]
//                      [--q-bound X | --q-bound-sweep] [--threads N] [--json FILE] [--out-dir DIR]
//                      [--boundary-distance D] [--seed N] [--levels K] [--rounds N] [--classify]
//                      [--verbose]
//
// make_hex_dominant_mesh_3 (dissertation 4.4, Tables 4.6-4.7): cell counts, hex volume,
// scaled Jacobians, alignment, boundary distance to the input against make_mesh_3's at
// the same vertex count, times per stage. The sweep merges the same tets at Q_bound
// 0, 0.1, ..., 0.9 (the Q_SJ / H_vol curve of Fig. 4.22c). --classify tells, after each merging,
// where the volume not in hexahedra goes (non_hex_causes.h).

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Frame_fields/scale_corrected_frame_field.h>

#include "box_surface.h"
#include "command_line.h"
#include "json_lines.h"
#include "non_hex_causes.h"
#include "surface_input.h"
#include "table.h"
#include "thickness_sizing.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/Closed_form_frame_field_3.h>
#include <CGAL/Frame_fields/Scaled_frame_field_3.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/GSM_mesh_optimization/mesh_with_vertex_count.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MEDIT.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MSH.h>
#include <CGAL/Hex_dominant_meshing/IO/write_VTU.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Domain_cross_field.h>
#include <CGAL/make_hex_dominant_mesh_3.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

typedef vvm_benchmark::K K;
typedef K::Point_3 Point_3;
typedef vvm_benchmark::Surface_mesh Surface_mesh;
typedef vvm_benchmark::Polyhedral_domain Domain;
typedef vvm_benchmark::Polyhedral_tr Tr;
typedef vvm_benchmark::Polyhedral_c3t3 C3T3;
typedef CGAL::Frame_fields::Closed_form_frame_field_3<K> Field;
typedef CGAL::Hex_dominant_mesh_3<Point_3> Mesh;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace FF = CGAL::Frame_fields;
namespace PMP = CGAL::Polygon_mesh_processing;
using vvm_benchmark::Input_error;

const char* usage =
    "usage: compare_hex_dominant INPUT [--particles N] [--features-angle DEG]\n"
    "                            [--field cross|identity|fig4.15a..f|cylinder|cylinder-scaled]\n"
    "                            [--q-bound X | --q-bound-sweep] [--threads N] [--json FILE] [--out-dir DIR]\n"
    "                            [--boundary-distance D] [--seed N] [--levels K] [--rounds N]\n"
    "                            [--sizing uniform|thickness] [--scale-correction RATIO]\n"
    "                            [--classify] [--verbose]\n"
    "  INPUT  a closed triangle surface (OFF, OBJ, PLY, STL, ...), or cube, warped-cube or cylinder:\n"
    "         cube is [-1,1]^3 ([0.1,1.1]^3 with fig4.15c and fig4.15d); warped-cube is T [-1,1]^3\n"
    "         for a constant field T (fig4.15b, e, f; scaled to volume 8), the warped cube of\n"
    "         Fig. 4.15 whose faces are lattice planes; cylinder is a tube about z,\n"
    "         radii 0.5 and 1, height 1 (256 facets around)\n"
    "  --particles N       the number of particles sought (default 30000; one more run with a\n"
    "                      corrected count if the mesh is more than 10% off)\n"
    "  --features-angle D  sharp edges of surfaces (default 0 = none; 60 for cube and cylinder)\n"
    "  --field F           cross (default for surfaces: generate_cross_field_3 on the domain);\n"
    "                      identity (default for cube) = fig4.15a; fig4.15b T = diag(4,1,1);\n"
    "                      fig4.15c T = diag(8x,1,1) (on [0.1,1.1]^3: the field is degenerate at x = 0);\n"
    "                      fig4.15d Fig. 4.8's T = diag(1.0125 - exp(-|x-0.6|),1,1) on [0.1,1.1]^3;\n"
    "                      fig4.15e / fig4.15f the shears; cylinder / cylinder-scaled: Fig. 4.16's\n"
    "                      cross field without / with the scale correction (reference radius 1)\n"
    "  --q-bound X         Q_bound of the merging (default 0.5)\n"
    "  --q-bound-sweep     merge the same tets at Q_bound 0, 0.1, ..., 0.9 (Fig. 4.22c)\n"
    "  --threads N         maximum number of threads (default: all cores)\n"
    "  --json FILE         one JSON line per merging\n"
    "  --out-dir DIR       write <model>_hexdom.vtu (cell type, scaled Jacobians), .msh and .mesh\n"
    "  --boundary-distance D  the boundary refinement of section 4.4.2 down to distance D (default 0:\n"
    "                      none)\n"
    "  --seed N            seed of the particles and of make_mesh_3 (default 0)\n"
    "  --levels K          multiresolution levels of the particles, K in [0, 6] (default: the package's choice)\n"
    "  --rounds N          the most insertion and deletion rounds per level (default: the package's, 16 at\n"
    "                      the coarsest level, 8 after)\n"
    "  --sizing S          uniform (default), or thickness: the field's frames scaled by the walls' and\n"
    "                      gaps' thickness, 3 cells across, graded by 0.3 (CGAL::Thickness_sizing_field_3)\n"
    "  --scale-correction R  the field's scales corrected so that the lattice follows its turning\n"
    "                      (Frame_fields::scale_corrected_frame_field, scales within a ratio R >= 1;\n"
    "                      default 2 for the cross field, as make_hex_dominant_mesh_3's, none for the\n"
    "                      others; 1 for none); a closed-form field is sampled at the vertices of the\n"
    "                      cross field's mesh first\n"
    "  --classify          after each merging, the volume not in hexahedra by cause: a hexahedron\n"
    "                      candidate under Q_bound, overlapping a kept one or not conforming; no\n"
    "                      candidate near a singular edge, at the boundary, at a particle off the lattice\n"
    "  --verbose           progress of the particle rounds\n";

// T of the constant fields
std::optional<Eigen::Matrix3d> constant_frame(const std::string& f)
{
  if(f == "identity" || f == "fig4.15a") return Eigen::Matrix3d::Identity();
  if(f == "fig4.15b") return FF::constant_stretch_frame_field<K>().T(Point_3(0, 0, 0));
  if(f == "fig4.15e") return FF::shear_y_frame_field<K>().T(Point_3(0, 0, 0));
  if(f == "fig4.15f") return FF::shear_yz_frame_field<K>().T(Point_3(0, 0, 0));
  return std::nullopt;
}

// INPUT: a surface file, or cube / warped-cube / cylinder
struct Options : vvm_benchmark::Common_options
{
  std::string field, sizing = "uniform";
  std::size_t particles = 30000;
  double q_bound = 0.5, boundary_distance = 0, scale_correction = -1; // -1: the default
  bool sweep = false, classify = false;
  int levels = -1, rounds = -1;
};

Options parse_command_line(int argc, char** argv)
{
  Options o;
  vvm_benchmark::Command_line c(argc, argv, usage);
  while(c.next()) {
    if(c.is("--particles")) o.particles = c.number_in<std::size_t>(8, 20000000);
    else if(c.is("--field")) o.field = c.value();
    else if(c.is("--q-bound")) o.q_bound = c.number_in<double>(0, 1);
    else if(c.is("--q-bound-sweep")) o.sweep = true;
    else if(c.is("--classify")) o.classify = true;
    else if(c.is("--boundary-distance")) {
      o.boundary_distance = c.number<double>();
      if(!(o.boundary_distance >= 0)) throw Input_error("--boundary-distance must be non-negative");
    } else if(c.is("--levels")) o.levels = c.number_in<int>(0, 6);
    else if(c.is("--rounds")) o.rounds = c.number_in<int>(0, 1000);
    else if(c.is("--sizing")) o.sizing = c.one_of({"uniform", "thickness"});
    else if(c.is("--scale-correction")) o.scale_correction = c.number_in<double>(1, 1000);
    else c.common(o);
  }
  vvm_benchmark::Command_line::require_input(o);
  const bool builtin = o.input == "cube" || o.input == "warped-cube" || o.input == "cylinder";
  if(o.field.empty())
    o.field = o.input == "cube" ? "identity" : o.input == "warped-cube" ? "fig4.15e"
            : o.input == "cylinder" ? "cylinder-scaled" : "cross";
  static const std::vector<std::string> fields = {"cross", "identity", "fig4.15a", "fig4.15b", "fig4.15c", "fig4.15d",
                                                  "fig4.15e", "fig4.15f", "cylinder", "cylinder-scaled"};
  if(std::find(fields.begin(), fields.end(), o.field) == fields.end()) throw Input_error("unknown --field '" + o.field + "'");
  if(o.field.rfind("fig4.15", 0) == 0 && o.input != "cube" && o.input != "warped-cube")
    throw Input_error("--field " + o.field + " is defined on INPUT cube or warped-cube");
  if(o.input == "warped-cube" && !constant_frame(o.field))
    throw Input_error("INPUT warped-cube needs a constant field: identity or fig4.15a, b, e, f");
  if(o.field.rfind("cylinder", 0) == 0 && o.input != "cylinder")
    throw Input_error("--field " + o.field + " is defined on INPUT cylinder");
  if(o.features_angle < 0) o.features_angle = builtin ? 60. : 0.;
  if(o.scale_correction < 0) o.scale_correction = o.field == "cross" ? 2. : 1.;
  return o;
}

Field make_field(const Options& o, const Domain& domain, double volume)
{
  const std::string& f = o.field;
  if(const auto T = constant_frame(f)) return Field([T = *T](const Point_3&) { return T; });
  if(f == "fig4.15c") return FF::linear_scale_frame_field<K>();
  if(f == "fig4.15d") return FF::single_direction_anisotropy_frame_field<K>();
  if(o.scale_correction == 1) {
    if(f == "cylinder") return FF::cylinder_frame_field<K>(1., false);
    if(f == "cylinder-scaled") return FF::cylinder_frame_field<K>(1., true);
  }
  // cross: on a mesh about as fine as the lattice
  const double size = std::cbrt(volume / double(o.particles));
  CGAL::Real_timer cross_timer;
  cross_timer.start();
  auto cross = std::make_shared<FF::Discrete_frame_field_3<K>>(TLM::internal::domain_cross_field(domain, size));
  std::cout << "cross field: " << cross->points().size() << " vertices, " << cross_timer.time() << " s\n";
  if(o.scale_correction > 1) {
    if(f != "cross") { // the closed-form field at the cross field's vertices
      Options uncorrected = o;
      uncorrected.scale_correction = 1;
      const Field closed_form = make_field(uncorrected, domain, volume);
      std::vector<Eigen::Matrix3d> frames;
      for(const Point_3& p : cross->points()) frames.push_back(closed_form.T(p));
      *cross = FF::Discrete_frame_field_3<K>(cross->points(), cross->cells(), std::move(frames), FF::Frame_location::VERTICES);
    }
    CGAL::Real_timer timer;
    timer.start();
    auto corrected = FF::scale_corrected_frame_field(*cross, FF::parameters::maximum_size_ratio(o.scale_correction));
    std::cout << "scale correction: integrability error " << corrected.integrability_error_before << " -> "
              << corrected.integrability_error_after << ", " << corrected.number_of_clamped_scales << " of "
              << 3 * cross->points().size() << " scales clamped, " << timer.time() << " s\n";
    *cross = std::move(corrected.field);
  }
  return Field([cross](const Point_3& p) { return cross->T(p); });
}

// triangles as a mesh of separate faces (own vertices each): a mesh's boundary may be non-manifold
// (two parts touching at an edge), and Surface_mesh would refuse such facets
Surface_mesh triangle_soup_mesh(const std::vector<std::array<Point_3, 3>>& triangles)
{
  Surface_mesh sm;
  for(const auto& t : triangles)
    sm.add_face(sm.add_vertex(t[0]), sm.add_vertex(t[1]), sm.add_vertex(t[2]));
  return sm;
}

// the boundary of the merged tets (the cells' boundary, each quad as its two tet facets)
Surface_mesh boundary_of(const Mesh& mesh, const HDM::Hex_dominant_merge_report& report)
{
  std::map<std::array<std::size_t, 3>, std::pair<int, std::array<std::size_t, 3>>> facets; // sorted -> (count, outward)
  for(const auto& t : report.tets)
    for(const auto& f : HDM::internal::cell_faces(CGAL::Hex_dominant_cell_type::TETRAHEDRON).triangles) {
      const std::array<std::size_t, 3> outward = {{t[std::size_t(f[0])], t[std::size_t(f[1])], t[std::size_t(f[2])]}};
      std::array<std::size_t, 3> key = outward;
      std::sort(key.begin(), key.end());
      auto& e = facets[key];
      ++e.first;
      e.second = outward;
    }
  std::vector<std::array<Point_3, 3>> triangles;
  for(const auto& f : facets)
    if(f.second.first == 1)
      triangles.push_back({{mesh.points[f.second.second[0]], mesh.points[f.second.second[1]], mesh.points[f.second.second[2]]}});
  return triangle_soup_mesh(triangles);
}

// the surface facets of a complex
Surface_mesh boundary_of(const C3T3& c3t3)
{
  std::vector<std::array<Point_3, 3>> triangles;
  auto point = c3t3.triangulation().geom_traits().construct_point_3_object();
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    std::array<Point_3, 3> t;
    for(int k = 0; k < 3; ++k)
      t[std::size_t(k)] = point(f->first->vertex((f->second + 1 + k) % 4)->point());
    triangles.push_back(t);
  }
  return triangle_soup_mesh(triangles);
}

using vvm_benchmark::two_sided_distance;

int run(const Options& o)
{
  const bool is_cube = o.input == "cube", is_cylinder = o.input == "cylinder";
  Surface_mesh surface;
  double volume = 0;
  std::string model;
  if(is_cube) {
    const bool shifted = o.field == "fig4.15c" || o.field == "fig4.15d";
    surface = vvm_benchmark::box_surface<Surface_mesh>(shifted ? 0.1 : -1., shifted ? 1.1 : 1.);
    model = "cube";
  } else if(o.input == "warped-cube") {
    surface = vvm_benchmark::box_surface<Surface_mesh>(-1., 1.);
    const Eigen::Matrix3d T = *constant_frame(o.field) / std::cbrt(std::abs(constant_frame(o.field)->determinant()));
    for(auto v : surface.vertices()) {
      const Point_3& p = surface.point(v);
      const Eigen::Vector3d x = T * Eigen::Vector3d(p.x(), p.y(), p.z());
      surface.point(v) = Point_3(x[0], x[1], x[2]);
    }
    if(T.determinant() < 0) PMP::reverse_face_orientations(surface);
    model = "warped-cube";
  } else if(is_cylinder) {
    surface = vvm_benchmark::tube_surface<Surface_mesh>(256);
    model = "cylinder";
  } else {
    vvm_benchmark::read_surface_input(o.input, surface);
    model = CGAL::GSM_mesh_optimization::IO::file_stem(o.input);
  }
  volume = std::abs(PMP::volume(surface));
  Domain domain(surface);
  if(o.features_angle > 0) domain.detect_features(o.features_angle);

  CGAL::Real_timer timer;
  timer.start();
  // the cross field at the uniform size is the one make_hex_dominant_mesh_3() makes when given
  // none (its boundary sampled beside it): made in the call below, kept here for the statistics
  const bool packages_field = o.field == "cross" && o.sizing == "uniform";
  Field field = packages_field ? Field([](const Point_3&) { return Eigen::Matrix3d(Eigen::Matrix3d::Identity()); })
                               : make_field(o, domain, volume);
  if(o.sizing == "thickness") { // T(x) h(x) / (h's median on the surface): the lattice's spacing follows the size
    const auto sizing = vvm_benchmark::thickness_sizing<K>(surface, 3., 0.3, o.features_angle);
    const auto size = sizing.field;
    field = Field([scaled = FF::Scaled_frame_field_3<Field, std::function<double(const Point_3&)>>(
                       field, [size](const Point_3& p) { return (*size)(p); }, sizing.median_size)](
                      const Point_3& p) { return scaled.T(p); });
    model += "_thickness";
  }
  double field_time = timer.time();
  auto B = [&field](const Eigen::Vector3d& x) { return Eigen::Matrix3d(field.B(Point_3(x[0], x[1], x[2]))); };

  // the particles and their tets once; the merging once per Q_bound
  HDM::Hex_dominant_report report;
  std::vector<double> bounds;
  if(o.sweep)
    for(int k = 0; k <= 9; ++k) bounds.push_back(0.1 * k);
  else
    bounds.push_back(o.q_bound);
  const double spacing = vvm_benchmark::distance_sampling_spacing(surface);
  double make_mesh_3_distance = -1;
  std::size_t make_mesh_3_vertices = 0;
  vvm_benchmark::Json_lines_file json(o.json_file, vvm_benchmark::Json_lines_file::APPEND);
  const vvm_benchmark::Table table({{"model", 10, -1, true}, {"field", 16, -1, true}, {"Qb", 5, 2},
                                    {"particles", 8}, {"hex", 7}, {"prism", 6}, {"pyr", 6}, {"tet", 6},
                                    {"H_vol%", 7, 2}, {"#hex%", 6, 2}, {"SJmin", 6, 3}, {"SJmean", 6, 3},
                                    {"Vmin", 6, 3}, {"align", 7, 2}, {"inv", 5}, {"ncf", 5}, {"hd/hd0", 8, 3},
                                    {"t_part", 7, 2}, {"t_tets", 7, 2}, {"t_merge", 7, 2}, {"t_total", 7, 2}});
  table.print_header();
  C3T3 tets;
  for(double q : bounds) {
    namespace TP = TLM::parameters;
    Mesh mesh;
    if(q == bounds.front()) {
      // one correction of the particle count when the mesh's is more than 10% off the target
      // (the lattice's estimate misses on graded fields and thin parts); times of the last run
      double wanted = double(o.particles);
      for(int attempt = 0; attempt < 2; ++attempt) {
        auto np = TP::number_of_particles(std::size_t(std::llround(wanted)), TP::number_of_threads(o.threads,
            HDM::parameters::quality_bound(q, HDM::parameters::boundary_distance(o.boundary_distance,
                HDM::parameters::report(&report,
                    HDM::parameters::tetrahedral_mesh(&tets, CGAL::parameters::random_seed(o.seed).verbose(o.verbose)))))));
        auto make = [&](const auto& np) {
          if(!packages_field) return CGAL::make_hex_dominant_mesh_3<C3T3>(domain, field, np);
          // as CGAL::make_hex_dominant_mesh_3(domain, np) does it, with the field kept
          CGAL::Real_timer field_timer;
          field_timer.start();
          const auto with_ratio = FF::parameters::maximum_size_ratio(o.scale_correction, np);
          return CGAL::VVM::internal::with_frame_field(domain, HDM::internal::read_hex_dominant_request(with_ratio), with_ratio,
                                                [&](const auto& made, const CGAL::VVM::internal::Lattice_request& r) {
            field_time = field_timer.time();
            const auto cross = std::make_shared<const std::decay_t<decltype(made)>>(made);
            field = Field([cross](const Point_3& p) { return cross->T(p); });
            std::cout << "cross field (the packages' own) and the boundary's sampling beside it: " << cross->points().size()
                      << " vertices, " << field_time << " s\n";
            return HDM::internal::make_hex_dominant_mesh<C3T3>(domain, made, r, with_ratio);
          });
        };
        auto with_levels = [&](const auto& np) {
          return o.levels < 0 ? make(np) : make(TP::multiresolution_levels(o.levels, np));
        };
        mesh = o.rounds < 0 ? with_levels(np) : with_levels(np.number_of_iterations(o.rounds));
        const double n = double(mesh.points.size());
        if(!(n > 0) || std::abs(n - double(o.particles)) <= 0.1 * double(o.particles)) break;
        wanted *= double(o.particles) / n;
      }
    }
    else { // the same tets merged again
      CGAL::Real_timer merge;
      merge.start();
      mesh = CGAL::tets_to_hex_dominant(tets, HDM::parameters::quality_bound(q, HDM::parameters::frame_field(std::cref(field),
                                                  HDM::parameters::report(&report.merge))));
      report.merge_time = merge.time();
    }
    const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, B, &report.merge);
    const auto directed = two_sided_distance(boundary_of(mesh, report.merge), surface, spacing);
    const double distance = (std::max)(directed.first, directed.second);
    if(make_mesh_3_distance < 0) { // make_mesh_3 at the same vertex count, uniform sizing
      namespace P = CGAL::parameters;
      auto with_size = [&](double size) {
        CGAL::get_default_random() = CGAL::Random(o.seed);
        CGAL::Mesh_criteria_3<Tr> criteria(P::edge_size = size, P::facet_angle = 25, P::facet_size = size,
                                           P::facet_distance = size / 10., P::cell_radius_edge_ratio = 3, P::cell_size = size);
        return CGAL::make_mesh_3<C3T3>(domain, criteria, P::no_perturb(), P::no_exude());
      };
      const auto r = CGAL::GSM_mesh_optimization::mesh_with_vertex_count(
          with_size, mesh.points.size(), std::cbrt(volume / (0.2 * double(mesh.points.size()))), 0.03);
      const auto d = two_sided_distance(boundary_of(r.c3t3), surface, spacing);
      make_mesh_3_distance = (std::max)(d.first, d.second);
      make_mesh_3_vertices = CGAL::GSM_mesh_optimization::number_of_vertices_in_complex(r.c3t3);
    }
    std::optional<vvm_benchmark::Non_hex_causes> causes;
    if(o.classify)
      causes = vvm_benchmark::classify_non_hex_volume(
          mesh, report.merge, [&field](const Eigen::Vector3d& x) { return Eigen::Matrix3d(field.T(Point_3(x[0], x[1], x[2]))); },
          q, report.edge_length);
    const double total = field_time + report.particle_time + report.tetrahedra_time + report.merge_time;
    const double ratio = make_mesh_3_distance > 1e-9 * std::sqrt(PMP::area(surface)) ? distance / make_mesh_3_distance : -1;
    table.print_row({model, o.field, q, mesh.points.size(), s.number_of_hexahedra, s.number_of_prisms,
                     s.number_of_pyramids, s.number_of_tetrahedra, s.hexahedron_volume_percent,
                     s.hexahedron_count_percent, s.scaled_jacobian_min, s.scaled_jacobian_mean,
                     s.verdict_scaled_jacobian_min, s.alignment_error_mean, s.number_of_inverted_cells,
                     s.number_of_nonconforming_faces, ratio, field_time + report.particle_time,
                     report.tetrahedra_time, report.merge_time, total});
    json.write(vvm_benchmark::Json_line()
                   .add("model", model).add("field", o.field).add("sizing", o.sizing).add("scale_correction", o.scale_correction).add("q_bound", q)
                   .add("n_particles", mesh.points.size()).add("n_hex", s.number_of_hexahedra)
                   .add("n_prism", s.number_of_prisms).add("n_pyramid", s.number_of_pyramids)
                   .add("n_tet", s.number_of_tetrahedra).add("h_vol_percent", s.hexahedron_volume_percent)
                   .add("hex_count_percent", s.hexahedron_count_percent).add("sj_min", s.scaled_jacobian_min)
                   .add("sj_mean", s.scaled_jacobian_mean).add("verdict_sj_min", s.verdict_scaled_jacobian_min)
                   .add("verdict_sj_mean", s.verdict_scaled_jacobian_mean)
                   .add("alignment_error_mean_deg", s.alignment_error_mean).add("hausdorff", distance)
                   .add("hausdorff_mesh_to_surface", directed.first).add("hausdorff_surface_to_mesh", directed.second)
                   .add("hausdorff_make_mesh_3", make_mesh_3_distance).add("make_mesh_3_vertices", make_mesh_3_vertices)
                   .add("hausdorff_ratio", ratio).add("n_inverted", s.number_of_inverted_cells)
                   .add("n_nonconforming", s.number_of_nonconforming_faces).add("time_field_s", field_time)
                   .add("time_particles_s", report.particle_time).add("time_tets_s", report.tetrahedra_time)
                   .add("time_merge_s", report.merge_time).add("time_s", total));
    if(causes) causes->print();
    if(!o.out_dir.empty() && q == bounds.front()) {
      std::vector<double> verdict; // Verdict's hexahedron measure: 0 for the other cells
      for(const auto& c : mesh.cells) {
        std::array<Eigen::Vector3d, 8> p;
        for(std::size_t k = 0; k < c.size(); ++k) {
          const Point_3& x = mesh.points[c.vertices[k]];
          p[k] = Eigen::Vector3d(x.x(), x.y(), x.z());
        }
        verdict.push_back(c.type == CGAL::Hex_dominant_cell_type::HEXAHEDRON ? HDM::verdict_hexahedron_scaled_jacobian(p) : 0.);
      }
      const std::string base = o.out_dir + "/" + model + "_hexdom";
      HDM::IO::write_VTU(base + ".vtu", mesh, {{"scaled_jacobian", HDM::cell_scaled_jacobians(mesh, B)}, {"verdict_scaled_jacobian", verdict}});
      HDM::IO::write_MSH(base + ".msh", mesh);
      HDM::IO::write_MEDIT(base + ".mesh", mesh);
    }
  }
  std::printf("merging (last): candidates %.2f s, selection %.2f s; %zu hexahedron, %zu prism, %zu pyramid candidates\n",
              report.merge.candidate_time, report.merge.selection_time, report.merge.number_of_hexahedron_candidates,
              report.merge.number_of_prism_candidates, report.merge.number_of_pyramid_candidates);
  std::printf("tets: %zu free particles projected, %zu boundary points added, %zu flips to the field's Delaunay\n",
              report.number_of_projected_particles, report.number_of_boundary_points, report.number_of_metric_flips);
  std::printf("make_mesh_3 at %zu vertices: boundary distance %.5g (hd0)\n", make_mesh_3_vertices, make_mesh_3_distance);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  return vvm_benchmark::benchmark_main("compare_hex_dominant", usage, argc, argv, parse_command_line, run);
}
