// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cells of one subdomain of a complex replaced by new cells filling the same
// region (flips, edge removals, splits): the bookkeeping of the complex
// (subdomain indices, surface-patch data of the facets on the region's
// boundary, the counters), shared by GSM's energy-guided changes and the
// lattice meshes' metric Delaunay flips.

#ifndef CGAL_VVM_INTERNAL_COMPLEX_CELL_REPLACEMENT_H
#define CGAL_VVM_INTERNAL_COMPLEX_CELL_REPLACEMENT_H

#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace VVM {
namespace internal {

/// whether the cells of `C3T3` carry per-facet surface data that a replacement must restore:
/// Mesh_3's do; a bare triangulation seen as a complex does not (it specializes this)
template <class C3T3>
struct Has_facet_surface_data : std::true_type {};

/// the bookkeeping of any change of connectivity inside one subdomain, whatever
/// decides it (GSM's energy, the metric Delaunay criterion of the lattice meshes)
template <class C3T3>
class Complex_cell_replacement
{
public:
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Facet Facet;
  typedef typename Tr::Edge Edge;
  typedef typename C3T3::Subdomain_index Subdomain_index;
  typedef typename C3T3::Surface_patch_index Surface_patch_index;

  explicit Complex_cell_replacement(C3T3& c3t3) : c3t3_(c3t3), tr_(c3t3.triangulation()) {}

  /// from now on, the vertices of the cells each change creates or peels go to `log`
  /// (none: nullptr), for passes that look again only where something changed
  void set_change_log(std::vector<Vertex_handle>* log) { log_ = log; }

protected:
  void log_vertices(const Cell_handle& c)
  {
    if(log_ != nullptr)
      for(int i = 0; i < 4; ++i) log_->push_back(c->vertex(i));
  }

  typename Tr::Geom_traits::Point_3 bare(const Vertex_handle& v) const
  {
    return tr_.geom_traits().construct_point_3_object()(tr_.point(v));
  }

  // exact, on the bare points
  CGAL::Orientation orientation(const Vertex_handle& a, const Vertex_handle& b, const Vertex_handle& c,
                                const Vertex_handle& d) const
  {
    return tr_.geom_traits().orientation_3_object()(bare(a), bare(b), bare(c), bare(d));
  }

  // the cell `c` with its vertex `replaced` at `p` is positively oriented (exact)
  bool is_positive_with(const Cell_handle& c, const Vertex_handle& replaced,
                        const typename Tr::Geom_traits::Point_3& p) const
  {
    typename Tr::Geom_traits::Point_3 q[4];
    for(int i = 0; i < 4; ++i) q[i] = c->vertex(i) == replaced ? p : bare(c->vertex(i));
    return tr_.geom_traits().orientation_3_object()(q[0], q[1], q[2], q[3]) == CGAL::POSITIVE;
  }

  // number of cells around `e`, counted up to `cap`
  std::size_t edge_degree(const Edge& e, std::size_t cap) const
  {
    std::size_t m = 0;
    auto cc = tr_.incident_cells(e), done = cc;
    do {
      ++m;
    } while(++cc != done && m < cap);
    return m;
  }

  // all given cells are finite, in the complex, and of one subdomain `s`
  bool same_subdomain(std::initializer_list<Cell_handle> cells, Subdomain_index& s) const
  {
    bool first = true;
    for(const Cell_handle& c : cells) {
      if(tr_.is_infinite(c) || !c3t3_.is_in_complex(c)) return false;
      if(first) s = c3t3_.subdomain_index(c);
      else if(!(c3t3_.subdomain_index(c) == s)) return false;
      first = false;
    }
    return true;
  }

