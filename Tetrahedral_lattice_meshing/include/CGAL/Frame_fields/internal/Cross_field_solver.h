// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The boundary-aligned smooth cross field of Ray et al. 2016 on an indexed
// tetrahedral mesh, one frame per vertex:
// 1. frames as 9 band-4 SH coefficients; a boundary vertex is restricted to the
//    frames with one axis on its normal, a vertex inside a sharp edge to those with
//    one axis on the edge (2 unknowns each: cos 4t and sin 4t, left free); a
//    corner (where sharp edges end, meet or turn by more than 45 degrees) to those
//    with one axis on the mean normal of its largest group of nearly parallel
//    boundary facets (the rotation about it follows its neighbours);
// 2. least squares of sum over mesh edges |c_i - c_j|^2 (sparse, Eigen CG, with
//    a sparse LDLT factorization if CG does not converge);
// 3. every vertex projected to its nearest valid (constrained) frame;
// 4. L-BFGS on the frames themselves (Cross_field_smoother.h), the constrained
//    ones turning about their axis only, until the energy stops decreasing.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_CROSS_FIELD_SOLVER_H
#define CGAL_FRAME_FIELDS_INTERNAL_CROSS_FIELD_SOLVER_H

#include <CGAL/Frame_fields/internal/Boundary_vertex_normals.h>
#include <CGAL/Frame_fields/internal/Cross_field_smoother.h>
#include <CGAL/Frame_fields/internal/L4_spherical_harmonics.h>
#include <CGAL/Frame_fields/internal/Singular_edges.h>

#include <CGAL/number_type_config.h> // CGAL_PI

#include <Eigen/Core>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

struct Cross_field_solution
{
  std::vector<Eigen::Matrix3d> vertex_frames; // rotations
  std::vector<SH_vector> coefficients;        // their SH vectors
  std::vector<std::array<std::size_t, 2>> edges;
  Singular_edge_report singularities;
  double smoothness_energy = 0; // sum over edges of |c_i - c_j|^2
  std::vector<double> round_energies; // after the projection, then after each smoothing round
  int solver_iterations = 0;    // CG iterations of the least-squares solve
  double solver_error = 0;      // its relative residual |Mx - b| / |b|
  bool direct_solver = false;   // CG did not converge: the sparse LDLT factorization solved it
};

class Cross_field_solver
{
  typedef Eigen::Matrix<double, 9, Eigen::Dynamic, Eigen::ColMajor, 9, 9> Parametrization;

public:
  Cross_field_solver(const std::vector<Eigen::Vector3d>& xyz,
                     const std::vector<std::array<std::size_t, 4>>& cells,
                     const std::vector<std::array<std::size_t, 3>>& boundary_facets,
                     const std::vector<std::array<std::size_t, 2>>& feature_edges)
    : xyz_(xyz), cells_(cells), boundary_facets_(boundary_facets)
  {
    const std::size_t n = xyz.size();
    for(const auto& c : cells)
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j)
          edges_.push_back({{(std::min)(c[std::size_t(i)], c[std::size_t(j)]),
                             (std::max)(c[std::size_t(i)], c[std::size_t(j)])}});
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    neighbours_.assign(n, {});
    for(const auto& e : edges_) {
      neighbours_[e[0]].push_back(e[1]);
      neighbours_[e[1]].push_back(e[0]);
    }
    classify_vertices(feature_edges);
  }

  std::size_t number_of_constrained_vertices() const { return n_constrained_; }
  /// the vertices whose frames are constrained to one axis on a boundary facet normal
  /// although they are on sharp edges (corners, curve ends, sharp turns)
  std::size_t number_of_corner_vertices() const { return n_corners_; }
  /// the constrained axis of each vertex (zero if free)
  const std::vector<Eigen::Vector3d>& constrained_axes() const { return axis_; }

  /// the most CG iterations before the direct solver takes over (default 5000)
  void set_max_iterations(int k) { max_iterations_ = k; }
  /// the most L-BFGS iterations of a smoothing round (default 25)
  void set_iterations_per_round(int k) { iterations_per_round_ = k; }

  /// At most `max_rounds` smoothing rounds, stopped when one lowers the energy by
  /// less than `tolerance` times it or when `after_round(round, energy)`, called before the
  /// first (round 0) and after each, returns `false`; a round under way ends early once
  /// `interrupted()` returns true.
  /// \throws std::runtime_error if neither CG nor the LDLT factorization solves the system
  Cross_field_solution solve(int max_rounds, double tolerance, bool verbose,
                             const std::function<bool(int, double)>& after_round = {},
                             const std::function<bool()>& interrupted = {}) const
  {
    const L4_frames& frames = L4_frames::instance();
    const std::size_t n = xyz_.size();
    Cross_field_solution s;
    std::vector<SH_vector> c = least_squares(verbose, s);
    s.vertex_frames.resize(n);
    s.coefficients.resize(n);
    parallel_for_each_index(n, [&](std::size_t v) { s.vertex_frames[v] = nearest_frame(v, c[v]); });
    parallel_for_each_index(n, [&](std::size_t v) { s.coefficients[v] = frames.frame(s.vertex_frames[v]); });
    const Cross_field_smoother smoother(neighbours_, axis_);
    s.round_energies = smoother.smooth(s.vertex_frames, s.coefficients, max_rounds, tolerance, iterations_per_round_,
                                       [&](int round, double e) {
                                         if(verbose && round > 0)
                                           std::cerr << "  smoothing round " << round << ": energy " << e << "\n";
                                         return !after_round || after_round(round, e);
                                       }, interrupted);
    s.smoothness_energy = s.round_energies.back();
    s.edges = edges_;
    // one frame per cell, interpolated at its centroid, for the matchings
    std::vector<Eigen::Matrix3d> cell_frames(cells_.size());
    parallel_for_each_index(cells_.size(), [&](std::size_t i) {
      SH_vector q = SH_vector::Zero();
      for(std::size_t v : cells_[i]) q += s.coefficients[v];
      cell_frames[i] = frames.nearest_frame(q);
    });
    s.singularities = singular_edges(cells_, cell_frames, boundary_facets_);
    return s;
  }

