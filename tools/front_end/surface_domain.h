// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the front end's meshing units share: the domain of a closed surface
// file, its make_mesh_3 meshes at a size or a vertex count, a complex as a
// Volume_mesh, and the progress of a stage.

#ifndef VVM_FRONT_END_SURFACE_DOMAIN_H
#define VVM_FRONT_END_SURFACE_DOMAIN_H

#include "frame_fields.h"
#include "vvm_front_end.h"

#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/GSM_mesh_optimization/mesh_with_vertex_count.h>
#include <CGAL/Local_thickness_3.h>
#include <CGAL/Thickness_sizing_field_3.h>

// make_mesh_3.h first: with CGAL_LINKED_WITH_TBB, CGAL 5.5.1's optimizer headers
// rely on TBB headers that only the mesher includes.
#include <CGAL/make_mesh_3.h>

#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <tbb/global_control.h>

#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>

namespace vvm {
namespace internal {

typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<Kernel, Surface_mesh> Surface_domain;
typedef CGAL::Mesh_triangulation_3<Surface_domain, CGAL::Default, CGAL::Sequential_tag>::type Surface_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Surface_tr, Surface_domain::Corner_index, Surface_domain::Curve_index>
    Surface_c3t3;

/// a closed surface, read from its file or built from its arrays, and its domain, sharp
/// edges protected
struct Surface_input
{
  Surface_mesh surface;
  double volume = 0;
  double features_angle = 0; // the domain's features are the edges sharper than this (0: none)
  std::unique_ptr<Surface_domain> domain;

