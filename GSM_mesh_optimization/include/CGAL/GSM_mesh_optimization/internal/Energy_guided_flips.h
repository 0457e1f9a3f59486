// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// GSM connectivity update (dissertation section 3.3.2): 2-3, 3-2 and 4-4 flips,
// each applied when it lowers the mean energy of the cells in the complex
// (sum_new - sum_old < (n_new - n_old) * mean), so that the mesh energy of
// eq. 3.9 never increases and no sequence of flips can cycle.
//
// Never across a surface facet, a feature edge or a subdomain boundary; only
// cells of one subdomain are replaced, and the new cells get that subdomain and
// the surface-patch data of the facets they border, with the complex's counters.
// 2-3 and 3-2 are CGAL's own `Triangulation_3::flip()`; 4-4 is a 2-3 then a 3-2.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ENERGY_GUIDED_FLIPS_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ENERGY_GUIDED_FLIPS_H

#include <CGAL/GSM_mesh_optimization/internal/Mesh_energy.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

/// counts of the flips done
struct Flip_counts
{
  std::size_t flips_2_3 = 0, flips_3_2 = 0, flips_4_4 = 0, boundary_peels = 0;
  std::size_t total() const { return flips_2_3 + flips_3_2 + flips_4_4 + boundary_peels; }
};

template <class C3T3>
class Energy_guided_flips
{
public:
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Facet Facet;
  typedef typename Tr::Edge Edge;
  typedef typename C3T3::Subdomain_index Subdomain_index;
  typedef typename C3T3::Surface_patch_index Surface_patch_index;
  typedef Mesh_energy<C3T3> Energy;

  /// `sum` and `count`: the running total of the energies of the cells in the complex
  Energy_guided_flips(C3T3& c3t3, const Energy& energy, double& sum, std::size_t& count)
    : c3t3_(c3t3), tr_(c3t3.triangulation()), energy_(energy), sum_(sum), count_(count)
  {}

