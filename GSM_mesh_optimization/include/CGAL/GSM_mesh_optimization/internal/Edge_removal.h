// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Edge removal (Shewchuk 2002, "Two discrete optimization algorithms for the
// topological improvement of tetrahedral meshes"): the m cells around an edge
// (a, b), whose other vertices form a closed ring r_0 .. r_{m-1}, are replaced
// by the 2(m - 2) cells (a, t) and (b, t) over the triangles t of a
// triangulation of the ring polygon. The triangulation is the one of least
// energy sum with every new cell positively oriented, from Klincsek's O(m^3)
// dynamic program. m = 4 is the 4-4 flip. For the polishing, the same program
// finds the triangulation of least sum of a penalty of the cells' smallest
// dihedral angles instead (Angle_penalty.h); m = 3 is then the 3-2 flip.
//
// It is made combinatorially, with the triangulation data structure's unchecked
// flips: m - 3 2-3 flips of the facets (a, b, r_j), each cutting an ear
// (r_i, r_j, r_k) off the ring, then a 3-2 flip of (a, b). Intermediate cells may
// be inverted; every final cell was checked before anything changed. All final
// cells positively oriented, with the same boundary as the old ones, tile the
// same region.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_EDGE_REMOVAL_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_EDGE_REMOVAL_H

#include <CGAL/GSM_mesh_optimization/internal/Cell_replacement.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

constexpr int max_polygon_size = 12;

/// a triangulation of the polygon 0 .. m-1: triangles (i, j, k), i < j < k, in an
/// order where each is an ear of the polygon left by the ones before (the last
/// one is what remains); `cost` is infinite if there is none
struct Polygon_triangulation
{
  double cost = std::numeric_limits<double>::infinity();
  std::vector<std::array<int, 3>> triangles;
};

/// the triangulation of the polygon 0 .. m-1 (3 <= m <= max_polygon_size) of least
/// sum of `weight(i, j, k)` (i < j < k) over its triangles (Klincsek 1980), if it is
/// below `bound`; `weight` is nonnegative, and infinite for a triangle that may not
/// be used
template <class Weight>
Polygon_triangulation best_polygon_triangulation(int m, const Weight& weight,
                                                 double bound = std::numeric_limits<double>::infinity())
{
  std::array<std::array<double, max_polygon_size>, max_polygon_size> cost; // of the polygon i .. k
  std::array<std::array<int, max_polygon_size>, max_polygon_size> split;
  for(int i = 0; i + 1 < m; ++i) cost[i][i + 1] = 0;
  for(int length = 2; length < m; ++length)
    for(int i = 0; i + length < m; ++i) {
      const int k = i + length;
      cost[i][k] = bound; // no part of a triangulation can cost more than all of it
      split[i][k] = -1;
      for(int j = i + 1; j < k; ++j) {
        const double parts = cost[i][j] + cost[j][k];
        if(!(parts < cost[i][k])) continue; // the weight cannot make up for it
        const double c = parts + weight(i, j, k);
        if(c < cost[i][k]) {
          cost[i][k] = c;
          split[i][k] = j;
        }
      }
    }
  Polygon_triangulation t;
  if(m < 3 || split[0][m - 1] < 0) return t;
  t.cost = cost[0][m - 1];
  // post-order: once the polygons (i .. j) and (j .. k) are cut away, (i, j, k) is an ear
  std::vector<std::array<int, 3>> stack{{{0, m - 1, 0}}}; // (i, k, children done)
  while(!stack.empty()) {
    std::array<int, 3>& top = stack.back();
    const int i = top[0], k = top[1], j = split[i][k];
    if(top[2] == 0) {
      top[2] = 1;
      if(j - i >= 2) stack.push_back({{i, j, 0}});
      if(k - j >= 2) stack.push_back({{j, k, 0}});
    } else {
      t.triangles.push_back({{i, j, k}});
      stack.pop_back();
    }
  }
  return t;
}

