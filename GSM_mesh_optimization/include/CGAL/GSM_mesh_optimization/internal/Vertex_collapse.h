// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex removal by edge collapse: an interior vertex v goes into one of its
// neighbours w. The cells around the edge (v, w) disappear, each gluing its two
// facets that are not on the edge's ring together; every other cell of v's star
// takes w in place of v, i.e. becomes the cone from w over its facet of v's
// link. The collapse is made only if all those cones are positively oriented
// (they then tile v's star: the same region, with the same boundary) and their
// smallest dihedral angle is at least a given bound, and if the edge meets the
// link condition (a vertex adjacent to both v and w is on the edge's ring).
//
// The polishing (Sliver_polisher.h) removes vertices where the mesh stays good
// without them, to pay for the edge splits its worst cells need: on thin organic
// models the splits that lift the cells under 30 degrees take ~5% more vertices,
// more than the vertex budget of 3%.
//
// Only a vertex inside one subdomain (dimension 3, every cell of its star in the
// complex with one subdomain index) is removed: the surface and the interfaces keep
// their facets (a surface facet of a cell around (v, w), opposite v, passes to the
// cell it is glued to, which takes it over from the facet's other side).

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_COLLAPSE_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_COLLAPSE_H

#include <CGAL/GSM_mesh_optimization/internal/Cell_replacement.h>

#include <algorithm>
#include <iterator>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class C3T3>
class Vertex_collapse : public Cell_replacement<C3T3>
{
  typedef Cell_replacement<C3T3> Base;

public:
  typedef typename Base::Tr Tr;
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Facet Facet;
  typedef typename Base::Subdomain_index Subdomain_index;

  using Base::Base;

  /// a removal of `v` into `w`, whose new cells have `angle` as their smallest dihedral angle
  struct Collapse
  {
    Vertex_handle v, w;
    double angle = -1;
  };

  /// the collapse of `v` into the neighbour that gives its new cells the largest smallest
  /// dihedral angle, if that is at least `least` degrees; false if there is none
  bool best_collapse(const Vertex_handle& v, double least, Collapse& best) const
  {
    std::vector<Cell_handle> star;
    Subdomain_index s;
    if(!removable_vertex(v, star, s)) return false;
    // in the order of the star, not of the handles' addresses: the first of equals wins
    std::vector<Vertex_handle> neighbours;
    for(const Cell_handle& c : star)
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != v && std::find(neighbours.begin(), neighbours.end(), c->vertex(i)) == neighbours.end())
          neighbours.push_back(c->vertex(i));
    best = Collapse();
    for(const Vertex_handle& w : neighbours) {
      const double q = collapse_angle(v, w, star, neighbours, (std::max)(least, best.angle));
      if(q > best.angle) best = Collapse{v, w, q};
    }
    return best.angle >= least;
  }

  /// makes the collapse `k`, found by `best_collapse()` on the triangulation as it is
  void apply(const Collapse& k) { collapse(k.v, k.w); }

  /// removes up to `n` vertices, those whose removal leaves the best cells first, each
  /// only if its new cells' smallest dihedral angle is at least `least` degrees; the stars
  /// of the removed vertices are not touched again; returns how many were removed
  std::size_t collapse_vertices(std::size_t n, double least)
  {
    std::vector<Collapse> found;
    for(const Vertex_handle& v : this->tr_.finite_vertex_handles()) {
      Collapse k;
      if(best_collapse(v, least, k)) found.push_back(k);
    }
    // the order of the triangulation's vertices breaks ties: not their addresses
    std::stable_sort(found.begin(), found.end(), [](const Collapse& a, const Collapse& b) { return a.angle > b.angle; });
    std::unordered_set<Vertex_handle> touched;
    std::size_t done = 0;
    for(const Collapse& k : found) {
      if(done == n) break;
      if(touched.count(k.v) != 0 || touched.count(k.w) != 0) continue;
      std::vector<Vertex_handle> ring;
      this->tr_.adjacent_vertices(k.v, std::back_inserter(ring));
      touched.insert(ring.begin(), ring.end());
      touched.insert(k.v);
      apply(k);
      ++done;
    }
    return done;
  }

private:
  // the star of `v` and its subdomain, if `v` is inside one subdomain
  bool removable_vertex(const Vertex_handle& v, std::vector<Cell_handle>& star, Subdomain_index& s) const
  {
    if(this->tr_.is_infinite(v) || this->c3t3_.in_dimension(v) != 3) return false;
    this->tr_.incident_cells(v, std::back_inserter(star));
    bool first = true;
    for(const Cell_handle& c : star) {
      if(this->tr_.is_infinite(c) || !this->c3t3_.is_in_complex(c)) return false;
      if(first) s = this->c3t3_.subdomain_index(c);
      else if(!(this->c3t3_.subdomain_index(c) == s)) return false;
      first = false;
    }
    return !star.empty();
  }

