// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A sizing field sampled at the vertices: each vertex keeps the field's value
// where it is, taken again when it moves, and a cell's target edge length is
// the mean of its corners' values. Measuring a cell then costs four lookups
// instead of a point location in the field, and a vertex's Newton step sees
// the sizes of its ring as constants, exact until it moves.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_SIZES_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_SIZES_H

#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h> // to_eigen
#include <CGAL/Unique_hash_map.h>

#include <Eigen/Core>

#include <functional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class Tr>
class Vertex_sizes
{
public:
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;

  /// the values of `field` at the finite vertices of `tr`
  Vertex_sizes(const Tr& tr, std::function<double(const Eigen::Vector3d&)> field)
    : field_(std::move(field)), size_(0., 2 * tr.number_of_vertices())
  {
    for(const Vertex_handle& v : tr.finite_vertex_handles()) size_[v] = at(to_eigen(tr.point(v)));
  }

  /// the field at `x`; an error if it is not positive and finite
  double at(const Eigen::Vector3d& x) const
  {
    const double s = field_(x);
    if(!(s > 0) || !std::isfinite(s)) {
      std::ostringstream os;
      os << "GSM: the sizing field is " << s << " at (" << x.transpose() << "); it must be positive and finite";
      throw std::invalid_argument(os.str());
    }
    return s;
  }

  double operator()(const Vertex_handle& v) const { return size_[v]; }

  /// the sum of the sizes of the corners of `c`, with those of `moved` replaced by `size_of_moved`
  double sum(const Cell_handle& c, const Vertex_handle& moved = Vertex_handle(), double size_of_moved = 0) const
  {
    double s = 0;
    for(int i = 0; i < 4; ++i) s += c->vertex(i) == moved ? size_of_moved : (*this)(c->vertex(i));
    return s;
  }

  /// takes the field again at `v`'s position `x`. Thread-safe for vertices that have a size
  /// and that no other thread reads (CGAL's map writes nothing but the value for a key it
  /// holds); a new vertex (created in a serial stage) gets its first one
  void update(const Vertex_handle& v, const Eigen::Vector3d& x) { size_[v] = at(x); }

  /// `v` is about to be removed from the triangulation: its entry stays, for the next vertex
  /// the triangulation puts at its address, whose `update()` overwrites it (CGAL's map has no
  /// removal)
  void erase(const Vertex_handle&) {}

private:
  std::function<double(const Eigen::Vector3d&)> field_;
  // CGAL's map of handles: one probe in a flat table where std::unordered_map takes two or
  // three scattered ones, and every cell energy takes four sizes
  CGAL::Unique_hash_map<Vertex_handle, double> size_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_SIZES_H
