// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The particle-based lattice optimization (dissertation Alg. 5 and its
// multiresolution start): random particles in the domain, rounds of L-BFGS
// (Alg. 2), deletion (Alg. 3) and insertion (Alg. 4) until they stop
// changing, first at 2^k l*, then refined level by level down to l*.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_LATTICE_OPTIMIZER_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_LATTICE_OPTIMIZER_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Boundary_samples.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_deletion.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_insertion.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_system.h>
#include <CGAL/Tetrahedral_lattice_meshing/lattice_particle_types.h>

#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/// the named parameters of `lattice_particles_3()`, each field named as its parameter
struct Lattice_options
{
  double kernel_width = -1;           // sigma in units of l*; < 0: the lattice's
  double neighbor_radius = -1;        // in units of l*; < 0: the lattice's
  int multiresolution_levels = 0;     // k: start at 2^k l*
  int number_of_iterations = -1;      // MaxRoundNum; < 0: 16 at the first level, 8 after
  double maximum_running_time = 0;    // seconds, 0: none
  unsigned random_seed = 0;
  bool verbose = false;
  std::function<bool(const Lattice_round_report&)> visitor; // false: stop
};

/// the volume of the domain measured in the imagined space, \f$ \int |\det B| \f$, over the boundary's cells
template <class Boundary, class FrameField, class Point_3>
double imagined_volume(const Boundary& boundary, const FrameField& field)
{
  const auto& cells = boundary.cells();
  std::vector<double> v(cells.size());
  parallel_for_each_index(cells.size(), [&](std::size_t k) {
    const auto& p = cells[k];
    const Eigen::Vector3d c = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    const Eigen::Matrix3d B = field.B(Point_3(c[0], c[1], c[2]));
    v[k] = std::abs(B.determinant() * (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0]))) / 6.;
  });
  return std::accumulate(v.begin(), v.end(), 0.);
}

/// the area of the domain's boundary measured in the imagined space, over the boundary's triangles
template <class Boundary, class FrameField, class Point_3>
double imagined_area(const Boundary& boundary, const FrameField& field)
{
  const auto& triangles = boundary.triangles();
  std::vector<double> a(triangles.size());
  parallel_for_each_index(triangles.size(), [&](std::size_t k) {
    const auto& t = triangles[k];
    const Eigen::Vector3d p0 = to_vector(t[0].x(), t[0].y(), t[0].z()), p1 = to_vector(t[1].x(), t[1].y(), t[1].z()),
                          p2 = to_vector(t[2].x(), t[2].y(), t[2].z()), c = (p0 + p1 + p2) / 3.;
    const Eigen::Matrix3d B = field.B(Point_3(c[0], c[1], c[2]));
    a[k] = 0.5 * (B * (p1 - p0)).cross(B * (p2 - p0)).norm();
  });
  return std::accumulate(a.begin(), a.end(), 0.);
}

/// the length of the domain's sharp edges measured in the imagined space
template <class Boundary, class FrameField, class Point_3>
double imagined_sharp_edge_length(const Boundary& boundary, const FrameField& field)
{
  double length = 0;
  for(const auto& s : boundary.segments()) {
    const Eigen::Vector3d a = to_vector(s[0].x(), s[0].y(), s[0].z()), b = to_vector(s[1].x(), s[1].y(), s[1].z()),
                          m = 0.5 * (a + b);
    length += (field.B(Point_3(m[0], m[1], m[2])) * (b - a)).norm();
  }
  return length;
}

/// what the number of particles of a lattice depends on, measured in the imagined space
struct Domain_measures
{
  double volume = 0, area = 0, sharp_edge_length = 0;
  std::size_t number_of_corners = 0;
};

template <class Boundary, class FrameField, class Point_3>
Domain_measures domain_measures(const Boundary& boundary, const FrameField& field)
{
  Domain_measures m;
  m.volume = imagined_volume<Boundary, FrameField, Point_3>(boundary, field);
  m.area = imagined_area<Boundary, FrameField, Point_3>(boundary, field);
  m.sharp_edge_length = imagined_sharp_edge_length<Boundary, FrameField, Point_3>(boundary, field);
  m.number_of_corners = boundary.corners().size();
  return m;
}