  Surface_input(const Surface_source& source, double features_angle) : features_angle(features_angle)
  {
    namespace IO = CGAL::GSM_mesh_optimization::IO;
    if(!(features_angle >= 0 && features_angle < 180))
      throw Input_error("the features angle must be in [0, 180) degrees");
    try {
      if(source.is_file()) {
        volume = IO::read_closed_surface(source.path, surface);
      } else {
        std::vector<Point> points;
        points.reserve(source.points.size());
        for(const auto& p : source.points) points.emplace_back(p[0], p[1], p[2]);
        volume = IO::closed_surface_from_polygon_soup(points, source.polygons, surface);
      }
    } catch(const std::invalid_argument& e) {
      throw Input_error(e.what());
    }
    domain = std::make_unique<Surface_domain>(surface);
    if(features_angle > 0) domain->detect_features(features_angle);
  }
};

/// sets `report.run_time` to the time of a front-end call when the call ends, normally or not
class Run_timer
{
public:
  explicit Run_timer(Run_report& report) : report_(report) { timer_.start(); }
  Run_timer(const Run_timer&) = delete;
  ~Run_timer() { report_.run_time = timer_.time(); }

private:
  Run_report& report_;
  CGAL::Real_timer timer_;
};

/// a stage's timer and its progress events; the last one (fraction 1) when it ends
class Stage
{
public:
  Stage(Progress progress, std::string name) : progress_(std::move(progress)), name_(std::move(name)) { timer_.start(); }
  Stage(const Stage&) = delete;
  ~Stage()
  {
    try {
      // no "done" while an exception (e.g. the caller's request to stop) unwinds the stage
      if(progress_ && std::uncaught_exceptions() == 0) progress_({name_, 1, last_, timer_.time()});
    } catch(...) { // a destructor must not throw; the stage's end is only news
    }
  }
  void report(const std::string& detail, double fraction = -1) const
  {
    last_ = detail;
    if(progress_) progress_({name_, fraction, detail, timer_.time()});
  }
  double time() const { return timer_.time(); }

private:
  Progress progress_;
  std::string name_;
  mutable std::string last_;
  CGAL::Real_timer timer_;
};

/// the thread limit of a run (0: all cores)
inline std::unique_ptr<tbb::global_control> thread_limit(int threads)
{
  if(threads < 0) throw Input_error("the number of threads must be non-negative");
  if(threads == 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
}

inline void check_mesh_size(const Mesh_size& s, const char* count_name = "vertices")
{
  if(s.size > 0) {
    if(!std::isfinite(s.size)) throw Input_error("the size must be positive and finite");
    return;
  }
  if(s.size < 0 || std::isnan(s.size)) throw Input_error("the size must be positive and finite");
  if(s.vertices < 100 || s.vertices > 20000000)
    throw Input_error(std::string("the number of ") + count_name + " must be between 100 and 2e7");
}

typedef CGAL::Thickness_sizing_field_3<Kernel> Thickness_size;

/// `sizing` of the options: nothing (uniform), or the thickness sizing of the surface (its walls,
/// gaps, and the faces between its protected features), relative to its median over the surface
inline std::shared_ptr<const Thickness_size> relative_sizing(const std::string& sizing, const Surface_input& in)
{
  if(sizing == "uniform") return nullptr;
  if(sizing != "thickness") throw Input_error("unknown sizing '" + sizing + "' (known: uniform, thickness)");
  try {
    std::unordered_map<Surface_mesh::Edge_index, bool> is_feature;
    if(in.features_angle > 0)
      CGAL::Polygon_mesh_processing::detect_sharp_edges(in.surface, in.features_angle,
                                                        boost::make_assoc_property_map(is_feature));
    const Thickness_size size{CGAL::Local_thickness_3<Kernel>(
        in.surface, CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(is_feature)))};
    return std::make_shared<const Thickness_size>(size.scaled(1 / size.typical_size()));
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
}

/// make_mesh_3 with edge, facet and cell sizes `s` (times `relative`, if given), facet distance
/// a tenth of them, no optimizer (seeded)
template <class C3T3, class MeshDomain>
C3T3 mesh_with_size(const MeshDomain& domain, double s, unsigned int seed, const Thickness_size* relative = nullptr)
{
  namespace P = CGAL::parameters;
  CGAL::get_default_random() = CGAL::Random(seed);
  typedef CGAL::Mesh_criteria_3<typename C3T3::Triangulation> Criteria;
  if(relative != nullptr) {
    const Thickness_size size = relative->scaled(s), distance = relative->scaled(s / 10);
    Criteria criteria(P::edge_size = size, P::facet_angle = 25, P::facet_size = size, P::facet_distance = distance,
                      P::cell_radius_edge_ratio = 3, P::cell_size = size);
    return CGAL::make_mesh_3<C3T3>(domain, criteria, P::no_perturb(), P::no_exude());
  }
  Criteria criteria(P::edge_size = s, P::facet_angle = 25, P::facet_size = s, P::facet_distance = s / 10.,
                    P::cell_radius_edge_ratio = 3, P::cell_size = s);
  return CGAL::make_mesh_3<C3T3>(domain, criteria, P::no_perturb(), P::no_exude());
}

/// the make_mesh_3 mesh of the requested size or vertex count (within 5%); with `relative`, the
/// size is that field's, scaled
template <class C3T3, class MeshDomain>
C3T3 initial_mesh(const MeshDomain& domain, double volume, const Mesh_size& size, unsigned int seed, const Stage& stage,
                  const Thickness_size* relative = nullptr)
{
  const std::string what = relative ? "median size " : "edge size ";
  if(size.size > 0) {
    stage.report(what + std::to_string(size.size));
    C3T3 c3t3 = mesh_with_size<C3T3>(domain, size.size, seed, relative);
    if(c3t3.number_of_cells_in_complex() == 0) throw Input_error("the size is too large: the mesh has no cell");
    return c3t3;
  }
  int attempt = 0;
  auto mesh = [&](double s) {
    stage.report("attempt " + std::to_string(++attempt) + ", " + what + std::to_string(s));
    return mesh_with_size<C3T3>(domain, s, seed, relative);
  };
  try {
    return CGAL::GSM_mesh_optimization::mesh_with_vertex_count(mesh, size.vertices,
                                                               std::cbrt(volume / (0.2 * double(size.vertices))), 0.05)
        .c3t3;
  } catch(const std::invalid_argument& e) {
    throw Input_error(std::string("make_mesh_3: ") + e.what());
  }
}

/// the cells of the complex, with their subdomain indices as labels
template <class C3T3>
Volume_mesh to_volume_mesh(const C3T3& c3t3)
{
  Volume_mesh mesh;
  std::map<typename C3T3::Triangulation::Vertex_handle, std::size_t> index;
  const auto& tr = c3t3.triangulation();
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Volume_mesh::Cell cell;
    for(int i = 0; i < 4; ++i) {
      const auto inserted = index.emplace(c->vertex(i), mesh.points.size());
      if(inserted.second) {
        const auto& p = tr.point(c, i);
        mesh.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
      cell.vertices[std::size_t(i)] = inserted.first->second;
    }
    cell.subdomain_index = int(c3t3.subdomain_index(c));
    mesh.cells.push_back(cell);
  }
  return mesh;
}

} // namespace internal
} // namespace vvm

#endif // VVM_FRONT_END_SURFACE_DOMAIN_H
