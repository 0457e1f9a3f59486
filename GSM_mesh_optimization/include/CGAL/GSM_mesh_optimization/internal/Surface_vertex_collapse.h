// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Surface vertex removal by edge collapse: a vertex v on one surface patch goes
// into a neighbour w across a surface edge (v, w) of that patch (Vertex_collapse.h
// for the interior). Where the input mesh's surface is much finer than its
// interior (most vertices on the boundary, long edges from it to the first interior
// vertices), the cells under the bound are flat wedges between fine surface edges
// and the interior vertices across them; no move or split lifts them, even with a
// larger split budget, but fewer surface vertices do.
//
// The collapse is made on the whole star of v, outside cells included (each cell
// keeps its subdomain), when every new finite cell is positive, the link condition
// holds (in the triangulation, and on the surface: no pinched surface edge), the
// smallest dihedral angle of the new cells in the complex beats that of v's star by
// half a degree (and, unless the star's worst cell is critical, their angle penalty
// is lower), and every surface facet that takes w for v strays from
// the surface no further than the boundary may (Boundary_fidelity.h), nor v's point
// (on the surface) lies further from them than that; a vertex on the
// convex hull (a convex domain's whole surface) is removed only if the hull stays
// convex. Vertices on feature curves, on a patch border, and those whose facets
// strayed more than the others at the start (where the boundary's distance to the
// surface is largest) are kept.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SURFACE_VERTEX_COLLAPSE_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SURFACE_VERTEX_COLLAPSE_H

#include <CGAL/GSM_mesh_optimization/internal/Angle_penalty.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_collapse.h>
#include <CGAL/GSM_mesh_optimization/internal/Vertex_smoother.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <iterator>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class C3T3, class MeshDomain>
class Surface_vertex_collapse : public Vertex_collapse<C3T3>
{
  typedef Vertex_collapse<C3T3> Base;

public:
  typedef typename Base::Tr Tr;
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Facet Facet;
  typedef typename C3T3::Surface_patch_index Surface_patch_index;
  typedef Vertex_smoother<C3T3, MeshDomain> Smoother;
  typedef typename Smoother::Bare_point Bare_point;
  typedef typename CGAL::Kernel_traits<Bare_point>::Kernel::Triangle_3 Triangle_3;

  /// degrees: a collapse must beat the smallest angle of the star by this much
  static constexpr double min_gain = 0.5;

  Surface_vertex_collapse(C3T3& c3t3, const typename Base::Energy& energy, double& sum, std::size_t& count,
                          Smoother& smoother, const Angle_penalty& penalty = Angle_penalty())
    : Base(c3t3, energy, sum, count), smoother_(smoother), penalty_(penalty)
  {}

  void set_penalty(const Angle_penalty& penalty) { penalty_ = penalty; }

  /// a collapse of the surface vertex `v` into `w`
  struct Plan
  {
    Vertex_handle v, w;
    double old_min = 0, new_min = 0;
    double old_penalty = 0, new_penalty = 0;
    bool critical = false;
    double gain() const { return new_min - old_min; }
    bool is_better() const { return gain() > min_gain && (critical || new_penalty < old_penalty); }
  };

  /// the best collapse of the surface vertex `v`, if one beats its star (see above)
  bool best_collapse(const Vertex_handle& v, Plan& best) const
  {
    if constexpr(Is_triangulation_complex<C3T3>::value || std::is_void<MeshDomain>::value) {
      CGAL_USE(v);
      CGAL_USE(best);
      return false; // a bare triangulation's boundary is its convex hull: fixed
    } else {
      Star s;
      if(!surface_star(v, s)) return false;
      best = Plan();
      for(const Vertex_handle& w : s.neighbours) {
        Plan p;
        if(plan(s, w, p) && p.is_better() && (!best.is_better() || p.gain() > best.gain())) best = p;
      }
      return best.is_better();
    }
  }

  /// removes the surface vertex of the cell `c` whose collapse gains most, if one beats its
  /// star; true if done: `c` and `removed` are then gone
  bool try_collapse_cell(const Cell_handle& c, Vertex_handle& removed)
  {
    Plan best;
    for(int i = 0; i < 4; ++i) {
      Plan p;
      if(best_collapse(c->vertex(i), p) && (!best.is_better() || p.gain() > best.gain())) best = p;
    }
    if(!best.is_better()) return false;
    removed = best.v;
    apply(best);
    return true;
  }

  /// makes the collapse `p`, found by `best_collapse()` on the triangulation as it is
  void apply(const Plan& p)
  {
    smoother_.boundary_vertex_removed(p.v);
    this->collapse(p.v, p.w);
  }

private:
  // the star of a surface vertex: its cells, its neighbours (in the order of the star), its
  // surface facets (the edge opposite v of each) and
  // their patch, the smallest angle and the penalty of its cells in the complex
  struct Star
  {
    Vertex_handle v;
    std::vector<Cell_handle> cells;
    std::vector<Vertex_handle> neighbours;
    std::vector<std::array<Vertex_handle, 2>> facets;
    Surface_patch_index patch;
    double min = 180, penalty = 0;
  };

