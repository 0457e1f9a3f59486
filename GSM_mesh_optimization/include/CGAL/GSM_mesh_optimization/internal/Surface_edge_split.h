// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Surface edge split: most cells the polishing leaves under the bound on thin
// organic models have their smallest dihedral angle at a surface edge, where the
// interior splits of Edge_split.h cannot reach:
// crest cells, whose two surface facets meet at 130-150 degrees, and cells with
// three or four vertices on the surface across a part one or two elements thick.
// Splitting the surface edge (a, b) puts a new surface vertex x on the domain's
// surface: every cell around the edge, inside the complex or not, becomes two,
// with a, respectively b, replaced by x, and the edge's two surface facets become
// four. Where x, on a curved surface, lies beyond a facet of an outside cell of
// the ring (the new cell on it would be inverted), the outside cells beyond are
// replaced too, by x's star (`hole()`): outside cells are no part of the mesh.
// From the edge's midpoint projected onto the surface (along the normal of the
// two facets), x climbs the smallest dihedral angle of the new cells in the
// complex, in the surface's tangent plane and projected back onto it. The split is
// kept if that angle beats the smallest one of the old cells by half a degree (and,
// unless the old cells are critical, lowers their angle penalty), every new finite
// cell is positive and the convex hull stays convex (exact predicates), and its
// four surface facets stray from the surface no further than the boundary may
// (Boundary_fidelity.h): x on the surface brings the boundary closer to it.
//
// The edge must lie on one surface patch (two surface facets of that patch, no
// feature edge); it may be an interface between two subdomains, each new cell
// keeps the subdomain of the cell it comes from.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SURFACE_EDGE_SPLIT_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SURFACE_EDGE_SPLIT_H

#include <CGAL/GSM_mesh_optimization/internal/Angle_penalty.h>
#include <CGAL/GSM_mesh_optimization/internal/Cell_replacement.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_smoother.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class C3T3, class MeshDomain>
class Surface_edge_split : public Cell_replacement<C3T3>
{
  typedef Cell_replacement<C3T3> Base;

public:
  typedef typename Base::Tr Tr;
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Facet Facet;
  typedef typename Base::Edge Edge;
  typedef typename Base::Subdomain_index Subdomain_index;
  typedef typename Base::Surface_patch_index Surface_patch_index;
  typedef Vertex_smoother<C3T3, MeshDomain> Smoother;
  typedef typename Smoother::Bare_point Bare_point;

  /// the largest number of cells around a split edge, outside cells included
  static constexpr std::size_t max_ring = 12;

  Surface_edge_split(C3T3& c3t3, const typename Base::Energy& energy, double& sum, std::size_t& count,
                     const Smoother& smoother, const Angle_penalty& penalty = Angle_penalty())
    : Base(c3t3, energy, sum, count), smoother_(smoother), penalty_(penalty)
  {}

  void set_penalty(const Angle_penalty& penalty) { penalty_ = penalty; }

  /// the number of splits that replaced outside cells beyond the edge's ring (see `hole()`)
  std::size_t number_of_grown_holes() const { return grown_holes_; }

