// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The particles and their GHK energy (dissertation eq. 4.4), minimized by
// L-BFGS (LBFGS++) with the kinds' constraints, then projected onto the
// boundary and the sharp edges (Alg. 2).
//
// Each round freezes the neighbour pairs (within R, widened by the field's
// largest stretch); the frame of each pair follows its midpoint to first
// order (the frame at the round's midpoint and its derivative there, the mean
// of the derivatives at the two particles), so that L-BFGS minimizes a smooth
// function with its exact gradient; both are renewed at the next round. The
// derivative term matters: without it a particle's balance weighs the pair on
// the side where the field stretches more by its larger B, and on a graded
// field the lattice drifts from uniform in the field's space (Fig. 4.8's field:
// layer spacing 0.119 to 0.161 l* where it should be constant). Only where the
// frames stretch: rotation fields (cross fields) keep each round's frames, as
// their frames are defined up to the lattice's symmetries and their
// representation jumps (with the derivative of those jumps, a cross-field
// lattice aligned much worse). L-BFGS moves each particle
// in the imagined space of its own frame (frozen for the round too), where the
// energy is isotropic: in
// Euclidean coordinates a stretched or graded field would make the problem
// ill-conditioned (curvatures ~ B^T B), and the particles of the stretched
// axes or the coarse parts would hardly move in a round's few iterations.
// Pairs are evaluated in parallel and summed in a fixed order, so the result
// does not depend on the number of threads.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_SYSTEM_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_SYSTEM_H

#include <CGAL/Tetrahedral_lattice_meshing/Lattice.h>
#include <CGAL/Tetrahedral_lattice_meshing/gaussian_hole_kernel.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Neighbor_grid.h>
#include <CGAL/Tetrahedral_lattice_meshing/lattice_particle_types.h>
#include <CGAL/VVM/internal/Parallel_for.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <LBFGS.h>


#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

using VVM::internal::parallel_for_each_index;

/// a boundary that is not there: every particle is free (tests, unbounded lattices)
struct No_boundary
{
  struct Closest
  {
    Eigen::Vector3d point, direction;
    int feature = -1;
    double distance = 0;
  };
  bool inside(const Eigen::Vector3d&) const { return true; }
  static constexpr bool has_thread_safe_inside = true;
  bool has_sharp_edges() const { return false; }
  Closest closest_on_surface(const Eigen::Vector3d&) const { return Closest(); }
  Closest closest_on_sharp_edge(const Eigen::Vector3d&) const { return Closest(); }
};

/// `boundary.inside()` of `point(0)`, ..., `point(n - 1)`: on all threads where the boundary's
/// domain allows it, else one after another on this one
template <class Boundary, class PointOf>
std::vector<char> inside_tests(const Boundary& boundary, std::size_t n, const PointOf& point)
{
  std::vector<char> inside(n);
  if constexpr(Boundary::has_thread_safe_inside)
    parallel_for_each_index(n, [&](std::size_t k) { inside[k] = boundary.inside(point(k)); });
  else
    for(std::size_t k = 0; k < n; ++k) inside[k] = boundary.inside(point(k));
  return inside;
}

/*
 * FrameField: a model of FrameField_3; Boundary: Domain_boundary or No_boundary.
 */
template <class FrameField, class Boundary, class Point_3>
class Particle_system
{
public:
  struct Pair
  {
    std::uint32_t i, j;
    Eigen::Matrix3d B; // the frame's inverse at the midpoint when the pairs were built
  };
  /// the derivatives of B along x, y and z (per unit of p / l*)
  typedef std::array<Eigen::Matrix3d, 3> Frame_derivative;

  Particle_system(const Lattice& lattice, const FrameField& field, const Boundary* boundary, double l_star,
                  double sigma, double radius)
    : lattice_(lattice), field_(field), boundary_(boundary), l_(l_star), sigma_(sigma), radius_(radius)
  {}

  // --- state (public: the deletion, insertion and driver read and edit it between rounds)
  std::vector<Eigen::Vector3d> points;
  std::vector<Particle_kind> kinds;
  std::vector<int> features;
  std::vector<Eigen::Vector3d> directions; // normal (BOUNDARY) or tangent (SHARP_EDGE)
  std::vector<double> clearance;           // FREE: distance to the boundary when last checked inside
  std::vector<double> moved;               // FREE: distance moved since then

