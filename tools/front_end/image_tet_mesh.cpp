// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// vvm::tet_mesh on a labelled 3D image (.inr, .inr.gz): make_mesh_3 of CGAL's
// labelled image domain, each label a subdomain, then the optimizer chain.

#include "optimizer_chain.h"

#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>

#include <fstream>

namespace vvm {
namespace internal {
namespace {

typedef CGAL::Labeled_mesh_domain_3<Kernel> Image_domain;
typedef CGAL::Mesh_triangulation_3<Image_domain, CGAL::Default, CGAL::Sequential_tag>::type Image_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Image_tr> Image_c3t3;

// the volume of the voxels of non-zero label
double labelled_volume(const CGAL::Image_3& image)
{
  std::size_t n = 0;
  for(std::size_t k = 0; k < image.zdim(); ++k)
    for(std::size_t j = 0; j < image.ydim(); ++j)
      for(std::size_t i = 0; i < image.xdim(); ++i) n += image.value(i, j, k) != 0;
  return double(n) * image.vx() * image.vy() * image.vz();
}

} // namespace

Volume_mesh image_tet_mesh(const std::string& input, const Tet_options& o, const Progress& progress, Run_report& r)
{
  {
    std::ifstream probe(input, std::ios::binary | std::ios::ate);
    if(!probe) throw Input_error("cannot open '" + input + "'");
    if(probe.tellg() <= 0) throw Input_error("'" + input + "' is an empty file");
  }
  if(o.field != "cross" && o.field != "identity") throw Input_error("a frame-field file (--field FILE) is for surfaces, not images");
  const auto threads = thread_limit(o.threads);
  CGAL::Image_3 image;
  if(!image.read(input.c_str()) || image.image() == nullptr || image.xdim() == 0 || image.ydim() == 0 ||
     image.zdim() == 0)
    throw Input_error("cannot read '" + input + "' as a 3D image (INRIMAGE .inr, .inr.gz)");
  if(!(image.vx() > 0 && image.vy() > 0 && image.vz() > 0) || !std::isfinite(image.vx() * image.vy() * image.vz()))
    throw Input_error("'" + input + "' has a voxel size that is not positive and finite");
  const double volume = labelled_volume(image);
  if(!(volume > 0)) throw Input_error("'" + input + "' has no voxel of non-zero label: nothing to mesh");
  const Image_domain domain = Image_domain::create_labeled_image_mesh_domain(image);
  Image_c3t3 c3t3;
  {
    const Stage stage(progress, "make_mesh_3");
    c3t3 = initial_mesh<Image_c3t3>(domain, volume, o.size, o.seed, stage);
    r.mesh_time = stage.time();
  }
  CGAL::Real_timer timer;
  timer.start();
  r.time_limit_reached = run_optimizer_chain(c3t3, domain, o, progress);
  r.optimize_time = timer.time();
  return to_volume_mesh(c3t3);
}

} // namespace internal
} // namespace vvm
