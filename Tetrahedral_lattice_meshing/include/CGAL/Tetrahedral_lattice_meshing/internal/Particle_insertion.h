// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Particle insertion (dissertation Alg. 4): the empty one-ring sites of every
// particle, along its frame, are candidates; those far enough from every
// particle are taken by ascending GHK energy, under the energy threshold and
// far enough from the candidates taken before them. Also the refinement
// between multiresolution levels (Alg. 5's text), which takes every empty site
// (best first, so that sites projected onto the boundary do not take a lattice site's place).

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_INSERTION_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_INSERTION_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Neighbor_grid.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_system.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

struct Insertion_candidate
{
  Eigen::Vector3d point;
  Particle_kind kind = Particle_kind::FREE;
  int feature = -1;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double energy = 0;
  double stretch = 0; // T's largest stretch at the particle whose one-ring holds the site
};

/*
 * The one-ring sites p_i + l* T(p_i) h_k, each at least `min_distance` l* (imagined space)
 * from every particle; sites outside the domain go onto its boundary (and are kept only
 * if still that far). In particle order, then hole order.
 */
template <class System>
std::vector<Insertion_candidate> empty_sites(const System& s, double min_distance, const std::vector<double>& stretch,
                                             const Neighbor_grid& grid, double euclidean_radius)
{
  const std::size_t n = s.size();
  const double l = s.edge_length();
  // the particles that may be too near, the nearest first: an occupied site's occupant is
  // usually that one, so that few of them cost a field lookup
  auto far_enough = [&](const Eigen::Vector3d& c, double stretch_c) {
    thread_local std::vector<std::pair<double, std::size_t>> near;
    near.clear();
    grid.for_each_within(c, euclidean_radius, [&](std::size_t j, double d2) {
      if(s.may_be_within(d2, stretch_c, stretch[j], min_distance)) near.emplace_back(d2, j);
    });
    if(!near.empty()) std::iter_swap(near.begin(), std::min_element(near.begin(), near.end()));
    for(const auto& x : near) {
      const std::size_t j = x.second;
      if((s.B(0.5 * (c + s.points[j])) * (c - s.points[j])).norm() <= min_distance * l) return false;
    }
    return true;
  };
  std::vector<std::vector<Insertion_candidate>> local(n);
  parallel_for_each_index(n, [&](std::size_t i) {
    const Eigen::Matrix3d T = s.T(s.points[i]);
    for(const Eigen::Vector3d& h : s.lattice().one_ring) {
      Insertion_candidate c;
      c.point = s.points[i] + l * (T * h);
      c.stretch = stretch[i];
      if(far_enough(c.point, c.stretch)) local[i].push_back(c);
    }
  });
  std::vector<Insertion_candidate> sites;
  for(auto& site : local) sites.insert(sites.end(), site.begin(), site.end());
  if(!s.boundary()) return sites;
  const std::vector<char> inside =
      inside_tests(*s.boundary(), sites.size(), [&](std::size_t k) { return sites[k].point; });
  std::vector<char> keep(sites.size(), 1);
  parallel_for_each_index(sites.size(), [&](std::size_t k) {
    if(inside[k]) return;
    Insertion_candidate& c = sites[k];
    const auto b = s.boundary()->closest_on_surface(c.point);
    c.point = b.point;
    c.kind = Particle_kind::BOUNDARY;
    c.feature = b.feature;
    c.direction = b.direction;
    if(s.boundary()->has_sharp_edges()) { // near a sharp edge: on it, as the projection would put it
      const auto e = s.boundary()->closest_on_sharp_edge(c.point);
      if((s.B(c.point) * (e.point - c.point)).norm() <= s.lattice().sharp_edge_snap * l) {
        c.point = e.point;
        c.kind = Particle_kind::SHARP_EDGE;
        c.feature = e.feature;
        c.direction = e.direction;
      }
    }
    keep[k] = far_enough(c.point, c.stretch);
  });
  std::vector<Insertion_candidate> out;
  for(std::size_t k = 0; k < sites.size(); ++k)
    if(keep[k]) out.push_back(sites[k]);
  return out;
}

/// keeps the candidates, in the given order, that are at least `min_distance` l* from those kept
template <class System>
std::vector<Insertion_candidate> spread(const System& s, const std::vector<Insertion_candidate>& candidates,
                                        const std::vector<std::size_t>& order, double min_distance,
                                        double euclidean_radius)
{
  const double l = s.edge_length(), h = std::max(euclidean_radius, 1e-300);
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  auto cell = [&](const Eigen::Vector3d& p, int a) { return std::int64_t(std::floor(p[a] / h)); };
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return ((x & 0x1FFFFF) << 42) | ((y & 0x1FFFFF) << 21) | (z & 0x1FFFFF);
  };
  std::vector<Insertion_candidate> kept;
  for(std::size_t k : order) {
    const Insertion_candidate& c = candidates[k];
    bool ok = true;
    const std::int64_t cx = cell(c.point, 0), cy = cell(c.point, 1), cz = cell(c.point, 2);
    for(std::int64_t x = cx - 1; ok && x <= cx + 1; ++x)
      for(std::int64_t y = cy - 1; ok && y <= cy + 1; ++y)
        for(std::int64_t z = cz - 1; ok && z <= cz + 1; ++z) {
          auto it = cells.find(key(x, y, z));
          if(it == cells.end()) continue;
          for(std::size_t m : it->second) {
            const Eigen::Vector3d v = c.point - kept[m].point;
            if(s.may_be_within(v.squaredNorm(), c.stretch, kept[m].stretch, min_distance) &&
               (s.B(c.point - 0.5 * v) * v).norm() <= min_distance * l) {
              ok = false;
              break;
            }
          }
        }
    if(!ok) continue;
    cells[key(cx, cy, cz)].push_back(kept.size());
    kept.push_back(c);
  }
  return kept;
}

/*
 * Alg. 4: inserts particles at empty one-ring sites, by ascending energy, those under the
 * energy threshold `max_energy` (the lattice's e_ins by default; +infinity takes every site,
 * as the refinement between multiresolution levels does). Returns how many.
 */
template <class System>
std::size_t insert_particles(System& s, double max_energy)
{
  if(s.size() == 0) return 0;
  const std::vector<double> stretch = s.stretches();
  const double r = s.euclidean_radius(stretch);
  const double d_ins = s.lattice().insertion_distance;
  const Neighbor_grid grid(s.points, r);
  // a particle within d_ins in the imagined space is within d_ins / R of the pairs' Euclidean
  // radius (both scale with the field's largest stretch): the sites' search needs no more
  // (it was a fifth of the particle optimization's time)
  std::vector<Insertion_candidate> candidates =
      empty_sites(s, d_ins, stretch, grid, r * (std::min)(1., d_ins / s.neighbor_radius()));
  parallel_for_each_index(candidates.size(), [&](std::size_t k) {
    candidates[k].energy = s.energy_at(candidates[k].point, candidates[k].stretch, stretch, grid, r);
  });
  std::vector<std::size_t> order;
  for(std::size_t k = 0; k < candidates.size(); ++k)
    if(candidates[k].energy < max_energy) order.push_back(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return candidates[a].energy < candidates[b].energy; });
  const std::vector<Insertion_candidate> kept = spread(s, candidates, order, d_ins, r);
  for(const Insertion_candidate& c : kept) s.add(c.point, c.kind, c.feature, c.direction);
  return kept.size();
}

template <class System>
std::size_t insert_particles(System& s)
{
  return insert_particles(s, s.lattice().insertion_energy);
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_INSERTION_H