/// the number of particles of a lattice of edge `l` in a domain: the volume's, plus the
/// boundary's closing layer, plus the closing rows of the sharp edges and the corners (a
/// lattice filling a box of n^3 cells: BCC (n+1)^3 + n^3, FCC 4n^3 + 6n^2 + 3n + 1, cubic (n+1)^3)
inline double lattice_particle_count(const Lattice& lattice, const Domain_measures& m, double l)
{
  return m.volume * lattice.particles_per_cube / (l * l * l) + m.area * lattice.particles_per_boundary_square / (l * l) +
         m.sharp_edge_length / (4 * l) + double(m.number_of_corners) / 8;
}

/// the edge length whose lattice has `n` particles (the inverse of `lattice_particle_count()`)
inline double lattice_edge_length(const Lattice& lattice, const Domain_measures& m, double n)
{
  // n = a x^3 + b x^2 + c x + d in x = 1/l, increasing: Newton from the volume-only root, above it
  const double a = m.volume * lattice.particles_per_cube, b = m.area * lattice.particles_per_boundary_square,
               c = m.sharp_edge_length / 4, d = double(m.number_of_corners) / 8;
  if(!(n > d)) return std::numeric_limits<double>::infinity();
  double x = a > 0 ? std::cbrt(n / a) : b > 0 ? std::sqrt(n / b) : (n - d) / c; // (a surface has no volume)
  for(int i = 0; i < 100; ++i) {
    const double f = ((a * x + b) * x + c) * x + d - n, df = (3 * a * x + 2 * b) * x + c;
    const double step = f / df;
    x -= step;
    if(std::abs(step) < 1e-14 * x) break;
  }
  return 1. / x;
}

template <class FrameField, class Boundary, class Point_3>
class Lattice_optimizer
{
  typedef Particle_system<FrameField, Boundary, Point_3> System;

public:
  Lattice_optimizer(const Lattice& lattice, const FrameField& field, const Boundary& boundary, double l_star,
                    const Lattice_options& options)
    : lattice_(lattice), field_(field), boundary_(boundary), l_(l_star), o_(options)
  {}

  Lattice_particles_3<Point_3> run()
  {
    optimize();
    return finish();
  }

  /// Alg. 5 at every level but the last round of the finest one (the L-BFGS to convergence);
  /// returns the energy per particle reached, by which `lattice_particles_3()` compares two starts
  double optimize()
  {
    timer_.start();
    const double sigma = o_.kernel_width > 0 ? o_.kernel_width : lattice_.sigma;
    const double radius = o_.neighbor_radius > 0 ? o_.neighbor_radius : lattice_.neighbor_radius;
    double l = l_;
    // the corners are particles at every level: where they outnumber a coarse level's own
    // particles more than sixteen times (a features angle that makes most edges sharp), each meets
    // as many times a lattice's neighbours there and the pairs outgrow the memory; the run
    // then starts from the coarsest level where they do not
    const std::size_t corners = boundary_.corners().size();
    for(;;) {
      l = l_ * std::pow(2., o_.multiresolution_levels);
      system_ = std::make_unique<System>(lattice_, field_, &boundary_, l, sigma, radius);
      random_start(*system_);
      if(o_.multiresolution_levels == 0 || corners <= 16 * (system_->size() - corners)) break;
      --o_.multiresolution_levels;
    }
    for(int level = o_.multiresolution_levels; level >= 0; --level) {
      if(level < o_.multiresolution_levels) { // refine: the sites of the lattice of half the edge length
        auto finer = std::make_unique<System>(lattice_, field_, &boundary_, l / 2, sigma, radius);
        finer->points = system_->points;
        finer->kinds = system_->kinds;
        finer->features = system_->features;
        finer->directions = system_->directions;
        finer->clearance = system_->clearance;
        finer->moved = system_->moved;
        refine(*finer);
        system_ = std::move(finer);
        l /= 2;
      }
      // a cubic lattice's coarsest level, from random positions, keeps each round's frames:
      // its moves span much of a spacing over which the field changes a lot, and the
      // first-order frames of the exact gradient then settle it into ill-fitting lattice rows
      // whose dislocations the finer levels inherit (BCC, FCC and surface lattices keep the exact
      // gradient: frozen frames did not help them, see benchmark/Hex_dominant_meshing/RESULTS.md)
      system_->frame_derivatives = lattice_.type != Lattice_type::CUBIC || level < o_.multiresolution_levels ||
                                   o_.multiresolution_levels == 0;
      const int max_rounds = o_.number_of_iterations >= 0 ? o_.number_of_iterations : (level == o_.multiresolution_levels ? 16 : 8);
      out_.number_of_rounds += optimize_level(*system_, level, max_rounds, level > 0);
      if(must_stop()) {
        record_stop();
        break;
      }
    }
    return energy_per_particle();
  }

