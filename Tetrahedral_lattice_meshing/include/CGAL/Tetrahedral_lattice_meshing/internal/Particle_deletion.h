// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Particle deletion (dissertation Alg. 3): a particle whose nearest
// neighbours (distances in the imagined space, sorted) are closer on average
// than the lattice allows is deleted; neighbours already deleted do not count.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_DELETION_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_DELETION_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Neighbor_grid.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_system.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/// true if the sorted distances `d` (in units of l*) break one of the lattice's deletion rules
inline bool breaks_deletion_rules(const Lattice& lattice, const std::vector<double>& d)
{
  for(const auto& rule : lattice.deletion_rules) {
    if(int(d.size()) < rule.first) break;
    double sum = 0;
    for(int k = 0; k < rule.first; ++k) sum += d[std::size_t(k)];
    if(sum / rule.first < rule.second) return true;
  }
  return false;
}

/*
 * Deletes the particles that break the deletion rules and returns how many. Free particles
 * are examined first, then boundary, then sharp-edge ones (each in index order), so that of
 * two crowded particles the one with more freedom goes; corners are never deleted.
 */
template <class System>
std::size_t delete_particles(System& s)
{
  const std::size_t n = s.size();
  if(n == 0) return 0;
  const double l = s.edge_length();
  const std::vector<double> stretch = s.stretches();
  const double r = s.euclidean_radius(stretch);
  const Neighbor_grid grid(s.points, r);
  // the distance of each pair i < j within R (the rules look no farther), in parallel: one
  // field lookup per pair, at its midpoint
  std::vector<std::vector<std::pair<double, std::size_t>>> above(n);
  parallel_for_each_index(n, [&](std::size_t i) {
    grid.for_each_within(s.points[i], r, [&](std::size_t j, double d2) {
      if(j <= i || (s.kinds[i] == Particle_kind::CORNER && s.kinds[j] == Particle_kind::CORNER) ||
         !s.may_be_within(d2, stretch[i], stretch[j], s.neighbor_radius()))
        return;
      const Eigen::Vector3d v = s.points[i] - s.points[j];
      above[i].emplace_back((s.B(0.5 * (s.points[i] + s.points[j])) * v).norm() / l, j);
    });
  });
  // the sorted neighbour distances of each particle
  std::vector<std::vector<std::pair<double, std::size_t>>> near(n);
  for(std::size_t i = 0; i < n; ++i)
    for(const auto& x : above[i]) {
      near[i].push_back(x);
      near[x.second].emplace_back(x.first, i);
    }
  parallel_for_each_index(n, [&](std::size_t i) { std::sort(near[i].begin(), near[i].end()); });
  std::vector<std::size_t> order;
  for(Particle_kind k : {Particle_kind::FREE, Particle_kind::BOUNDARY, Particle_kind::SHARP_EDGE})
    for(std::size_t i = 0; i < n; ++i)
      if(s.kinds[i] == k) order.push_back(i);
  std::vector<char> deleted(n, 0);
  std::vector<double> d;
  std::size_t count = 0;
  for(std::size_t i : order) {
    d.clear();
    for(const auto& x : near[i])
      if(!deleted[x.second]) d.push_back(x.first);
    if(breaks_deletion_rules(s.lattice(), d)) {
      deleted[i] = 1;
      ++count;
    }
  }
  if(count) s.remove(deleted);
  return count;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_DELETION_H
