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
// models the splits that lift the cells under 30 degrees take ~5% more vertices
// (armadillo, dino at 10k), more than the vertex budget of 3%.
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
  void apply(const Collapse& k)
  {
    const Vertex_handle v = k.v, w = k.w;
    std::vector<Cell_handle> star, around, others;
    Subdomain_index s;
    removable_vertex(v, star, s);
    double old_sum = 0, new_sum = 0;
    for(const Cell_handle& c : star) {
      old_sum += this->energy_.cell(c);
      if(c->has_vertex(w)) {
        around.push_back(c);
      } else {
        others.push_back(c);
        new_sum += new_cell_energy(c, v, w);
      }
    }
    this->release(star);
    auto& tds = this->tr_.tds();
    for(const Cell_handle& c : around) {
      // the facets of c opposite v and opposite w become one
      const Cell_handle nv = c->neighbor(c->index(v)), nw = c->neighbor(c->index(w));
      const int iv = nv->index(c), iw = nw->index(c);
      nv->set_neighbor(iv, nw);
      nw->set_neighbor(iw, nv);
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != v) c->vertex(i)->set_cell(nv);
    }
    for(const Cell_handle& c : others) c->set_vertex(c->index(v), w);
    for(const Cell_handle& c : around) tds.delete_cell(c);
    this->energy_.vertex_removed(v);
    tds.delete_vertex(v);
    this->claim(others, s);
    this->account(old_sum, new_sum, -int(around.size()));
  }

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

  // the smallest dihedral angle of the cells of the collapse of `v` into `w`, or -1 if it is
  // not allowed or not over `floor`
  double collapse_angle(const Vertex_handle& v, const Vertex_handle& w, const std::vector<Cell_handle>& star,
                        const std::vector<Vertex_handle>& neighbours, double floor) const
  {
    std::vector<Vertex_handle> ring;
    const Eigen::Vector3d x = this->energy_.position(w);
    double q = 180;
    for(const Cell_handle& c : star) {
      if(c->has_vertex(w)) {
        for(int i = 0; i < 4; ++i)
          if(c->vertex(i) != v && c->vertex(i) != w) ring.push_back(c->vertex(i));
        continue;
      }
      const int i = c->index(v);
      std::array<Vertex_handle, 4> t{{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}};
      t[i] = w;
      if(this->orientation(t[0], t[1], t[2], t[3]) != CGAL::POSITIVE) return -1;
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
    return q;
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
