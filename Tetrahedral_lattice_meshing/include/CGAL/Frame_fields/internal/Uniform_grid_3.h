// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The constant-time lookup of a discrete frame field (dissertation 4.4.3): a
// regular grid over the mesh's bounding box, about one element per grid cell,
// each grid cell listing the elements whose bounding box meets it.

#ifndef CGAL_FRAME_FIELDS_INTERNAL_UNIFORM_GRID_3_H
#define CGAL_FRAME_FIELDS_INTERNAL_UNIFORM_GRID_3_H

#include <CGAL/assertions.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

class Uniform_grid_3
{
public:
  Uniform_grid_3() = default;

  /// a grid over the boxes [lo[i], hi[i]], with about as many grid cells as boxes
  Uniform_grid_3(const std::vector<Eigen::Vector3d>& lo, const std::vector<Eigen::Vector3d>& hi)
  {
    if(lo.empty()) return;
    origin_ = lo[0];
    Eigen::Vector3d top = hi[0];
    for(std::size_t i = 0; i < lo.size(); ++i) {
      origin_ = origin_.cwiseMin(lo[i]);
      top = top.cwiseMax(hi[i]);
    }
    const Eigen::Vector3d extent = (top - origin_).cwiseMax(1e-300);
    // cubic grid cells, as many as elements; a flat set of points gets one layer
    const double volume = extent.prod();
    double h = std::cbrt(volume / double(lo.size()));
    if(!(h > 0) || !std::isfinite(h)) h = extent.maxCoeff() / std::cbrt(double(lo.size()));
    if(!(h > 0) || !std::isfinite(h)) h = 1;
    // flat or needle-like sets: coarsen until the grid holds O(n) cells
    const double most_cells = 8. * double(lo.size()) + 64;
    while(set_dimensions(extent, h) > most_cells) h *= 1.5;
    // points filling a small part of their box (a domain's vertices, say): finer, until an
    // occupied grid cell holds about two of them, so that nearest() looks at few points
    const bool points = std::equal(lo.begin(), lo.end(), hi.begin());
    const double per_cell = points ? double(lo.size()) / double(occupied_cells(lo)) : 0.;
    if(per_cell > 2) {
      const double finer = h / std::cbrt(per_cell / 2);
      if(set_dimensions(extent, finer) > most_cells) set_dimensions(extent, h);
    }
    // counting sort of the (element, grid cell) pairs into CSR arrays
    offsets_.assign(std::size_t(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    for(int pass = 0; pass < 2; ++pass) {
      std::vector<std::size_t> fill;
      if(pass == 1) {
        for(std::size_t c = 1; c < offsets_.size(); ++c) offsets_[c] += offsets_[c - 1];
        items_.resize(offsets_.back());
        fill.assign(offsets_.begin(), offsets_.end() - 1);
      }
      for(std::size_t i = 0; i < lo.size(); ++i) {
        const std::array<int, 3> a = index_of(lo[i]), b = index_of(hi[i]);
        for(int x = a[0]; x <= b[0]; ++x)
          for(int y = a[1]; y <= b[1]; ++y)
            for(int z = a[2]; z <= b[2]; ++z) {
              const std::size_t c = linear({x, y, z});
              if(pass == 0) ++offsets_[c + 1];
              else items_[fill[c]++] = i;
            }
      }
    }
    // a point grid keeps its points in grid order: nearest() reads them one after another
    if(points) {
      item_points_.resize(items_.size());
      for(std::size_t k = 0; k < items_.size(); ++k) item_points_[k] = lo[items_[k]];
    }
  }

  bool empty() const { return items_.empty(); }

  /// the grid cell of p, clamped to the grid
  std::array<int, 3> index_of(const Eigen::Vector3d& p) const
  {
    std::array<int, 3> i;
    for(int a = 0; a < 3; ++a) {
      const double t = (p[a] - origin_[a]) / cell_size_[a];
      i[a] = t > 0 ? int(std::min(std::floor(t), double(dims_[a] - 1))) : 0;
    }
    return i;
  }

  /// the elements listed in the grid cell of p
  template <class F>
  void for_each_in_cell(const Eigen::Vector3d& p, F f) const
  {
    const std::size_t c = linear(index_of(p));
    for(std::size_t k = offsets_[c]; k < offsets_[c + 1]; ++k) f(items_[k]);
  }

  /// the index minimizing (squared distance(p, point(i)), i) over the points this grid
  /// was built on (boxes lo = hi); -1 if there are none or the grid holds boxes. Visits
  /// shells of grid cells around p's cell until no unvisited cell can hold a nearer point.
  /// `p` must be finite; far from the grid, where squared distances overflow to infinity,
  /// every point ties and the smallest index wins.
  std::ptrdiff_t nearest(const Eigen::Vector3d& p) const
  {
    CGAL_precondition(p.allFinite());
    if(item_points_.empty()) return -1;
    const std::array<int, 3> c = index_of(p);
    std::ptrdiff_t best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    // the squared distance from p to the slab of grid cells with index i along axis a; a
    // little less, so that rounding in index_of() never makes it exceed a listed point's
    auto gap2 = [&](int a, int i) {
      const double below = origin_[a] + i * cell_size_[a] - p[a], above = p[a] - (origin_[a] + (i + 1) * cell_size_[a]);
      const double g = (std::max)(0., (std::max)(below, above) - 1e-9 * cell_size_[a]);
      return g * g;
    };
    // a grid cell (or a row, a slab of them) farther than the best point so far cannot hold
    // a nearer point, nor a tie with a smaller index
    auto farther = [&](double g2) { return best >= 0 && g2 > best_d2; };
    auto visit = [&](int x, int y, int z, double g2) {
      if(farther(g2)) return;
      const std::size_t g = linear({x, y, z});
      for(std::size_t k = offsets_[g]; k < offsets_[g + 1]; ++k) {
        const std::size_t i = items_[k];
        const double d2 = (item_points_[k] - p).squaredNorm();
        if(best < 0 || d2 < best_d2 || (d2 == best_d2 && std::ptrdiff_t(i) < best)) {
          best_d2 = d2;
          best = std::ptrdiff_t(i);
        }
      }
    };
    for(int r = 0;; ++r) {
      std::array<int, 3> lo, hi;
      for(int a = 0; a < 3; ++a) {
        lo[a] = std::max(0, c[a] - r);
        hi[a] = std::min(dims_[a] - 1, c[a] + r);
      }
      // the shell at Chebyshev distance r only
      for(int x = lo[0]; x <= hi[0]; ++x) {
        const double gx = gap2(0, x);
        if(farther(gx)) continue;
        for(int y = lo[1]; y <= hi[1]; ++y) {
          const double gxy = gx + gap2(1, y);
          if(farther(gxy)) continue;
          if(std::abs(x - c[0]) == r || std::abs(y - c[1]) == r) {
            for(int z = lo[2]; z <= hi[2]; ++z) visit(x, y, z, gxy + gap2(2, z));
          } else {
            if(c[2] - r >= 0) visit(x, y, c[2] - r, gxy + gap2(2, c[2] - r));
            if(r > 0 && c[2] + r < dims_[2]) visit(x, y, c[2] + r, gxy + gap2(2, c[2] + r));
          }
        }
      }
      // every unvisited grid cell lies in the grid box beyond a face of the visited box
      // (the bound may overflow to infinity far from the grid: then all cells are visited)
      double bound2 = std::numeric_limits<double>::infinity();
      bool unvisited = false;
      for(int a = 0; a < 3; ++a)
        for(int side = 0; side < 2; ++side) {
          if(side == 0 ? lo[a] == 0 : hi[a] == dims_[a] - 1) continue;
          unvisited = true;
          Eigen::Vector3d box_lo = origin_, box_hi = origin_ + cell_size_.cwiseProduct(
              Eigen::Vector3d(dims_[0], dims_[1], dims_[2]));
          if(side == 0) box_hi[a] = origin_[a] + lo[a] * cell_size_[a];
          else box_lo[a] = origin_[a] + (hi[a] + 1) * cell_size_[a];
          const Eigen::Vector3d gap = (box_lo - p).cwiseMax(p - box_hi).cwiseMax(0.);
          bound2 = std::min(bound2, gap.squaredNorm());
        }
      if(!unvisited || (best >= 0 && best_d2 < bound2)) break;
    }
    CGAL_postcondition(best >= 0); // the grid is not empty and every cell was visited if needed
    return best;
  }

private:
  // dims_ and cell_size_ for grid cells of about size h over `extent`; returns their number
  double set_dimensions(const Eigen::Vector3d& extent, double h)
  {
    double cells = 1;
    for(int a = 0; a < 3; ++a) {
      const double n = std::ceil(extent[a] / h);
      dims_[a] = n >= 1 ? int(std::min(n, 1e6)) : 1; // NaN (inf / inf): one layer
      cells *= dims_[a];
    }
    cell_size_ = extent.cwiseQuotient(Eigen::Vector3d(dims_[0], dims_[1], dims_[2]));
    return cells;
  }

  // the number of grid cells holding at least one of the points
  std::size_t occupied_cells(const std::vector<Eigen::Vector3d>& points) const
  {
    std::vector<bool> met(std::size_t(dims_[0]) * dims_[1] * dims_[2], false);
    std::size_t count = 0;
    for(const Eigen::Vector3d& p : points) {
      const std::size_t c = linear(index_of(p));
      if(!met[c]) ++count;
      met[c] = true;
    }
    return (std::max)(count, std::size_t(1));
  }

  std::size_t linear(const std::array<int, 3>& i) const
  {
    return (std::size_t(i[0]) * dims_[1] + i[1]) * dims_[2] + i[2];
  }

  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero(), cell_size_ = Eigen::Vector3d::Ones();
  std::array<int, 3> dims_{{1, 1, 1}};
  std::vector<std::size_t> offsets_{0, 0};
  std::vector<std::size_t> items_;
  std::vector<Eigen::Vector3d> item_points_; // a point grid's points, as items_ lists them
};

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_UNIFORM_GRID_3_H
