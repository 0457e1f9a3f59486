// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Multi-face removal (Shewchuk 2002), the inverse of edge removal: k triangles
// t_1 .. t_k forming a triangulated polygon "sandwiched" between two vertices a
// and b (the cells (a, t_i) and (b, t_i) exist) are replaced, with the facets and
// edges between them, by the new edge (a, b) and the k + 2 cells (a, b, e) over
// the polygon's boundary edges e. k = 1 is the 2-3 flip, k = 2 the 4-4 flip.
//
// Shewchuk finds the best set of triangles by a dynamic program over the tree of
// candidate triangles; we grow it greedily instead, from one facet: each step
// adds the triangle beyond the boundary edge whose new cell is worst (inverted
// first, as the new edge must cross the polygon), and the best polygon of the
// growth is kept. The flip pass starts a growth from every facet, so each
// sandwich is grown from each of its triangles.
//
// It is made combinatorially, with the triangulation data structure's flips: a
// 2-3 flip of t_1 makes (a, b), then a 3-2 flip of each edge shared by t_j and a
// triangle before it, in the order of growth. Every final cell was checked
// positive before anything changed.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_MULTI_FACE_REMOVAL_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_MULTI_FACE_REMOVAL_H

#include <CGAL/GSM_mesh_optimization/internal/Cell_replacement.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class C3T3>
class Multi_face_removal : public Cell_replacement<C3T3>
{
  typedef Cell_replacement<C3T3> Base;

public:
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Facet Facet;
  typedef typename Base::Subdomain_index Subdomain_index;

  using Base::Base;

  /// removes up to `max_faces` faces, starting with `f`, from between its two
  /// opposite vertices, if that lowers the mean energy; returns how many (or 0).
  /// With `grow_from_bad_cell`, more than one face only if a cell on `f` is worse
  /// than the mean: a pass over all facets is much faster and finds nearly every
  /// removal, which nearly always takes such a cell.
  int try_remove_faces(const Facet& f, int max_faces, bool grow_from_bad_cell = false)
  {
    const Cell_handle ca = f.first, cb = ca->neighbor(f.second);
    Subdomain_index s;
    if(!this->same_subdomain({ca, cb}, s) || this->c3t3_.is_in_complex(f)) return 0;
    const Vertex_handle a = ca->vertex(f.second), b = cb->vertex(cb->index(ca));

    std::vector<Vertex_handle> polygon; // its vertices, in no order
    std::vector<Side> sides;
    for(int k = 1; k <= 3; ++k) polygon.push_back(ca->vertex((f.second + k) & 3));
    for(int k = 0; k < 3; ++k) sides.push_back(side(a, b, polygon[k], polygon[(k + 1) % 3], polygon[(k + 2) % 3], ca, cb));
    std::vector<Cell_handle> old_cells{ca, cb};
    std::vector<Side> crossed; // the growth: the sides crossed by it, in order
    const double ea = this->energy_.cell(ca), eb = this->energy_.cell(cb);
    double old_sum = ea + eb;
    if(grow_from_bad_cell && (std::max)(ea, eb) <= this->mean()) max_faces = 1;

    int best_k = 0;
    double best_gain = 0, best_new_sum = 0, best_old_sum = 0;
    for(int k = 1;; ++k) {
      double new_sum = 0; // infinite if a new cell would not be positive
      for(const Side& e : sides) new_sum += e.energy;
      // negative iff the mean goes down (lowers_mean()); the mean's change is nearly proportional
      const double gain = new_sum - old_sum - double(2 - k) * this->mean();
      if(gain < best_gain) {
        best_k = k;
        best_gain = gain;
        best_new_sum = new_sum;
        best_old_sum = old_sum;
      }
      if(k == max_faces) break;
      // grow across the side of the worst new cell that allows it
      std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return x.energy > y.energy; });
      std::size_t n = 0;
      Cell_handle xa, xb;
      Vertex_handle x;
      while(n < sides.size() && !beyond(a, b, sides[n], polygon, s, xa, xb, x)) ++n;
      if(n == sides.size()) break;
      const Side e = sides[n];
      crossed.push_back(e);
      old_cells.push_back(xa);
      old_cells.push_back(xb);
      polygon.push_back(x);
      old_sum += this->energy_.cell(xa) + this->energy_.cell(xb);
      sides[n] = side(a, b, e.p, x, e.q, xa, xb);
      sides.push_back(side(a, b, x, e.q, e.p, xa, xb));
    }
    if(best_k == 0) return 0;

    old_cells.resize(2 * best_k);
    this->release(old_cells);
    auto& tds = this->tr_.tds();
    tds.flip_flippable(ca, f.second);
    for(int j = 0; j + 1 < best_k; ++j) {
      // the cells (a, p, q, x), (b, p, q, x) beyond the side (p, q) are untouched so far
      const Cell_handle c = old_cells[2 * (j + 1)];
      tds.flip_flippable(c, c->index(crossed[j].p), c->index(crossed[j].q));
    }
    const std::vector<Cell_handle> new_cells = this->cells_around(a, b);
    CGAL_assertion(new_cells.size() == std::size_t(best_k + 2));
    this->claim(new_cells, s);
    this->account(best_old_sum, best_new_sum, 2 - best_k);
    return best_k;
  }

private:
  // a boundary edge (p, q) of the polygon, the third vertex w of its triangle, the
  // cells (a, p, q, w) and (b, p, q, w) of that triangle, and the energy of the new
  // cell (a, b, p, q), infinite if it would not be positive
  struct Side
  {
    Vertex_handle p, q, w;
    Cell_handle ca, cb;
    double energy;
  };

  Side side(const Vertex_handle& a, const Vertex_handle& b, const Vertex_handle& p, const Vertex_handle& q,
            const Vertex_handle& w, const Cell_handle& ca, const Cell_handle& cb) const
  {
    // (a, b, p, q) replaces (a, p, q, w) next to the facet (a, p, q): b and w on one side of it
    const CGAL::Orientation o = this->orientation(a, p, q, w);
    const bool positive = o != CGAL::ZERO && this->orientation(a, p, q, b) == o;
    return {p, q, w, ca, cb, positive ? this->tet_energy(a, b, p, q) : std::numeric_limits<double>::infinity()};
  }

  // the cells (a, p, q, x), (b, p, q, x) beyond the side e, if the triangle (p, q, x)
  // can join the polygon: x new to it, cells of subdomain s, and no facet or edge
  // that would disappear in the complex
  bool beyond(const Vertex_handle& a, const Vertex_handle& b, const Side& e,
              const std::vector<Vertex_handle>& polygon, const Subdomain_index& s, Cell_handle& xa,
              Cell_handle& xb, Vertex_handle& x) const
  {
    const int wa = e.ca->index(e.w), wb = e.cb->index(e.w);
    xa = e.ca->neighbor(wa);
    xb = e.cb->neighbor(wb);
    Subdomain_index sx;
    if(!this->same_subdomain({xa, xb}, sx) || !(sx == s)) return false;
    x = xa->vertex(xa->index(e.ca));
    if(x == b || xb->vertex(xb->index(e.cb)) != x) return false;
    if(std::find(polygon.begin(), polygon.end(), x) != polygon.end()) return false;
    const auto& c3t3 = this->c3t3_;
    return !c3t3.is_in_complex(e.ca, wa) && !c3t3.is_in_complex(e.cb, wb) &&
           !c3t3.is_in_complex(xa, xa->index(a)) && !c3t3.is_in_complex(e.p, e.q);
  }
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_MULTI_FACE_REMOVAL_H
