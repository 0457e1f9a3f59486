// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quality measures of hex-dominant meshes (dissertation section 4.4.2,
// 4.4.3): the scaled Jacobian of eq. 4.5 in the frame field's space and
// Verdict's isotropic one, the hex merging quality Q_hex = Q_p * min Q_o, and
// the corner Jacobians that tell an inverted cell. Points are in VTK order
// (CGAL/Hex_dominant_mesh_3.h).

#ifndef CGAL_HEX_DOMINANT_MESHING_CELL_QUALITY_H
#define CGAL_HEX_DOMINANT_MESHING_CELL_QUALITY_H

#include <CGAL/Hex_dominant_mesh_3.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {

/// \ingroup PkgHexDominantMeshingRef
/// the three edge neighbours of each corner of a VTK hexahedron, in right-handed order
inline const std::array<std::array<int, 3>, 8>& hexahedron_corner_neighbors()
{
  static const std::array<std::array<int, 3>, 8> n = {{{{1, 3, 4}}, {{2, 0, 5}}, {{3, 1, 6}}, {{0, 2, 7}},
                                                       {{7, 5, 0}}, {{4, 6, 1}}, {{5, 7, 2}}, {{6, 4, 3}}}};
  return n;
}

/// \ingroup PkgHexDominantMeshingRef
/// the six quad faces of a VTK hexahedron, each counter-clockwise seen from outside
inline const std::array<std::array<int, 4>, 6>& hexahedron_faces()
{
  static const std::array<std::array<int, 4>, 6> f = {{{{0, 3, 2, 1}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}},
                                                       {{1, 2, 6, 5}}, {{2, 3, 7, 6}}, {{3, 0, 4, 7}}}};
  return f;
}

/// \ingroup PkgHexDominantMeshingRef
/// the three edge neighbours of each corner of a VTK prism (wedge), in right-handed order
inline const std::array<std::array<int, 3>, 6>& prism_corner_neighbors()
{
  static const std::array<std::array<int, 3>, 6> n = {
      {{{1, 2, 3}}, {{2, 0, 4}}, {{0, 1, 5}}, {{5, 4, 0}}, {{3, 5, 1}}, {{4, 3, 2}}}};
  return n;
}

/// \ingroup PkgHexDominantMeshingRef
/// the three quad faces of a VTK prism, each counter-clockwise seen from outside
inline const std::array<std::array<int, 4>, 3>& prism_quad_faces()
{
  static const std::array<std::array<int, 4>, 3> f = {{{{0, 1, 4, 3}}, {{1, 2, 5, 4}}, {{2, 0, 3, 5}}}};
  return f;
}

/// \ingroup PkgHexDominantMeshingRef
/// the three edge neighbours of each base corner of a VTK pyramid (two base edges, then the apex)
inline const std::array<std::array<int, 3>, 4>& pyramid_corner_neighbors()
{
  static const std::array<std::array<int, 3>, 4> n = {{{{1, 3, 4}}, {{2, 0, 4}}, {{3, 1, 4}}, {{0, 2, 4}}}};
  return n;
}

/// \ingroup PkgHexDominantMeshingRef
/// \f$ \det[e_1, e_2, e_3] / (|e_1| |e_2| |e_3|) \f$: 1 for orthogonal edges, negative if inverted
inline double corner_scaled_jacobian(const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, const Eigen::Vector3d& e3)
{
  const double n = e1.norm() * e2.norm() * e3.norm();
  if(!(n > 0)) return -1;
  return e1.dot(e2.cross(e3)) / n;
}

