// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality table of a volume mesh (the tets' dihedral angles and radius
// ratios as GSM measures them, every cell's scaled Jacobian and H_vol% as the
// hex-dominant package does), and a run's figures as one JSON line.

#include "vvm_front_end.h"

#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h>
#include <CGAL/Hex_dominant_meshing/cell_quality.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

namespace vvm {

Mesh_quality mesh_quality(const Volume_mesh& mesh)
{
  namespace GSM = CGAL::GSM_mesh_optimization;
  Mesh_quality q;
  GSM::Mesh_quality_statistics tets;
  std::set<std::size_t> used;
  std::set<int> labels;
  for(const Volume_mesh::Cell& c : mesh.cells) {
    for(std::size_t v : c) used.insert(v);
    labels.insert(c.subdomain_index);
    if(c.type != CGAL::Hex_dominant_cell_type::TETRAHEDRON) continue;
    const GSM::Tetrahedron_quality t = GSM::tetrahedron_quality(mesh.points[c.vertices[0]], mesh.points[c.vertices[1]],
                                                                mesh.points[c.vertices[2]], mesh.points[c.vertices[3]]);
    tets.add(t);
    const double angle = t.min_dihedral_angle();
    if(std::isfinite(angle)) ++q.min_dihedral_histogram[std::min<std::size_t>(17, std::size_t(std::max(0., angle) / 10.))];
  }
  tets.finish();
  q.vertices = used.size();
  q.cells = mesh.number_of_cells();
  q.labels.assign(labels.begin(), labels.end());
  q.tetrahedra = mesh.number_of_cells(CGAL::Hex_dominant_cell_type::TETRAHEDRON);
  q.hexahedra = mesh.number_of_cells(CGAL::Hex_dominant_cell_type::HEXAHEDRON);
  q.prisms = mesh.number_of_cells(CGAL::Hex_dominant_cell_type::PRISM);
  q.pyramids = mesh.number_of_cells(CGAL::Hex_dominant_cell_type::PYRAMID);
  if(q.tetrahedra > 0) {
    q.min_dihedral = tets.min_dihedral_angle;
    q.max_dihedral = tets.max_dihedral_angle;
    q.mean_min_dihedral = tets.mean_min_dihedral_angle;
    q.tets_under = tets.n_min_dihedral_below;
    q.min_radius_ratio = tets.min_radius_ratio;
    q.mean_radius_ratio = tets.mean_radius_ratio;
  }
  if(q.cells > 0) {
    const auto s = CGAL::Hex_dominant_meshing::hex_dominant_statistics(mesh);
    q.inverted = s.number_of_inverted_cells;
    q.hex_volume_percent = s.hexahedron_volume_percent;
    q.mean_hex_scaled_jacobian = q.hexahedra > 0 ? s.scaled_jacobian_mean : 0;
    const std::vector<double> sj = CGAL::Hex_dominant_meshing::cell_scaled_jacobians(mesh);
    q.min_scaled_jacobian = *std::min_element(sj.begin(), sj.end());
  }
  return q;
}

std::vector<std::pair<std::string, std::vector<double>>> cell_quality_arrays(const Volume_mesh& mesh)
{
  namespace GSM = CGAL::GSM_mesh_optimization;
  std::vector<double> angle(mesh.number_of_cells(), 0.);
  for(std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const Volume_mesh::Cell& c = mesh.cells[k];
    if(c.type == CGAL::Hex_dominant_cell_type::TETRAHEDRON)
      angle[k] = GSM::tetrahedron_quality(mesh.points[c.vertices[0]], mesh.points[c.vertices[1]],
                                          mesh.points[c.vertices[2]], mesh.points[c.vertices[3]])
                     .min_dihedral_angle();
  }
  return {{"min_dihedral_angle", angle},
          {"scaled_jacobian", CGAL::Hex_dominant_meshing::cell_scaled_jacobians(mesh)}};
}

namespace {

std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for(char c : s) {
    if(c == '"' || c == '\\') out += '\\';
    if(static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", c);
      out += code;
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// a number, or null if it is not finite (JSON has no NaN)
struct Json_number
{
  double value;
};

std::ostream& operator<<(std::ostream& os, const Json_number& n)
{
  if(std::isfinite(n.value)) return os << n.value;
  return os << "null";
}

} // namespace

std::string json_line(const Run_report& r, const Mesh_quality& quality)
{
  Mesh_quality q = quality;
  std::ostringstream os;
  os.precision(17);
  os << "{\"input\": " << json_string(r.input) << ", \"method\": " << json_string(r.method)
     << ", \"n_vertices\": " << q.vertices << ", \"n_cells\": " << q.cells << ", \"n_tets\": " << q.tetrahedra
     << ", \"n_hex\": " << q.hexahedra << ", \"n_prism\": " << q.prisms << ", \"n_pyramid\": " << q.pyramids
     << ", \"n_inverted\": " << q.inverted;
  if(q.tetrahedra > 0) {
    os << ", \"theta_min\": " << Json_number{q.min_dihedral} << ", \"theta_max\": " << Json_number{q.max_dihedral}
       << ", \"mean_min_dihedral\": " << Json_number{q.mean_min_dihedral};
    const int thresholds[4] = {10, 20, 30, 40};
    for(int i = 0; i < 4; ++i) os << ", \"n_min_dih_lt" << thresholds[i] << "\": " << q.tets_under[std::size_t(i)];
    os << ", \"gamma_min\": " << Json_number{q.min_radius_ratio} << ", \"gamma_mean\": " << Json_number{q.mean_radius_ratio};
  }
  os << ", \"hex_volume_percent\": " << Json_number{q.hex_volume_percent}
     << ", \"scaled_jacobian_min\": " << Json_number{q.min_scaled_jacobian}
     << ", \"hex_scaled_jacobian_mean\": " << Json_number{q.mean_hex_scaled_jacobian} << ", \"labels\": [";
  for(std::size_t i = 0; i < q.labels.size(); ++i) os << (i ? ", " : "") << q.labels[i];
  os << "], \"mesh_time_s\": " << r.mesh_time << ", \"opt_time_s\": " << r.optimize_time;
  if(r.run_time > 0) os << ", \"run_time_s\": " << r.run_time;
  os << ", \"time_limit_reached\": " << (r.time_limit_reached ? "true" : "false");
  if(r.input_vertices > 0) os << ", \"input_vertices\": " << r.input_vertices;
  if(r.boundary_distance_bound >= 0) os << ", \"boundary_distance_bound\": " << Json_number{r.boundary_distance_bound};
  if(r.boundary_hausdorff >= 0) os << ", \"boundary_hausdorff\": " << Json_number{r.boundary_hausdorff};
  os << "}\n";
  return os.str();
}

std::string json_line(const Run_report& r, const Surface_quality& q)
{
  std::ostringstream os;
  os.precision(17);
  os << "{\"input\": " << json_string(r.input)
     << ", \"model\": " << json_string(std::filesystem::path(r.input).stem().string())
     << ", \"method\": " << json_string(r.method) << ", \"field\": " << json_string(r.field)
     << ", \"n_vertices\": " << q.number_of_vertices << ", \"n_faces\": " << q.number_of_faces
     << ", \"r6\": " << Json_number{q.r6} << ", \"xi_mean\": " << Json_number{q.xi_mean}
     << ", \"xi_min\": " << Json_number{q.xi_min} << ", \"min_angle_metric_deg\": " << Json_number{q.min_angle}
     << ", \"mean_min_angle_metric_deg\": " << Json_number{q.mean_min_angle}
     << ", \"alignment_error_mean_deg\": " << Json_number{q.alignment_error_mean}
     << ", \"is_closed_manifold\": " << (q.is_closed_manifold ? "true" : "false") << ", \"time_s\": " << r.optimize_time
     << ", \"field_time_s\": " << r.mesh_time << ", \"run_time_s\": " << r.run_time
     << ", \"time_limit_reached\": " << (r.time_limit_reached ? "true" : "false") << "}\n";
  return os.str();
}

} // namespace vvm