  /// the time limit was reached or the visitor asked to stop
  bool stopped() const { return out_.time_limit_reached || out_.stopped_by_visitor; }
  bool stopped_by_visitor() const { return out_.stopped_by_visitor; }
  /// the visitor asked another run to stop: this one stops too (`finish()` runs no last round)
  void request_stop() { stop_requested_ = true; }
  /// the rounds run so far
  int number_of_rounds() const { return out_.number_of_rounds; }
  /// the levels of the run: those asked for, fewer where the corners outnumber a coarse level
  int multiresolution_levels() const { return o_.multiresolution_levels; }

  /// the last round (unless the time is up) and the particles
  Lattice_particles_3<Point_3> finish()
  {
    if(!stopped()) {
      if(must_stop()) record_stop();
      else {
        lattice_round(*system_, 0, last_round_number_, 1e-4, 100, 0, 0); // to convergence
        ++out_.number_of_rounds;
      }
    }
    // the final projection may bring two particles together: keep one
    remove_coincident(*system_);
    Lattice_particles_3<Point_3> out = out_;
    out.lattice = lattice_;
    out.edge_length = l_;
    out.multiresolution_levels = o_.multiresolution_levels;
    for(std::size_t i = 0; i < system_->size(); ++i) {
      const Eigen::Vector3d& p = system_->points[i];
      out.points.emplace_back(p[0], p[1], p[2]);
    }
    out.kinds = system_->kinds;
    out.features = system_->features;
    out.energy = energy_per_particle();
    out.time = timer_.time();
    return out;
  }

private:
  bool must_stop() const { return stop_requested_ || (o_.maximum_running_time > 0 && timer_.time() > o_.maximum_running_time); }
  void record_stop()
  {
    if(stop_requested_) out_.stopped_by_visitor = true;
    else out_.time_limit_reached = true;
  }