  bool surface_star(const Vertex_handle& v, Star& s) const
  {
    if(this->tr_.is_infinite(v) || this->c3t3_.in_dimension(v) != 2 || smoother_.has_own_boundary_bound(v))
      return false;
    s.v = v;
    this->tr_.incident_cells(v, std::back_inserter(s.cells));
    bool first = true;
    for(const Cell_handle& c : s.cells) {
      for(int i = 0; i < 4; ++i) {
        const Vertex_handle u = c->vertex(i);
        if(u != v && std::find(s.neighbours.begin(), s.neighbours.end(), u) == s.neighbours.end())
          s.neighbours.push_back(u);
      }
      if(!this->c3t3_.is_in_complex(c)) continue;
      const double q = this->energy_.min_dihedral_angle(c);
      s.min = (std::min)(s.min, q);
      s.penalty += penalty_(q);
      const int iv = c->index(v);
      for(int i = 0; i < 4; ++i) {
        if(i == iv || !this->c3t3_.is_in_complex(c, i) || !this->seen_from(c, i)) continue;
        const Surface_patch_index patch = this->c3t3_.surface_patch_index(c, i);
        if(!first && !(patch == s.patch)) return false; // on a patch border
        s.patch = patch;
        first = false;
        std::array<Vertex_handle, 2> ab;
        int n = 0;
        for(int k = 0; k < 4; ++k)
          if(k != i && k != iv) ab[n++] = c->vertex(k);
        s.facets.push_back(ab);
      }
    }
    return !first;
  }

  bool plan(const Star& s, const Vertex_handle& w, Plan& p) const
  {
    const Vertex_handle v = s.v;
    // (v, w) must be an edge of exactly two of v's surface facets
    int through = 0;
    std::vector<Vertex_handle> apexes;
    for(const auto& f : s.facets)
      if(f[0] == w || f[1] == w) {
        ++through;
        apexes.push_back(f[0] == w ? f[1] : f[0]);
      }
    if(through != 2) return false;
    // the link condition on the surface: a surface neighbour of both v and w is an apex of
    // (v, w) (else, as across a neck, the surface would be pinched at an edge)
    for(const auto& f : s.facets)
      for(const Vertex_handle& u : f)
        if(u != w && std::find(apexes.begin(), apexes.end(), u) == apexes.end() && is_surface_edge(u, w))
          return false;
    // v, a point of the surface, stays as near the new facets as the boundary may be to the
    // surface: new facets near the surface can still cut off what v stood for (the tip of a thin
    // part), the other direction of the Hausdorff distance
    double nearest2 = std::numeric_limits<double>::infinity();
    for(const auto& f : s.facets)
      if(f[0] != w && f[1] != w)
        nearest2 = (std::min)(nearest2, CGAL::to_double(CGAL::squared_distance(
                                            this->bare(v), Triangle_3(this->bare(w), this->bare(f[0]), this->bare(f[1])))));
    // (a hair more on a flat patch, whose bound is 0: rounding decides nothing)
    const double allowed = (std::max)(smoother_.boundary_bound(v),
                                      1e-9 * std::sqrt(CGAL::to_double(CGAL::squared_distance(this->bare(v), this->bare(w)))));
    if(!(nearest2 <= allowed * allowed)) return false;
    // a gone cell must not glue two surface facets together
    for(const Cell_handle& c : s.cells)
      if(c->has_vertex(w) && this->c3t3_.is_in_complex(c, c->index(v)) && this->c3t3_.is_in_complex(c, c->index(w)))
        return false;
    p.v = v;
    p.w = w;
    p.old_min = s.min;
    p.old_penalty = s.penalty;
    p.critical = penalty_.is_critical(s.min);
    p.new_min = this->collapse_angle(v, w, s.cells, s.neighbours, s.min + min_gain);
    if(!(p.new_min > s.min + min_gain)) return false;
    const Eigen::Vector3d x = this->energy_.position(w);
    p.new_penalty = 0;
    for(const Cell_handle& c : s.cells)
      if(!c->has_vertex(w) && this->c3t3_.is_in_complex(c))
        p.new_penalty += penalty_(this->energy_.min_dihedral_angle(c, v, x));
    if(!p.critical && !(p.new_penalty < p.old_penalty)) return false;
    // the facets that take w for v
    std::vector<std::array<Bare_point, 3>> star;
    std::vector<std::array<Vertex_handle, 3>> star_vertices;
    for(const auto& f : s.facets) {
      if(f[0] == w || f[1] == w) continue;
      star.push_back({{this->bare(w), this->bare(f[0]), this->bare(f[1])}});
      star_vertices.push_back({{w, f[0], f[1]}});
      if(!smoother_.is_faithful_triangle(star.back(), s.patch, star_vertices.back())) return false;
    }
    return smoother_.keeps_corners_near(star, star_vertices);
  }

  // whether (u, w) is an edge of a surface facet
  bool is_surface_edge(const Vertex_handle& u, const Vertex_handle& w) const
  {
    Cell_handle c;
    int i, j;
    if(!this->tr_.is_edge(u, w, c, i, j)) return false;
    auto cc = this->tr_.incident_cells(typename Tr::Edge(c, i, j)), done = cc;
    do {
      const Cell_handle d = cc;
      const int iu = d->index(u), iw = d->index(w);
      for(int k = 0; k < 4; ++k)
        if(k != iu && k != iw && this->c3t3_.is_in_complex(d, k)) return true;
    } while(++cc != done);
    return false;
  }

  Smoother& smoother_;
  Angle_penalty penalty_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_SURFACE_VERTEX_COLLAPSE_H