protected:
  // the smallest dihedral angle of the new cells in the complex of the collapse of `v` (with
  // the incident cells `star` and the adjacent vertices `neighbours`) into `w`, or -1 if it is
  // not allowed (a new finite cell not positive, the convex hull no longer convex, the link
  // condition) or not over `floor`
  double collapse_angle(const Vertex_handle& v, const Vertex_handle& w, const std::vector<Cell_handle>& star,
                        const std::vector<Vertex_handle>& neighbours, double floor) const
  {
    std::vector<Vertex_handle> ring;
    std::vector<Cell_handle> new_hull;
    const Eigen::Vector3d x = this->energy_.position(w);
    double q = 180;
    for(const Cell_handle& c : star) {
      if(this->tr_.is_infinite(c) && !c->has_vertex(w)) {
        new_hull.push_back(c);
        continue;
      }
      if(c->has_vertex(w)) {
        for(int i = 0; i < 4; ++i)
          if(c->vertex(i) != v && c->vertex(i) != w) ring.push_back(c->vertex(i));
        continue;
      }
      const int i = c->index(v);
      std::array<Vertex_handle, 4> t{{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
      t[i] = w;
      if(this->orientation(t[0], t[1], t[2], t[3]) != CGAL::POSITIVE) return -1;
      if(!this->c3t3_.is_in_complex(c)) continue; // outside cells only need to be valid
      q = (std::min)(q, this->energy_.min_dihedral_angle(c, v, x));
      if(!(q > floor)) return -1;
    }
    // the link condition: a neighbour of both v and w is on the ring of (v, w)
    for(const Vertex_handle& u : neighbours) {
      if(u == w || std::find(ring.begin(), ring.end(), u) != ring.end()) continue;
      Cell_handle c;
      int i, j;
      if(this->tr_.is_edge(u, w, c, i, j)) return -1;
    }
    return new_hull.empty() || stays_convex(v, w, new_hull) ? q : -1;
  }

  // whether the hull facets of the infinite cells `new_hull` of the star of `v`, with `w` for
  // `v`, leave the convex hull convex: no hull vertex next to `v` or `w`, or across an edge of
  // them, beyond one of them (locally convex everywhere, the hull is convex)
  bool stays_convex(const Vertex_handle& v, const Vertex_handle& w, const std::vector<Cell_handle>& new_hull) const
  {
    std::vector<Vertex_handle> near;
    for(const Vertex_handle& u : {v, w}) {
      std::vector<Cell_handle> cells;
      this->tr_.incident_cells(u, std::back_inserter(cells));
      for(const Cell_handle& c : cells)
        if(this->tr_.is_infinite(c))
          for(int i = 0; i < 4; ++i)
            if(!this->tr_.is_infinite(c->vertex(i)) && c->vertex(i) != v &&
               std::find(near.begin(), near.end(), c->vertex(i)) == near.end())
              near.push_back(c->vertex(i));
    }
    // and the hull vertices across the edges opposite `v` of its hull facets
    for(const Cell_handle& c : new_hull) {
      const Cell_handle n = c->neighbor(c->index(v));
      const Vertex_handle z = n->vertex(n->index(c));
      if(std::find(near.begin(), near.end(), z) == near.end()) near.push_back(z);
    }
    for(const Cell_handle& c : new_hull) {
      std::array<Vertex_handle, 4> t{{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
      t[c->index(v)] = w;
      const int inf = c->index(this->tr_.infinite_vertex());
      for(const Vertex_handle& z : near) {
        if(std::find(t.begin(), t.end(), z) != t.end()) continue;
        // an infinite cell is positive with its infinite vertex beyond its facet
        t[inf] = z;
        const CGAL::Orientation o = this->orientation(t[0], t[1], t[2], t[3]);
        t[inf] = this->tr_.infinite_vertex();
        if(o == CGAL::POSITIVE) return false;
      }
    }
    return true;
  }

  // Removes `v` into its neighbour `w`; each cell keeps its subdomain. The facets through
  // (v, w) go with the cells around it; where one of the two facets a gone cell glues
  // together was a surface facet, the glued facet takes its data (callers exclude the case
  // of both). A surface facet of `v` elsewhere stays a surface facet, with `w` for `v`.
  void collapse(const Vertex_handle& v, const Vertex_handle& w)
  {
    std::vector<Cell_handle> star, around, others;
    this->tr_.incident_cells(v, std::back_inserter(star));
    double old_sum = 0, new_sum = 0;
    int gone = 0;
    for(const Cell_handle& c : star) {
      const bool in = this->c3t3_.is_in_complex(c);
      if(in) old_sum += this->energy_.cell(c);
      if(c->has_vertex(w)) {
        around.push_back(c);
        gone += in ? 1 : 0;
      } else {
        others.push_back(c);
        if(in) new_sum += new_cell_energy(c, v, w);
      }
    }
    for(const Cell_handle& c : around) {
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != v && c->vertex(i) != w) this->c3t3_.remove_from_complex(Facet(c, i));
      this->c3t3_.remove_from_complex(c);
    }
    auto& tds = this->tr_.tds();
    for(const Cell_handle& c : around) {
      // the facets of c opposite v and opposite w become one
      const Cell_handle nv = c->neighbor(c->index(v)), nw = c->neighbor(c->index(w));
      const int iv = nv->index(c), iw = nw->index(c);
      if constexpr(!Is_triangulation_complex<C3T3>::value) {
        if(nv->is_facet_on_surface(iv)) this->copy_facet_data(nv, iv, nw, iw);
        else if(nw->is_facet_on_surface(iw)) this->copy_facet_data(nw, iw, nv, iv);
      }
      nv->set_neighbor(iv, nw);
      nw->set_neighbor(iw, nv);
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != v) c->vertex(i)->set_cell(nv);
    }
    for(const Cell_handle& c : others) {
      c->set_vertex(c->index(v), w);
      this->log_vertices(c);
    }
    for(const Cell_handle& c : around) tds.delete_cell(c);
    this->energy_.vertex_removed(v);
    tds.delete_vertex(v);
    this->account(old_sum, new_sum, -gone);
  }

  // energy of cell `c` with `w` in place of its vertex `v`
  double new_cell_energy(const Cell_handle& c, const Vertex_handle& v, const Vertex_handle& w) const
  {
    std::array<Vertex_handle, 4> t{{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
    t[c->index(v)] = w;
    return this->energy_.tetrahedron(t[0], t[1], t[2], t[3]);
  }
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_COLLAPSE_H
