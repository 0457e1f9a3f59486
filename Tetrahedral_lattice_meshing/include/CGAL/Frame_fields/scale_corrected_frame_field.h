// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The scale correction of a frame field (dissertation 4.4.3, Fig. 4.16, for
// any field): where the axes turn, a lattice of constant spacing cannot follow
// them and leaves gaps of a fraction of a layer; lengths that grow as the axes
// fan out let whole layers follow them.

#ifndef CGAL_FRAME_FIELDS_SCALE_CORRECTED_FRAME_FIELD_H
#define CGAL_FRAME_FIELDS_SCALE_CORRECTED_FRAME_FIELD_H

#include <CGAL/Frame_fields/Discrete_frame_field_3.h>
#include <CGAL/Frame_fields/internal/Singular_edges.h>
#include <CGAL/Frame_fields/parameters.h>
#include <CGAL/VVM/internal/Eigen_conversion.h>

#include <CGAL/Named_function_parameters.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Frame_fields {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * The output of `scale_corrected_frame_field()`.
 *
 * \tparam GeomTraits a model of `Kernel`
 */
template <class GeomTraits>
struct Scale_corrected_frame_field_3
{
  /// the corrected field: the input's mesh, each frame's axis \f$ i \f$ times \f$ e^{s_i} \f$
  Discrete_frame_field_3<GeomTraits> field;
  /// per vertex, the logarithms \f$ s_i \f$ of the three axes' scales, in the order of the input
  /// frame's columns; their volume-weighted mean is 0
  std::vector<Eigen::Vector3d> log_scales;
  /// the field's departure from a lattice's, before and after the correction: the root mean square
  /// over the mesh's triangles (weighted by \f$ area^{3/2} \f$, the volume each stands for) and the
  /// axes of \f$ |(\nabla \times b_i) \cdot n| / |b_i|^2 \f$ (the circulation of \f$ b_i \f$ around
  /// the triangle over its area), \f$ b_i \f$
  /// the rows of \f$ B = T^{-1} \f$ (the turn of an axis, in radians, over one length of the
  /// axis: over a lattice step if the frames are as long as the lattice's edges); 0 where a
  /// lattice fits exactly
  double integrability_error_before = 0;
  double integrability_error_after = 0; ///< see `integrability_error_before`
  /// the scales held to `maximum_size_ratio`
  std::size_t number_of_clamped_scales = 0;
};

