// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The measures of a hex-dominant mesh (dissertation 4.4.3): cell counts and
// hex volume ratio, scaled Jacobians (eq. 4.5 in the field's space, and
// Verdict's), alignment error of the hexahedra's edges, inverted cells, and
// interfaces where the cells do not conform.

#ifndef CGAL_HEX_DOMINANT_MESHING_HEX_DOMINANT_STATISTICS_H
#define CGAL_HEX_DOMINANT_MESHING_HEX_DOMINANT_STATISTICS_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/cell_quality.h>
#include <CGAL/Hex_dominant_meshing/internal/Merge_candidates.h> // cell_faces()
#include <CGAL/tets_to_hex_dominant.h> // Hex_dominant_merge_report

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {

/// \ingroup PkgHexDominantMeshingRef
/// the measures of a `Hex_dominant_mesh_3`
struct Hex_dominant_statistics
{
  std::size_t number_of_hexahedra = 0, number_of_prisms = 0, number_of_pyramids = 0, number_of_tetrahedra = 0;
  double total_volume = 0;           ///< sum of the cell volumes (`cell_volume()`)
  double hexahedron_volume_percent = 0; ///< \f$ H_{vol}\% \f$
  double hexahedron_count_percent = 0, prism_count_percent = 0, pyramid_count_percent = 0, tetrahedron_count_percent = 0;
  /// scaled Jacobian of eq. 4.5 (8 corners, edges mapped by the frame inverse at the hexahedron's centroid)
  double scaled_jacobian_min = 0, scaled_jacobian_mean = 0;
  /// Verdict's hexahedron scaled Jacobian (8 corners and the centre's axes, isotropic)
  double verdict_scaled_jacobian_min = 0, verdict_scaled_jacobian_mean = 0;
  /// \f$ \overline{\theta_a} \f$: the hexahedra's edges (each once), mapped by the frame inverse at
  /// their midpoint, against the nearest of the six axis directions, in degrees
  double alignment_error_mean = 0;
  std::size_t number_of_inverted_cells = 0;       ///< a corner Jacobian \f$ \le 0 \f$
  std::size_t number_of_nonconforming_faces = 0;  ///< see `count_nonconforming_faces()`
};

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the volume of a cell: each face split into triangles around its centre (quads into
 * four), each triangle with the cell's centroid as a tetrahedron. It does not depend on how a
 * non-planar quad is split and is exact for planar faces.
 */
template <class Point_3>
double cell_volume(const Hex_dominant_mesh_3<Point_3>& mesh, const typename Hex_dominant_mesh_3<Point_3>::Cell& cell)
{
  const std::size_t n = cell.size();
  std::array<Eigen::Vector3d, 8> p;
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for(std::size_t k = 0; k < n; ++k) {
    const Point_3& q = mesh.points[cell.vertices[k]];
    p[k] = Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
    g += p[k];
  }
  g /= double(n);
  // faces are listed counter-clockwise seen from outside: the tet (g, a, b, c) is positive
  auto tet = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return (a - g).dot((b - g).cross(c - g)) / 6.;
  };
  const internal::Cell_faces& faces = internal::cell_faces(cell.type);
  double v = 0;
  for(const auto& f : faces.triangles) v += tet(p[std::size_t(f[0])], p[std::size_t(f[1])], p[std::size_t(f[2])]);
  for(const auto& f : faces.quads) {
    const Eigen::Vector3d m = 0.25 * (p[std::size_t(f[0])] + p[std::size_t(f[1])] + p[std::size_t(f[2])] + p[std::size_t(f[3])]);
    for(int k = 0; k < 4; ++k) v += tet(p[std::size_t(f[std::size_t(k)])], p[std::size_t(f[std::size_t((k + 1) & 3)])], m);
  }
  return v;
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the number of tet facets between two cells of `mesh` (made by `tets_to_hex_dominant()`,
 * which filled `report`) where the cells do not conform: the cells' faces through the facet
 * are two quads of different corners, or a quad and a triangle while the quad's other half
 * meets a quad. A quad met by the same quad, or by two triangles (the tets' own facets along
 * its diagonal), conforms, as in Sokolov et al. 2016.
 */
template <class Point_3>
std::size_t count_nonconforming_faces(const Hex_dominant_mesh_3<Point_3>& mesh, const Hex_dominant_merge_report& report)
{
  typedef std::array<std::size_t, 3> Tri;
  std::vector<std::size_t> cell_of(report.tets.size(), std::size_t(-1));
  for(std::size_t c = 0; c < report.cell_tets.size(); ++c)
    for(std::size_t t : report.cell_tets[c]) cell_of[t] = c;
  std::map<Tri, std::vector<std::size_t>> tets_of; // facet -> its tets
  for(std::size_t t = 0; t < report.tets.size(); ++t)
    for(int k = 0; k < 4; ++k) {
      Tri f;
      for(int j = 0, m = 0; j < 4; ++j)
        if(j != k) f[std::size_t(m++)] = report.tets[t][std::size_t(j)];
      std::sort(f.begin(), f.end());
      tets_of[f].push_back(t);
    }
  // the quad face of cell c through facet f, as sorted corners (empty: a triangle face)
  auto quad_through = [&](std::size_t c, const Tri& f) {
    const auto& cell = mesh.cells[c];
    for(const auto& q : internal::cell_faces(cell.type).quads) {
      std::array<std::size_t, 4> corners;
      for(int k = 0; k < 4; ++k) corners[std::size_t(k)] = cell.vertices[std::size_t(q[std::size_t(k)])];
      std::sort(corners.begin(), corners.end());
      if(std::includes(corners.begin(), corners.end(), f.begin(), f.end())) return std::vector<std::size_t>(corners.begin(), corners.end());
    }
    return std::vector<std::size_t>();
  };
  // the cell across facet f from cell c, or -1
  auto across = [&](std::size_t c, const Tri& f) {
    auto it = tets_of.find(f);
    if(it == tets_of.end()) return std::size_t(-1);
    for(std::size_t t : it->second)
      if(cell_of[t] != c) return cell_of[t];
    return std::size_t(-1);
  };
  std::size_t bad = 0;
  for(const auto& ft : tets_of) {
    if(ft.second.size() > 2) { ++bad; continue; }
    if(ft.second.size() < 2) continue;
    const std::size_t A = cell_of[ft.second[0]], B = cell_of[ft.second[1]];
    if(A == B) continue;
    const std::vector<std::size_t> qa = quad_through(A, ft.first), qb = quad_through(B, ft.first);
    if(qa.empty() && qb.empty()) continue;
    if(!qa.empty() && !qb.empty()) { bad += (qa != qb); continue; }
    // a quad against a triangle: the quad's other half must meet a triangle too
    const std::size_t Q = qa.empty() ? B : A;
    const std::vector<std::size_t>& q = qa.empty() ? qb : qa;
    bool other_ok = true;
    for(std::size_t t : ft.second) {
      if(cell_of[t] != Q) continue;
      // the other half: the quad's facets in Q's tets other than this one
      for(std::size_t u : report.cell_tets[Q])
        for(int k = 0; k < 4; ++k) {
          Tri g;
          for(int j = 0, m = 0; j < 4; ++j)
            if(j != k) g[std::size_t(m++)] = report.tets[u][std::size_t(j)];
          std::sort(g.begin(), g.end());
          if(g == ft.first || !std::includes(q.begin(), q.end(), g.begin(), g.end())) continue;
          const std::size_t C = across(Q, g);
          if(C != std::size_t(-1) && !quad_through(C, g).empty()) other_ok = false;
        }
    }
    bad += !other_ok;
  }
  return bad;
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the measures of `mesh`; `B` maps a point to the frame inverse there (empty: the
 * identity) for the scaled Jacobian of eq. 4.5 and the alignment error. The non-conforming
 * faces are counted if `report` (filled by the `tets_to_hex_dominant()` that made `mesh`) is given.
 */
template <class Point_3>
Hex_dominant_statistics hex_dominant_statistics(const Hex_dominant_mesh_3<Point_3>& mesh,
                                                const std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>& B = {},
                                                const Hex_dominant_merge_report* report = nullptr)
{
  Hex_dominant_statistics s;
  auto P = [&](std::size_t i) {
    const Point_3& q = mesh.points[i];
    return Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
  };
  auto frame = [&](const Eigen::Vector3d& x) {
    Eigen::Matrix3d b = B ? B(x) : Eigen::Matrix3d(Eigen::Matrix3d::Identity());
    return Eigen::Matrix3d(b.determinant() < 0 ? -b : b); // left-handed frames measure the same cells
  };
  double hex_volume = 0, sj_sum = 0, verdict_sum = 0, align_sum = 0;
  s.scaled_jacobian_min = s.verdict_scaled_jacobian_min = std::numeric_limits<double>::infinity();
  std::set<std::pair<std::size_t, std::size_t>> hex_edges;
  for(const auto& c : mesh.cells) {
    const double v = cell_volume(mesh, c);
    s.total_volume += v;
    s.number_of_inverted_cells += !(minimum_corner_jacobian(mesh, c) > 0);
    switch(c.type) {
      case Hex_dominant_cell_type::HEXAHEDRON: {
        ++s.number_of_hexahedra;
        hex_volume += v;
        std::array<Eigen::Vector3d, 8> p;
        Eigen::Vector3d g = Eigen::Vector3d::Zero();
        for(std::size_t k = 0; k < 8; ++k) g += (p[k] = P(c.vertices[k]));
        const double sj = hexahedron_scaled_jacobian(p, frame(g / 8.)), vj = verdict_hexahedron_scaled_jacobian(p);
        s.scaled_jacobian_min = (std::min)(s.scaled_jacobian_min, sj);
        s.verdict_scaled_jacobian_min = (std::min)(s.verdict_scaled_jacobian_min, vj);
        sj_sum += sj;
        verdict_sum += vj;
        for(std::size_t k = 0; k < 8; ++k)
          for(int n : hexahedron_corner_neighbors()[k]) {
            const std::size_t a = c.vertices[k], b = c.vertices[std::size_t(n)];
            hex_edges.emplace((std::min)(a, b), (std::max)(a, b));
          }
        break;
      }
      case Hex_dominant_cell_type::PRISM: ++s.number_of_prisms; break;
      case Hex_dominant_cell_type::PYRAMID: ++s.number_of_pyramids; break;
      default: ++s.number_of_tetrahedra;
    }
  }
  for(const auto& e : hex_edges) {
    const Eigen::Vector3d a = P(e.first), b = P(e.second);
    const Eigen::Vector3d u = frame(0.5 * (a + b)) * (b - a);
    const double m = u.cwiseAbs().maxCoeff(), n = u.norm();
    align_sum += n > 0 ? std::acos(std::clamp(m / n, -1., 1.)) * 180. / 3.14159265358979323846 : 90.;
  }
  const double cells = double(mesh.cells.size());
  if(cells > 0) {
    s.hexahedron_count_percent = 100. * double(s.number_of_hexahedra) / cells;
    s.prism_count_percent = 100. * double(s.number_of_prisms) / cells;
    s.pyramid_count_percent = 100. * double(s.number_of_pyramids) / cells;
    s.tetrahedron_count_percent = 100. * double(s.number_of_tetrahedra) / cells;
  }
  if(s.total_volume > 0) s.hexahedron_volume_percent = 100. * hex_volume / s.total_volume;
  if(s.number_of_hexahedra) {
    s.scaled_jacobian_mean = sj_sum / double(s.number_of_hexahedra);
    s.verdict_scaled_jacobian_mean = verdict_sum / double(s.number_of_hexahedra);
  } else
    s.scaled_jacobian_min = s.verdict_scaled_jacobian_min = 0;
  if(!hex_edges.empty()) s.alignment_error_mean = align_sum / double(hex_edges.size());
  if(report) s.number_of_nonconforming_faces = count_nonconforming_faces(mesh, *report);
  return s;
}

} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_HEX_DOMINANT_STATISTICS_H