  /// splits the surface edge of the cell `c` whose split gives the largest smallest
  /// dihedral angle, if it beats the one of the cells around the edge (and, unless they
  /// are critical, lowers their penalty); true if done: `c` is then gone
  bool try_split_cell(const Cell_handle& c)
  {
    if constexpr(Is_triangulation_complex<C3T3>::value || std::is_void<MeshDomain>::value) {
      CGAL_USE(c);
      return false; // a bare triangulation's boundary is its convex hull: fixed
    } else {
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
  }

private:
  struct Split
  {
    Edge edge;
    Vertex_handle a, b;
    std::vector<Cell_handle> ring;             // all the cells around the edge, infinite ones included
    std::array<Vertex_handle, 2> apexes;       // the third vertices of the edge's surface facets
    Surface_patch_index patch;
    Eigen::Vector3d normal;                    // of the surface at the edge
    Bare_point x;
    double old_sum = 0, new_sum = 0;
    double old_min = 0, new_min = 0;
    double old_penalty = 0, new_penalty = 0;
    bool critical = false;
    double gain() const { return new_min - old_min; }
    bool is_better() const { return gain() > min_gain && (critical || new_penalty < old_penalty); }
  };

  // the edge's ring and surface data, then where the new vertex goes
  bool plan(const Edge& e, Split& s) const
  {
    s.edge = e;
    s.a = e.first->vertex(e.second);
    s.b = e.first->vertex(e.third);
    if(c3t3_.is_in_complex(s.a, s.b)) return false; // a feature edge
    int n_surface = 0;
    bool has_complex_cell = false;
    s.old_min = 180;
    s.normal = Eigen::Vector3d::Zero();
    auto cc = tr_.incident_cells(e), done = cc;
    do {
      const Cell_handle c = cc;
      s.ring.push_back(c);
      if(s.ring.size() > max_ring) return false;
      if(!tr_.is_infinite(c) && c3t3_.is_in_complex(c)) {
        has_complex_cell = true;
        s.old_sum += energy_.cell(c);
        const double q = energy_.min_dihedral_angle(c);
        s.old_min = (std::min)(s.old_min, q);
        s.old_penalty += penalty_(q);
      }
      // the facets of c through the edge: count the surface ones, each seen from its complex side
      const int ia = c->index(s.a), ib = c->index(s.b);
      for(int i = 0; i < 4; ++i) {
        if(i == ia || i == ib || !c3t3_.is_in_complex(c, i)) continue;
        if(!this->seen_from(c, i)) continue;
        if(n_surface == 2) return false;
        const Surface_patch_index patch = c3t3_.surface_patch_index(c, i);
        if(n_surface == 1 && !(patch == s.patch)) return false; // the edge is on a patch border
        s.patch = patch;
        s.apexes[n_surface++] = c->vertex(6 - ia - ib - i);
        // outward from c
        const Eigen::Vector3d pa = energy_.position(s.a), pb = energy_.position(s.b),
                              pw = energy_.position(c->vertex(6 - ia - ib - i)), inner = energy_.position(c->vertex(i));
        Eigen::Vector3d n = (pb - pa).cross(pw - pa);
        if(n.dot(inner - pa) > 0) n = -n;
        const double len = n.norm();
        if(!(len > 0)) return false;
        s.normal += n / len;
      }
    } while(++cc != done);
    if(n_surface != 2 || !has_complex_cell || !(s.normal.norm() > 0)) return false;
    s.normal.normalize();
    s.critical = penalty_.is_critical(s.old_min);

    // the projected midpoint, then up the smallest angle on the surface
    const double length = (energy_.position(s.a) - energy_.position(s.b)).norm();
    if(!project(s, 0.5 * (energy_.position(s.a) + energy_.position(s.b)), 0.5 * length, s.x)) return false;
    s.new_min = quality(s, s.x);
    for(int k = 0; k < ascent_steps; ++k)
      if(!lift(s, length)) break;
    if(!(s.new_min > s.old_min + min_gain) || !is_valid(s, s.x) || !is_faithful(s, s.x)) return false;
    s.new_sum = 0;
    s.new_penalty = 0;
    for_each_new_complex_cell(s, s.x, [&](const Cell_handle& c, const Vertex_handle& replaced, const Eigen::Vector3d& x) {
      s.new_sum += energy_.cell(c, replaced, x);
      s.new_penalty += penalty_(energy_.min_dihedral_angle(c, replaced, x));
    });
    return std::isfinite(s.new_sum);
  }

  // the point where the line through `x` along the normal meets the edge's patch, within `reach`
  bool project(const Split& s, const Eigen::Vector3d& x, double reach, Bare_point& p) const
  {
    const Eigen::Vector3d lo = x - reach * s.normal, hi = x + reach * s.normal;
    return smoother_.project_on_patch(
        typename Smoother::Segment_3(Bare_point(lo[0], lo[1], lo[2]), Bare_point(hi[0], hi[1], hi[2])), s.patch, p);
  }

  template <class F>
  void for_each_new_complex_cell(const Split& s, const Bare_point& p, const F& f) const
  {
    const Eigen::Vector3d x = Base::Energy::to_eigen(p);
    for(const Cell_handle& c : s.ring)
      if(!tr_.is_infinite(c) && c3t3_.is_in_complex(c))
        for(const Vertex_handle& replaced : {s.a, s.b}) f(c, replaced, x);
  }

  // smallest dihedral angle of the new cells in the complex, 0 if a new finite cell is not
  // positive (outside cells too: the ascent must stay where the split can be made)
  double quality(const Split& s, const Bare_point& p) const
  {
    std::vector<Cell_handle> cells;
    if(!hole(s, p, cells)) return 0;
    double q = 180;
    for_each_new_complex_cell(s, p, [&](const Cell_handle& c, const Vertex_handle& replaced, const Eigen::Vector3d& x) {
      if(!this->is_positive_with(c, replaced, p)) q = 0;
      else q = (std::min)(q, energy_.min_dihedral_angle(c, replaced, x));
    });
    return q;
  }

  // one step of the new vertex up the gradient of `quality()` in the tangent plane,
  // projected back onto the surface, with backtracking; false if none raises it
  bool lift(Split& s, double length) const
  {
    const double h = 1e-4 * length;
    const Eigen::Vector3d x0 = Base::Energy::to_eigen(s.x);
    const auto at = [&](const Eigen::Vector3d& y) { return quality(s, Bare_point(y[0], y[1], y[2])); };
    Eigen::Vector3d g;
    for(int k = 0; k < 3; ++k) {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      d[k] = h;
      g[k] = at(x0 + d) - at(x0 - d);
    }
    g -= s.normal.dot(g) * s.normal;
    if(!(g.norm() > 0)) return false;
    g.normalize();
    double alpha = 0.1 * length;
    for(int k = 0; k < max_backtracking_steps; ++k, alpha *= 0.5) {
      Bare_point p;
      if(!project(s, x0 + alpha * g, alpha + 0.5 * length, p)) continue;
      const double q = quality(s, p);
      if(q > s.new_min + 1e-3 && is_valid(s, p)) {
        s.x = p;
        s.new_min = q;
        return true;
      }
    }
    return false;
  }

  // The cells that the star of a new vertex at `p` replaces: the edge's ring, and the
  // outside cells beyond any facet of it that `p` sees from behind (the new cell on it would
  // be inverted), and so on; false if a cell in the complex or an infinite one would have to
  // go, if a surface facet other than the edge's two would be inside, if a vertex would be
  // (it would be lost), or past `max_added_cells` (a cell of the complex that the new vertex
  // would invert is left to the callers: its new cell is not positive). The edge's midpoint projected onto a
  // curved surface often lies beyond an outside cell's facet (around a cell whose four
  // vertices all lie on the surface, say): those cells do not belong to the mesh, and their
  // region takes any
  // triangulation that fills it.
  bool hole(const Split& s, const Bare_point& p, std::vector<Cell_handle>& cells) const
  {
    cells = s.ring;
    const auto in_hole = [&cells](const Cell_handle& c) { return std::find(cells.begin(), cells.end(), c) != cells.end(); };
    for(std::size_t k = 0; k < cells.size(); ++k) {
      const Cell_handle c = cells[k];
      if(tr_.is_infinite(c)) continue; // the hull's convexity: is_valid()
      for(int i = 0; i < 4; ++i) {
        const Cell_handle n = c->neighbor(i);
        if(in_hole(n) || this->is_positive_with(c, c->vertex(i), p)) continue;
        if(tr_.is_infinite(n) || c3t3_.is_in_complex(n) || cells.size() == s.ring.size() + max_added_cells)
          return false;
        cells.push_back(n);
      }
    }
    if(cells.size() == s.ring.size()) return true;
    std::vector<Vertex_handle> on_boundary;
    for(const Cell_handle& c : cells)
      for(int i = 0; i < 4; ++i) {
        const bool inside = in_hole(c->neighbor(i));
        if(inside && c3t3_.is_in_complex(c, i) && !(c->has_vertex(s.a) && c->has_vertex(s.b) && c->vertex(i) != s.a &&
                                                   c->vertex(i) != s.b))
          return false;
        if(!inside)
          for(int j = 1; j < 4; ++j) on_boundary.push_back(c->vertex((i + j) & 3));
      }
    for(const Cell_handle& c : cells)
      for(int i = 0; i < 4; ++i)
        if(std::find(on_boundary.begin(), on_boundary.end(), c->vertex(i)) == on_boundary.end()) return false;
    return true;
  }

  // every new finite cell is positive, and the convex hull stays convex: each new hull
  // facet has its interior witness strictly inside and the hull vertices across its
  // edges inside or on its plane (as Vertex_smoother::is_valid_position())
  bool is_valid(const Split& s, const Bare_point& p) const
  {
    const auto orient = tr_.geom_traits().orientation_3_object();
    for(const Cell_handle& c : s.ring) {
      if(tr_.is_infinite(c) || !c3t3_.is_in_complex(c)) continue;
      for(const Vertex_handle& replaced : {s.a, s.b})
        if(!this->is_positive_with(c, replaced, p)) return false;
    }
    std::vector<Cell_handle> cells;
    if(!hole(s, p, cells)) return false;
    // the hull vertices next to the edge (a, b) through its infinite cells
    std::vector<Vertex_handle> hull;
    for(const Cell_handle& c : s.ring)
      if(tr_.is_infinite(c)) hull.push_back(c->vertex(6 - c->index(s.a) - c->index(s.b) - c->index(tr_.infinite_vertex())));
    for(const Cell_handle& c : s.ring) {
      if(!tr_.is_infinite(c)) continue;
      const int inf = c->index(tr_.infinite_vertex()), ia = c->index(s.a), ib = c->index(s.b);
      const int iw = 6 - inf - ia - ib;
      const Vertex_handle w = c->vertex(iw);
      const Cell_handle inside = c->neighbor(inf);
      const Bare_point witness = this->bare(inside->vertex(inside->index(c)));
      for(const Vertex_handle& kept : {s.a, s.b}) {
        const Vertex_handle gone = kept == s.a ? s.b : s.a;
        // the new hull facet (kept, x, w) and the vertices across its edges: beyond (kept, w)
        // the old neighbour's, beyond (x, w) the other half's, beyond (kept, x) the other
        // hull vertex next to the edge
        const Bare_point f[3] = {this->bare(kept), p, this->bare(w)};
        const CGAL::Orientation side = orient(f[0], f[1], f[2], witness);
        if(side == CGAL::COPLANAR) return false;
        const Cell_handle nb = c->neighbor(c->index(gone));
        std::vector<Bare_point> across{this->bare(nb->vertex(nb->index(c))), this->bare(gone)};
        for(const Vertex_handle& h : hull)
          if(h != w) across.push_back(this->bare(h));
        for(const Bare_point& d : across) {
          const CGAL::Orientation o = orient(f[0], f[1], f[2], d);
          if(o != side && o != CGAL::COPLANAR) return false;
        }
      }
    }
    return true;
  }

  // the four new surface facets stray no further from the surface than the boundary may,
  // or than the facet each halves
  bool is_faithful(const Split& s, const Bare_point& p) const
  {
    std::vector<std::array<Bare_point, 3>> parts;
    std::vector<std::array<Vertex_handle, 3>> vertices;
    for(const Vertex_handle& w : s.apexes) {
      const std::array<Bare_point, 3> whole{{this->bare(s.a), this->bare(s.b), this->bare(w)}};
      for(const Vertex_handle& kept : {s.a, s.b}) {
        parts.push_back({{this->bare(kept), p, this->bare(w)}});
        vertices.push_back({{s.a, s.b, w}});
        if(!smoother_.is_faithful_part(parts.back(), whole, s.patch, vertices.back())) return false;
      }
    }
    return smoother_.keeps_corners_near(parts, vertices);
  }

  void apply(const Split& s)
  {
    // the subdomain of each new cell, known by its facet opposite the new vertex: one of the
    // facets of a ring cell opposite a or b
    std::vector<std::pair<std::array<Vertex_handle, 3>, Subdomain_index>> subdomains;
    for(const Cell_handle& c : s.ring) {
      if(tr_.is_infinite(c) || !c3t3_.is_in_complex(c)) continue;
      for(const Vertex_handle& replaced : {s.a, s.b}) {
        const int i = c->index(replaced);
        subdomains.push_back({sorted_facet(c, i), c3t3_.subdomain_index(c)});
      }
      c3t3_.remove_from_complex(c);
    }
    std::vector<Cell_handle> cells;
    hole(s, s.x, cells);
    if(cells.size() > s.ring.size()) ++grown_holes_;
    for(const Vertex_handle& w : s.apexes) {
      Cell_handle c;
      int i, j, k;
      tr_.is_facet(s.a, s.b, w, c, i, j, k);
      c3t3_.remove_from_complex(Facet(c, 6 - i - j - k));
    }

    Facet start;
    for(const Cell_handle& c : cells)
      for(int i = 0; i < 4; ++i)
        if(std::find(cells.begin(), cells.end(), c->neighbor(i)) == cells.end()) start = Facet(c, i);
    const Vertex_handle v = tr_.tds().insert_in_hole(cells.begin(), cells.end(), start.first, start.second);
    set_bare_point(tr_, v, s.x, true);
    energy_.vertex_moved(v);
    c3t3_.set_dimension(v, 2);
    c3t3_.set_index(v, s.patch);
    std::vector<Cell_handle> star;
    tr_.incident_cells(v, std::back_inserter(star));
    for(const Cell_handle& c : star) {
      this->log_vertices(c);
      const std::array<Vertex_handle, 3> base = sorted_facet(c, c->index(v));
      for(const auto& sd : subdomains)
        if(sd.first == base) c3t3_.add_to_complex(c, sd.second);
    }
    // the old facets of the star take their data from the cells beyond; the new ones have none
    this->copy_surface_data(star);
    for(const Vertex_handle& w : s.apexes)
      for(const Vertex_handle& kept : {s.a, s.b}) {
        Cell_handle c;
        int i, j, k;
        tr_.is_facet(kept, v, w, c, i, j, k);
        const int l = 6 - i - j - k;
        c3t3_.add_to_complex(Facet(c, l), s.patch);
        const Facet m = tr_.mirror_facet(Facet(c, l));
        const auto centre = tr_.geom_traits().construct_centroid_3_object()(this->bare(kept), s.x, this->bare(w));
        c->set_facet_surface_center(l, centre);
        m.first->set_facet_surface_center(m.second, centre);
      }
    this->account(s.old_sum, s.new_sum, int(subdomains.size() / 2));
  }

  static std::array<Vertex_handle, 3> sorted_facet(const Cell_handle& c, int i)
  {
    std::array<Vertex_handle, 3> f{{c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)}};
    std::sort(f.begin(), f.end());
    return f;
  }

  std::size_t grown_holes_ = 0;
  /// at most this many outside cells beyond the edge's ring are replaced
  static constexpr std::size_t max_added_cells = 16;
  static constexpr int ascent_steps = 10;
  static constexpr double min_gain = 0.5; // degrees
  static constexpr int max_backtracking_steps = 10;

  const Smoother& smoother_;
  Angle_penalty penalty_;

  using Base::c3t3_;
  using Base::tr_;
  using Base::energy_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SURFACE_EDGE_SPLIT_H
