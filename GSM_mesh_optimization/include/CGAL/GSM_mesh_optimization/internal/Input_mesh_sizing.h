// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The local size of the input mesh, GSM's default target edge length (as
// CGAL's Lloyd and ODT take theirs from the mesh): at each vertex the mean
// length of its edges, averaged with its neighbours' so that the target keeps
// the mesh's grading but not the noise of its edges, and interpolated linearly
// in the Delaunay tetrahedralization of the input vertices, so that the energy
// of a cell changes continuously as its vertices move.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_INPUT_MESH_SIZING_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_INPUT_MESH_SIZING_H

#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h> // to_eigen

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

class Input_mesh_sizing
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  typedef Triangulation_vertex_base_with_info_3<double, K> Vb;
  typedef Delaunay_triangulation_3<K, Triangulation_data_structure_3<Vb>> Dt;
  typedef Dt::Cell_handle Dt_cell;

public:
  /// the size of the vertices of the cells in the complex of `c3t3`; `smoothing_passes`
  /// rounds of averaging each vertex's size with the mean of its neighbours'
  template <class C3T3>
  explicit Input_mesh_sizing(const C3T3& c3t3, int smoothing_passes = 2)
  {
    typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
    const auto& tr = c3t3.triangulation();
    std::unordered_map<Vertex_handle, std::size_t> index;
    std::vector<Eigen::Vector3d> points;
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      std::array<std::size_t, 4> id;
      for(int i = 0; i < 4; ++i) {
        const auto inserted = index.emplace(c->vertex(i), points.size());
        if(inserted.second) points.push_back(to_eigen(tr.point(c->vertex(i))));
        id[i] = inserted.first->second;
      }
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j) edges.emplace_back((std::min)(id[i], id[j]), (std::max)(id[i], id[j]));
    }
    if(points.size() < 4) throw std::invalid_argument("GSM: the complex has no cell");
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    std::vector<double> size(points.size(), 0.), next(points.size());
    std::vector<int> degree(points.size(), 0);
    for(const auto& e : edges) {
      const double l = (points[e.first] - points[e.second]).norm();
      size[e.first] += l;
      size[e.second] += l;
      ++degree[e.first];
      ++degree[e.second];
    }
    for(std::size_t i = 0; i < size.size(); ++i) size[i] /= double(degree[i]);
    for(int pass = 0; pass < smoothing_passes; ++pass) {
      std::fill(next.begin(), next.end(), 0.);
      for(const auto& e : edges) {
        next[e.first] += size[e.second];
        next[e.second] += size[e.first];
      }
      for(std::size_t i = 0; i < size.size(); ++i) size[i] = 0.5 * (size[i] + next[i] / double(degree[i]));
    }
    for(double s : size)
      if(!(s > 0) || !std::isfinite(s)) throw std::invalid_argument("GSM: the mesh has an edge of zero or non-finite length");

    std::vector<std::pair<K::Point_3, double>> sites;
    sites.reserve(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      sites.emplace_back(K::Point_3(points[i][0], points[i][1], points[i][2]), size[i]);
    dt_.insert(sites.begin(), sites.end());
    build_hints(points);
  }

  /// the size at `x`: linear in the tetrahedron of the input vertices that holds it, the
  /// nearest hull facet's mean outside their hull
  double operator()(const Eigen::Vector3d& x) const
  {
    // a visibility walk from the grid's cell near `x`, on the signs of the volumes that
    // are also the barycentric weights: no randomness and no exact arithmetic, so that
    // the same point gives the same value in any thread at the cost of a few products
    Dt_cell c = hint(x);
    for(int step = 0; step < max_walk_steps; ++step) {
      if(dt_.is_infinite(c)) return hull_facet_mean(c);
      const std::array<double, 4> w = volumes(c, x);
      double total = 0, most_negative = 0;
      int beyond = -1;
      for(int i = 0; i < 4; ++i) {
        total += std::abs(w[i]);
        if(w[i] < most_negative) {
          most_negative = w[i];
          beyond = i;
        }
      }
      // on a facet (to round-off) is inside: no back-and-forth between two cells
      if(beyond < 0 || most_negative > -1e-12 * total) return interpolate(c, w);
      c = c->neighbor(beyond);
    }
    // a walk that does not end (round-off on nearly flat cells): CGAL's exact location
    c = dt_.locate(K::Point_3(x[0], x[1], x[2]), c);
    return dt_.is_infinite(c) ? hull_facet_mean(c) : interpolate(c, volumes(c, x));
  }