  const Lattice& lattice() const { return lattice_; }
  const FrameField& field() const { return field_; }
  const Boundary* boundary() const { return boundary_; }
  double edge_length() const { return l_; }
  double sigma() const { return sigma_; }
  double neighbor_radius() const { return radius_; }
  std::size_t size() const { return points.size(); }

  void add(const Eigen::Vector3d& p, Particle_kind k, int feature = -1,
           const Eigen::Vector3d& direction = Eigen::Vector3d::Zero())
  {
    points.push_back(p);
    kinds.push_back(k);
    features.push_back(feature);
    directions.push_back(direction);
    clearance.push_back(0);
    moved.push_back(std::numeric_limits<double>::infinity()); // check it at the next projection
  }

  /// keeps the particles whose flag is false
  void remove(const std::vector<char>& erase)
  {
    std::size_t k = 0;
    for(std::size_t i = 0; i < points.size(); ++i) {
      if(erase[i]) continue;
      points[k] = points[i];
      kinds[k] = kinds[i];
      features[k] = features[i];
      directions[k] = directions[i];
      clearance[k] = clearance[i];
      moved[k] = moved[i];
      ++k;
    }
    points.resize(k);
    kinds.resize(k);
    features.resize(k);
    directions.resize(k);
    clearance.resize(k);
    moved.resize(k);
  }

  Point_3 point_3(const Eigen::Vector3d& p) const { return Point_3(p[0], p[1], p[2]); }
  Eigen::Matrix3d B(const Eigen::Vector3d& p) const { return Eigen::Matrix3d(field_.B(point_3(p))); }
  Eigen::Matrix3d T(const Eigen::Vector3d& p) const { return Eigen::Matrix3d(field_.T(point_3(p))); }

  /// the largest stretch of T at each particle: the longest Euclidean vector a unit vector of
  /// the imagined space becomes there
  std::vector<double> stretches() const
  {
    std::vector<double> stretch(points.size(), 0.);
    parallel_for_each_index(points.size(), [&](std::size_t i) {
      const Eigen::Matrix3d t = T(points[i]);
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
      es.computeDirect(t.transpose() * t, Eigen::EigenvaluesOnly);
      stretch[i] = std::sqrt(std::max(es.eigenvalues().maxCoeff(), 0.));
    });
    return stretch;
  }

  /// the Euclidean radius that holds every pair within R in the imagined space:
  /// R l* times the largest of the particles' `stretch`
  double euclidean_radius(const std::vector<double>& stretch) const
  {
    double s = 0;
    for(double x : stretch) s = std::max(s, x);
    return radius_ * l_ * s;
  }
  double euclidean_radius() const { return euclidean_radius(stretches()); }

  /*
   * false if two points at the squared Euclidean distance `d2`, where T stretches by at most
   * `stretch_p` and `stretch_q`, are farther apart than `imagined` l* in the imagined space,
   * provided that the field between them stretches less than `stretch_variation` times as
   * much: the cheap test that spares the field's lookups at the midpoints of far pairs (on a
   * graded field most pairs within the largest Euclidean radius are far)
   */
  bool may_be_within(double d2, double stretch_p, double stretch_q, double imagined) const
  {
    const double r = imagined * l_ * stretch_variation * std::max(stretch_p, stretch_q);
    return d2 <= r * r;
  }
  static constexpr double stretch_variation = 2.;

