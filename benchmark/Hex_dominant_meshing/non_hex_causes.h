// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the hex volume goes: every tet of a hex-dominant mesh that is not in a
// hexahedron, classified twice.
// By what the candidate search (at any quality) offered it, the first that holds:
//  - a good hexahedron candidate (quality at least 0.5, or Q_bound) that overlaps a kept
//    hexahedron: a better one took some of its tets;
//  - a good candidate overlapping no kept hexahedron: the greedy selection refused it
//    because a quad of it would not conform;
//  - only poor candidates (between Q_bound and 0.5): the tets around it make a
//    hexahedron only by a distorted choice of corners;
//  - only candidates under Q_bound;
//  - no candidate.
// By where it is, the first that holds: a vertex on a singular edge of the field (the
// holonomy of the frames around the edge is not the identity), a vertex on the boundary
// (a facet of one tet, or between subdomains), an inner vertex off the lattice (one of
// its six axis directions has no neighbour within 0.3 l* of l* along it, in the field's
// space), elsewhere.
// Then two measures of the remedies: the kept hexahedra that two disjoint good
// candidates overlapping only them could replace (what a local search of the selection
// could gain), and the inner particles off the lattice by how fast the field turns at
// them (what the particles cannot follow).

#ifndef VVM_BENCHMARK_NON_HEX_CAUSES_H
#define VVM_BENCHMARK_NON_HEX_CAUSES_H

#include <CGAL/Frame_fields/internal/Singular_edges.h>
#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/internal/Merge_candidates.h>
#include <CGAL/Hex_dominant_meshing/internal/Tetrahedral_adjacency.h>
#include <CGAL/tets_to_hex_dominant.h>

#include <Eigen/Core>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace vvm_benchmark {

struct Non_hex_causes
{
  // what the candidate search offered the tet (the first that holds)
  enum Status { CONFLICT, NOT_CONFORMING, POOR, BELOW_Q_BOUND, NONE, NUMBER_OF_STATUSES };
  // where the tet is (the first that holds)
  enum Place { SINGULAR, BOUNDARY, OFF_LATTICE, ELSEWHERE, NUMBER_OF_PLACES };
  static const char* status_name(int c)
  {
    static const char* names[] = {"good candidate overlapping a kept hex", "good candidate, quads not conforming",
                                  "only poor candidates (quality < good)", "only candidates under Q_bound",
                                  "no candidate"};
    return names[c];
  }
  static constexpr int turning_bins = 8;         // of 2 degrees per l*, the last open
  double good_quality = 0;                       // the quality from which a candidate is called good
  double total_volume = 0;                       // of all tets
  double non_hex_volume = 0;
  // volume of the tets not in hexahedra per status and place
  std::array<std::array<double, NUMBER_OF_PLACES>, NUMBER_OF_STATUSES> volume{};
  // volume of the tets not in hexahedra per cell type: prism, pyramid, tetrahedron
  std::array<double, 3> volume_by_type{};
  // the volume of the tets not in hexahedra by their best hexahedron candidate's quality, in tenths
  std::array<double, 11> volume_by_best_quality{};
  std::size_t number_of_singular_edges = 0, number_of_off_lattice_vertices = 0, number_of_inner_vertices = 0;
  double spacing = 0, median_shortest_edge = 0;  // in the field's space
  std::size_t number_of_hexahedra = 0, number_of_swaps = 0; // kept; replaceable by two
  // inner particles (on, off the lattice) by the field's turning at them
  std::array<std::array<std::size_t, turning_bins>, 2> by_turning{};