private:
  // six times the signed volumes of cell `c` with its vertex i replaced by `x`: positive
  // inside, and the barycentric weights of `x` once divided by their sum
  static std::array<double, 4> volumes(const Dt_cell& c, const Eigen::Vector3d& x)
  {
    std::array<Eigen::Vector3d, 4> q;
    for(int i = 0; i < 4; ++i) q[i] = to_eigen(c->vertex(i)->point());
    std::array<double, 4> w;
    for(int i = 0; i < 4; ++i) {
      std::array<Eigen::Vector3d, 4> r = q;
      r[i] = x;
      w[i] = (r[1] - r[0]).dot((r[2] - r[0]).cross(r[3] - r[0]));
    }
    return w;
  }

  // the vertices' sizes weighted by `w`, negative weights (round-off) taken as zero
  static double interpolate(const Dt_cell& c, const std::array<double, 4>& w)
  {
    double s = 0, sum = 0;
    for(int i = 0; i < 4; ++i) {
      const double wi = (std::max)(w[i], 0.);
      s += wi * c->vertex(i)->info();
      sum += wi;
    }
    return sum > 0 ? s / sum
                   : 0.25 * (c->vertex(0)->info() + c->vertex(1)->info() + c->vertex(2)->info() + c->vertex(3)->info());
  }

  double hull_facet_mean(const Dt_cell& c) const
  {
    double s = 0;
    for(int i = 0; i < 4; ++i)
      if(!dt_.is_infinite(c->vertex(i))) s += c->vertex(i)->info();
    return s / 3.;
  }

  static constexpr int max_walk_steps = 200;

  // a grid of start cells, eight per input vertex, so that walks are a step or two
  void build_hints(const std::vector<Eigen::Vector3d>& points)
  {
    lo_ = hi_ = points.front();
    for(const Eigen::Vector3d& p : points) {
      lo_ = lo_.cwiseMin(p);
      hi_ = hi_.cwiseMax(p);
    }
    const int n = (std::max)(1, int(2 * std::cbrt(double(points.size()))));
    const Eigen::Vector3d extent = (hi_ - lo_).cwiseMax(1e-300);
    const double cell = std::cbrt(extent.prod() / double(n * n * n));
    for(int k = 0; k < 3; ++k) dims_[k] = std::clamp(int(std::ceil(extent[k] / cell)), 1, 4 * n);
    step_ = extent.cwiseQuotient(Eigen::Vector3d(dims_[0], dims_[1], dims_[2]));
    hints_.resize(std::size_t(dims_[0]) * dims_[1] * dims_[2]);
    Dt_cell last;
    for(int i = 0; i < dims_[0]; ++i)
      for(int j = 0; j < dims_[1]; ++j)
        for(int k = 0; k < dims_[2]; ++k) {
          const Eigen::Vector3d c = lo_ + step_.cwiseProduct(Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5));
          last = dt_.locate(K::Point_3(c[0], c[1], c[2]), last);
          if(dt_.is_infinite(last)) last = last->neighbor(last->index(dt_.infinite_vertex()));
          hints_[(std::size_t(i) * dims_[1] + j) * dims_[2] + k] = last;
        }
  }

  Dt_cell hint(const Eigen::Vector3d& x) const
  {
    std::array<int, 3> g;
    for(int k = 0; k < 3; ++k) {
      const double t = (x[k] - lo_[k]) / step_[k];
      g[k] = std::isfinite(t) ? std::clamp(int(std::floor(t)), 0, dims_[k] - 1) : 0;
    }
    return hints_[(std::size_t(g[0]) * dims_[1] + g[1]) * dims_[2] + g[2]];
  }

  Dt dt_;
  Eigen::Vector3d lo_, hi_, step_;
  std::array<int, 3> dims_ = {{1, 1, 1}};
  std::vector<Dt_cell> hints_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_INPUT_MESH_SIZING_H