  /// the pairs of particles within R of each other (in the imagined space), with their B,
  /// and the derivatives of B at the particles if the field varies
  void build_pairs()
  {
    build_frame_derivatives();
    const std::vector<double> stretch = stretches();
    const double r = euclidean_radius(stretch);
    const Neighbor_grid grid(points, r);
    std::vector<std::vector<Pair>> local(points.size());
    parallel_for_each_index(points.size(), [&](std::size_t i) {
      grid.for_each_within(points[i], r, [&](std::size_t j, double d2) {
        if(j <= i || !may_be_within(d2, stretch[i], stretch[j], radius_)) return;
        const Eigen::Matrix3d b = B(0.5 * (points[i] + points[j]));
        if((b * (points[i] - points[j])).norm() <= radius_ * l_)
          local[i].push_back(Pair{std::uint32_t(i), std::uint32_t(j), b});
      });
      std::sort(local[i].begin(), local[i].end(), [](const Pair& a, const Pair& b) { return a.j < b.j; });
    });
    pairs_.clear();
    for(auto& l : local) pairs_.insert(pairs_.end(), l.begin(), l.end());
    // per particle: its pairs, with the sign of its gradient
    start_.assign(points.size() + 1, 0);
    for(const Pair& p : pairs_) {
      ++start_[p.i + 1];
      ++start_[p.j + 1];
    }
    for(std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
    incident_.resize(2 * pairs_.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for(std::size_t k = 0; k < pairs_.size(); ++k) {
      incident_[fill[pairs_[k].i]++] = std::int64_t(k) + 1;    // +: gradient of p_i
      incident_[fill[pairs_[k].j]++] = -(std::int64_t(k) + 1); // -: of p_j
    }
  }

  const std::vector<Pair>& pairs() const { return pairs_; }
  /// false if the frames do not stretch (rotations of one scale) or are constant at the
  /// particles: the pairs' frames then stay as built for the round
  bool frames_vary() const { return !derivatives_.empty(); }
  /// false: the pairs' frames stay as built for each round even where the frames stretch (the
  /// optimizer's coarsest level)
  bool frame_derivatives = true;

  /*
   * E = sum_i sum_{j != i} E_ij = 2 sum_pairs E_ij over the frozen pairs, at positions
   * x = p / l*, and its gradient with respect to x (projected on each particle's freedom
   * if `constrain`).
   */
  double energy_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& grad, bool constrain = true) const
  {
    const bool vary = frames_vary();
    std::vector<double> e(pairs_.size());
    // the gradient of E_ij with respect to x_i is g + h, with respect to x_j -g + h;
    // h, from the midpoint's frame, is 0 in a constant field
    std::vector<Eigen::Vector3d> g(pairs_.size()), h(vary ? pairs_.size() : 0);
    parallel_for_each_index(pairs_.size(), [&](std::size_t k) {
      const Pair& p = pairs_[k];
      const Eigen::Vector3d v = x.segment<3>(3 * p.i) - x.segment<3>(3 * p.j);
      Eigen::Matrix3d b = p.B;
      Frame_derivative D;
      if(vary) {
        const Eigen::Vector3d dm =
            0.5 * (x.segment<3>(3 * p.i) + x.segment<3>(3 * p.j)) - 0.5 * (built_at_[p.i] + built_at_[p.j]);
        for(int c = 0; c < 3; ++c) {
          D[c] = 0.5 * (derivatives_[p.i][c] + derivatives_[p.j][c]);
          b += dm[c] * D[c];
        }
      }
      Eigen::Vector3d de;
      e[k] = gaussian_hole_kernel(lattice_, Eigen::Vector3d(b * v), sigma_, &de);
      g[k] = b.transpose() * de;
      if(vary)
        for(int c = 0; c < 3; ++c) h[k][c] = 0.5 * de.dot(D[c] * v);
    });
    grad.resize(x.size());
    parallel_for_each_index(points.size(), [&](std::size_t i) {
      Eigen::Vector3d gi = Eigen::Vector3d::Zero();
      for(std::size_t s = start_[i]; s < start_[i + 1]; ++s) {
        const std::int64_t k = incident_[s];
        const std::size_t pk = std::size_t(k > 0 ? k - 1 : -k - 1);
        if(k > 0) gi += g[pk];
        else gi -= g[pk];
        if(vary) gi += h[pk];
      }
      grad.segment<3>(3 * i) = 2. * (constrain ? constrained(i, gi) : gi);
    });
    double sum = 0;
    for(double v : e) sum += v;
    return 2. * sum;
  }

  /// the gradient `g` of particle `i` restricted to its freedom
  Eigen::Vector3d constrained(std::size_t i, const Eigen::Vector3d& g) const
  {
    return constrained(i, g, directions[i]);
  }

  /// the gradient `g` restricted to the freedom of particle `i`, whose normal (BOUNDARY) or
  /// tangent (SHARP_EDGE) is the unit vector `d` in the coordinates of `g`
  Eigen::Vector3d constrained(std::size_t i, const Eigen::Vector3d& g, const Eigen::Vector3d& d) const
  {
    switch(kinds[i]) {
      case Particle_kind::CORNER: return Eigen::Vector3d::Zero();
      case Particle_kind::SHARP_EDGE: return g.dot(d) * d;
      case Particle_kind::BOUNDARY: return g - g.dot(d) * d;
      default: return g;
    }
  }

  Eigen::VectorXd positions() const
  {
    Eigen::VectorXd x(3 * points.size());
    for(std::size_t i = 0; i < points.size(); ++i) x.segment<3>(3 * i) = points[i] / l_;
    return x;
  }

  struct Round_result
  {
    double energy = 0;
    double gradient_norm = 0;
    int iterations = 0;
  };

  /*
   * One L-BFGS run (Alg. 2's loop) on the frozen pairs: stops when the gradient's RMS per
   * particle (in the particles' imagined spaces) is under eps_g, after max_iterations (0: no
   * bound), or before a particle moves farther than l* from where it started. A failed line
   * search ends the run at the best point seen.
   */
  Round_result lbfgs_round(double eps_g, int max_iterations)
  {
    build_pairs();
    Round_result r;
    if(points.empty()) return r;
    // the variables: y_i = B_i x_i, B_i the frame's inverse at particle i; a normal n becomes
    // T_i^T n, a tangent t becomes B_i t (a move dy_i keeps n . T_i dy_i = 0, or along t)
    const std::size_t n = points.size();
    std::vector<Eigen::Matrix3d> T_i(n), B_i(n);
    std::vector<Eigen::Vector3d> d_i(n);
    parallel_for_each_index(n, [&](std::size_t i) {
      T_i[i] = T(points[i]);
      B_i[i] = T_i[i].inverse();
      const Eigen::Vector3d d = kinds[i] == Particle_kind::SHARP_EDGE ? Eigen::Vector3d(B_i[i] * directions[i])
                                                                       : Eigen::Vector3d(T_i[i].transpose() * directions[i]);
      d_i[i] = d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : d;
    });
    const Eigen::VectorXd x0 = positions();
    Eigen::VectorXd y(x0.size());
    parallel_for_each_index(n, [&](std::size_t i) { y.segment<3>(3 * i) = B_i[i] * x0.segment<3>(3 * i); });
    const Eigen::VectorXd y0 = y;
    auto to_x = [&](const Eigen::VectorXd& v) { // x0 + T dy: a particle that did not move stays put exactly
      Eigen::VectorXd x(v.size());
      parallel_for_each_index(n, [&](std::size_t i) {
        x.segment<3>(3 * i) = x0.segment<3>(3 * i) + T_i[i] * (v.segment<3>(3 * i) - y0.segment<3>(3 * i));
      });
      return x;
    };
    // the frozen pairs and frames hold near the round's start only: the run ends when a
    // particle would go farther than max_move (in its imagined space, units of l*)
    struct Moved_too_far {};
    const double max_move = 1.;
    Eigen::VectorXd best_y = y;
    double best_e = std::numeric_limits<double>::infinity();
    auto f = [&](const Eigen::VectorXd& v, Eigen::VectorXd& grad, bool check = true) {
      if(check) {
        std::vector<char> far(n, 0);
        parallel_for_each_index(n, [&](std::size_t i) {
          far[i] = (v.segment<3>(3 * i) - y0.segment<3>(3 * i)).squaredNorm() > max_move * max_move;
        });
        if(std::find(far.begin(), far.end(), 1) != far.end()) throw Moved_too_far();
      }
      Eigen::VectorXd gx;
      const double e = energy_and_gradient(to_x(v), gx, false);
      grad.resize(v.size());
      parallel_for_each_index(n, [&](std::size_t i) {
        grad.segment<3>(3 * i) = constrained(i, T_i[i].transpose() * gx.segment<3>(3 * i), d_i[i]);
      });
      if(e < best_e) {
        best_e = e;
        best_y = v;
      }
      return e;
    };
    LBFGSpp::LBFGSParam<double> param;
    param.epsilon = eps_g * std::sqrt(double(n));
    param.epsilon_rel = 0;
    param.max_iterations = max_iterations;
    param.max_linesearch = 30;
    LBFGSpp::LBFGSSolver<double> solver(param);
    double fy = 0;
    try {
      r.iterations = solver.minimize(f, y, fy);
    } catch(const std::runtime_error&) { // a line search that cannot progress: keep the best point
      r.iterations = max_iterations;
    } catch(const std::logic_error&) {
      r.iterations = max_iterations;
    } catch(const Moved_too_far&) {
      r.iterations = max_iterations;
    }
    const Eigen::VectorXd best_x = to_x(best_y);
    for(std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d p = best_x.template segment<3>(3 * i) * l_;
      moved[i] += (p - points[i]).norm();
      points[i] = p;
    }
    Eigen::VectorXd grad;
    r.energy = f(best_y, grad, false);
    r.gradient_norm = grad.norm();
    return r;
  }

  /*
   * After a round (Alg. 2, end): particles outside the domain, or within 0.3 l* of the
   * boundary (in the imagined space), go onto the surface and become boundary particles;
   * boundary particles within the lattice's `sharp_edge_snap` of a sharp edge go onto it. Boundary and sharp-edge
   * particles that slid in their tangent plane or line go back onto their surface or edge.
   */
  void project(double snap = 0.3)
  {
    if(!boundary_) return;
    const std::size_t n = points.size();
    std::vector<char> check_inside(n, 0);
    auto to_edge = [&](std::size_t i) {
      if(!boundary_->has_sharp_edges()) return;
      const auto e = boundary_->closest_on_sharp_edge(points[i]);
      if(kinds[i] == Particle_kind::SHARP_EDGE ||
         (B(points[i]) * (e.point - points[i])).norm() <= lattice_.sharp_edge_snap * l_) {
        points[i] = e.point;
        kinds[i] = Particle_kind::SHARP_EDGE;
        features[i] = e.feature;
        directions[i] = e.direction;
      }
    };
    parallel_for_each_index(n, [&](std::size_t i) {
      if(kinds[i] == Particle_kind::CORNER) return;
      if(kinds[i] == Particle_kind::SHARP_EDGE) return to_edge(i);
      Eigen::Matrix3d b;
      if(kinds[i] == Particle_kind::FREE) {
        // still inside and farther from the surface than clearance - moved, which B shrinks by
        // at most 1 / |B^-1|_F: farther than snap in the imagined space, nothing to do
        b = B(points[i]);
        if(moved[i] < clearance[i] && clearance[i] - moved[i] > snap * l_ * b.inverse().norm()) return;
      }
      const auto c = boundary_->closest_on_surface(points[i]);
      if(kinds[i] == Particle_kind::FREE) {
        if((b * (c.point - points[i])).norm() > snap * l_) {
          if(moved[i] >= clearance[i]) check_inside[i] = 1; // may have crossed the boundary
          else return;
        }
      }
      if(!check_inside[i]) {
        points[i] = c.point;
        kinds[i] = Particle_kind::BOUNDARY;
        features[i] = c.feature;
        directions[i] = c.direction;
        to_edge(i);
      } else {
        clearance[i] = c.distance;
      }
    });
    // the domain's inside test (in parallel only where the domain allows it)
    std::vector<std::size_t> tested;
    for(std::size_t i = 0; i < n; ++i)
      if(check_inside[i]) tested.push_back(i);
    const std::vector<char> inside =
        inside_tests(*boundary_, tested.size(), [&](std::size_t k) { return points[tested[k]]; });
    parallel_for_each_index(tested.size(), [&](std::size_t k) {
      const std::size_t i = tested[k];
      moved[i] = 0;
      if(inside[k]) return;
      const auto c = boundary_->closest_on_surface(points[i]);
      points[i] = c.point;
      kinds[i] = Particle_kind::BOUNDARY;
      features[i] = c.feature;
      directions[i] = c.direction;
      to_edge(i);
    });
  }

  /// the GHK energy a particle at `c`, where T stretches by at most `stretch_c`, would have
  /// with the particles within R of it (each pair once)
  double energy_at(const Eigen::Vector3d& c, double stretch_c, const std::vector<double>& stretch,
                   const Neighbor_grid& grid, double euclidean_radius) const
  {
    double e = 0;
    grid.for_each_within(c, euclidean_radius, [&](std::size_t j, double d2) {
      if(!may_be_within(d2, stretch_c, stretch[j], radius_)) return;
      const Eigen::Matrix3d b = B(0.5 * (c + points[j]));
      if((b * (c - points[j])).norm() <= radius_ * l_) e += gaussian_hole_pair_energy(lattice_, b, c - points[j], l_, sigma_);
    });
    return e;
  }

private:
  // entrywise, the smaller of two differences of the same sign, else 0 (the minmod limiter):
  // the slope of a smooth field, and the smooth side of a jump
  static Eigen::Matrix3d minmod(const Eigen::Matrix3d& forward, const Eigen::Matrix3d& backward)
  {
    Eigen::Matrix3d d;
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c) {
        const double f = forward(r, c), g = backward(r, c);
        d(r, c) = f * g <= 0 ? 0. : std::abs(f) < std::abs(g) ? f : g;
      }
    return d;
  }