  void print() const
  {
    auto percent = [&](double v) { return total_volume > 0 ? 100. * v / total_volume : 0.; };
    std::printf("where the hex volume goes: %.2f%% of the volume not in hexahedra (prisms %.2f, pyramids %.2f, tets %.2f);\n"
                "  %zu singular edges; %zu of %zu inner particles off the lattice (an axis neighbour missing within\n"
                "  0.3 l*; l* = %.4g, the median shortest edge %.3f l*, both in the field's space)\n",
                percent(non_hex_volume), percent(volume_by_type[0]), percent(volume_by_type[1]), percent(volume_by_type[2]),
                number_of_singular_edges, number_of_off_lattice_vertices, number_of_inner_vertices, spacing,
                spacing > 0 ? median_shortest_edge / spacing : 0.);
    std::printf("  %-40s %8s %8s %8s %8s %8s\n", "% of the volume: candidates / place", "singular", "boundary",
                "off-latt", "else", "all");
    for(int s = 0; s < NUMBER_OF_STATUSES; ++s) {
      double all = 0;
      std::printf("  %-40s", status_name(s));
      for(int p = 0; p < NUMBER_OF_PLACES; ++p) {
        std::printf(" %8.2f", percent(volume[std::size_t(s)][std::size_t(p)]));
        all += volume[std::size_t(s)][std::size_t(p)];
      }
      std::printf(" %8.2f\n", percent(all));
    }
    std::printf("  by the best candidate's quality (0.0-0.1, ..., 0.9-1.0):");
    for(int k = 0; k < 10; ++k) std::printf(" %.2f", percent(volume_by_best_quality[std::size_t(k)]));
    std::printf("; none %.2f\n", percent(volume_by_best_quality[10]));
    std::printf("  selection: %zu of %zu kept hexahedra could be traded for two disjoint good candidates (conformity not checked)\n",
                number_of_swaps, number_of_hexahedra);
    std::printf("  inner particles off the lattice, by the field's turning at them (degrees per l*, bins of 2):\n   ");
    for(int b = 0; b < turning_bins; ++b) {
      const std::size_t all = by_turning[0][std::size_t(b)] + by_turning[1][std::size_t(b)];
      std::printf(" %s%d: %zu/%zu", b + 1 < turning_bins ? "<" : ">=", b + 1 < turning_bins ? 2 * (b + 1) : 2 * b,
                  by_turning[1][std::size_t(b)], all);
    }
    std::printf("\n");
  }
};