template <class C3T3>
class Edge_removal : public Cell_replacement<C3T3>
{
  typedef Cell_replacement<C3T3> Base;

public:
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Edge Edge;
  typedef typename Base::Subdomain_index Subdomain_index;

  using Base::Base;

  /// removes the edge `e` with 4 to `max_ring` cells around it, if some
  /// triangulation of its ring lowers the mean energy
  bool try_remove_edge(const Edge& e, std::size_t max_ring)
  {
    Ring g;
    if(!make_ring(e, max_ring, 4, g)) return false;
    const int m = int(g.r.size());
    double old_sum = 0;
    for(const Cell_handle& c : g.cells) old_sum += this->energy_.cell(c);
    // the bound is the criterion of lowers_mean()
    const Polygon_triangulation t = best_polygon_triangulation(m, [&](int i, int j, int k) {
      if(!is_positive(g, i, j, k)) return infinity;
      return this->tet_energy(g.a, g.r[i], g.r[j], g.r[k]) + this->tet_energy(g.b, g.r[i], g.r[j], g.r[k]);
    }, old_sum + double(m - 4) * this->mean());
    if(t.triangles.empty() || !this->lowers_mean(old_sum, t.cost, m - 4)) return false;
    replace(g, t, old_sum, t.cost);
    return true;
  }

  /// removes the edge `e` with 3 to `max_ring` cells around it, if the triangulation of
  /// its ring of least `penalty` sum (of the smallest dihedral angle of each cell) lowers
  /// that sum by `Penalty::min_relative_gain` of it without lowering the smallest angle of
  /// the cells, whatever the energy (for m = 3, a 3-2
  /// flip by that criterion rather than `try_flip_3_2()`'s energy)
  template <class Penalty>
  bool try_remove_edge_for_quality(const Edge& e, std::size_t max_ring, const Penalty& penalty)
  {
    Ring g;
    if(!make_ring(e, max_ring, 3, g)) return false;
    const int m = int(g.r.size());
    double old_penalty = 0, old_sum = 0, old_angle = 180;
    for(const Cell_handle& c : g.cells) {
      const double q = this->energy_.min_dihedral_angle(c);
      old_penalty += penalty(q);
      old_angle = (std::min)(old_angle, q);
      old_sum += this->energy_.cell(c);
    }
    const auto angle = [&](const Vertex_handle& v, int i, int j, int k) {
      return this->energy_.min_dihedral_angle(this->energy_.position(v), this->energy_.position(g.r[i]),
                                              this->energy_.position(g.r[j]), this->energy_.position(g.r[k]));
    };
    const Polygon_triangulation t = best_polygon_triangulation(m, [&](int i, int j, int k) {
      if(!is_positive(g, i, j, k)) return infinity;
      return penalty(angle(g.a, i, j, k)) + penalty(angle(g.b, i, j, k));
    }, (1 - Penalty::min_relative_gain) * old_penalty);
    if(t.triangles.empty()) return false;
    // a sum of penalties may trade several poor cells for one worse: never below the worst old one
    double new_sum = 0;
    for(const auto& tri : t.triangles) {
      if((std::min)(angle(g.a, tri[0], tri[1], tri[2]), angle(g.b, tri[0], tri[1], tri[2])) < old_angle) return false;
      new_sum += this->tet_energy(g.a, g.r[tri[0]], g.r[tri[1]], g.r[tri[2]]) +
                 this->tet_energy(g.b, g.r[tri[0]], g.r[tri[1]], g.r[tri[2]]);
    }
    replace(g, t, old_sum, new_sum);
    return true;
  }

private:
  static constexpr double infinity = std::numeric_limits<double>::infinity();

  // an edge (a, b) to remove, its ring r_0 .. r_{m-1}, the cells (a, b, r_i, r_{i+1})
  // in that order, all positive, and their subdomain
  struct Ring
  {
    Vertex_handle a, b;
    std::vector<Vertex_handle> r;
    std::vector<Cell_handle> cells;
    Subdomain_index s;
  };

