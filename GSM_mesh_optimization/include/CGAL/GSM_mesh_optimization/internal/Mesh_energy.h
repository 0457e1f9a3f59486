// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shape matching energy of the cells of a C3T3, measured in the metric or
// in the sizes carried by the vertices, and the running mean that vertex moves
// and flips must lower (eq. 3.9).

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_MESH_ENERGY_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_MESH_ENERGY_H

#include <CGAL/GSM_mesh_optimization/internal/Vertex_sizes.h>
#include <CGAL/GSM_mesh_optimization/internal/Metric_field.h>
#include <CGAL/GSM_mesh_optimization/shape_matching_energy.h>
#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h>
#include <CGAL/VVM/internal/Parallel_for.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>


#include <algorithm>
#include <array>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

using VVM::internal::Index_range;
using VVM::internal::parallel_for_ranges;

/// moves the vertex `v` of `tr` to `p`; if the points are weighted, keeps its
/// weight, or gives it weight 0 if it is new
template <class Tr>
void set_bare_point(Tr& tr, const typename Tr::Vertex_handle& v, const typename Tr::Geom_traits::Point_3& p,
                    bool is_new = false)
{
  if constexpr(std::is_same<typename Tr::Point, typename Tr::Geom_traits::Point_3>::value)
    v->set_point(p);
  else
    v->set_point(typename Tr::Point(p, is_new ? 0 : tr.point(v).weight()));
}

template <class C3T3>
class Mesh_energy
{
public:
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Geom_traits::Point_3 Bare_point;
  typedef Vertex_sizes<Tr> Sizes;

  /// cells measured by `metric`, or, if `sizing` is given, by `metric`'s scale over the
  /// mean size of their vertices
  Mesh_energy(const C3T3& c3t3, const Metric_field& metric, Shape_matching_energy energy,
              std::shared_ptr<Sizes> sizing = nullptr)
    : c3t3_(c3t3), metric_(metric), energy_(energy), sizing_(std::move(sizing))
  {}

  Eigen::Vector3d position(const Vertex_handle& v) const
  {
    return internal::to_eigen(c3t3_.triangulation().point(v));
  }
  static Eigen::Vector3d to_eigen(const Bare_point& p) { return internal::to_eigen(p); }

  const Metric_field& metric() const { return metric_; }
  /// the map B of a cell depends on where the cell is or on its vertices
  bool has_varying_frames() const { return sizing_ != nullptr || !metric_.is_constant(); }

  /// cells take their size from their vertices
  bool has_vertex_sizes() const { return sizing_ != nullptr; }
  /// the size a vertex would take at `x` (only with vertex sizes)
  double size_at(const Eigen::Vector3d& x) const { return sizing_->at(x); }

  /// `v` has moved or is new: its size is taken again where it is (with vertex sizes;
  /// thread-safe as long as no other thread reads `v`, and new vertices come in serial stages)
  void vertex_moved(const Vertex_handle& v) const
  {
    if(sizing_) sizing_->update(v, position(v));
  }
  /// `v` is about to be removed from the triangulation
  void vertex_removed(const Vertex_handle& v) const
  {
    if(sizing_) sizing_->erase(v);
  }
  Shape_matching_energy energy_kind() const { return energy_; }

  /// energy of the tetrahedron with these corners, mapped by B at its centroid
  double tetrahedron(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                     const Eigen::Vector3d& p3) const
  {
    if(metric_.is_constant()) {
      const Eigen::Matrix3d B = metric_(p0);
      return tetrahedron_energy(energy_, B * p0, B * p1, B * p2, B * p3);
    }
    const Eigen::Matrix3d B = metric_(0.25 * (p0 + p1 + p2 + p3));
    return tetrahedron_energy(energy_, B * p0, B * p1, B * p2, B * p3);
  }

  /// energy of the tetrahedron with these vertices where they are
  double tetrahedron(const Vertex_handle& a, const Vertex_handle& b, const Vertex_handle& c,
                     const Vertex_handle& d) const
  {
    const Eigen::Vector3d p0 = position(a), p1 = position(b), p2 = position(c), p3 = position(d);
    if(!sizing_) return tetrahedron(p0, p1, p2, p3);
    const Eigen::Matrix3d B = sized_frame((*sizing_)(a) + (*sizing_)(b) + (*sizing_)(c) + (*sizing_)(d));
    return tetrahedron_energy(energy_, B * p0, B * p1, B * p2, B * p3);
  }

