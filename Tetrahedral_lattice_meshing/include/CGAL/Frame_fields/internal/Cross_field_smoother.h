// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The second stage of Ray et al. 2016: the smoothness energy
// E = sum over edges ij |f(R_i) - f(R_j)|^2 of the frames' unit SH vectors
// minimised over the frames themselves (the octahedral variety), by L-BFGS
// (LBFGS++) on per-vertex rotations:
// - a free vertex rotates by exp([w]) from its frame at the start of the round
//   (3 unknowns); the gradient is J_l(w)^T (L_a f . dE/df)_a, J_l the left
//   Jacobian of SO(3), exact for any w;
// - a constrained vertex (boundary, sharp edge, corner) rotates by an angle t
//   about its axis only (1 unknown), so its axis stays on the normal or the edge
//   exactly whatever the optimizer does.
// Rounds of L-BFGS start again from the frames reached (w = 0, where J_l = I);
// they stop when a round lowers E by less than a relative tolerance.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_CROSS_FIELD_SMOOTHER_H
#define CGAL_FRAME_FIELDS_INTERNAL_CROSS_FIELD_SMOOTHER_H

#include <CGAL/Frame_fields/internal/L4_spherical_harmonics.h>
#include <CGAL/VVM/internal/Parallel_for.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <LBFGS.h>

#ifdef CGAL_LINKED_WITH_TBB
#endif

#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

using VVM::internal::parallel_for_each_index;

/// the left Jacobian of SO(3): exp([w + d]) = exp([J_l(w) d]) exp([w]) to first order in d
inline Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& w)
{
  const double t = w.norm();
  Eigen::Matrix3d W;
  W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  if(t < 1e-6) return Eigen::Matrix3d::Identity() + 0.5 * W + W * W / 6.;
  return Eigen::Matrix3d::Identity() + (1 - std::cos(t)) / (t * t) * W + (t - std::sin(t)) / (t * t * t) * W * W;
}

