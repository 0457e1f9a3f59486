// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// vvm::tet_mesh on a closed surface: make_mesh_3 of its domain (sharp edges
// protected) at a size or vertex count, then an optimizer chain. Images and
// lattices are in their own units.

#include "optimizer_chain.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <memory>

namespace vvm {
namespace internal {

bool has_extension(const std::string& path, const std::string& extension)
{
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return lower.size() >= extension.size() && lower.compare(lower.size() - extension.size(), extension.size(), extension) == 0;
}

bool is_image_file(const std::string& path) { return has_extension(path, ".inr") || has_extension(path, ".inr.gz"); }

/// GSM's target metric from a frame-field file (B^T B); empty for cross and identity
std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> metric_of_field(const std::string& field)
{
  if(field == "cross" || field == "identity") return {};
  const auto f = std::make_shared<CGAL::Frame_fields::Discrete_frame_field_3<Kernel>>(read_frame_field_file(field));
  return [f](const Eigen::Vector3d& x) {
    const Eigen::Matrix3d B = f->B(Point(x[0], x[1], x[2]));
    return Eigen::Matrix3d(B.transpose() * B);
  };
}

} // namespace internal

Volume_mesh tet_mesh(const Surface_source& input, const Tet_options& o, const Progress& progress, Run_report* report)
{
  Run_report local;
  Run_report& r = report ? *report : local;
  const internal::Run_timer run_timer(r);
  r.input = input.name();
  r.method = o.method;
  internal::check_mesh_size(o.size);
  const bool image = input.is_file() && internal::is_image_file(input.path);
  if(o.method == "bcc" || o.method == "fcc") {
    if(image) throw Input_error("the method " + o.method + " meshes surfaces, not images");
    return internal::lattice_tet_mesh(input, o, progress, r);
  }
  if(!internal::is_optimizer_chain(o.method))
    throw Input_error("unknown method '" + o.method + "' (known: gsm, odt+gsm, perturb+exude, bcc, fcc)");
  if(image && o.sizing != "uniform") throw Input_error("the sizing " + o.sizing + " needs a surface, not an image");
  if(image) return internal::image_tet_mesh(input.path, o, progress, r);
  const auto metric = internal::metric_of_field(o.field);
  const auto threads = internal::thread_limit(o.threads);
  internal::Surface_input in(input, o.features_angle);
  if(metric && o.sizing != "uniform") throw Input_error("a frame-field file is GSM's metric: it cannot go with a sizing");
  internal::Surface_c3t3 c3t3;
  std::shared_ptr<const internal::Thickness_size> sizing;
  {
    const internal::Stage stage(progress, "make_mesh_3");
    if(o.sizing != "uniform") stage.report("the surface's thickness");
    sizing = internal::relative_sizing(o.sizing, in);
    c3t3 = internal::initial_mesh<internal::Surface_c3t3>(*in.domain, in.volume, o.size, o.seed, stage, sizing.get());
    r.mesh_time = stage.time();
  }
  CGAL::Real_timer timer;
  timer.start();
  r.time_limit_reached = internal::run_optimizer_chain(c3t3, *in.domain, o, progress, metric, sizing.get());
  r.optimize_time = timer.time();
  return internal::to_volume_mesh(c3t3);
}

} // namespace vvm
