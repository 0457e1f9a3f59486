// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// GSM connectivity update (dissertation section 3.3.2): 2-3, 3-2 and 4-4 flips,
// edge removal and multi-face removal (Shewchuk 2002), and the peel of flat
// boundary cells, each applied when it lowers the mean energy of the cells in
// the complex (see Cell_replacement.h).
//
// Never across a surface facet, a feature edge or a subdomain boundary; only
// cells of one subdomain are replaced, and the new cells get that subdomain and
// the surface-patch data of the facets they border, with the complex's counters.
// 3-2 is CGAL's own `Triangulation_3::flip()`; 4-4 is the edge removal of a
// ring of four, 2-3 the multi-face removal of one face.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ENERGY_GUIDED_FLIPS_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ENERGY_GUIDED_FLIPS_H

#include <CGAL/GSM_mesh_optimization/internal/Cell_replacement.h>
#include <CGAL/GSM_mesh_optimization/internal/Edge_removal.h>
#include <CGAL/GSM_mesh_optimization/internal/Multi_face_removal.h>

#include <algorithm>
#include <array>
#include <set>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

/// counts of the flips done; an edge removal of a ring of four counts as a 4-4
/// flip, a multi-face removal of one (two) faces as a 2-3 (4-4) flip
struct Flip_counts
{
  std::size_t flips_2_3 = 0, flips_3_2 = 0, flips_4_4 = 0, boundary_peels = 0;
  std::size_t edge_removals = 0;       ///< rings of 5 or more
  std::size_t multi_face_removals = 0; ///< 3 faces or more
  std::size_t total() const
  {
    return flips_2_3 + flips_3_2 + flips_4_4 + boundary_peels + edge_removals + multi_face_removals;
  }
};

