// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// vvm::optimize_tet_mesh: GSM on the tetrahedra of a mesh made by any mesher,
// its boundary and label interfaces the surfaces its vertices slide on.

#include "optimizer_chain.h"

#include <CGAL/GSM_mesh_optimization/Complex_from_tetrahedra_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <array>
#include <map>

namespace vvm {
namespace {

// the facets of exactly one tetrahedron, as a mesh of separate triangles
internal::Surface_mesh boundary_of(const Volume_mesh& mesh)
{
  std::map<std::array<std::size_t, 3>, int> count;
  for(const Volume_mesh::Cell& c : mesh.cells)
    for(int i = 0; i < 4; ++i) {
      std::array<std::size_t, 3> f{c.vertices[std::size_t((i + 1) & 3)], c.vertices[std::size_t((i + 2) & 3)],
                                   c.vertices[std::size_t((i + 3) & 3)]};
      std::sort(f.begin(), f.end());
      ++count[f];
    }
  internal::Surface_mesh sm;
  for(const auto& fc : count)
    if(fc.second == 1)
      sm.add_face(sm.add_vertex(mesh.points[fc.first[0]]), sm.add_vertex(mesh.points[fc.first[1]]),
                  sm.add_vertex(mesh.points[fc.first[2]]));
  return sm;
}

double mean_edge_length(const internal::Surface_mesh& sm)
{
  double sum = 0;
  for(auto e : sm.edges()) sum += std::sqrt(CGAL::squared_distance(sm.point(sm.vertex(e, 0)), sm.point(sm.vertex(e, 1))));
  return sm.number_of_edges() > 0 ? sum / double(sm.number_of_edges()) : 0.;
}

// two-sided, on a grid of about 100,000 points on each boundary
double hausdorff_distance(const internal::Surface_mesh& a, const internal::Surface_mesh& b)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const double spacing = std::sqrt(PMP::area(a) / 1e5);
  const auto np = PMP::parameters::use_grid_sampling(true).grid_spacing(spacing);
  return (std::max)(PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(a, b, np),
                    PMP::approximate_Hausdorff_distance<CGAL::Parallel_if_available_tag>(b, a, np));
}

} // namespace

Volume_mesh optimize_tet_mesh(const Volume_mesh& mesh, const Optimize_options& o, const Progress& progress,
                              Run_report* report)
{
  typedef CGAL::GSM_mesh_optimization::Complex_from_tetrahedra_3<Kernel> Complex;
  Run_report local;
  Run_report& r = report ? *report : local;
  const internal::Run_timer run_timer(r);
  r.method = "gsm";
  if(!(o.features_angle >= 0 && o.features_angle <= 180))
    throw Input_error("the features angle must be in [0, 180] degrees");
  if(!(o.boundary_distance < HUGE_VAL)) throw Input_error("the boundary distance must be finite");
  std::vector<Complex::Tetrahedron> tets;
  std::vector<int> labels;
  std::size_t others = 0;
  for(const Volume_mesh::Cell& c : mesh.cells) {
    if(c.type != CGAL::Hex_dominant_cell_type::TETRAHEDRON) {
      ++others;
      continue;
    }
    tets.push_back({c.vertices[0], c.vertices[1], c.vertices[2], c.vertices[3]});
    labels.push_back(c.subdomain_index);
  }
  if(others > 0)
    throw Input_error("the mesh has " + std::to_string(others) +
                      " cells that are not tetrahedra; optimize improves tetrahedral meshes");
  const auto threads = internal::thread_limit(o.threads);
  std::unique_ptr<Complex> complex;
  internal::Surface_mesh input_boundary;
  {
    const internal::Stage stage(progress, "import");
    try {
      // 0: no sharp edge kept, as for the other commands (only where surfaces meet)
      complex = std::make_unique<Complex>(mesh.points, tets, labels, o.features_angle > 0 ? o.features_angle : 180.);
    } catch(const std::invalid_argument& e) {
      throw Input_error(e.what());
    }
    r.input_vertices = complex->c3t3().triangulation().number_of_vertices();
    input_boundary = boundary_of(mesh);
    r.boundary_distance_bound =
        o.boundary_distance >= 0 ? o.boundary_distance : 0.01 * mean_edge_length(input_boundary);
    stage.report(std::to_string(complex->number_of_surface_patches()) + " surface patches, " +
                 std::to_string(complex->number_of_curves()) + " feature curves");
    r.mesh_time = stage.time();
  }
  CGAL::Real_timer timer;
  timer.start();
  try {
    r.time_limit_reached = internal::run_gsm(complex->c3t3(), complex->domain(), o.threads, o.seed, o.time_limit,
                                             progress, {}, r.boundary_distance_bound, o.fixed_boundary);
  } catch(const std::invalid_argument& e) {
    throw Input_error(e.what());
  }
  r.optimize_time = timer.time();
  std::vector<Point> points;
  std::vector<int> out_labels;
  complex->get_tetrahedra(points, tets, out_labels);
  Volume_mesh out;
  out.points = std::move(points);
  out.cells.resize(tets.size());
  for(std::size_t k = 0; k < tets.size(); ++k) {
    std::copy(tets[k].begin(), tets[k].end(), out.cells[k].vertices.begin());
    out.cells[k].subdomain_index = out_labels[k];
  }
  r.boundary_hausdorff = hausdorff_distance(input_boundary, boundary_of(out));
  return out;
}

} // namespace vvm
