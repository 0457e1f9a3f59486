// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The standard field of anisotropic surface meshing: at each vertex of a
// triangle mesh the principal curvature directions (CGAL's jet fitting,
// Jet_fitting_3), lengths that keep the chordal error of an edge the same in
// every direction (l_i ~ 1 / sqrt|k_i|, bounded where the surface is flat and
// in their ratio), the directions smoothed where the curvatures are near equal
// (umbilics, flat parts: the direction is undefined there) and turned along
// the sharp edges at their vertices.

#ifndef CGAL_FRAME_FIELDS_PRINCIPAL_CURVATURE_FRAME_FIELD_H
#define CGAL_FRAME_FIELDS_PRINCIPAL_CURVATURE_FRAME_FIELD_H

#include <CGAL/Frame_fields/Surface_frame_field_3.h>
#include <CGAL/Frame_fields/internal/Triangle_mesh_features.h>
#include <CGAL/Frame_fields/internal/Triangle_soup.h>
#include <CGAL/Frame_fields/parameters.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * returns the principal curvature field of the triangle mesh (`points`, `faces`), for
 * `make_lattice_surface_mesh()`: at each vertex, the first axis along the direction of largest
 * curvature \f$ k_1 \f$, the lengths \f$ l_i = 1 / \sqrt{\max(|k_i|, k_0)} \f$ (the chordal error
 * \f$ k l^2 / 8 \f$ of an edge is then the same along both axes), \f$ k_0 \f$ the curvature of a
 * sphere of half the mesh's bounding box diagonal (flatter parts are meshed as flat), the ratio
 * \f$ l_2 / l_1 \f$ at most `maximum_anisotropy`, every length at most `maximum_size_ratio` times the
 * shortest, the lengths' logarithms smoothed over the neighbours (20 rounds) so that the size grades.
 *
 * The curvatures come from a degree-2 jet fitted (`CGAL::Monge_via_jet_fitting`) to the vertex's
 * rings (at least 16 vertices, at most 3 rings), on the side of each face: across a sharp edge
 * (faces' normals more than `features_angle` apart) the other side is not fitted. The directions
 * are then smoothed as lines (a direction and its opposite are one; for isotropic frames, as the
 * hexagonal lattice's directions, 60 degrees apart) in 20 rounds of averaging with the neighbours, each vertex held to its own direction in proportion to its anisotropy
 * \f$ (|k_1| - |k_2|) / (|k_1| + |k_2|) \f$; vertices on a sharp edge take the edge's direction.
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{Frame_fields::parameters::features_angle}
 *     \cgalParamDescription{an edge whose faces' normals make a larger angle, in degrees, is a sharp edge}
 *     \cgalParamType{`double`} \cgalParamDefault{60}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::maximum_anisotropy}
 *     \cgalParamDescription{the largest ratio of the two lengths; 1 gives isotropic frames aligned
 *       with the curvature directions}
 *     \cgalParamType{`double`, at least 1} \cgalParamDefault{3}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::maximum_size_ratio}
 *     \cgalParamDescription{the largest ratio of a length to the shortest first length: on organic
 *       shapes the curvature spans orders of magnitude, and a lattice graded that much is mostly
 *       defects; 1 gives one size everywhere}
 *     \cgalParamType{`double`, at least 1} \cgalParamDefault{4}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws std::invalid_argument on no face, an index out of range, a degenerate face, a
 *   non-finite coordinate, a maximum anisotropy or size ratio under 1
 */
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Surface_frame_field_3<GeomTraits>
principal_curvature_frame_field(const std::vector<typename GeomTraits::Point_3>& points,
                                const std::vector<std::array<std::size_t, 3>>& faces,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GeomTraits::Point_3 Point_3;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::string who = "principal_curvature_frame_field: ";
  const double features_angle = choose_parameter(get_parameter(np, internal_np::features_angle), 60.);
  const double anisotropy = choose_parameter(get_parameter(np, internal_np::maximum_anisotropy), 3.);
  if(!(anisotropy >= 1) || !std::isfinite(anisotropy)) throw std::invalid_argument(who + "the maximum anisotropy must be at least 1");
  const double size_ratio = choose_parameter(get_parameter(np, internal_np::maximum_size_ratio), 4.);
  if(!(size_ratio >= 1) || !std::isfinite(size_ratio)) throw std::invalid_argument(who + "the maximum size ratio must be at least 1");
  std::vector<Eigen::Vector3d> p;
  for(const Point_3& q : points) p.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
  const internal::Triangle_mesh_features mesh(p, faces, features_angle, "principal_curvature_frame_field");
  const std::vector<std::array<Eigen::Vector3d, 3>> corner_normal = mesh.corner_normals(faces);
  const std::vector<std::vector<std::size_t>>& around = mesh.vertex_faces();
  const std::vector<Eigen::Vector3d>& face_normal = mesh.face_normals();
  const std::size_t n = points.size();
  // the sharp edges at each vertex: their unit directions
  std::vector<std::vector<Eigen::Vector3d>> sharp(n);
  for(const auto& e : mesh.feature_edges()) {
    const Eigen::Vector3d d = (p[e.second] - p[e.first]).normalized();
    sharp[e.first].push_back(d);
    sharp[e.second].push_back(d);
  }
  // per vertex: the neighbours, and the side (the faces smoothly joined to a first face)
  std::vector<std::set<std::size_t>> ring(n);
  for(const auto& f : faces)
    for(int k = 0; k < 3; ++k) {
      ring[f[k]].insert(f[(k + 1) % 3]);
      ring[f[k]].insert(f[(k + 2) % 3]);
    }
  Eigen::Vector3d lo = p[0], hi = p[0];
  for(const Eigen::Vector3d& q : p) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const double k0 = 2. / std::max((hi - lo).norm(), 1e-300);

  std::vector<Eigen::Vector3d> d1(n, Eigen::Vector3d::Zero()), normal(n, Eigen::Vector3d::Zero());
  std::vector<double> k1(n, 0), k2(n, 0), weight(n, 0);
  std::vector<char> on_sharp_edge(n, 0);
  typedef CGAL::Simple_cartesian<double> Local;
  typedef CGAL::Monge_via_jet_fitting<Local> Fitting;
  for(std::size_t v = 0; v < n; ++v) {
    if(around[v].empty()) continue;
    const std::size_t f0 = around[v][0];
    for(std::size_t f : around[v])
      if(mesh.are_smoothly_joined(f, f0)) normal[v] += face_normal[f];
    normal[v].normalize();
    if(!sharp[v].empty()) { // along the sharp edge (the first one met)
      on_sharp_edge[v] = 1;
      d1[v] = sharp[v][0];
      weight[v] = 1;
      continue;
    }
    // the rings, on the vertex's side of the sharp edges
    std::vector<std::size_t> near = {v};
    std::set<std::size_t> seen = {v};
    for(int r = 0; r < 3 && near.size() < 16; ++r) {
      const std::vector<std::size_t> last = near;
      for(std::size_t u : last)
        for(std::size_t w : ring[u])
          if(seen.insert(w).second) near.push_back(w);
    }
    std::vector<Local::Point_3> fit_points;
    for(std::size_t u : near) fit_points.emplace_back(p[u][0], p[u][1], p[u][2]);
    try {
      Fitting fitting;
      typename Fitting::Monge_form form = fitting(fit_points.begin(), fit_points.end(), 2, 2);
      form.comply_wrt_given_normal(Local::Vector_3(normal[v][0], normal[v][1], normal[v][2]));
      const auto d = form.maximal_principal_direction();
      k1[v] = form.principal_curvatures(0);
      k2[v] = form.principal_curvatures(1);
      if(!std::isfinite(k1[v]) || !std::isfinite(k2[v])) k1[v] = k2[v] = 0;
      d1[v] = Eigen::Vector3d(d.x(), d.y(), d.z());
      const double a = std::abs(k1[v]), b = std::abs(k2[v]);
      weight[v] = a + b > 0 ? std::abs(a - b) / (a + b) : 0;
    } catch(...) { // too few or degenerate points: no direction of its own
      d1[v] = normal[v].unitOrthogonal();
    }
    if(std::abs(k2[v]) > std::abs(k1[v])) { // the first axis along the larger curvature
      std::swap(k1[v], k2[v]);
      d1[v] = normal[v].cross(d1[v]);
    }
  }
  // directions smoothed as lines, or, for isotropic frames, as the hexagonal lattice's six
  // directions: `u`'s direction turned to agree with `v`'s
  const bool isotropic = anisotropy == 1;
  auto matched = [&](std::size_t u, std::size_t v) {
    Eigen::Vector3d du = d1[u] - d1[u].dot(normal[v]) * normal[v];
    if(!(du.norm() > 0)) return Eigen::Vector3d(Eigen::Vector3d::Zero());
    return internal::matched_direction(du.normalized(), normal[v], d1[v], isotropic);
  };
  for(int round = 0; round < 20; ++round) {
    std::vector<Eigen::Vector3d> next = d1;
    for(std::size_t v = 0; v < n; ++v) {
      if(on_sharp_edge[v] || around[v].empty()) continue;
      Eigen::Vector3d sum = 4 * weight[v] * d1[v];
      for(std::size_t u : ring[v]) sum += matched(u, v);
      sum -= sum.dot(normal[v]) * normal[v];
      if(sum.norm() > 0) next[v] = sum.normalized();
    }
    d1.swap(next);
  }
  // lengths, their logarithms smoothed
  std::vector<double> log1(n), log2(n);
  for(std::size_t v = 0; v < n; ++v) {
    log1[v] = -0.5 * std::log(std::max(std::abs(k1[v]), k0));
    log2[v] = std::min(-0.5 * std::log(std::max(std::abs(k2[v]), k0)), log1[v] + std::log(anisotropy));
  }
  // the shortest first length sets the size range: no length over `size_ratio` times it
  const double shortest = *std::min_element(log1.begin(), log1.end());
  for(std::size_t v = 0; v < n; ++v) {
    log1[v] = std::min(log1[v], shortest + std::log(size_ratio));
    log2[v] = std::min(log2[v], shortest + std::log(size_ratio));
  }
  for(int round = 0; round < 20; ++round)
    for(std::vector<double>* l : {&log1, &log2}) {
      std::vector<double> next = *l;
      for(std::size_t v = 0; v < n; ++v) {
        if(ring[v].empty()) continue;
        double sum = (*l)[v];
        for(std::size_t u : ring[v]) sum += (*l)[u];
        next[v] = sum / double(ring[v].size() + 1);
      }
      *l = next;
    }
  std::vector<typename Surface_frame_field_3<GeomTraits>::Corner_frames> corners(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const std::size_t v = faces[f][k];
      corners[f].normals[k] = corner_normal[f][k];
      Tangent_frame& t = corners[f].frames[k];
      t.direction = d1[v];
      t.length_1 = std::exp(log1[v]);
      t.length_2 = std::min(std::exp(log2[v]), anisotropy * t.length_1);
    }
  return Surface_frame_field_3<GeomTraits>(points, faces, std::move(corners));
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * the same for the triangle mesh `tm` (a model of `FaceListGraph` whose faces are triangles),
 * its points those of the named parameter `vertex_point_map` (default: `tm`'s own); the field's
 * kernel is that of the points
 */
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto principal_curvature_frame_field(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef typename Kernel_traits<Point_3>::Kernel K;
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> faces;
  internal::triangle_soup(tm, CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                                 get_const_property_map(CGAL::vertex_point, tm)),
                          points, faces, "principal_curvature_frame_field");
  return principal_curvature_frame_field<K>(points, faces, np);
}

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_PRINCIPAL_CURVATURE_FRAME_FIELD_H