namespace internal {

/// the rotation of the polar decomposition of `T`, made proper (a left-handed frame measures the same lattice)
inline Eigen::Matrix3d frame_rotation(const Eigen::Matrix3d& T)
{
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(T, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d R = svd.matrixU() * svd.matrixV().transpose();
  return R.determinant() < 0 ? Eigen::Matrix3d(-R) : R;
}

} // namespace internal

/// `mesh` and `merge` from `make_hex_dominant_mesh_3()` (or `tets_to_hex_dominant()`) with the
/// report; `T` the field's frame (columns: the lattice axes, scaled); `spacing` the lattice's
/// spacing l* in the field's space (0: the median of the shortest edge at each vertex); a
/// candidate is good from `good_quality` (or Q_bound if larger) on
template <class Point_3>
Non_hex_causes classify_non_hex_volume(const CGAL::Hex_dominant_mesh_3<Point_3>& mesh,
                                       const CGAL::Hex_dominant_meshing::Hex_dominant_merge_report& merge,
                                       const std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>& T,
                                       double q_bound, double spacing, double good_quality = 0.5)
{
  namespace HDI = CGAL::Hex_dominant_meshing::internal;
  typedef CGAL::Hex_dominant_cell_type Type;
  constexpr std::size_t no_cell = HDI::no_index;
  Non_hex_causes out;
  HDI::Tetrahedral_adjacency adj;
  for(const Point_3& p : mesh.points) adj.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  adj.tets = merge.tets;
  adj.subdomain.assign(adj.tets.size(), 0);
  const std::size_t n = adj.tets.size(), nv = adj.points.size();
  std::vector<int> tet_type(n, -1);      // -1 in a hexahedron, else 0 prism, 1 pyramid, 2 tet
  std::vector<std::size_t> hex_of(n, no_cell); // the kept hexahedron holding the tet
  for(std::size_t k = 0; k < mesh.cells.size(); ++k) {
    const Type type = mesh.cells[k].type;
    out.number_of_hexahedra += type == Type::HEXAHEDRON;
    for(std::size_t t : merge.cell_tets[k]) {
      adj.subdomain[t] = mesh.cells[k].subdomain_index;
      if(type == Type::HEXAHEDRON) hex_of[t] = k;
      tet_type[t] = type == Type::HEXAHEDRON ? -1 : type == Type::PRISM ? 0 : type == Type::PYRAMID ? 1 : 2;
    }
  }
  adj.build();
  std::vector<double> volume(n);
  for(std::size_t t = 0; t < n; ++t) {
    const auto& v = adj.tets[t];
    const Eigen::Vector3d& a = adj.points[v[0]];
    volume[t] = std::abs((adj.points[v[1]] - a).dot((adj.points[v[2]] - a).cross(adj.points[v[3]] - a))) / 6.;
    out.total_volume += volume[t];
    if(hex_of[t] == no_cell) out.non_hex_volume += volume[t];
  }

  // hexahedron candidates of every quality, against the kept hexahedra
  out.good_quality = (std::max)(q_bound, good_quality);
  auto B = [&T](const Eigen::Vector3d& x) { return Eigen::Matrix3d(T(x).inverse()); };
  const HDI::Merge_candidate_finder finder(adj, B, 0.);
  const std::vector<HDI::Merge_candidate> candidates = finder.find(true, false, false);
  std::vector<char> has_below(n, 0), has_poor(n, 0), has_conflict(n, 0), has_free(n, 0);
  std::vector<double> best_quality(n, -1.);
  std::vector<std::vector<std::size_t>> overlapping_only(mesh.cells.size()); // good candidates overlapping one kept hex
  for(std::size_t i = 0; i < candidates.size(); ++i) {
    const HDI::Merge_candidate& c = candidates[i];
    std::size_t overlapped = no_cell;
    bool several = false;
    for(int k = 0; k < c.number_of_tets; ++k) {
      const std::size_t h = hex_of[c.tets[std::size_t(k)]];
      if(h == no_cell) continue;
      several = several || (overlapped != no_cell && overlapped != h);
      overlapped = h;
    }
    if(c.quality >= out.good_quality && overlapped != no_cell && !several) overlapping_only[overlapped].push_back(i);
    for(int k = 0; k < c.number_of_tets; ++k) {
      const std::size_t t = c.tets[std::size_t(k)];
      best_quality[t] = (std::max)(best_quality[t], c.quality);
      if(c.quality < q_bound) has_below[t] = 1;
      else if(c.quality < out.good_quality) has_poor[t] = 1;
      else if(overlapped != no_cell) has_conflict[t] = 1;
      else has_free[t] = 1;
    }
  }
  for(const std::vector<std::size_t>& l : overlapping_only) {
    bool found = false;
    for(std::size_t a = 0; a < l.size() && !found; ++a)
      for(std::size_t b = a + 1; b < l.size() && !found; ++b) {
        const HDI::Merge_candidate &A = candidates[l[a]], &C = candidates[l[b]];
        found = std::none_of(A.tets.begin(), A.tets.begin() + A.number_of_tets, [&](std::size_t t) {
          return std::find(C.tets.begin(), C.tets.begin() + C.number_of_tets, t) != C.tets.begin() + C.number_of_tets;
        });
      }
    out.number_of_swaps += found;
  }

  // boundary vertices: of a facet with one tet, or between two subdomains
  std::vector<char> on_boundary(nv, 0);
  std::vector<std::array<std::size_t, 3>> walls;
  for(std::size_t t = 0; t < n; ++t)
    for(int k = 0; k < 4; ++k) {
      const std::size_t o = adj.neighbor[t][std::size_t(k)];
      if(o != HDI::no_index && adj.subdomain[o] == adj.subdomain[t]) continue;
      std::array<std::size_t, 3> f;
      for(int i = 1; i < 4; ++i) f[std::size_t(i - 1)] = adj.tets[t][std::size_t((k + i) & 3)];
      for(std::size_t v : f) on_boundary[v] = 1;
      walls.push_back(f);
    }

  // singular edges of the field sampled at the tets' centroids
  std::vector<Eigen::Matrix3d> frames(n);
  for(std::size_t t = 0; t < n; ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(std::size_t v : adj.tets[t]) c += adj.points[v];
    frames[t] = internal::frame_rotation(T(0.25 * c));
  }
  const auto singular = CGAL::Frame_fields::internal::singular_edges(adj.tets, frames, walls);
  out.number_of_singular_edges = singular.singular_edges.size();
  std::vector<char> on_singular(nv, 0);
  for(const auto& e : singular.singular_edges) on_singular[e[0]] = on_singular[e[1]] = 1;

  // inner particles off the lattice: a lattice axis direction with no neighbour near it
  std::vector<Eigen::Matrix3d> vertex_B(nv), vertex_R(nv);
  for(std::size_t v = 0; v < nv; ++v) {
    vertex_B[v] = B(adj.points[v]);
    vertex_R[v] = internal::frame_rotation(T(adj.points[v]));
  }
  std::vector<double> shortest(nv, 1e300);
  for(std::size_t v = 0; v < nv; ++v)
    for(std::size_t w : adj.vertex_neighbors[v])
      shortest[v] = (std::min)(shortest[v], (vertex_B[v] * (adj.points[w] - adj.points[v])).norm());
  std::nth_element(shortest.begin(), shortest.begin() + std::ptrdiff_t(nv / 2), shortest.end());
  out.median_shortest_edge = shortest[nv / 2];
  if(!(spacing > 0)) spacing = out.median_shortest_edge;
  out.spacing = spacing;
  std::vector<char> off_lattice(nv, 0);
  for(std::size_t v = 0; v < nv; ++v) {
    if(on_boundary[v]) continue;
    ++out.number_of_inner_vertices;
    int found = 0;
    for(int axis = 0; axis < 6; ++axis) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[axis / 2] = axis % 2 ? -1. : 1.;
      found += std::any_of(adj.vertex_neighbors[v].begin(), adj.vertex_neighbors[v].end(), [&](std::size_t w) {
        return (vertex_B[v] * (adj.points[w] - adj.points[v]) / spacing - e).norm() < 0.3;
      });
    }
    off_lattice[v] = found < 6;
    out.number_of_off_lattice_vertices += std::size_t(off_lattice[v]);
    // the field's turning: the largest rotation angle to a neighbour's matched frame, per l*
    double turning = 0;
    for(std::size_t w : adj.vertex_neighbors[v]) {
      const Eigen::Matrix3d D =
          (vertex_R[v] * CGAL::Frame_fields::internal::matching(vertex_R[v], vertex_R[w])).transpose() * vertex_R[w];
      const double degrees = std::acos(std::clamp((D.trace() - 1) / 2, -1., 1.)) * 180 / CGAL_PI;
      const double distance = (vertex_B[v] * (adj.points[w] - adj.points[v])).norm() / spacing;
      turning = (std::max)(turning, degrees / (std::max)(distance, 0.5));
    }
    ++out.by_turning[std::size_t(off_lattice[v])][std::size_t((std::min)(Non_hex_causes::turning_bins - 1, int(turning / 2)))];
  }

