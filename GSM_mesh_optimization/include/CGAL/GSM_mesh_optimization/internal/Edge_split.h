// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Edge split: the cells that vertex moves and flips leave bad are, on real
// models, those of parts of the domain only a few elements thick, whose
// vertices all sit on the surface (or on feature curves) and so cannot give
// them volume. Splitting one of their interior edges (a, b) puts a free
// interior vertex x there: the m cells around the edge become the 2m cells
// with a, respectively b, replaced by x. At the midpoint every new cell is half
// of a positively oriented cell; from there x takes a few damped Newton steps
// of the energy of its star, each keeping every new cell positive, then climbs
// the smallest dihedral angle of its star. The split is kept if that angle beats
// the smallest one of the old cells and, unless the old cells are critical, if
// the new cells' angle penalty (Angle_penalty.h) is below the old ones': splits
// serve the final polishing (Sliver_polisher.h), not the energy, which smaller
// cells raise.
//
// The edge must be a removable one: no feature edge, on no surface facet,
// inside one subdomain; the new vertex is interior (dimension 3) and takes
// that subdomain's index.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_EDGE_SPLIT_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_EDGE_SPLIT_H

#include <CGAL/GSM_mesh_optimization/internal/Angle_penalty.h>
#include <CGAL/GSM_mesh_optimization/internal/Cell_replacement.h>
#include <CGAL/GSM_mesh_optimization/internal/Central_differences.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class C3T3>
class Edge_split : public Cell_replacement<C3T3>
{
  typedef Cell_replacement<C3T3> Base;

public:
  typedef typename Base::Tr Tr;
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Edge Edge;
  typedef typename Base::Subdomain_index Subdomain_index;
  typedef typename Tr::Geom_traits::Point_3 Bare_point;

  /// the largest number of cells around a split edge
  static constexpr std::size_t max_ring = 12;

  /// a split of cells that are not critical must also lower the sum of `penalty` over
  /// their smallest dihedral angles (by default every cell under 30 degrees is critical)
  Edge_split(C3T3& c3t3, const typename Base::Energy& energy, double& sum, std::size_t& count,
             const Angle_penalty& penalty = Angle_penalty())
    : Base(c3t3, energy, sum, count), penalty_(penalty)
  {}

  void set_penalty(const Angle_penalty& penalty) { penalty_ = penalty; }

  /// splits the edge of the cell `c` whose split gives the largest smallest dihedral
  /// angle, if it beats the one of the cells around the edge (and, unless they are
  /// critical, lowers their penalty); true if done: `c` is then gone
  bool try_split_cell(const Cell_handle& c)
  {
    Split best;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        Split s;
        if(plan(Edge(c, i, j), s) && s.is_better() && s.gain() > best.gain()) best = s;
      }
    if(!best.is_better()) return false;
    apply(best);
    return true;
  }

  /// splits the edge `e`, if that raises the smallest dihedral angle around it (and,
  /// unless the cells around it are critical, lowers their penalty)
  bool try_split_edge(const Edge& e)
  {
    Split s;
    if(!plan(e, s) || !s.is_better()) return false;
    apply(s);
    return true;
  }