template <class C3T3>
class Energy_guided_flips : public Cell_replacement<C3T3>
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
  typedef typename Base::Energy Energy;

  /// the largest ring of an edge removal, and of the new edge of a multi-face removal
  static constexpr int max_ring = 7;
  /// flips are tried around the cells whose energy exceeds this times the mean
  static constexpr double candidate_factor = 1.2;

  /// `sum` and `count`: the running total of the energies of the cells in the complex
  Energy_guided_flips(C3T3& c3t3, const Energy& energy, double& sum, std::size_t& count)
    : Base(c3t3, energy, sum, count), edge_removal_(c3t3, energy, sum, count),
      face_removal_(c3t3, energy, sum, count)
  {}

  /// one pass over the edges (3-2, edge removal) then the facets (multi-face
  /// removal) of the complex, then the flat boundary cells; with `around`, only
  /// those of the cells with two vertices or more in it (the vertices of the cells
  /// the last pass changed: elsewhere only the mean, which a change must beat, has changed
  /// since that pass tried them).
  /// The vertices of the cells this pass changes go to `changed`, if given.
  Flip_counts flip_pass(const std::vector<Vertex_handle>* around = nullptr,
                        std::vector<Vertex_handle>* changed = nullptr)
  {
    Flip_counts done;
    std::unordered_set<Vertex_handle> near;
    if(around != nullptr) near.insert(around->begin(), around->end());
    const auto is_near = [&](const Cell_handle& c) {
      if(around == nullptr) return true;
      int n = 0;
      for(int i = 0; i < 4; ++i) n += near.count(c->vertex(i)) ? 1 : 0;
      return n >= 2;
    };
    set_change_log(changed);
    // Handles go stale as cells are replaced: collect vertex tuples, re-find each.
    // Only around cells worse than the mean: replacing cells that are all better
    // than the mean seldom lowers it, and checking them all is most of the cost.
    std::vector<std::array<Vertex_handle, 2>> edges;
    std::vector<std::array<Vertex_handle, 3>> facets;
    const double threshold = candidate_factor * this->mean();
    const std::vector<Cell_handle> cells = around == nullptr ? energy_.cells_in_complex() : cells_near(near);
    const std::vector<double> cell_energy = Energy::per_cell(cells, [this](const Cell_handle& c) { return energy_.cell(c); });
    for(std::size_t n = 0; n < cells.size(); ++n) {
      const Cell_handle& c = cells[n];
      if(!(cell_energy[n] > threshold)) continue;
      for(int i = 0; i < 4; ++i) {
        for(int j = i + 1; j < 4; ++j) edges.push_back(sorted(std::array<Vertex_handle, 2>{{c->vertex(i), c->vertex(j)}}));
        if(!c3t3_.is_in_complex(c, i))
          facets.push_back(sorted(std::array<Vertex_handle, 3>{
              {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3), c->vertex((i + 3) & 3)}}));
      }
    }
    std::sort(edges.begin(), edges.end(), [this](const auto& x, const auto& y) { return precedes(x, y); });
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::sort(facets.begin(), facets.end(), [this](const auto& x, const auto& y) { return precedes(x, y); });
    facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
    for(const auto& e : edges) {
      Cell_handle c;
      int i, j;
      if(!tr_.is_edge(e[0], e[1], c, i, j)) continue;
      const std::size_t m = this->edge_degree(Edge(c, i, j), max_ring + 1);
      if(m == 3) {
        if(try_flip_3_2(Edge(c, i, j))) ++done.flips_3_2;
      } else if(m <= std::size_t(max_ring) && try_remove_edge(Edge(c, i, j)))
        ++(m == 4 ? done.flips_4_4 : done.edge_removals);
    }
    for(const auto& f : facets) {
      Cell_handle c;
      int i, j, k;
      if(!tr_.is_facet(f[0], f[1], f[2], c, i, j, k)) continue;
      switch(face_removal_.try_remove_faces(Facet(c, 6 - i - j - k), max_ring - 2, true)) {
      case 0: break;
      case 1: ++done.flips_2_3; break;
      case 2: ++done.flips_4_4; break;
      default: ++done.multi_face_removals;
      }
    }
    // flat cells lying on the surface: no flip and no move can give them volume
    if(boundary_fixed_) {
      set_change_log(nullptr);
      return done;
    }
    std::vector<std::array<Vertex_handle, 4>> flat_boundary_cells;
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c) {
      int surface_facets = 0;
      for(int i = 0; i < 4; ++i) surface_facets += c3t3_.is_in_complex(c, i) ? 1 : 0;
      if(surface_facets == 2 && is_near(c))
        flat_boundary_cells.push_back({{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}});
    }
    for(const auto& t : flat_boundary_cells) {
      Cell_handle c;
      int i, j, k, l;
      if(tr_.is_cell(t[0], t[1], t[2], t[3], c, i, j, k, l) && try_peel_boundary_cell(c))
        ++done.boundary_peels;
    }
    set_change_log(nullptr);
    return done;
  }

  // the cells in the complex with two vertices or more in `near`, each once, in no particular
  // order: gathered from the stars of `near`, not by a scan of the complex (after the first
  // pass of a round, a few thousand vertices of 100k)
  std::vector<Cell_handle> cells_near(const std::unordered_set<Vertex_handle>& near) const
  {
    std::vector<Cell_handle> cells, star;
    for(const Vertex_handle& v : near) {
      star.clear();
      tr_.incident_cells(v, std::back_inserter(star));
      for(const Cell_handle& c : star) {
        if(!c3t3_.is_in_complex(c)) continue;
        // the cell is taken by its first vertex in `near`, and only if it has a second one
        int first = -1, n = 0;
        for(int i = 0; i < 4; ++i)
          if(near.count(c->vertex(i))) {
            if(first < 0) first = i;
            ++n;
          }
        if(n >= 2 && c->vertex(first) == v) cells.push_back(c);
      }
    }
    return cells;
  }

  /// the vertices of the cells the changes create or peel go to `log` (none: nullptr)
  void set_change_log(std::vector<Vertex_handle>* log)
  {
    Base::set_change_log(log);
    edge_removal_.set_change_log(log);
    face_removal_.set_change_log(log);
  }

  /// removes from the complex a nearly flat cell `c` with two surface facets of one
  /// patch, replacing them by its two other facets (a 2-2 flip of the surface
  /// triangulation that moves the surface by less than the cell's small height),
  /// if that lowers the mean energy
  bool try_peel_boundary_cell(const Cell_handle& c)
  {
    return try_peel_boundary_cell(c, [this, &c](const Facet&, const Facet&) {
      return is_flat(c) && lowers_mean(energy_.cell(c), 0., -1);
    });
  }

  /// the same peel of a cell with two surface facets of one patch, if `accept(f, g)`
  /// says yes for its two other facets, the new surface facets; or of a cell with three
  /// (a cap), if `accept(f, f)` says yes for its fourth facet
  template <class Accept>
  bool try_peel_boundary_cell(const Cell_handle& c, const Accept& accept)
  {
    if constexpr(Is_triangulation_complex<C3T3>::value) {
      CGAL_USE(c);
      CGAL_USE(accept);
      return false; // a bare triangulation's boundary is its convex hull: fixed
    } else
      return peel_boundary_cell(c, accept);
  }

  /// keeps the surface where it is: no boundary peel
  void set_boundary_fixed(bool fixed) { boundary_fixed_ = fixed; }