  /// one pass over the edges (3-2, 4-4) then the facets (2-3) of the complex
  Flip_counts flip_pass()
  {
    Flip_counts done;
    // Handles go stale as cells are replaced: collect vertex tuples, re-find each.
    std::set<std::array<Vertex_handle, 2>> edges;
    std::set<std::array<Vertex_handle, 3>> facets;
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c) {
      for(int i = 0; i < 4; ++i) {
        for(int j = i + 1; j < 4; ++j) edges.insert(sorted(std::array<Vertex_handle, 2>{{c->vertex(i), c->vertex(j)}}));
        if(!c3t3_.is_in_complex(c, i))
          facets.insert(sorted(std::array<Vertex_handle, 3>{
              {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)}}));
      }
    }
    for(const auto& e : edges) {
      Cell_handle c;
      int i, j;
      if(!tr_.is_edge(e[0], e[1], c, i, j)) continue;
      const std::size_t m = edge_degree(Edge(c, i, j));
      if(m == 3 && try_flip_3_2(Edge(c, i, j))) ++done.flips_3_2;
      else if(m == 4 && try_flip_4_4(Edge(c, i, j))) ++done.flips_4_4;
    }
    for(const auto& f : facets) {
      Cell_handle c;
      int i, j, k;
      if(!tr_.is_facet(f[0], f[1], f[2], c, i, j, k)) continue;
      if(try_flip_2_3(Facet(c, 6 - i - j - k))) ++done.flips_2_3;
    }
    // flat cells lying on the surface: no flip and no move can give them volume
    std::vector<std::array<Vertex_handle, 4>> flat_boundary_cells;
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c) {
      int surface_facets = 0;
      for(int i = 0; i < 4; ++i) surface_facets += c3t3_.is_in_complex(c, i) ? 1 : 0;
      if(surface_facets == 2)
        flat_boundary_cells.push_back({{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}});
    }
    for(const auto& t : flat_boundary_cells) {
      Cell_handle c;
      int i, j, k, l;
      if(tr_.is_cell(t[0], t[1], t[2], t[3], c, i, j, k, l) && try_peel_boundary_cell(c))
        ++done.boundary_peels;
    }
    return done;
  }

  /// removes from the complex a nearly flat cell `c` with two surface facets of one
  /// patch, replacing them by its two other facets (a 2-2 flip of the surface
  /// triangulation that moves the surface by less than the cell's small height),
  /// if that lowers the mean energy
  bool try_peel_boundary_cell(const Cell_handle& c)
  {
    int in[2], out[2], n_in = 0, n_out = 0;
    for(int i = 0; i < 4; ++i) {
      if(c3t3_.is_in_complex(c, i)) {
        if(n_in == 2) return false;
        in[n_in++] = i;
      } else {
        if(n_out == 2) return false;
        out[n_out++] = i;
      }
    }
    if(n_in != 2 || !c3t3_.is_in_complex(c)) return false;
    const Surface_patch_index patch = c3t3_.surface_patch_index(c, in[0]);
    if(!(c3t3_.surface_patch_index(c, in[1]) == patch)) return false;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(c3t3_.is_in_complex(c->vertex(i), c->vertex(j))) return false; // a feature edge
    // the new surface edge (the vertices opposite the old surface facets) must be new
    const Vertex_handle u = c->vertex(in[0]), w = c->vertex(in[1]);
    Cell_handle ec;
    int ei, ej;
    if(!tr_.is_edge(u, w, ec, ei, ej)) return false;
    auto fc = tr_.incident_facets(Edge(ec, ei, ej)), fdone = fc;
    do
      if(c3t3_.is_in_complex(*fc)) return false;
    while(++fc != fdone);
    // flat: the surface moves by the height of the cell, small next to its edges
    if(!is_flat(c)) return false;
    const double e = energy_.cell(c);
    if(!(-e < -mean())) return false;

    c3t3_.remove_from_complex(Facet(c, in[0]));
    c3t3_.remove_from_complex(Facet(c, in[1]));
    c3t3_.remove_from_complex(c);
    for(int k = 0; k < 2; ++k) {
      c3t3_.add_to_complex(Facet(c, out[k]), patch);
      const Facet m = tr_.mirror_facet(Facet(c, out[k]));
      const auto centre = tr_.geom_traits().construct_centroid_3_object()(
          bare(c->vertex((out[k] + 1) & 3)), bare(c->vertex((out[k] + 2) & 3)), bare(c->vertex((out[k] + 3) & 3)));
      c->set_facet_surface_center(out[k], centre);
      m.first->set_facet_surface_center(m.second, centre);
    }
    account(e, 0., -1);
    return true;
  }

  double mean() const { return count_ > 0 ? sum_ / double(count_) : 0.; }

  // --- the flips; each returns true if done --------------------------------

  /// 2-3 flip of the facet `f`, if it lowers the mean energy
  bool try_flip_2_3(const Facet& f)
  {
    const Cell_handle c = f.first, n = c->neighbor(f.second);
    Subdomain_index s;
    if(!same_subdomain({c, n}, s) || c3t3_.is_in_complex(f)) return false;
    const Vertex_handle p = c->vertex(f.second), q = n->vertex(n->index(c));
    std::array<Vertex_handle, 3> abc;
    for(int k = 0; k < 3; ++k) abc[k] = c->vertex((f.second + 1 + k) & 3);
    const double old_sum = energy_.cell(c) + energy_.cell(n);
    double new_sum = 0;
    for(int k = 0; k < 3; ++k) new_sum += tet_energy(p, q, abc[k], abc[(k + 1) % 3]);
    if(!(new_sum - old_sum < mean())) return false;

    release({c, n});
    if(!tr_.flip(c, f.second)) {
      claim({c, n}, s);
      return false;
    }
    claim(cells_around(p, q), s);
    account(old_sum, new_sum, +1);
    return true;
  }

  /// 3-2 flip of the edge `e` (three incident cells), if it lowers the mean energy
  bool try_flip_3_2(const Edge& e)
  {
    std::vector<Cell_handle> ring;
    std::vector<Vertex_handle> others;
    Subdomain_index s;
    if(!removable_edge(e, ring, others, s) || ring.size() != 3) return false;
    const Vertex_handle a = e.first->vertex(e.second), b = e.first->vertex(e.third);
    double old_sum = 0;
    for(const Cell_handle& c : ring) old_sum += energy_.cell(c);
    const double new_sum = tet_energy(a, others[0], others[1], others[2]) +
                           tet_energy(b, others[0], others[1], others[2]);
    if(!(new_sum - old_sum < -mean())) return false;

    release(ring);
    if(!tr_.flip(e)) {
      claim(ring, s);
      return false;
    }
    claim(cells_on(others[0], others[1], others[2]), s);
    account(old_sum, new_sum, -1);
    return true;
  }

  /// 4-4 flip of the edge `e` (four incident cells) to the better of the two
  /// other diagonals of its ring, if it lowers the mean energy
  bool try_flip_4_4(const Edge& e)
  {
    std::vector<Cell_handle> ring;
    std::vector<Vertex_handle> r; // ring vertices in circular order
    Subdomain_index s;
    if(!removable_edge(e, ring, r, s) || ring.size() != 4) return false;
    const Vertex_handle a = e.first->vertex(e.second), b = e.first->vertex(e.third);
    double old_sum = 0;
    for(const Cell_handle& c : ring) old_sum += energy_.cell(c);
    // the diagonal (r[k], r[k+2]) splits the ring into (r[k], r[k+1], r[k+2]) and (r[k+2], r[k+3], r[k])
    double best = old_sum;
    int best_k = -1;
    for(int k = 0; k < 2; ++k) {
      const Vertex_handle d0 = r[k], d1 = r[k + 2], m0 = r[k + 1], m1 = r[(k + 3) % 4];
      const double sum = tet_energy(a, d0, m0, d1) + tet_energy(b, d0, m0, d1) +
                         tet_energy(a, d0, m1, d1) + tet_energy(b, d0, m1, d1);
      if(sum < best) {
        best = sum;
        best_k = k;
      }
    }
    if(best_k < 0) return false;

    // a 2-3 flip of the facet (a, b, m) makes the diagonal (r[k], r[k+2]), for the
    // m of r[k+1], r[k+3] whose triangle with (a, b) the diagonal crosses;
    // then the edge (a, b) has three cells and a 3-2 flip removes it
    const Vertex_handle d0 = r[best_k], d1 = r[best_k + 2];
    release(ring);
    bool first_flip = false;
    for(const Vertex_handle& m : {r[best_k + 1], r[(best_k + 3) % 4]}) {
      Cell_handle c;
      int i, j, k;
      if(tr_.is_facet(a, b, m, c, i, j, k) && tr_.flip(c, 6 - i - j - k)) {
        first_flip = true;
        break;
      }
    }
    if(!first_flip) {
      claim(ring, s);
      return false;
    }
    Cell_handle ec;
    int ei, ej;
    const bool has_edge = tr_.is_edge(a, b, ec, ei, ej);
    if(!has_edge || !tr_.flip(Edge(ec, ei, ej))) {
      // not convex for the second half: undo the first (3-2 around the new diagonal)
      Cell_handle uc;
      int ui, uj;
      if(tr_.is_edge(d0, d1, uc, ui, uj)) tr_.flip(Edge(uc, ui, uj));
      claim(cells_around(a, b), s);
      return false;
    }
    claim(cells_around(d0, d1), s);
    account(old_sum, best, 0);
    return true;
  }