namespace internal {

/// the columns of `T` made unit: the rotation the cube matching compares
inline Eigen::Matrix3d unit_axes(const Eigen::Matrix3d& T)
{
  Eigen::Matrix3d R = T;
  for(int i = 0; i < 3; ++i) R.col(i).normalize();
  return R;
}

/// the rows of `B_k` (the inverse of `T_k`) relabelled as the axes of the unit frame `R0`:
/// with \f$ R_k \approx R_0 P \f$, they are \f$ P B_k \f$; `axis[j]` is the axis of `T_k`
/// matched with axis `j` of `R0`
inline Eigen::Matrix3d matched_rows(const Eigen::Matrix3d& R0, const Eigen::Matrix3d& T_k, const Eigen::Matrix3d& B_k,
                                    std::array<int, 3>& axis)
{
  const Eigen::Matrix3d& P = matching(R0, unit_axes(T_k));
  for(int j = 0; j < 3; ++j)
    for(int a = 0; a < 3; ++a)
      if(P(j, a) != 0) axis[std::size_t(j)] = a;
  return P * B_k;
}

/// the faces (or, with `N` = 2, the edges) of the cells, each once
template <std::size_t N>
std::vector<std::array<std::size_t, N>> cell_simplices(const std::vector<std::array<std::size_t, 4>>& cells)
{
  std::vector<std::array<std::size_t, N>> out;
  for(const auto& c : cells) {
    std::array<std::size_t, 4> v = c;
    std::sort(v.begin(), v.end());
    for(int mask = 0; mask < 16; ++mask) {
      std::array<std::size_t, N> s;
      std::size_t n = 0;
      for(std::size_t k = 0; k < 4; ++k)
        if(mask >> k & 1) {
          if(n == N) { n = N + 1; break; }
          s[n++] = v[k];
        }
      if(n == N) out.push_back(s);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// a triangle of the mesh with its corners' rows of B relabelled as its first corner's axes
struct Matched_face
{
  std::array<Eigen::Vector3d, 3> x;
  std::array<Eigen::Matrix3d, 3> B;
  std::array<std::array<int, 3>, 3> axis;
  double area = 0;
};

/// `false` for a triangle without area
inline bool match_face(const std::array<std::size_t, 3>& f, const std::vector<Eigen::Vector3d>& xyz,
                       const std::vector<Eigen::Matrix3d>& T, const std::vector<Eigen::Matrix3d>& B, Matched_face& m)
{
  for(std::size_t k = 0; k < 3; ++k) m.x[k] = xyz[f[k]];
  m.area = 0.5 * (m.x[1] - m.x[0]).cross(m.x[2] - m.x[0]).norm();
  if(!(m.area > 1e-12 * (m.x[1] - m.x[0]).squaredNorm())) return false;
  const Eigen::Matrix3d R0 = unit_axes(T[f[0]]);
  for(std::size_t k = 0; k < 3; ++k) m.B[k] = matched_rows(R0, T[f[k]], B[f[k]], m.axis[k]);
  return true;
}

/// the circulation of row `j` of B around the face (linear along the edges), corner k's row
/// times `factor[k]`: \f$ \sum_k \frac12 b_k \cdot (x_{k+1} - x_{k-1}) \f$
inline double circulation(const Matched_face& m, int j, const std::array<double, 3>& factor)
{
  double c = 0;
  for(std::size_t k = 0; k < 3; ++k)
    c += 0.5 * factor[k] * m.B[k].row(j).dot(m.x[(k + 1) % 3] - m.x[(k + 2) % 3]);
  return c;
}

/// `integrability_error_before` of `Scale_corrected_frame_field_3`, with the axes scaled by
/// `exp(log_scales)` (none if empty)
inline double integrability_error(const std::vector<Eigen::Vector3d>& xyz,
                                  const std::vector<std::array<std::size_t, 3>>& faces,
                                  const std::vector<Eigen::Matrix3d>& T, const std::vector<Eigen::Matrix3d>& B,
                                  const std::vector<Eigen::Vector3d>& log_scales)
{
  double sum = 0, weight = 0;
  Matched_face m;
  for(const auto& f : faces) {
    if(!match_face(f, xyz, T, B, m)) continue;
    const double w = m.area * std::sqrt(m.area); // the volume the face stands for
    for(int j = 0; j < 3; ++j) {
      std::array<double, 3> factor;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for(std::size_t k = 0; k < 3; ++k) {
        factor[k] = log_scales.empty() ? 1. : std::exp(-log_scales[f[k]][m.axis[k][std::size_t(j)]]);
        mean += factor[k] * m.B[k].row(j).transpose() / 3;
      }
      const double curl = circulation(m, j, factor) / m.area; // the curl's component normal to the face
      sum += w * curl * curl / (mean.squaredNorm() * mean.squaredNorm());
      weight += w;
    }
  }
  return weight > 0 ? std::sqrt(sum / weight) : 0.;
}

} // namespace internal

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * returns `field` with each frame's axes scaled so that a lattice can follow the field where its
 * axes turn: the scale correction of the cylinder (Fig. 4.16 of the dissertation, the tangential
 * axis as long as the radius) for any field on the vertices of a tetrahedral mesh, such as
 * `generate_cross_field_3()`'s.
 *
 * A lattice fits a frame field \f$ T \f$ when each row \f$ b_i \f$ of \f$ B = T^{-1} \f$ is
 * the gradient of a lattice coordinate, i.e. \f$ \nabla \times b_i = 0 \f$. Scaling axis \f$ i \f$
 * by \f$ e^{s_i} \f$ turns the row into \f$ e^{-s_i} b_i \f$, whose curl
 * \f$ e^{-s_i} (\nabla \times b_i - \nabla s_i \times b_i) \f$ vanishes when
 * \f$ \nabla s_i \times b_i = \nabla \times b_i \f$. In discrete form (Stokes): the circulation
 * of the scaled row around every triangle of the mesh vanishes. The three scales \f$ s_i \f$ per
 * vertex minimize the squared circulations, linearized in \f$ s \f$ (each triangle's frames
 * matched to its first corner's by the cube's rotations, so that an axis keeps its scale across
 * the field's relabellings and around its singular curves), plus a small smoothness term over
 * the edges for the scales' gradient along their own axis, which the equations leave free
 * (a sparse least-squares solve). The part of the curl along \f$ b_i \f$ (the axes' twist)
 * cannot be removed by scales and remains in `integrability_error_after`. The scales are then
 * centred (volume-weighted mean 0) and held within a factor \f$ \sqrt{\rho} \f$ of 1,
 * \f$ \rho \f$ = `maximum_size_ratio`.
 *
 * \tparam GeomTraits a model of `Kernel`
 * \tparam NamedParameters a sequence of named parameters
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{Frame_fields::parameters::maximum_size_ratio}
 *     \cgalParamDescription{the largest ratio of two scales of the corrected field (an axis scaled
 *       by at most \f$ \sqrt{\rho} \f$ and at least \f$ 1 / \sqrt{\rho} \f$); 1 leaves the field as it is}
 *     \cgalParamType{`double`, at least 1} \cgalParamDefault{4}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws std::invalid_argument if `field` is not given at the vertices of a mesh with cells,
 *   if no cell has a volume, or if `maximum_size_ratio` is under 1 or not finite
 * \throws std::runtime_error if the least-squares system cannot be factorized
 */
template <class GeomTraits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Scale_corrected_frame_field_3<GeomTraits>
scale_corrected_frame_field(const Discrete_frame_field_3<GeomTraits>& field,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const char* who = "scale_corrected_frame_field: ";
  const double ratio = choose_parameter(get_parameter(np, internal_np::maximum_size_ratio), 4.);
  if(!(ratio >= 1) || !std::isfinite(ratio))
    throw std::invalid_argument(std::string(who) + "maximum_size_ratio must be at least 1 and finite");
  if(field.location() != Frame_location::VERTICES || field.cells().empty())
    throw std::invalid_argument(std::string(who) + "the field must be given at the vertices of a tetrahedral mesh");

  const auto& cells = field.cells();
  const auto& T = field.frames();
  const auto& B = field.inverse_frames();
  const std::size_t n = field.points().size();
  std::vector<Eigen::Vector3d> xyz;
  xyz.reserve(n);
  for(const auto& p : field.points()) xyz.push_back(VVM::internal::to_eigen(p));

  // the normal equations of, per face and axis j, the linearized circulation of the scaled rows
  // sum_k c_k (s_k - mean s) - C = 0 (C: the circulation of b_j, c_k: its corner k's part), weighted by
  // the volume the face stands for (area^3/2) over its area squared (circulation per area is the
  // curl) and |b_j|^2; plus epsilon |e| (s_a - s_b)^2 per edge and axis (the smoothness the
  // equations leave free along each axis), and mu V s^2 / L^2 per vertex (V: its share of the
  // volume, L: the bounding box diagonal), which fixes the constants
  const double epsilon = 0.05, mu = 1e-3;
  Eigen::Vector3d lo = xyz[0], hi = xyz[0];
  for(const auto& x : xyz) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double L2 = (hi - lo).squaredNorm();
  std::vector<double> vertex_volume(n, 0.);
  double volume = 0;
  for(const auto& c : cells) {
    Eigen::Matrix3d E;
    for(int i = 0; i < 3; ++i) E.col(i) = xyz[c[std::size_t(i + 1)]] - xyz[c[0]];
    const double v = std::abs(E.determinant()) / 6;
    volume += v;
    for(std::size_t k = 0; k < 4; ++k) vertex_volume[c[k]] += v / 4;
  }
  const auto faces = internal::cell_simplices<3>(cells);
  const auto edges = internal::cell_simplices<2>(cells);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(faces.size() * 27 + edges.size() * 12 + n * 3);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(3 * n));
  internal::Matched_face m;
  for(const auto& f : faces) {
    if(!internal::match_face(f, xyz, T, B, m)) continue;
    for(int j = 0; j < 3; ++j) {
      std::array<double, 3> c;
      std::array<Eigen::Index, 3> u;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for(std::size_t k = 0; k < 3; ++k) {
        c[k] = 0.5 * m.B[k].row(j).dot(m.x[(k + 1) % 3] - m.x[(k + 2) % 3]);
        u[k] = Eigen::Index(3 * f[k] + std::size_t(m.axis[k][std::size_t(j)]));
        mean += m.B[k].row(j).transpose() / 3;
      }
      // linearized about the face's mean scale, which only multiplies the circulation: the
      // equations see the scales' differences, not their size
      const double C = c[0] + c[1] + c[2];
      for(std::size_t k = 0; k < 3; ++k) c[k] -= C / 3;
      const double w = 1 / (std::sqrt(m.area) * mean.squaredNorm());
      for(std::size_t k = 0; k < 3; ++k) {
        rhs[u[k]] += w * c[k] * C;
        for(std::size_t l = 0; l < 3; ++l) entries.emplace_back(u[k], u[l], w * c[k] * c[l]);
      }
    }
  }
  for(const auto& e : edges) {
    std::array<int, 3> axis;
    internal::matched_rows(internal::unit_axes(T[e[0]]), T[e[1]], B[e[1]], axis);
    const double w = epsilon * (xyz[e[1]] - xyz[e[0]]).norm();
    for(int j = 0; j < 3; ++j) {
      const Eigen::Index a = Eigen::Index(3 * e[0] + std::size_t(j)), b = Eigen::Index(3 * e[1] + std::size_t(axis[std::size_t(j)]));
      entries.emplace_back(a, a, w), entries.emplace_back(b, b, w);
      entries.emplace_back(a, b, -w), entries.emplace_back(b, a, -w);
    }
  }
  for(std::size_t v = 0; v < n; ++v) // vertices of no cell: scale 0
    for(int j = 0; j < 3; ++j) {
      const Eigen::Index u = Eigen::Index(3 * v + std::size_t(j));
      entries.emplace_back(u, u, vertex_volume[v] > 0 ? mu * vertex_volume[v] / L2 : 1.);
    }
  if(!(volume > 0)) throw std::invalid_argument(std::string(who) + "no cell of the mesh has a volume");
  Eigen::SparseMatrix<double> M(Eigen::Index(3 * n), Eigen::Index(3 * n));
  M.setFromTriplets(entries.begin(), entries.end());
  // the conjugate gradient is the fast one on these systems; a direct factorization if it
  // does not converge
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> iterative(M);
  iterative.setTolerance(1e-6);
  Eigen::VectorXd s = iterative.solve(rhs);
  if(iterative.info() != Eigen::Success || !s.allFinite()) {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(M);
    if(direct.info() == Eigen::Success) s = direct.solve(rhs);
    if(direct.info() != Eigen::Success || !s.allFinite())
      throw std::runtime_error(std::string(who) + "the least-squares system could not be solved");
  }

  Scale_corrected_frame_field_3<GeomTraits> out;
  double mean = 0;
  for(std::size_t v = 0; v < n; ++v)
    for(int j = 0; j < 3; ++j) mean += vertex_volume[v] * s[Eigen::Index(3 * v + std::size_t(j))];
  mean /= 3 * volume;
  const double bound = 0.5 * std::log(ratio);
  out.log_scales.resize(n);
  std::vector<Eigen::Matrix3d> frames(T);
  for(std::size_t v = 0; v < n; ++v)
    for(int j = 0; j < 3; ++j) {
      double sj = vertex_volume[v] > 0 ? s[Eigen::Index(3 * v + std::size_t(j))] - mean : 0.;
      if(std::abs(sj) > bound) sj = std::copysign(bound, sj), ++out.number_of_clamped_scales;
      out.log_scales[v][j] = sj;
      frames[v].col(j) *= std::exp(sj);
    }
  out.integrability_error_before = internal::integrability_error(xyz, faces, T, B, {});
  out.integrability_error_after = internal::integrability_error(xyz, faces, T, B, out.log_scales);
  out.field = Discrete_frame_field_3<GeomTraits>(field.points(), cells, std::move(frames), Frame_location::VERTICES);
  return out;
}

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_SCALE_CORRECTED_FRAME_FIELD_H
