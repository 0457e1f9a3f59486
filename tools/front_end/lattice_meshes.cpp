// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The front end's particle meshes of a closed surface: BCC / FCC lattice tet
// meshes (vvm::tet_mesh), hex-dominant meshes, and the cross field alone.

#include "lattice_progress.h"

#include <CGAL/Frame_fields/Closed_form_frame_field_3.h>
#include <CGAL/Frame_fields/Constant_frame_field_3.h>
#include <CGAL/Frame_fields/Scaled_frame_field_3.h>
#include <CGAL/Frame_fields/IO/frame_field_text_format.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/make_hex_dominant_mesh_3.h>
#include <CGAL/make_lattice_mesh_3.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Domain_cross_field.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

namespace vvm {
namespace internal {
namespace {

namespace FF = CGAL::Frame_fields;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace HDM = CGAL::Hex_dominant_meshing;

/// calls `run(field)` with the field `name` names: identity, a frame-field file, or (cross)
/// no field, for the packages' own boundary-aligned cross field. With `sizing`, the field's
/// frames scaled by it (`Scaled_frame_field_3`); the cross field is then made here, on a mesh
/// of `domain` of edge `cross_size`, its scales corrected within `cross_scale_ratio` (1: none)
/// as the packages do it.
template <class Run>
auto with_field(const std::string& name, const Thickness_size* sizing, const Surface_domain& domain, double cross_size,
                double cross_scale_ratio, double time_limit, const Run& run)
{
  if(sizing != nullptr) {
    typedef FF::Closed_form_frame_field_3<Kernel> Field;
    Field field([](const Point&) { return Eigen::Matrix3d(Eigen::Matrix3d::Identity()); });
    try {
      if(name != "identity") {
        const auto frames = std::make_shared<const FF::Discrete_frame_field_3<Kernel>>(
            name == "cross" ? TLM::internal::domain_cross_field(domain, cross_size, time_limit, cross_scale_ratio)
                            : read_frame_field_file(name));
        field = Field([frames](const Point& p) { return frames->T(p); });
      }
    } catch(const std::invalid_argument& e) {
      throw Input_error(e.what());
    }
    const FF::Scaled_frame_field_3<Field, Thickness_size> scaled(std::move(field), *sizing, 1.);
    return run(&scaled);
  }
  if(name == "cross") return run(static_cast<const FF::Discrete_frame_field_3<Kernel>*>(nullptr));
  if(name == "identity") {
    const FF::Constant_frame_field_3<Kernel> identity;
    return run(&identity);
  }
  const FF::Discrete_frame_field_3<Kernel> field = read_frame_field_file(name);
  return run(&field);
}

} // namespace

Volume_mesh lattice_tet_mesh(const Surface_source& input, const Tet_options& o, const Progress& progress, Run_report& r)
{
  const auto threads = thread_limit(o.threads);
  Surface_input in(input, o.features_angle);
  const Stage stage(progress, "lattice " + o.method);
  TLM::Lattice_mesh_report report;
  auto np = TLM::parameters::lattice(o.method == "bcc" ? TLM::Lattice_type::BCC : TLM::Lattice_type::FCC,
                                     TLM::parameters::report(&report, TLM::parameters::number_of_threads(o.threads,
                                         CGAL::parameters::random_seed(o.seed).maximum_running_time(o.time_limit).visitor(
                                             progress_visitor(stage)))));
  const auto sizing = relative_sizing(o.sizing, in);
  // the cross field's mesh about as fine as a BCC lattice of the requested count
  const double cross_size = o.size.size > 0 ? o.size.size : std::cbrt(2 * in.volume / double(o.size.vertices));
  Surface_c3t3 c3t3 = with_field(o.field, sizing.get(), *in.domain, cross_size, 1., o.time_limit, [&](const auto* field) {
    try {
      if(o.size.size > 0) {
        auto sized = TLM::parameters::edge_length(o.size.size, np);
        return field ? CGAL::make_lattice_mesh_3<Surface_c3t3>(*in.domain, *field, sized)
                     : CGAL::make_lattice_mesh_3<Surface_c3t3>(*in.domain, sized);
      }
      auto counted = TLM::parameters::number_of_particles(o.size.vertices, np);
      return field ? CGAL::make_lattice_mesh_3<Surface_c3t3>(*in.domain, *field, counted)
                   : CGAL::make_lattice_mesh_3<Surface_c3t3>(*in.domain, counted);
    } catch(const std::invalid_argument& e) {
      throw Input_error(e.what());
    }
  });
  r.optimize_time = stage.time();
  r.time_limit_reached = report.time_limit_reached;
  return to_volume_mesh(c3t3);
}

} // namespace internal

Volume_mesh hex_dominant_mesh(const Surface_source& input, const Hex_dominant_options& o, const Progress& progress,
                              Run_report* report)
{
  Run_report local;
  Run_report& r = report ? *report : local;
  const internal::Run_timer run_timer(r);
  r.input = input.name();
  r.method = "hexdom";
  internal::check_mesh_size(o.size, "particles");
  if(!(o.quality_bound >= 0 && o.quality_bound <= 1)) throw Input_error("the quality bound (--q-bound) must be in [0, 1]");
  if(!(o.boundary_distance >= 0) || !std::isfinite(o.boundary_distance))
    throw Input_error("the boundary distance (--boundary-distance) must be non-negative and finite");
  if(!(o.maximum_size_ratio >= 1) || !std::isfinite(o.maximum_size_ratio))
    throw Input_error("the maximum size ratio (--maximum-size-ratio) must be at least 1 and finite");
  const auto threads = internal::thread_limit(o.threads);
  internal::Surface_input in(input, o.features_angle);
  const internal::Stage stage(progress, "hexdom");
  CGAL::Hex_dominant_meshing::Hex_dominant_report hex_report;
  auto np = internal::HDM::parameters::report(&hex_report, internal::HDM::parameters::quality_bound(
      o.quality_bound,
      internal::HDM::parameters::boundary_distance(
          o.boundary_distance,
          internal::FF::parameters::maximum_size_ratio(
              o.maximum_size_ratio,
              internal::TLM::parameters::number_of_threads(
                  o.threads, CGAL::parameters::random_seed(o.seed).maximum_running_time(o.time_limit).visitor(
                                 internal::progress_visitor(stage)))))));
  const auto sizing = internal::relative_sizing(o.sizing, in);
  const double cross_size = o.size.size > 0 ? o.size.size : std::cbrt(in.volume / double(o.size.vertices));
  Volume_mesh mesh = internal::with_field(o.field, sizing.get(), *in.domain, cross_size, o.maximum_size_ratio, o.time_limit,
                                          [&](const auto* field) {
    try {
      if(o.size.size > 0) {
        auto sized = internal::TLM::parameters::edge_length(o.size.size, np);
        return field ? CGAL::make_hex_dominant_mesh_3<internal::Surface_c3t3>(*in.domain, *field, sized)
                     : CGAL::make_hex_dominant_mesh_3<internal::Surface_c3t3>(*in.domain, sized);
      }
      auto counted = internal::TLM::parameters::number_of_particles(o.size.vertices, np);
      return field ? CGAL::make_hex_dominant_mesh_3<internal::Surface_c3t3>(*in.domain, *field, counted)
                   : CGAL::make_hex_dominant_mesh_3<internal::Surface_c3t3>(*in.domain, counted);
    } catch(const std::invalid_argument& e) {
      throw Input_error(e.what());
    }
  });
  r.optimize_time = stage.time();
  r.time_limit_reached = hex_report.time_limit_reached;
  return mesh;
}

std::string cross_field(const Surface_source& input, const Field_options& o, const Progress& progress, Run_report* report)
{
  Run_report local;
  Run_report& r = report ? *report : local;
  const internal::Run_timer run_timer(r);
  r.input = input.name();
  r.method = "field";
  internal::check_mesh_size(o.size);
  internal::Surface_input in(input, o.features_angle);
  internal::Surface_c3t3 c3t3;
  {
    const internal::Stage stage(progress, "make_mesh_3");
    c3t3 = internal::initial_mesh<internal::Surface_c3t3>(*in.domain, in.volume, o.size, o.seed, stage);
    r.mesh_time = stage.time();
  }
  const internal::Stage stage(progress, "cross field");
  stage.report("generate_cross_field_3 on " + std::to_string(c3t3.number_of_cells_in_complex()) + " cells");
  std::ostringstream os;
  const auto generated = CGAL::Frame_fields::generate_cross_field_3(c3t3, CGAL::parameters::maximum_running_time(o.time_limit));
  CGAL::Frame_fields::IO::write_frame_field(os, generated.field);
  r.optimize_time = stage.time();
  r.time_limit_reached = generated.time_limit_reached;
  return os.str();
}

Frame_field_arrays frame_field_from_text(const std::string& text)
{
  std::istringstream is(text);
  internal::FF::Discrete_frame_field_3<Kernel> field;
  try {
    field = internal::FF::IO::read_frame_field<Kernel>(is);
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
  Frame_field_arrays a;
  for(const Point& p : field.points()) a.points.push_back({p.x(), p.y(), p.z()});
  a.tetrahedra.assign(field.cells().begin(), field.cells().end());
  for(const Eigen::Matrix3d& T : field.frames())
    a.frames.push_back({T(0, 0), T(0, 1), T(0, 2), T(1, 0), T(1, 1), T(1, 2), T(2, 0), T(2, 1), T(2, 2)});
  a.on_cells = field.location() == internal::FF::Frame_location::CELLS;
  return a;
}

std::string frame_field_text(const Frame_field_arrays& a)
{
  std::vector<Point> points;
  for(const auto& p : a.points) points.emplace_back(p[0], p[1], p[2]);
  std::vector<Eigen::Matrix3d> frames;
  for(const auto& f : a.frames) {
    Eigen::Matrix3d T;
    T << f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8];
    frames.push_back(T);
  }
  std::ostringstream os;
  try {
    internal::FF::IO::write_frame_field(
        os, internal::FF::Discrete_frame_field_3<Kernel>(
                std::move(points), a.tetrahedra, std::move(frames),
                a.on_cells ? internal::FF::Frame_location::CELLS : internal::FF::Frame_location::VERTICES));
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
  return os.str();
}

} // namespace vvm