  // B's derivatives at the particles by one-sided differences (steps of 1e-3 l* in the
  // field's space) joined by the minmod limiter: a field given on a mesh (piecewise constant,
  // or with a smooth factor) jumps where the nearest vertex changes, and the difference
  // across a jump is no slope; kept only if the frames stretch (B^T B is not the same multiple
  // of the identity at every particle) and some derivative is not 0; and the positions they
  // were taken at
  void build_frame_derivatives()
  {
    const std::size_t n = points.size();
    derivatives_.clear();
    built_at_.clear();
    if(!frame_derivatives) return;
    std::vector<Eigen::Matrix3d> b_i(n);
    std::vector<double> scale(n);
    std::vector<char> stretches(n, 0);
    parallel_for_each_index(n, [&](std::size_t i) {
      b_i[i] = B(points[i]);
      const Eigen::Matrix3d M = b_i[i].transpose() * b_i[i];
      scale[i] = M.trace() / 3.;
      stretches[i] = (M - scale[i] * Eigen::Matrix3d::Identity()).norm() > 1e-9 * scale[i];
    });
    const bool conformal = std::find(stretches.begin(), stretches.end(), 1) == stretches.end() &&
                           (n == 0 || std::all_of(scale.begin(), scale.end(), [&](double s) {
                              return std::abs(s - scale[0]) <= 1e-9 * scale[0];
                            }));
    if(conformal) return;
    // the surface lattice keeps the central differences its results were measured with (its
    // field is interpolated over faces); the limiter there is not measured yet
    const bool surface_central_differences = lattice_.is_surface_lattice();
    derivatives_.resize(n);
    built_at_.resize(n);
    std::vector<char> varies(n, 0);
    parallel_for_each_index(n, [&](std::size_t i) {
      const Eigen::Matrix3d& b = b_i[i];
      const double step = 1e-3 * l_ / (std::max)(b.norm(), 1e-300);
      for(int c = 0; c < 3; ++c) {
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[c] = step;
        const Eigen::Matrix3d plus = B(points[i] + e), minus = B(points[i] - e);
        derivatives_[i][c] = surface_central_differences ? Eigen::Matrix3d((plus - minus) * (l_ / (2 * step)))
                                                         : Eigen::Matrix3d(minmod(plus - b, b - minus) * (l_ / step));
        if(derivatives_[i][c].norm() > 1e-9 * b.norm()) varies[i] = 1;
      }
      built_at_[i] = points[i] / l_;
    });
    if(std::find(varies.begin(), varies.end(), 1) == varies.end()) {
      derivatives_.clear();
      built_at_.clear();
    }
  }

  const Lattice& lattice_;
  const FrameField& field_;
  const Boundary* boundary_;
  double l_, sigma_, radius_;
  std::vector<Frame_derivative> derivatives_; // empty unless the frames stretch and vary
  std::vector<Eigen::Vector3d> built_at_;     // p / l* when the pairs were built
  std::vector<Pair> pairs_;
  std::vector<std::size_t> start_;
  std::vector<std::int64_t> incident_;
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_SYSTEM_H