private:
  // an axis direction per constrained vertex: the normal on the boundary, the
  // tangent inside a sharp edge (2 sharp edges turning by less than 45 degrees), and
  // at a corner (any other vertex of sharp edges) the normal of its largest group of
  // boundary facets
  void classify_vertices(const std::vector<std::array<std::size_t, 2>>& feature_edges)
  {
    const std::size_t n = xyz_.size();
    const std::vector<Eigen::Matrix3d> normal_tensor =
        boundary_normal_tensors(n, boundary_facets_, [this](std::size_t v) { return xyz_[v]; });
    std::vector<char> on_boundary(n, 0);
    std::vector<std::vector<std::size_t>> facets_of(n);
    for(std::size_t i = 0; i < boundary_facets_.size(); ++i)
      for(std::size_t v : boundary_facets_[i]) {
        on_boundary[v] = 1;
        facets_of[v].push_back(i);
      }
    std::vector<std::vector<std::size_t>> sharp(n);
    for(const auto& e : feature_edges) {
      sharp[e[0]].push_back(e[1]);
      sharp[e[1]].push_back(e[0]);
    }
    axis_.assign(n, Eigen::Vector3d::Zero());
    n_corners_ = 0;
    for(std::size_t v = 0; v < n; ++v) {
      if(sharp[v].size() == 2) {
        const Eigen::Vector3d d0 = (xyz_[v] - xyz_[sharp[v][0]]).normalized();
        const Eigen::Vector3d d1 = (xyz_[sharp[v][1]] - xyz_[v]).normalized();
        if(d0.dot(d1) > std::cos(CGAL_PI / 4)) axis_[v] = (d0 + d1).normalized();
      } else if(sharp[v].empty() && on_boundary[v]) {
        axis_[v] = principal_normal(normal_tensor[v]);
      }
      if(!sharp[v].empty() && axis_[v].squaredNorm() == 0) { // a corner
        axis_[v] = dominant_facet_normal(facets_of[v]);
        if(axis_[v].squaredNorm() > 0) ++n_corners_;
      }
      if(!axis_[v].allFinite()) axis_[v].setZero();
    }
    constrained_.resize(n);
    n_constrained_ = 0;
    for(std::size_t v = 0; v < n; ++v)
      if(axis_[v].squaredNorm() > 0) {
        constrained_[v] = std::make_shared<Axis_constrained_frames>(axis_[v]);
        ++n_constrained_;
      }
  }

  // the mean unit normal of the largest (by area) group of facets whose normals are
  // within 30 degrees of each other (orientation ignored); zero if all are degenerate
  Eigen::Vector3d dominant_facet_normal(const std::vector<std::size_t>& facets) const
  {
    struct Group
    {
      Eigen::Vector3d sum;  // area-weighted, oriented like the first normal
      double area;
    };
    std::vector<Group> groups;
    const double cos_bound = std::cos(CGAL_PI / 6);
    for(std::size_t i : facets) {
      const auto& f = boundary_facets_[i];
      const Eigen::Vector3d N = (xyz_[f[1]] - xyz_[f[0]]).cross(xyz_[f[2]] - xyz_[f[0]]);
      const double area = 0.5 * N.norm();
      if(!(area > 0)) continue;
      const Eigen::Vector3d u = N.normalized();
      Group* into = nullptr;
      for(Group& g : groups)
        if(std::abs(g.sum.normalized().dot(u)) > cos_bound) {
          into = &g;
          break;
        }
      if(into == nullptr) {
        groups.push_back({Eigen::Vector3d::Zero(), 0.});
        into = &groups.back();
      }
      into->sum += (into->sum.dot(u) < 0 ? -area : area) * u;
      into->area += area;
    }
    const Group* best = nullptr;
    for(const Group& g : groups)
      if(best == nullptr || g.area > best->area) best = &g;
    return best != nullptr && best->sum.norm() > 0 ? Eigen::Vector3d(best->sum.normalized())
                                                   : Eigen::Vector3d::Zero();
  }

  Eigen::Matrix3d nearest_frame(std::size_t v, const SH_vector& q) const
  {
    return constrained_[v] ? constrained_[v]->nearest_frame(q) : L4_frames::instance().nearest_frame(q);
  }

  // c_v = A_v x_v + b_v: the identity for a free vertex, 9x2 for a constrained one
  Parametrization A(std::size_t v) const
  {
    if(constrained_[v]) return constrained_[v]->basis;
    return Parametrization(SH_matrix::Identity());
  }
  SH_vector b(std::size_t v) const { return constrained_[v] ? constrained_[v]->offset : SH_vector::Zero(); }

  std::vector<SH_vector> least_squares(bool verbose, Cross_field_solution& report) const
  {
    const std::size_t n = xyz_.size();
    std::vector<Eigen::Index> offset(n + 1, 0);
    for(std::size_t v = 0; v < n; ++v) offset[v + 1] = offset[v] + (constrained_[v] ? 2 : 9);
    const Eigen::Index size = offset[n];
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
    auto add_block = [&](std::size_t u, std::size_t v, double sign) {
      const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 9, 9> M = A(u).transpose() * A(v);
      for(Eigen::Index r = 0; r < M.rows(); ++r)
        for(Eigen::Index k = 0; k < M.cols(); ++k)
          if(M(r, k) != 0) triplets.emplace_back(offset[u] + r, offset[v] + k, sign * M(r, k));
    };
    // sum over edges |A_i x_i + b_i - A_j x_j - b_j|^2
    for(const auto& e : edges_) {
      const std::size_t i = e[0], j = e[1];
      add_block(i, i, 1);
      add_block(j, j, 1);
      add_block(i, j, -1);
      add_block(j, i, -1);
      const SH_vector d = b(i) - b(j);
      rhs.segment(offset[i], offset[i + 1] - offset[i]) -= A(i).transpose() * d;
      rhs.segment(offset[j], offset[j + 1] - offset[j]) += A(j).transpose() * d;
    }
    // a free part with no constrained vertex would be singular: pin it softly to 0
    for(Eigen::Index k = 0; k < size; ++k) triplets.emplace_back(k, k, 1e-9);
    Eigen::SparseMatrix<double> M(size, size);
    M.setFromTriplets(triplets.begin(), triplets.end());
    triplets.clear();
    triplets.shrink_to_fit();
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
    cg.setTolerance(1e-8);
    cg.setMaxIterations(max_iterations_);
    cg.compute(M);
    Eigen::VectorXd x = cg.solve(rhs);
    report.solver_iterations = int(cg.iterations());
    report.solver_error = cg.error();
    const bool converged = cg.info() == Eigen::Success && x.allFinite();
    if(verbose)
      std::cerr << "  least squares: " << size << " unknowns, " << M.nonZeros() << " non-zeros, CG "
                << cg.iterations() << " iterations, error " << cg.error()
                << (converged ? "" : " (not converged: sparse LDLT instead)") << "\n";
    if(!converged) {
      std::ostringstream why;
      why << "generate_cross_field_3: the least-squares solve failed: CG stopped after " << cg.iterations()
          << " iterations at relative error " << cg.error();
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(M);
      if(ldlt.info() != Eigen::Success) throw std::runtime_error(why.str() + ", and the LDLT factorization failed");
      x = ldlt.solve(rhs);
      const double norm = rhs.norm();
      report.solver_error = norm > 0 ? (M * x - rhs).norm() / norm : (M * x).norm();
      report.direct_solver = true;
      if(ldlt.info() != Eigen::Success || !x.allFinite() || !(report.solver_error < 1e-6))
        throw std::runtime_error(why.str() + ", and the LDLT solve failed");
      if(verbose) std::cerr << "  least squares: LDLT, relative error " << report.solver_error << "\n";
    }
    std::vector<SH_vector> c(n);
    for(std::size_t v = 0; v < n; ++v)
      c[v] = A(v) * x.segment(offset[v], offset[v + 1] - offset[v]) + b(v);
    return c;
  }

  const std::vector<Eigen::Vector3d>& xyz_;
  const std::vector<std::array<std::size_t, 4>>& cells_;
  const std::vector<std::array<std::size_t, 3>>& boundary_facets_;
  std::vector<std::array<std::size_t, 2>> edges_;
  std::vector<std::vector<std::size_t>> neighbours_;
  std::vector<Eigen::Vector3d> axis_;
  std::vector<std::shared_ptr<const Axis_constrained_frames>> constrained_;
  std::size_t n_constrained_ = 0, n_corners_ = 0;
  int max_iterations_ = 5000;
  int iterations_per_round_ = 25;
};

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_CROSS_FIELD_SOLVER_H