private:
  typename Tr::Geom_traits::Point_3 bare(const Vertex_handle& v) const
  {
    return tr_.geom_traits().construct_point_3_object()(tr_.point(v));
  }

  // height of the cell over its largest facet below 5% of its longest edge
  bool is_flat(const Cell_handle& c) const
  {
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = energy_.position(c->vertex(i));
    const double six_v = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
    double max_area2 = 0, max_edge = 0; // twice the area
    for(int i = 0; i < 4; ++i) {
      const Eigen::Vector3d& a = p[(i + 1) & 3], &b = p[(i + 2) & 3], &d = p[(i + 3) & 3];
      max_area2 = (std::max)(max_area2, (b - a).cross(d - a).norm());
      for(int j = i + 1; j < 4; ++j) max_edge = (std::max)(max_edge, (p[i] - p[j]).norm());
    }
    const double height = max_area2 > 0 ? six_v / max_area2 : 0;
    return height < 0.05 * max_edge;
  }


  template <std::size_t N>
  static std::array<Vertex_handle, N> sorted(std::array<Vertex_handle, N> a)
  {
    std::sort(a.begin(), a.end());
    return a;
  }

  double tet_energy(const Vertex_handle& a, const Vertex_handle& b, const Vertex_handle& c,
                    const Vertex_handle& d) const
  {
    return energy_.tetrahedron(energy_.position(a), energy_.position(b), energy_.position(c),
                               energy_.position(d));
  }

  std::size_t edge_degree(const Edge& e) const
  {
    std::size_t m = 0;
    auto cc = tr_.incident_cells(e), done = cc;
    do {
      ++m;
    } while(++cc != done && m < 6);
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

  // the cells around `e` (in circular order), their ring vertices, and their common
  // subdomain; false if `e` is a feature edge, touches a surface facet or another subdomain
  bool removable_edge(const Edge& e, std::vector<Cell_handle>& ring, std::vector<Vertex_handle>& others,
                      Subdomain_index& s) const
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
      if(ring.size() > 8) return false;
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
      for(int i = 0; i < 4; ++i) c->set_surface_patch_index(i, Surface_patch_index());
    }
    for(const Cell_handle& c : cells)
      for(int i = 0; i < 4; ++i) {
        const Cell_handle n = c->neighbor(i);
        if(std::find(cells.begin(), cells.end(), n) != cells.end()) continue;
        const int in = n->index(c);
        if(n->is_facet_on_surface(in)) {
          c->set_surface_patch_index(i, n->surface_patch_index(in));
          c->set_facet_surface_center(i, n->get_facet_surface_center(in));
          c->set_facet_surface_center_index(i, n->get_facet_surface_center_index(in));
        }
      }
  }
  void claim(std::initializer_list<Cell_handle> cells, const Subdomain_index& s)
  {
    claim(std::vector<Cell_handle>(cells), s);
  }

  void account(double old_sum, double new_sum, int cell_difference)
  {
    sum_ += new_sum - old_sum;
    count_ = std::size_t(std::ptrdiff_t(count_) + cell_difference);
  }

  C3T3& c3t3_;
  Tr& tr_;
  const Energy& energy_;
  double& sum_;
  std::size_t& count_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ENERGY_GUIDED_FLIPS_H