  // the cells around `e` (in circular order), their ring vertices (`others[k]` is
  // shared by `ring[k]` and `ring[k + 1]`), and their common subdomain; false if
  // `e` is a feature edge, touches a surface facet or another subdomain, or has
  // more than `max_ring` cells
  bool removable_edge(const Edge& e, std::vector<Cell_handle>& ring, std::vector<Vertex_handle>& others,
                      Subdomain_index& s, std::size_t max_ring = 8) const
  {
    const Vertex_handle a = e.first->vertex(e.second), b = e.first->vertex(e.third);
    if(c3t3_.is_in_complex(a, b)) return false;
    auto cc = tr_.incident_cells(e), done = cc;
    bool first = true;
    do {
      const Cell_handle c = cc;
      if(tr_.is_infinite(c) || !c3t3_.is_in_complex(c)) return false;
      if(first) s = c3t3_.subdomain_index(c);
      else if(!(c3t3_.subdomain_index(c) == s)) return false;
      first = false;
      // the facets of c that contain the edge must not be in the complex
      const int ia = c->index(a), ib = c->index(b);
      for(int i = 0; i < 4; ++i)
        if(i != ia && i != ib && c3t3_.is_in_complex(c, i)) return false;
      ring.push_back(c);
      if(ring.size() > max_ring) return false;
    } while(++cc != done);
    // ring vertices in circular order: consecutive cells share one of them
    for(std::size_t k = 0; k < ring.size(); ++k) {
      const Cell_handle c = ring[k], next = ring[(k + 1) % ring.size()];
      for(int i = 0; i < 4; ++i) {
        const Vertex_handle v = c->vertex(i);
        if(v != a && v != b && next->has_vertex(v)) {
          others.push_back(v);
          break;
        }
      }
    }
    return others.size() == ring.size();
  }

  std::vector<Cell_handle> cells_around(const Vertex_handle& u, const Vertex_handle& w) const
  {
    std::vector<Cell_handle> cells;
    Cell_handle c;
    int i, j;
    if(!tr_.is_edge(u, w, c, i, j)) return cells;
    auto cc = tr_.incident_cells(Edge(c, i, j)), done = cc;
    do cells.push_back(cc);
    while(++cc != done);
    return cells;
  }

  std::vector<Cell_handle> cells_on(const Vertex_handle& u, const Vertex_handle& v,
                                    const Vertex_handle& w) const
  {
    Cell_handle c;
    int i, j, k;
    if(!tr_.is_facet(u, v, w, c, i, j, k)) return {};
    return {c, c->neighbor(6 - i - j - k)};
  }

  // takes cells out of the complex before a flip reuses them
  void release(const std::vector<Cell_handle>& cells)
  {
    for(const Cell_handle& c : cells) c3t3_.remove_from_complex(c);
  }
  void release(std::initializer_list<Cell_handle> cells) { release(std::vector<Cell_handle>(cells)); }

  // puts (new) cells into subdomain `s` and gives each of their facets the surface
  // data of its mirror facet: a flip reuses cells, whose old facet data are stale.
  // Facets between two of the new cells are inside the flipped region: never surface.
  void claim(const std::vector<Cell_handle>& cells, const Subdomain_index& s)
  {
    for(const Cell_handle& c : cells) {
      c3t3_.add_to_complex(c, s);
      log_vertices(c);
    }
    if constexpr(Has_facet_surface_data<C3T3>::value) copy_surface_data(cells);
  }
  void claim(std::initializer_list<Cell_handle> cells, const Subdomain_index& s)
  {
    claim(std::vector<Cell_handle>(cells), s);
  }

  void copy_surface_data(const std::vector<Cell_handle>& cells)
  {
    for(const Cell_handle& c : cells)
      for(int i = 0; i < 4; ++i) c->set_surface_patch_index(i, Surface_patch_index());
    for(const Cell_handle& c : cells)
      for(int i = 0; i < 4; ++i) {
        const Cell_handle n = c->neighbor(i);
        if(std::find(cells.begin(), cells.end(), n) != cells.end()) continue;
        const int in = n->index(c);
        if(n->is_facet_on_surface(in)) copy_facet_data(n, in, c, i);
      }
  }

  // whether the surface facet `(c, i)` is seen from `c`: each once, from the cell in the
  // complex, or of larger subdomain index on an interface (as the smoother orients them)
  bool seen_from(const Cell_handle& c, int i) const
  {
    if(tr_.is_infinite(c) || !c3t3_.is_in_complex(c)) return false;
    const Cell_handle m = c->neighbor(i);
    if(tr_.is_infinite(m) || !c3t3_.is_in_complex(m)) return true;
    return c3t3_.subdomain_index(m) < c3t3_.subdomain_index(c);
  }

  // the surface data of the facet (from, i) to the facet (to, j)
  static void copy_facet_data(const Cell_handle& from, int i, const Cell_handle& to, int j)
  {
    to->set_surface_patch_index(j, from->surface_patch_index(i));
    to->set_facet_surface_center(j, from->get_facet_surface_center(i));
    to->set_facet_surface_center_index(j, from->get_facet_surface_center_index(i));
  }

  C3T3& c3t3_;
  Tr& tr_;
  std::vector<Vertex_handle>* log_ = nullptr;
};

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_COMPLEX_CELL_REPLACEMENT_H