  /// smallest dihedral angle, in degrees, of the tetrahedron mapped by B at its centroid
  double min_dihedral_angle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                            const Eigen::Vector3d& p3) const
  {
    if(metric_.is_isotropic()) return tetrahedron_min_dihedral_angle({{p0, p1, p2, p3}});
    const Eigen::Matrix3d B = metric_(0.25 * (p0 + p1 + p2 + p3));
    return tetrahedron_min_dihedral_angle({{B * p0, B * p1, B * p2, B * p3}});
  }

  /// the same for cell `c` with its vertex `v` at `x`
  double min_dihedral_angle(const Cell_handle& c, const Vertex_handle& v, const Eigen::Vector3d& x) const
  {
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = c->vertex(i) == v ? x : position(c->vertex(i));
    return min_dihedral_angle(p[0], p[1], p[2], p[3]);
  }

  double min_dihedral_angle(const Cell_handle& c) const
  {
    return min_dihedral_angle(position(c->vertex(0)), position(c->vertex(1)), position(c->vertex(2)),
                              position(c->vertex(3)));
  }

  double cell(const Cell_handle& c) const
  {
    return tetrahedron(c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3));
  }

  /// energy of cell `c` with the vertex `v` of it placed at `x`
  double cell(const Cell_handle& c, const Vertex_handle& v, const Eigen::Vector3d& x) const
  {
    if(sizing_) return cell(c, v, x, frame(c, v, sizing_->at(x)));
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = c->vertex(i) == v ? x : position(c->vertex(i));
    return tetrahedron(p[0], p[1], p[2], p[3]);
  }

  /// the map B of cell `c` with its vertex `v` moved where its size is `size_of_v` (vertex sizes)
  Eigen::Matrix3d frame(const Cell_handle& c, const Vertex_handle& v, double size_of_v) const
  {
    return sized_frame(sizing_->sum(c, v, size_of_v));
  }

  /// the map B of cell `c` where it is: from its vertices' sizes, or the metric at its centroid
  Eigen::Matrix3d frame(const Cell_handle& c) const
  {
    if(sizing_) return sized_frame(sizing_->sum(c));
    return metric_(0.25 * (position(c->vertex(0)) + position(c->vertex(1)) + position(c->vertex(2)) +
                           position(c->vertex(3))));
  }

  /// energy of cell `c` with its vertex `v` at `x`, mapped by a given `B`
  double cell(const Cell_handle& c, const Vertex_handle& v, const Eigen::Vector3d& x, const Eigen::Matrix3d& B) const
  {
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = B * (c->vertex(i) == v ? x : position(c->vertex(i)));
    return tetrahedron_energy(energy_, p[0], p[1], p[2], p[3]);
  }

  /// derivatives of the energy of cell `c`, mapped by a given `B`, with respect to its vertex `v` at `x`
  Energy_derivatives cell_derivatives(const Cell_handle& c, const Vertex_handle& v, const Eigen::Vector3d& x,
                                      const Eigen::Matrix3d& B) const
  {
    std::array<Eigen::Vector3d, 3> others;
    for(int i = 0, k = 0; i < 4; ++i)
      if(c->vertex(i) != v) others[k++] = B * position(c->vertex(i));
    return tetrahedron_energy_derivatives(energy_, B * x, others[0], others[1], others[2]).mapped_back(B);
  }

  /// derivatives of the energy of cell `c` with respect to its vertex `v`, placed at `x`
  Energy_derivatives cell_derivatives(const Cell_handle& c, const Vertex_handle& v,
                                      const Eigen::Vector3d& x) const
  {
    if(sizing_) return cell_derivatives(c, v, x, sized_frame(sizing_->sum(c)));
    std::array<Eigen::Vector3d, 3> others;
    Eigen::Vector3d centroid = x;
    for(int i = 0, k = 0; i < 4; ++i)
      if(c->vertex(i) != v) {
        others[k] = position(c->vertex(i));
        centroid += others[k++];
      }
    const Eigen::Matrix3d B = metric_(0.25 * centroid);
    return tetrahedron_energy_derivatives(energy_, B * x, B * others[0], B * others[1], B * others[2])
        .mapped_back(B);
  }

  /// sum and number of the energies of the cells in the complex
  std::pair<double, std::size_t> total() const
  {
    const std::vector<double> e = per_cell(cells_in_complex(), [this](const Cell_handle& c) { return cell(c); });
    double sum = 0;
    for(double x : e) sum += x; // in the complex's order, whatever the threads
    return {sum, e.size()};
  }

  /// the smallest dihedral angle (degrees, in the metric) of the cells in the complex, and how
  /// many of them are under `bound`
  std::pair<double, std::size_t> worst_and_count_under(double bound) const
  {
    double worst = 180;
    std::size_t n = 0;
    for(double q : per_cell(cells_in_complex(), [this](const Cell_handle& c) { return min_dihedral_angle(c); })) {
      worst = (std::min)(worst, q);
      n += q < bound ? 1 : 0;
    }
    return {worst, n};
  }

  /// `total()` and `worst_and_count_under(bound)` in one scan of the complex (each round and
  /// each polishing pass needs both)
  struct Summary
  {
    std::pair<double, std::size_t> total;
    std::pair<double, std::size_t> worst_and_count_under;
  };
  Summary summary(double bound) const
  {
    Summary s{{0., 0}, {180., 0}};
    const auto cells = per_cell(cells_in_complex(), [this](const Cell_handle& c) {
      return std::array<double, 2>{{cell(c), min_dihedral_angle(c)}};
    });
    for(const auto& e : cells) { // in the complex's order, whatever the threads
      s.total.first += e[0];
      s.worst_and_count_under.first = (std::min)(s.worst_and_count_under.first, e[1]);
      s.worst_and_count_under.second += e[1] < bound ? 1 : 0;
    }
    s.total.second = cells.size();
    return s;
  }

  /// the cells in the complex, in its order
  std::vector<Cell_handle> cells_in_complex() const
  {
    std::vector<Cell_handle> cells;
    cells.reserve(c3t3_.number_of_cells_in_complex());
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c) cells.push_back(c);
    return cells;
  }

  /// `f(c)` for each of `cells`, computed in parallel (the scans of the whole mesh that the
  /// rounds and the polishing make are most of their time where little moves)
  template <class F>
  static auto per_cell(const std::vector<Cell_handle>& cells, const F& f)
  {
    std::vector<std::decay_t<decltype(f(cells.front()))>> out(cells.size());
    parallel_for_ranges(cells.size(), 1024,
                      [&](const Index_range& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i) out[i] = f(cells[i]);
    });
    return out;
  }

private:
  // I / h for the mean h of four sizes given by their sum, times the metric's scale
  Eigen::Matrix3d sized_frame(double sum_of_sizes) const { return metric_(Eigen::Vector3d::Zero()) * (4. / sum_of_sizes); }

  const C3T3& c3t3_;
  const Metric_field& metric_;
  Shape_matching_energy energy_;
  std::shared_ptr<Sizes> sizing_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_MESH_ENERGY_H