namespace internal {

template <std::size_t N, std::size_t C>
double min_corner_scaled_jacobian(const std::array<Eigen::Vector3d, N>& p,
                                  const std::array<std::array<int, 3>, C>& neighbors, const Eigen::Matrix3d& B)
{
  double q = std::numeric_limits<double>::infinity();
  for(std::size_t c = 0; c < C; ++c) {
    const auto& n = neighbors[c];
    q = (std::min)(q, corner_scaled_jacobian(B * (p[std::size_t(n[0])] - p[c]), B * (p[std::size_t(n[1])] - p[c]),
                                             B * (p[std::size_t(n[2])] - p[c])));
  }
  return q;
}

// Q_p of one quad: 1 - 2/pi acos(min n_i . n_j) over the normals at its four corners
inline double quad_planarity(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                             const Eigen::Vector3d& d)
{
  const std::array<Eigen::Vector3d, 4> q = {{a, b, c, d}};
  std::array<Eigen::Vector3d, 4> n;
  for(int i = 0; i < 4; ++i) {
    n[std::size_t(i)] = (q[std::size_t((i + 1) & 3)] - q[std::size_t(i)]).cross(q[std::size_t((i + 3) & 3)] - q[std::size_t(i)]);
    const double l = n[std::size_t(i)].norm();
    if(!(l > 0)) return 0;
    n[std::size_t(i)] /= l;
  }
  double m = 1;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j) m = (std::min)(m, n[std::size_t(i)].dot(n[std::size_t(j)]));
  return 1. - 2. / 3.14159265358979323846 * std::acos(std::clamp(m, -1., 1.));
}

// Q_o of a hexahedron's corner with edges a, b, d (right-handed): the mean ratio
// 12 (3V)^(2/3) / sum l^2 of their tetrahedron over that of a cube's corner, capped at 1; 0 if inverted
inline double corner_orthogonality(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& d)
{
  static const double cube_corner = 12. * std::pow(0.5, 2. / 3.) / 9.;
  const double v6 = a.dot(b.cross(d));
  if(!(v6 > 0)) return 0;
  const double l2 = a.squaredNorm() + b.squaredNorm() + d.squaredNorm() + (a - b).squaredNorm() + (b - d).squaredNorm() +
                    (d - a).squaredNorm();
  return (std::min)(1., 12. * std::pow(0.5 * v6, 2. / 3.) / l2 / cube_corner);
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the scaled Jacobian of eq. 4.5 of a hexahedron (VTK order): the minimum over its 8
 * corners of \f$ \det[v'_1, v'_2, v'_3] / (|v'_1| |v'_2| |v'_3|) \f$, the corner's three edges
 * mapped to the frame field's space by `B` (\f$ v' = B v \f$; the identity for the isotropic
 * measure). Unlike eq. 4.5 it keeps the sign, so that an inverted corner shows negative.
 */