inline Eigen::Matrix3d so3_exp(const Eigen::Vector3d& w)
{
  const double t = w.norm();
  if(t == 0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(t, w / t).toRotationMatrix();
}

class Cross_field_smoother
{
public:
  /// `neighbours[v]`: the vertices sharing an edge with v; `axes[v]`: the unit
  /// axis v's frame must keep (zero if v is free)
  Cross_field_smoother(const std::vector<std::vector<std::size_t>>& neighbours,
                       const std::vector<Eigen::Vector3d>& axes)
    : neighbours_(neighbours), axes_(axes), offset_(axes.size() + 1, 0)
  {
    for(std::size_t v = 0; v < axes.size(); ++v)
      offset_[v + 1] = offset_[v] + (axes[v].squaredNorm() > 0 ? 1 : 3);
  }

  /// E = sum over edges |c_i - c_j|^2 (each edge once)
  double energy(const std::vector<SH_vector>& c) const
  {
    std::vector<double> e(c.size());
    parallel_for_each_index(c.size(), [&](std::size_t v) { e[v] = vertex_energy(c, v); });
    double sum = 0;
    for(double x : e) sum += x; // in index order: the same sum for any thread count
    return 0.5 * sum;
  }

  /// Smooths `frames` (rotations) in place, with `c` their SH vectors, for at most
  /// `max_rounds` rounds of at most `iterations_per_round` L-BFGS iterations; stops
  /// when a round lowers the energy by less than `tolerance` times it, or when
  /// `after_round(round, energy)`, called before the first round (round 0) and after each,
  /// returns `false`. Once `interrupted()` returns true, the round under way ends at its best
  /// point so far. Returns the energies: before the first round, then after each.
  std::vector<double> smooth(std::vector<Eigen::Matrix3d>& frames, std::vector<SH_vector>& c, int max_rounds,
                             double tolerance, int iterations_per_round,
                             const std::function<bool(int, double)>& after_round,
                             const std::function<bool()>& interrupted = {}) const
  {
    std::vector<double> energies{energy(c)};
    const Eigen::Index size = offset_.back();
    if(after_round && !after_round(0, energies.back())) return energies;
    for(int round = 1; round <= max_rounds && energies.back() > 0; ++round) {
      const std::vector<Eigen::Matrix3d> start = frames;
      std::vector<SH_vector> trial(c.size());
      Eigen::VectorXd best_x = Eigen::VectorXd::Zero(size);
      double best_e = energies.back();
      auto f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& grad) {
        if(interrupted && interrupted()) throw std::runtime_error("interrupted"); // caught below
        const double e = energy_and_gradient(start, x, grad, trial);
        if(std::isfinite(e) && e < best_e) {
          best_e = e;
          best_x = x;
        }
        return e;
      };
      LBFGSpp::LBFGSParam<double> param;
      param.epsilon = 1e-10 * std::sqrt(double(size));
      param.max_iterations = iterations_per_round;
      param.max_linesearch = 30;
      LBFGSpp::LBFGSSolver<double> solver(param);
      Eigen::VectorXd x = Eigen::VectorXd::Zero(size);
      double fx = 0;
      try {
        solver.minimize(f, x, fx);
      } catch(const std::runtime_error&) { // a line search that cannot progress: keep the best point
      } catch(const std::logic_error&) {
      }
      parallel_for_each_index(c.size(), [&](std::size_t v) {
        frames[v] = rotation_of(v, start[v], best_x);
        c[v] = L4_frames::instance().frame(frames[v]);
      });
      const double before = energies.back(), e = energy(c);
      if(e > before) { // round-off only (best_e < before): keep the frames of the round before
        frames = start;
        parallel_for_each_index(c.size(), [&](std::size_t v) { c[v] = L4_frames::instance().frame(frames[v]); });
      }
      energies.push_back((std::min)(e, before));
      if(after_round && !after_round(round, energies.back())) break;
      if(before - energies.back() <= tolerance * before) break;
    }
    return energies;
  }

  /// the number of unknowns: 3 per free vertex, 1 per constrained one
  Eigen::Index number_of_unknowns() const { return offset_.back(); }

  /// the energy of the frames rotated by `x` from `start`, and its gradient; `c` gets
  /// their SH vectors
  double energy_and_gradient(const std::vector<Eigen::Matrix3d>& start, const Eigen::VectorXd& x,
                             Eigen::VectorXd& grad, std::vector<SH_vector>& c) const
  {
    const std::size_t n = start.size();
    c.resize(n);
    parallel_for_each_index(n, [&](std::size_t v) { c[v] = L4_frames::instance().frame(rotation_of(v, start[v], x)); });
    grad.resize(offset_.back());
    std::vector<double> e(n);
    parallel_for_each_index(n, [&](std::size_t v) {
      e[v] = vertex_energy(c, v);
      SH_vector d = SH_vector::Zero(); // dE/dc_v = 2 sum over neighbours (c_v - c_w)
      for(std::size_t w : neighbours_[v]) d += c[v] - c[w];
      d *= 2;
      Eigen::Vector3d G; // dE along the rotations about the three axes
      for(int a = 0; a < 3; ++a) G[a] = (L4_frames::instance().generator(a) * c[v]).dot(d);
      if(axes_[v].squaredNorm() > 0)
        grad[offset_[v]] = axes_[v].dot(G);
      else
        grad.segment<3>(offset_[v]) = so3_left_jacobian(x.segment<3>(offset_[v])).transpose() * G;
    });
    double sum = 0;
    for(double x_v : e) sum += x_v; // in index order: the same sum for any thread count
    return 0.5 * sum;
  }

private:
  double vertex_energy(const std::vector<SH_vector>& c, std::size_t v) const
  {
    double e = 0;
    for(std::size_t w : neighbours_[v]) e += (c[v] - c[w]).squaredNorm();
    return e;
  }

  Eigen::Matrix3d rotation_of(std::size_t v, const Eigen::Matrix3d& start, const Eigen::VectorXd& x) const
  {
    if(axes_[v].squaredNorm() > 0)
      return Eigen::AngleAxisd(x[offset_[v]], axes_[v]).toRotationMatrix() * start;
    return so3_exp(x.segment<3>(offset_[v])) * start;
  }

  const std::vector<std::vector<std::size_t>>& neighbours_;
  const std::vector<Eigen::Vector3d>& axes_;
  std::vector<Eigen::Index> offset_;
};

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_CROSS_FIELD_SMOOTHER_H