  // the ring of `e`, if it is removable and has `min_size` to `max_ring` cells
  bool make_ring(const Edge& e, std::size_t max_ring, std::size_t min_size, Ring& g) const
  {
    std::vector<Cell_handle> ring;
    if(!this->removable_edge(e, ring, g.r, g.s, max_ring) || ring.size() < min_size) return false;
    const std::size_t m = ring.size();
    g.a = e.first->vertex(e.second);
    g.b = e.first->vertex(e.third);
    // cells[i] = (a, b, r_i, r_{i+1}); turn the ring so that these are positive
    g.cells.resize(m);
    for(std::size_t i = 0; i < m; ++i) g.cells[i] = ring[(i + 1) % m];
    const CGAL::Orientation o = this->orientation(g.a, g.b, g.r[0], g.r[1]);
    if(o == CGAL::ZERO) return false;
    if(o == CGAL::NEGATIVE) {
      std::reverse(g.r.begin(), g.r.end());
      std::reverse(g.cells.begin(), g.cells.end());
      std::rotate(g.cells.begin(), g.cells.begin() + 1, g.cells.end());
    }
    return true;
  }

  // the new cells (a, r_i, r_j, r_k) and (b, r_i, r_k, r_j), i < j < k, are positive
  bool is_positive(const Ring& g, int i, int j, int k) const
  {
    return this->orientation(g.a, g.r[i], g.r[j], g.r[k]) == CGAL::POSITIVE &&
           this->orientation(g.b, g.r[i], g.r[k], g.r[j]) == CGAL::POSITIVE;
  }

  // replaces the cells of `g` (energies `old_sum`) by those over `t` (`new_sum`)
  void replace(const Ring& g, const Polygon_triangulation& t, double old_sum, double new_sum)
  {
    const int m = int(g.r.size());
    this->release(g.cells);
    flip_ring(g.a, g.b, g.r, g.cells, t);
    std::vector<Cell_handle> new_cells;
    for(const auto& tri : t.triangles)
      for(const Cell_handle& c : this->cells_on(g.r[tri[0]], g.r[tri[1]], g.r[tri[2]])) new_cells.push_back(c);
    CGAL_assertion(new_cells.size() == std::size_t(2 * (m - 2)));
    this->claim(new_cells, g.s);
    this->account(old_sum, new_sum, m - 4);
  }

  // the flips that make `t`; `cells[i]` is the cell (a, b, r_i, r_{i+1})
  void flip_ring(const Vertex_handle& a, const Vertex_handle& b, const std::vector<Vertex_handle>& r,
                 std::vector<Cell_handle> cells, const Polygon_triangulation& t)
  {
    auto& tds = this->tr_.tds();
    for(std::size_t n = 0; n + 1 < t.triangles.size(); ++n) {
      const int i = t.triangles[n][0], k = t.triangles[n][2];
      // the facet (a, b, r_j), between the cells over (r_i, r_j) and (r_j, r_k)
      const Cell_handle c = cells[i];
      tds.flip_flippable(c, c->index(r[i]));
      // the three new cells share the edge (r_i, r_k): c and two of its neighbours
      cells[i] = c;
      for(int l = 0; l < 4 && !is_ring_cell(cells[i], a, b, r[i], r[k]); ++l) cells[i] = c->neighbor(l);
      CGAL_assertion(is_ring_cell(cells[i], a, b, r[i], r[k]));
    }
    const Cell_handle c = cells[t.triangles.back()[0]];
    tds.flip_flippable(c, c->index(a), c->index(b));
  }

  static bool is_ring_cell(const Cell_handle& c, const Vertex_handle& a, const Vertex_handle& b,
                           const Vertex_handle& u, const Vertex_handle& w)
  {
    return c->has_vertex(a) && c->has_vertex(b) && c->has_vertex(u) && c->has_vertex(w);
  }
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_EDGE_REMOVAL_H
