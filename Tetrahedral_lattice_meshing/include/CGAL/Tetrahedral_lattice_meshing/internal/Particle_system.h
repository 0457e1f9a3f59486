// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The particles and their GHK energy (dissertation eq. 4.4), minimized by
// L-BFGS (LBFGS++) with the kinds' constraints, then projected onto the
// boundary and the sharp edges (Alg. 2).
//
// Each round freezes the neighbour pairs (within R, widened by the field's
// largest stretch) and the frame of each pair's midpoint, so that L-BFGS
// minimizes a smooth function with its exact gradient; both are renewed at
// the next round. Pairs are evaluated in parallel and summed in a fixed
// order, so the result does not depend on the number of threads.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_SYSTEM_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_SYSTEM_H

#include <CGAL/Tetrahedral_lattice_meshing/Lattice.h>
#include <CGAL/Tetrahedral_lattice_meshing/gaussian_hole_kernel.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Neighbor_grid.h>
#include <CGAL/Tetrahedral_lattice_meshing/lattice_particle_types.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <LBFGS.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

template <class F>
void parallel_for_each_index(std::size_t n, F f)
{
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for(std::size_t i = r.begin(); i != r.end(); ++i) f(i);
  });
}

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
  bool has_sharp_edges() const { return false; }
  Closest closest_on_surface(const Eigen::Vector3d&) const { return Closest(); }
  Closest closest_on_sharp_edge(const Eigen::Vector3d&) const { return Closest(); }
};

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
    Eigen::Matrix3d B; // the frame's inverse at the midpoint, frozen for the round
  };

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

  /// the Euclidean radius that holds every pair within R in the imagined space:
  /// R l* times the largest stretch of T at the particles
  double euclidean_radius() const
  {
    std::vector<double> stretch(points.size(), 0.);
    parallel_for_each_index(points.size(), [&](std::size_t i) {
      const Eigen::Matrix3d t = T(points[i]);
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
      es.computeDirect(t.transpose() * t, Eigen::EigenvaluesOnly);
      stretch[i] = std::sqrt(std::max(es.eigenvalues().maxCoeff(), 0.));
    });
    double s = 0;
    for(double x : stretch) s = std::max(s, x);
    return radius_ * l_ * s;
  }

  /// the pairs of particles within R of each other (in the imagined space), with their B
  void build_pairs()
  {
    const double r = euclidean_radius();
    const Neighbor_grid grid(points, r);
    std::vector<std::vector<Pair>> local(points.size());
    parallel_for_each_index(points.size(), [&](std::size_t i) {
      grid.for_each_within(points[i], r, [&](std::size_t j, double) {
        if(j <= i) return;
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

  /*
   * E = sum_i sum_{j != i} E_ij = 2 sum_pairs E_ij over the frozen pairs, at positions
   * x = p / l*, and its gradient with respect to x (projected on each particle's freedom).
   */
  double energy_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& grad) const
  {
    std::vector<double> e(pairs_.size());
    std::vector<Eigen::Vector3d> g(pairs_.size());
    parallel_for_each_index(pairs_.size(), [&](std::size_t k) {
      const Pair& p = pairs_[k];
      const Eigen::Vector3d u = p.B * (x.segment<3>(3 * p.i) - x.segment<3>(3 * p.j));
      Eigen::Vector3d de;
      e[k] = gaussian_hole_kernel(lattice_, u, sigma_, &de);
      g[k] = p.B.transpose() * de;
    });
    grad.resize(x.size());
    parallel_for_each_index(points.size(), [&](std::size_t i) {
      Eigen::Vector3d gi = Eigen::Vector3d::Zero();
      for(std::size_t s = start_[i]; s < start_[i + 1]; ++s) {
        const std::int64_t k = incident_[s];
        if(k > 0) gi += g[std::size_t(k - 1)];
        else gi -= g[std::size_t(-k - 1)];
      }
      grad.segment<3>(3 * i) = 2. * constrained(i, gi);
    });
    double sum = 0;
    for(double v : e) sum += v;
    return 2. * sum;
  }

  /// the gradient `g` of particle `i` restricted to its freedom
  Eigen::Vector3d constrained(std::size_t i, const Eigen::Vector3d& g) const
  {
    switch(kinds[i]) {
      case Particle_kind::CORNER: return Eigen::Vector3d::Zero();
      case Particle_kind::SHARP_EDGE: return g.dot(directions[i]) * directions[i];
      case Particle_kind::BOUNDARY: return g - g.dot(directions[i]) * directions[i];
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
   * particle is under eps_g, or after max_iterations (0: no bound). A failed line search
   * ends the run at the best point seen.
   */
  Round_result lbfgs_round(double eps_g, int max_iterations)
  {
    build_pairs();
    Round_result r;
    if(points.empty()) return r;
    Eigen::VectorXd x = positions();
    Eigen::VectorXd best_x = x;
    double best_e = std::numeric_limits<double>::infinity();
    auto f = [&](const Eigen::VectorXd& y, Eigen::VectorXd& grad) {
      const double e = energy_and_gradient(y, grad);
      if(e < best_e) {
        best_e = e;
        best_x = y;
      }
      return e;
    };
    LBFGSpp::LBFGSParam<double> param;
    param.epsilon = eps_g * std::sqrt(double(points.size()));
    param.epsilon_rel = 0;
    param.max_iterations = max_iterations;
    param.max_linesearch = 30;
    LBFGSpp::LBFGSSolver<double> solver(param);
    double fx = 0;
    try {
      r.iterations = solver.minimize(f, x, fx);
    } catch(const std::runtime_error&) { // a line search that cannot progress: keep the best point
      r.iterations = max_iterations;
    } catch(const std::logic_error&) {
      r.iterations = max_iterations;
    }
    for(std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d p = best_x.template segment<3>(3 * i) * l_;
      moved[i] += (p - points[i]).norm();
      points[i] = p;
    }
    Eigen::VectorXd grad;
    r.energy = energy_and_gradient(best_x, grad);
    r.gradient_norm = grad.norm();
    return r;
  }

  /*
   * After a round (Alg. 2, end): particles outside the domain, or within 0.3 l* of the
   * boundary (in the imagined space), go onto the surface and become boundary particles;
   * boundary particles within 0.3 l* of a sharp edge go onto it. Boundary and sharp-edge
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
      if(kinds[i] == Particle_kind::SHARP_EDGE || (B(points[i]) * (e.point - points[i])).norm() <= snap * l_) {
        points[i] = e.point;
        kinds[i] = Particle_kind::SHARP_EDGE;
        features[i] = e.feature;
        directions[i] = e.direction;
      }
    };
    parallel_for_each_index(n, [&](std::size_t i) {
      if(kinds[i] == Particle_kind::CORNER) return;
      if(kinds[i] == Particle_kind::SHARP_EDGE) return to_edge(i);
      const auto c = boundary_->closest_on_surface(points[i]);
      if(kinds[i] == Particle_kind::FREE) {
        if((B(points[i]) * (c.point - points[i])).norm() > snap * l_) {
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
    // the domain's inside test, sequential (it need not be thread-safe)
    for(std::size_t i = 0; i < n; ++i) {
      if(!check_inside[i]) continue;
      moved[i] = 0;
      if(boundary_->inside(points[i])) continue;
      const auto c = boundary_->closest_on_surface(points[i]);
      points[i] = c.point;
      kinds[i] = Particle_kind::BOUNDARY;
      features[i] = c.feature;
      directions[i] = c.direction;
      to_edge(i);
    }
  }

  /// the GHK energy a particle at `c` would have with the particles near it (each pair once)
  double energy_at(const Eigen::Vector3d& c, const Neighbor_grid& grid, double euclidean_radius) const
  {
    double e = 0;
    grid.for_each_within(c, euclidean_radius, [&](std::size_t j, double) {
      e += gaussian_hole_pair_energy(lattice_, B(0.5 * (c + points[j])), c - points[j], l_, sigma_);
    });
    return e;
  }

private:
  const Lattice& lattice_;
  const FrameField& field_;
  const Boundary* boundary_;
  double l_, sigma_, radius_;
  std::vector<Pair> pairs_;
  std::vector<std::size_t> start_;
  std::vector<std::int64_t> incident_;
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_SYSTEM_H