inline double hexahedron_scaled_jacobian(const std::array<Eigen::Vector3d, 8>& p,
                                         const Eigen::Matrix3d& B = Eigen::Matrix3d::Identity())
{
  return internal::min_corner_scaled_jacobian(p, hexahedron_corner_neighbors(), B);
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns Verdict's hexahedron scaled Jacobian (isotropic): the minimum of the 8 corners'
 * scaled Jacobians and that of the centre's principal axes
 * \f$ x_1 = (p_1 - p_0) + (p_2 - p_3) + (p_5 - p_4) + (p_6 - p_7) \f$ and likewise \f$ x_2, x_3 \f$.
 */
inline double verdict_hexahedron_scaled_jacobian(const std::array<Eigen::Vector3d, 8>& p)
{
  const Eigen::Vector3d x1 = (p[1] - p[0]) + (p[2] - p[3]) + (p[5] - p[4]) + (p[6] - p[7]);
  const Eigen::Vector3d x2 = (p[3] - p[0]) + (p[2] - p[1]) + (p[7] - p[4]) + (p[6] - p[5]);
  const Eigen::Vector3d x3 = (p[4] - p[0]) + (p[5] - p[1]) + (p[6] - p[2]) + (p[7] - p[3]);
  return (std::min)(hexahedron_scaled_jacobian(p), corner_scaled_jacobian(x1, x2, x3));
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns \f$ Q_{hex} = Q_p \min_c Q_o(c) \f$ (dissertation 4.4.2), in the space mapped by `B`:
 * \f$ Q_p \f$ the planarity of the worst of the six quad faces, \f$ Q_o(c) \f$ the mean ratio
 * \f$ 12 (3V)^{2/3} / \sum l_{ij}^2 \f$ of the tetrahedron of corner \f$ c \f$ and its three
 * neighbours, divided by that of a cube's corner (0.84) so that a cube scores 1, capped at 1.
 * Returns 0 if a corner is inverted.
 */
inline double hexahedron_merging_quality(const std::array<Eigen::Vector3d, 8>& x,
                                         const Eigen::Matrix3d& B = Eigen::Matrix3d::Identity())
{
  std::array<Eigen::Vector3d, 8> p;
  for(std::size_t i = 0; i < 8; ++i) p[i] = B * x[i];
  double q_o = 1;
  for(std::size_t c = 0; c < 8; ++c) {
    const auto& n = hexahedron_corner_neighbors()[c];
    q_o = (std::min)(q_o, internal::corner_orthogonality(p[std::size_t(n[0])] - p[c], p[std::size_t(n[1])] - p[c],
                                                         p[std::size_t(n[2])] - p[c]));
    if(!(q_o > 0)) return 0;
  }
  double q_p = 1;
  for(const auto& f : hexahedron_faces())
    q_p = (std::min)(q_p, internal::quad_planarity(p[std::size_t(f[0])], p[std::size_t(f[1])], p[std::size_t(f[2])],
                                                   p[std::size_t(f[3])]));
  return q_p * q_o;
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the merging quality of a prism (VTK order) in the space mapped by `B`: the planarity
 * of its worst quad face times the smallest corner scaled Jacobian divided by that of a right
 * prism over an equilateral triangle (\f$ \sin 60^\circ \f$), capped at 1; 0 if a corner is inverted.
 */
inline double prism_merging_quality(const std::array<Eigen::Vector3d, 6>& x,
                                    const Eigen::Matrix3d& B = Eigen::Matrix3d::Identity())
{
  std::array<Eigen::Vector3d, 6> p;
  for(std::size_t i = 0; i < 6; ++i) p[i] = B * x[i];
  const double sj = internal::min_corner_scaled_jacobian(p, prism_corner_neighbors(), Eigen::Matrix3d::Identity());
  if(!(sj > 0)) return 0;
  double q_p = 1;
  for(const auto& f : prism_quad_faces())
    q_p = (std::min)(q_p, internal::quad_planarity(p[std::size_t(f[0])], p[std::size_t(f[1])], p[std::size_t(f[2])],
                                                   p[std::size_t(f[3])]));
  return q_p * (std::min)(1., sj / std::sqrt(0.75));
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the merging quality of a pyramid (VTK order) in the space mapped by `B`: the
 * planarity of its base times the smallest scaled Jacobian of its base corners divided by that
 * of the pyramid with all edges equal (\f$ 1/\sqrt 2 \f$), capped at 1; 0 if a corner is inverted.
 */
inline double pyramid_merging_quality(const std::array<Eigen::Vector3d, 5>& x,
                                      const Eigen::Matrix3d& B = Eigen::Matrix3d::Identity())
{
  std::array<Eigen::Vector3d, 5> p;
  for(std::size_t i = 0; i < 5; ++i) p[i] = B * x[i];
  const double sj = internal::min_corner_scaled_jacobian(p, pyramid_corner_neighbors(), Eigen::Matrix3d::Identity());
  if(!(sj > 0)) return 0;
  return internal::quad_planarity(p[0], p[1], p[2], p[3]) * (std::min)(1., sj * std::sqrt(2.));
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the smallest corner Jacobian determinant \f$ \det[e_1, e_2, e_3] \f$ of a cell of
 * `mesh` (tetrahedron: its orientation; pyramid: its four base corners), Euclidean: a cell is
 * inverted if it is \f$ \le 0 \f$.
 */
template <class Point_3>
double minimum_corner_jacobian(const Hex_dominant_mesh_3<Point_3>& mesh, const typename Hex_dominant_mesh_3<Point_3>::Cell& cell)
{
  auto P = [&](int k) {
    const Point_3& q = mesh.points[cell.vertices[std::size_t(k)]];
    return Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
  };
  auto det = [&](int c, int a, int b, int d) { return (P(a) - P(c)).dot((P(b) - P(c)).cross(P(d) - P(c))); };
  double m = std::numeric_limits<double>::infinity();
  switch(cell.type) {
    case Hex_dominant_cell_type::TETRAHEDRON: return det(0, 1, 2, 3);
    case Hex_dominant_cell_type::HEXAHEDRON:
      for(int c = 0; c < 8; ++c) {
        const auto& n = hexahedron_corner_neighbors()[std::size_t(c)];
        m = (std::min)(m, det(c, n[0], n[1], n[2]));
      }
      return m;
    case Hex_dominant_cell_type::PRISM:
      for(int c = 0; c < 6; ++c) {
        const auto& n = prism_corner_neighbors()[std::size_t(c)];
        m = (std::min)(m, det(c, n[0], n[1], n[2]));
      }
      return m;
    default:
      for(int c = 0; c < 4; ++c) {
        const auto& n = pyramid_corner_neighbors()[std::size_t(c)];
        m = (std::min)(m, det(c, n[0], n[1], n[2]));
      }
      return m;
  }
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 * returns the scaled Jacobian of each cell of `mesh` in the frame field's space, for a
 * per-cell output such as `IO::write_VTU()`: the smallest corner value of eq. 4.5,
 * \f$ \det[B e_1, B e_2, B e_3] / (|B e_1| |B e_2| |B e_3|) \f$, over the corners where three
 * edges meet (every corner of a hexahedron, prism or tetrahedron, the base corners of a
 * pyramid), `B` the frame inverse at the cell's centroid (empty: the identity, the Euclidean
 * measure). A left-handed `B` counts as its negation, as in `hex_dominant_statistics()`.
 */
template <class Point_3>
std::vector<double> cell_scaled_jacobians(const Hex_dominant_mesh_3<Point_3>& mesh,
                                          const std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>& B = {})
{
  static const std::array<std::array<int, 3>, 4> tetrahedron_corner_neighbors = {
      {{{1, 2, 3}}, {{2, 0, 3}}, {{0, 1, 3}}, {{0, 2, 1}}}};
  std::vector<double> sj;
  sj.reserve(mesh.number_of_cells());
  for(const auto& c : mesh.cells) {
    std::array<Eigen::Vector3d, 8> p;
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for(std::size_t k = 0; k < c.size(); ++k) {
      const Point_3& q = mesh.points[c.vertices[k]];
      g += (p[k] = Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())));
    }
    Eigen::Matrix3d b = B ? B(g / double(c.size())) : Eigen::Matrix3d(Eigen::Matrix3d::Identity());
    if(b.determinant() < 0) b = -b;
    switch(c.type) {
      case Hex_dominant_cell_type::HEXAHEDRON:
        sj.push_back(internal::min_corner_scaled_jacobian(p, hexahedron_corner_neighbors(), b));
        break;
      case Hex_dominant_cell_type::PRISM:
        sj.push_back(internal::min_corner_scaled_jacobian(p, prism_corner_neighbors(), b));
        break;
      case Hex_dominant_cell_type::PYRAMID:
        sj.push_back(internal::min_corner_scaled_jacobian(p, pyramid_corner_neighbors(), b));
        break;
      default: sj.push_back(internal::min_corner_scaled_jacobian(p, tetrahedron_corner_neighbors, b));
    }
  }
  return sj;
}

} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_CELL_QUALITY_H