  for(std::size_t t = 0; t < n; ++t) {
    if(hex_of[t] != no_cell) continue;
    bool singular_vertex = false, boundary_vertex = false, off_vertex = false;
    for(std::size_t v : adj.tets[t]) {
      singular_vertex = singular_vertex || on_singular[v];
      boundary_vertex = boundary_vertex || on_boundary[v];
      off_vertex = off_vertex || off_lattice[v];
    }
    const int status = has_conflict[t] ? Non_hex_causes::CONFLICT
                     : has_free[t] ? Non_hex_causes::NOT_CONFORMING
                     : has_poor[t] ? Non_hex_causes::POOR
                     : has_below[t] ? Non_hex_causes::BELOW_Q_BOUND : Non_hex_causes::NONE;
    const int place = singular_vertex ? Non_hex_causes::SINGULAR
                    : boundary_vertex ? Non_hex_causes::BOUNDARY
                    : off_vertex ? Non_hex_causes::OFF_LATTICE : Non_hex_causes::ELSEWHERE;
    out.volume[std::size_t(status)][std::size_t(place)] += volume[t];
    out.volume_by_type[std::size_t(tet_type[t])] += volume[t];
    const double q = best_quality[t];
    out.volume_by_best_quality[q < 0 ? 10 : (std::min)(std::size_t(9), std::size_t(10 * q))] += volume[t];
  }
  return out;
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_NON_HEX_CAUSES_H