private:
  // a split worked out before anything changes
  struct Split
  {
    Edge edge;
    std::vector<Cell_handle> ring;
    Subdomain_index subdomain;
    Eigen::Vector3d x;
    double old_sum = 0, new_sum = 0;
    double old_min = 0, new_min = 0; // smallest dihedral angles, degrees
    double old_penalty = 0, new_penalty = 0;
    bool critical = false; // the old cells' smallest angle is under the penalty's critical one
    double gain() const { return new_min - old_min; }
    bool is_better() const { return gain() > min_gain && (critical || new_penalty < old_penalty); }
  };

  // where the new vertex goes: a few Newton steps of the energy of its star from
  // the midpoint, then up the smallest angle of its star
  bool plan(const Edge& e, Split& s) const
  {
    std::vector<Vertex_handle> others;
    if(!this->removable_edge(e, s.ring, others, s.subdomain, max_ring)) return false;
    s.edge = e;
    const Vertex_handle a = e.first->vertex(e.second), b = e.first->vertex(e.third);
    s.old_min = 180;
    for(const Cell_handle& c : s.ring) {
      s.old_sum += energy_.cell(c);
      const double q = energy_.min_dihedral_angle(c);
      s.old_min = (std::min)(s.old_min, q);
      s.old_penalty += penalty_(q);
    }
    s.x = 0.5 * (energy_.position(a) + energy_.position(b));
    s.new_sum = star_energy(s.ring, a, b, s.x);
    for(int k = 0; k < newton_steps; ++k)
      if(!newton_move(s.ring, a, b, s.x, s.new_sum)) break;
    s.new_min = star_quality(s.ring, a, b, s.x);
    const double length = (energy_.position(a) - energy_.position(b)).norm();
    for(int k = 0; k < ascent_steps; ++k)
      if(!lift(s.ring, a, b, length, s.x, s.new_min)) break;
    s.new_sum = star_energy(s.ring, a, b, s.x);
    s.new_penalty = star_penalty(s.ring, a, b, s.x);
    s.critical = penalty_.is_critical(s.old_min);
    return std::isfinite(s.new_sum);
  }

  void apply(const Split& s)
  {
    this->release(s.ring);
    const Vertex_handle v = tr_.tds().insert_in_edge(s.edge);
    set_bare_point(tr_, v, Bare_point(s.x[0], s.x[1], s.x[2]), true);
    energy_.vertex_moved(v);
    c3t3_.set_dimension(v, 3);
    c3t3_.set_index(v, s.subdomain);
    std::vector<Cell_handle> star;
    tr_.incident_cells(v, std::back_inserter(star));
    this->claim(star, s.subdomain);
    this->account(s.old_sum, s.new_sum, int(s.ring.size()));
  }

  // smallest dihedral angle of the 2m cells of the split with the new vertex at `x`
  double star_quality(const std::vector<Cell_handle>& ring, const Vertex_handle& a, const Vertex_handle& b,
                      const Eigen::Vector3d& x) const
  {
    double q = 180;
    for(const Cell_handle& c : ring)
      for(const Vertex_handle& replaced : {a, b}) {
        if(!is_positive(c, replaced, x)) return 0;
        q = (std::min)(q, energy_.min_dihedral_angle(c, replaced, x));
      }
    return q;
  }

  // penalty of the 2m cells of the split with the new vertex at `x`
  double star_penalty(const std::vector<Cell_handle>& ring, const Vertex_handle& a, const Vertex_handle& b,
                      const Eigen::Vector3d& x) const
  {
    double p = 0;
    for(const Cell_handle& c : ring)
      for(const Vertex_handle& replaced : {a, b}) p += penalty_(energy_.min_dihedral_angle(c, replaced, x));
    return p;
  }

  // one step up the gradient of star_quality (central differences: it is only
  // piecewise smooth), with backtracking; false if none raises it
  bool lift(const std::vector<Cell_handle>& ring, const Vertex_handle& a, const Vertex_handle& b,
            double length, Eigen::Vector3d& x, double& q) const
  {
    Eigen::Vector3d g = central_differences([&](const Eigen::Vector3d& y) { return star_quality(ring, a, b, y); },
                                            x, 1e-4 * length);
    if(!(g.norm() > 0)) return false;
    g.normalize();
    double alpha = 0.1 * length;
    for(int k = 0; k < max_backtracking_steps; ++k, alpha *= 0.5) {
      const Eigen::Vector3d y = x + alpha * g;
      const double qy = star_quality(ring, a, b, y);
      if(qy > q + 1e-3) {
        x = y;
        q = qy;
        return true;
      }
    }
    return false;
  }

  static constexpr int newton_steps = 8;
  static constexpr int ascent_steps = 10;
  static constexpr double min_gain = 0.5; // degrees
  static constexpr int max_backtracking_steps = 10;

  // the energy of the 2m cells of the split with the new vertex at `x`; infinite
  // if one is not positively oriented
  double star_energy(const std::vector<Cell_handle>& ring, const Vertex_handle& a, const Vertex_handle& b,
                     const Eigen::Vector3d& x) const
  {
    double sum = 0;
    for(const Cell_handle& c : ring)
      for(const Vertex_handle& replaced : {a, b}) {
        if(!is_positive(c, replaced, x)) return std::numeric_limits<double>::infinity();
        sum += energy_.cell(c, replaced, x);
      }
    return sum;
  }

  // one Newton step of the star energy with backtracking; false if none lowers it
  bool newton_move(const std::vector<Cell_handle>& ring, const Vertex_handle& a, const Vertex_handle& b,
                   Eigen::Vector3d& x, double& e) const
  {
    Energy_derivatives d;
    for(const Cell_handle& c : ring) {
      d += energy_.cell_derivatives(c, a, x);
      d += energy_.cell_derivatives(c, b, x);
    }
    if(!d.gradient.allFinite() || !d.hessian.allFinite()) return false;
    Eigen::LLT<Eigen::Matrix3d> llt(d.hessian);
    if(llt.info() != Eigen::Success) return false;
    const Eigen::Vector3d step = llt.solve(d.gradient);
    // never farther than the half edge: beyond, the star's shape has nothing to do with the split
    const double limit = 0.5 * (energy_.position(a) - energy_.position(b)).norm();
    double alpha = step.norm() > limit ? limit / step.norm() : 1.;
    for(int k = 0; k < max_backtracking_steps; ++k, alpha *= 0.5) {
      const Eigen::Vector3d y = x - alpha * step;
      const double ey = star_energy(ring, a, b, y);
      if(ey < e) {
        x = y;
        e = ey;
        return true;
      }
    }
    return false;
  }

  bool is_positive(const Cell_handle& c, const Vertex_handle& replaced, const Eigen::Vector3d& x) const
  {
    return this->is_positive_with(c, replaced, Bare_point(x[0], x[1], x[2]));
  }

  Angle_penalty penalty_;

  using Base::c3t3_;
  using Base::tr_;
  using Base::energy_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_EDGE_SPLIT_H