  // the corners as fixed particles, then the volume's share of particles (a surface lattice: the
  // area's) uniformly in the imagined space: a cell (triangle) drawn by its imagined measure, a
  // uniform point in it; insertion fills the boundary layer (a denser start settles in more defects)
  void random_start(System& s)
  {
    const double l = s.edge_length();
    if(lattice_.is_surface_lattice()) {
      const auto& triangles = boundary_.triangles();
      auto corner = [&](std::size_t k, int i) { const auto& p = triangles[k][i]; return to_vector(p.x(), p.y(), p.z()); };
      random_start_by_measure(
          s, triangles.size(), lattice_.particles_per_boundary_square, l * l,
          [&](std::size_t k) {
            const Eigen::Matrix3d B = s.B((corner(k, 0) + corner(k, 1) + corner(k, 2)) / 3.);
            return 0.5 * (B * (corner(k, 1) - corner(k, 0))).cross(B * (corner(k, 2) - corner(k, 0))).norm();
          },
          [&](std::size_t k, CGAL::Random& random) {
            double a = random.get_double(), b = random.get_double();
            if(a + b > 1) { a = 1 - a; b = 1 - b; }
            s.add(corner(k, 0) + a * (corner(k, 1) - corner(k, 0)) + b * (corner(k, 2) - corner(k, 0)), Particle_kind::BOUNDARY,
                  boundary_.triangle_patches()[k], boundary_.triangle_normals()[k]);
          });
      return;
    }
    const auto& cells = boundary_.cells();
    random_start_by_measure(
        s, cells.size(), lattice_.particles_per_cube, l * l * l,
        [&](std::size_t k) {
          const auto& p = cells[k];
          const Eigen::Vector3d c = 0.25 * (p[0] + p[1] + p[2] + p[3]);
          return std::abs(s.B(c).determinant() * (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0]))) / 6.;
        },
        [&](std::size_t k, CGAL::Random& random) {
          // a uniform point of a tetrahedron (Rocchini and Cignoni's folding of the unit cube)
          double a = random.get_double(), b = random.get_double(), d = random.get_double();
          if(a + b > 1) { a = 1 - a; b = 1 - b; }
          if(b + d > 1) { const double t2 = d; d = 1 - a - b; b = 1 - t2; }
          else if(a + b + d > 1) { const double t2 = d; d = a + b + d - 1; a = 1 - b - t2; }
          const auto& p = cells[k];
          s.add(p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]) + d * (p[3] - p[0]), Particle_kind::FREE);
        });
  }

  // the corners, then measure * density / unit particles, each added by `add(k, random)` in an
  // element k drawn in proportion to `measure(k)`
  template <class Measure, class Add>
  void random_start_by_measure(System& s, std::size_t elements, double density, double unit, const Measure& measure,
                               const Add& add)
  {
    std::vector<double> w(elements);
    for(std::size_t k = 0; k < elements; ++k) w[k] = measure(k);
    std::partial_sum(w.begin(), w.end(), w.begin());
    const double total = w.empty() ? 0. : w.back();
    const std::size_t n = std::size_t(std::llround(total * density / unit));
    for(std::size_t k = 0; k < boundary_.corners().size(); ++k)
      s.add(boundary_.corners()[k], Particle_kind::CORNER, boundary_.corner_numbers()[k]);
    CGAL::Random random(o_.random_seed);
    for(std::size_t k = 0; k < n && total > 0; ++k) {
      const double t = random.get_double(0, total);
      add(std::min(std::size_t(std::upper_bound(w.begin(), w.end(), t) - w.begin()), elements - 1), random);
    }
    s.project();
  }

  void refine(System& s) { insert_particles(s, std::numeric_limits<double>::infinity()); }

  void remove_coincident(System& s)
  {
    Lattice strict = lattice_;
    strict.deletion_rules.resize(1); // the nearest neighbour closer than half l_closest
    System copy(strict, field_, &boundary_, s.edge_length(), s.sigma(), s.neighbor_radius());
    copy.points = s.points;
    copy.kinds = s.kinds;
    copy.features = s.features;
    copy.directions = s.directions;
    copy.clearance = s.clearance;
    copy.moved = s.moved;
    if(delete_particles(copy) == 0) return;
    s.points = copy.points;
    s.kinds = copy.kinds;
    s.features = copy.features;
    s.directions = copy.directions;
    s.clearance = copy.clearance;
    s.moved = copy.moved;
  }

  double energy_per_particle()
  {
    if(system_->size() == 0) return 0.;
    system_->build_pairs();
    Eigen::VectorXd g;
    return system_->energy_and_gradient(system_->positions(), g) / double(system_->size());
  }

  // a round of L-BFGS, the projection, and its report
  void lattice_round(System& s, int level, int r, double eps, int its, std::size_t deleted, std::size_t inserted)
  {
    const auto res = s.lbfgs_round(eps, its);
    s.project();
    Lattice_round_report rep;
    rep.stage = VVM::Stage::PARTICLES;
    rep.level = level;
    rep.round = r;
    rep.energy = s.size() ? res.energy / double(s.size()) : 0.;
    rep.number_of_particles = s.size();
    rep.number_deleted = deleted;
    rep.number_inserted = inserted;
    rep.lbfgs_iterations = res.iterations;
    rep.elapsed_time = timer_.time();
    if(o_.verbose)
      std::cerr << "  lattice level " << level << " round " << r << ": " << s.size() << " particles (-" << deleted
                << " +" << inserted << "), energy/particle " << rep.energy << ", " << res.iterations
                << " L-BFGS its, " << rep.elapsed_time << " s\n";
    if(o_.visitor && !o_.visitor(rep)) stop_requested_ = true;
  }

  // Alg. 5 at one edge length, with its last round or not (then `finish()` runs it); returns
  // the number of rounds
  int optimize_level(System& s, int level, int max_rounds, bool last_round)
  {
    int rounds = 1;
    lattice_round(s, level, 0, 1e-2, 13, 0, 0);
    for(int r = 0; r < max_rounds && !must_stop(); ++r) {
      const std::size_t deleted = delete_particles(s);
      const std::size_t inserted = insert_particles(s);
      if(deleted + inserted == 0) break;
      lattice_round(s, level, r + 1, 1e-2, r + 1 < 5 ? 13 : 8, deleted, inserted);
      ++rounds;
    }
    last_round_number_ = rounds;
    if(last_round && !must_stop()) {
      lattice_round(s, level, rounds, 1e-4, 100, 0, 0); // the last round, to convergence
      ++rounds;
    }
    return rounds;
  }

  const Lattice& lattice_;
  const FrameField& field_;
  const Boundary& boundary_;
  double l_;
  Lattice_options o_;
  CGAL::Real_timer timer_;
  std::unique_ptr<System> system_;
  Lattice_particles_3<Point_3> out_; // the counters so far
  int last_round_number_ = 0;
  bool stop_requested_ = false; // by the visitor
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_LATTICE_OPTIMIZER_H