private:
  template <class Accept>
  bool peel_boundary_cell(const Cell_handle& c, const Accept& accept)
  {
    int in[3], out[2], n_in = 0, n_out = 0;
    for(int i = 0; i < 4; ++i) {
      if(c3t3_.is_in_complex(c, i)) {
        if(n_in == 3) return false;
        in[n_in++] = i;
      } else {
        if(n_out == 2) return false;
        out[n_out++] = i;
      }
    }
    if(n_in < 2 || !c3t3_.is_in_complex(c)) return false;
    const Surface_patch_index patch = c3t3_.surface_patch_index(c, in[0]);
    for(int k = 1; k < n_in; ++k)
      if(!(c3t3_.surface_patch_index(c, in[k]) == patch)) return false;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(c3t3_.is_in_complex(c->vertex(i), c->vertex(j))) return false; // a feature edge
    if(n_in == 3) return peel_cap(c, out[0], patch, accept);
    // the new surface edge (the vertices opposite the old surface facets) must be new
    const Vertex_handle u = c->vertex(in[0]), w = c->vertex(in[1]);
    Cell_handle ec;
    int ei, ej;
    if(!tr_.is_edge(u, w, ec, ei, ej)) return false;
    auto fc = tr_.incident_facets(Edge(ec, ei, ej)), fdone = fc;
    do
      if(c3t3_.is_in_complex(*fc)) return false;
    while(++fc != fdone);
    if(!accept(Facet(c, out[0]), Facet(c, out[1]))) return false;
    const double e = energy_.cell(c);
    this->log_vertices(c);

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

  // a cell with three surface facets of one patch is a cap on the surface around the vertex
  // opposite its fourth facet (an ear, all four vertices on the surface, that no move of
  // them can open; if the vertex has other cells, the surface is pinched there): that facet
  // becomes the surface, and the vertex stays on the surface of its other cells, if any
  template <class Accept>
  bool peel_cap(const Cell_handle& c, int inner, const Surface_patch_index& patch, const Accept& accept)
  {
    if(c3t3_.in_dimension(c->vertex(inner)) != 2) return false; // a vertex of a feature curve or a corner
    const Facet f(c, inner);
    if(!accept(f, f)) return false;
    const double e = energy_.cell(c);
    this->log_vertices(c);
    for(int i = 0; i < 4; ++i)
      if(i != inner) c3t3_.remove_from_complex(Facet(c, i));
    c3t3_.remove_from_complex(c);
    c3t3_.add_to_complex(f, patch);
    const Facet m = tr_.mirror_facet(f);
    const auto centre = tr_.geom_traits().construct_centroid_3_object()(
        bare(c->vertex((inner + 1) & 3)), bare(c->vertex((inner + 2) & 3)), bare(c->vertex((inner + 3) & 3)));
    c->set_facet_surface_center(inner, centre);
    m.first->set_facet_surface_center(m.second, centre);
    account(e, 0., -1);
    return true;
  }

public:
  // --- the flips; each returns true if done --------------------------------

  /// 2-3 flip of the facet `f`, if it lowers the mean energy
  bool try_flip_2_3(const Facet& f) { return try_remove_faces(f, 1) == 1; }

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
    if(!lowers_mean(old_sum, new_sum, -1)) return false;

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
  bool try_flip_4_4(const Edge& e) { return this->edge_degree(e, 5) == 4 && try_remove_edge(e); }

  /// edge removal of `e`, with 4 to `max_ring` cells around it
  bool try_remove_edge(const Edge& e) { return edge_removal_.try_remove_edge(e, max_ring); }

  /// edge removal of `e` (3-2 flip included), with 3 to `max_ring` cells around it, if it
  /// lowers the sum of `penalty` over the smallest dihedral angles of the cells around `e`
  template <class Penalty>
  bool try_remove_edge_for_quality(const Edge& e, const Penalty& penalty)
  {
    return edge_removal_.try_remove_edge_for_quality(e, max_ring, penalty);
  }

  /// multi-face removal from `f` on, of at most `max_faces` faces; returns how many
  int try_remove_faces(const Facet& f, int max_faces = max_ring - 2)
  {
    return face_removal_.try_remove_faces(f, max_faces);
  }

private:
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

  // Vertices ordered by position, not by handle: a handle's address depends on what the
  // process allocated before, and the order of the flips, so the result, must not.
  bool precedes(const Vertex_handle& a, const Vertex_handle& b) const
  {
    return tr_.geom_traits().compare_xyz_3_object()(bare(a), bare(b)) == SMALLER;
  }

  template <std::size_t N>
  bool precedes(const std::array<Vertex_handle, N>& a, const std::array<Vertex_handle, N>& b) const
  {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        [this](const Vertex_handle& x, const Vertex_handle& y) { return precedes(x, y); });
  }

  template <std::size_t N>
  std::array<Vertex_handle, N> sorted(std::array<Vertex_handle, N> a) const
  {
    std::sort(a.begin(), a.end(), [this](const Vertex_handle& x, const Vertex_handle& y) { return precedes(x, y); });
    return a;
  }

  using Base::c3t3_;
  using Base::tr_;
  using Base::energy_;
  using Base::lowers_mean;
  using Base::bare;
  using Base::tet_energy;
  using Base::removable_edge;
  using Base::cells_on;
  using Base::release;
  using Base::claim;
  using Base::account;

  Edge_removal<C3T3> edge_removal_;
  Multi_face_removal<C3T3> face_removal_;
  bool boundary_fixed_ = false;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_ENERGY_GUIDED_FLIPS_H
