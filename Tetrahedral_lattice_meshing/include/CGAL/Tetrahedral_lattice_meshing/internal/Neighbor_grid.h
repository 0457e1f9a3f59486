// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fixed-radius neighbour search among particles: a cell list with cells of the
// search radius, points sorted by cell, so a query visits 27 cells. Rebuilt
// each round; queries are const (run from several threads) and list the
// points in a fixed order.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_NEIGHBOR_GRID_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_NEIGHBOR_GRID_H

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

class Neighbor_grid
{
public:
  Neighbor_grid() = default;

  /// the grid of `points` (copied); `radius` is the largest query radius
  Neighbor_grid(const std::vector<Eigen::Vector3d>& points, double radius)
  {
    if(points.empty()) return;
    lo_ = points[0];
    Eigen::Vector3d hi = points[0];
    for(const Eigen::Vector3d& p : points) {
      lo_ = lo_.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    // cells no smaller than the radius, and not more of them than 8 per point
    h_ = std::max(radius, 1e-300);
    for(;;) {
      double n = 1;
      for(int a = 0; a < 3; ++a) {
        dims_[a] = std::int64_t(std::floor((hi[a] - lo_[a]) / h_)) + 1;
        n *= double(dims_[a]);
      }
      if(n <= 8. * double(points.size()) + 64) break;
      h_ *= 1.5;
    }
    // counting sort of the points by cell, in index order within a cell
    std::vector<std::int64_t> keys(points.size());
    start_.assign(std::size_t(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
    for(std::size_t i = 0; i < points.size(); ++i) {
      keys[i] = key(cell_of(points[i]));
      ++start_[std::size_t(keys[i]) + 1];
    }
    for(std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(points.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for(std::size_t i = 0; i < points.size(); ++i) order_[fill[std::size_t(keys[i])]++] = i;
    sorted_points_.resize(points.size());
    for(std::size_t s = 0; s < order_.size(); ++s) sorted_points_[s] = points[order_[s]];
  }

  bool empty() const { return order_.empty(); }

  /// calls `f(j, squared distance)` for every point `j` within `radius` of `p`
  template <class F>
  void for_each_within(const Eigen::Vector3d& p, double radius, F f) const
  {
    any_within(p, radius, [&f](std::size_t j, double d2) {
      f(j, d2);
      return false;
    });
  }

  /// `true` if `found(j, squared distance)` is `true` for some point `j` within `radius` of
  /// `p`; stops at the first
  template <class F>
  bool any_within(const Eigen::Vector3d& p, double radius, F found) const
  {
    if(order_.empty()) return false;
    const double r2 = radius * radius;
    const int span = int(std::ceil(radius / h_));
    const std::array<std::int64_t, 3> c = cell_of(p);
    for(std::int64_t x = c[0] - span; x <= c[0] + span; ++x) {
      if(x < 0 || x >= dims_[0]) continue;
      for(std::int64_t y = c[1] - span; y <= c[1] + span; ++y) {
        if(y < 0 || y >= dims_[1]) continue;
        for(std::int64_t z = c[2] - span; z <= c[2] + span; ++z) {
          if(z < 0 || z >= dims_[2]) continue;
          const std::size_t k = std::size_t(key({x, y, z}));
          for(std::size_t s = start_[k]; s < start_[k + 1]; ++s) {
            const std::size_t j = order_[s];
            const double d2 = (sorted_points_[s] - p).squaredNorm();
            if(d2 <= r2 && found(j, d2)) return true;
          }
        }
      }
    }
    return false;
  }

private:
  std::array<std::int64_t, 3> cell_of(const Eigen::Vector3d& p) const
  {
    std::array<std::int64_t, 3> c;
    for(int a = 0; a < 3; ++a) {
      const double t = std::floor((p[a] - lo_[a]) / h_);
      c[a] = std::int64_t(std::clamp(t, -1., double(dims_[a]))); // outside: one cell beyond (NaN: 0)
      if(!(t == t)) c[a] = 0;
    }
    return c;
  }
  std::int64_t key(const std::array<std::int64_t, 3>& c) const { return (c[0] * dims_[1] + c[1]) * dims_[2] + c[2]; }

  Eigen::Vector3d lo_ = Eigen::Vector3d::Zero();
  double h_ = 1;
  std::array<std::int64_t, 3> dims_{{1, 1, 1}};
  std::vector<std::size_t> order_, start_;
  std::vector<Eigen::Vector3d> sorted_points_; // the points in the order of order_: a query reads them in sequence
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_NEIGHBOR_GRID_H
