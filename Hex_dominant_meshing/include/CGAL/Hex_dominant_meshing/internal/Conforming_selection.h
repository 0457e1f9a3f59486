// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The greedy choice among merge candidates (dissertation 4.4.2): hexahedra by
// descending quality, then prisms, then pyramids, each kept if it shares no
// tet with a kept cell and its faces conform to theirs (Sokolov et al. 2016,
// Meshkat and Talmor 2000): a quad face meets either the same quad (same four
// corners, same diagonal) or triangles; never half of another quad. The same
// corners split along the other diagonal are accepted when a flat tet of these
// four corners lies between (Delaunay leaves one between cells of a nearly
// regular lattice): the later cell takes it in, and both show the same quad.
// A flat tet left on one kept quad (on a planar or convex piece of the
// boundary) is taken in by that cell at the end.

#ifndef CGAL_HEX_DOMINANT_MESHING_INTERNAL_CONFORMING_SELECTION_H
#define CGAL_HEX_DOMINANT_MESHING_INTERNAL_CONFORMING_SELECTION_H

#include <CGAL/Hex_dominant_meshing/internal/Merge_candidates.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace internal {

typedef std::array<std::size_t, 4> Quad_corners; // sorted
typedef std::array<std::size_t, 2> Quad_diagonal; // sorted

struct Array_hash
{
  template <std::size_t N>
  std::size_t operator()(const std::array<std::size_t, N>& a) const { return boost::hash_range(a.begin(), a.end()); }
};

/// a quad face of a candidate: its sorted corners, its diagonal, and its two triangles
struct Quad_face
{
  Quad_corners corners;
  Quad_diagonal diagonal;
  std::array<Triangle_key, 2> halves;
};

inline std::vector<Quad_face> quad_faces(const Merge_candidate& c)
{
  std::vector<Quad_face> out;
  const auto& quads = cell_faces(c.type).quads;
  for(std::size_t f = 0; f < quads.size(); ++f) {
    Quad_face q;
    for(int k = 0; k < 4; ++k) q.corners[std::size_t(k)] = c.vertices[std::size_t(quads[f][std::size_t(k)])];
    std::sort(q.corners.begin(), q.corners.end());
    const std::size_t a = c.vertices[std::size_t(c.diagonals[f][0])], b = c.vertices[std::size_t(c.diagonals[f][1])];
    q.diagonal = {{(std::min)(a, b), (std::max)(a, b)}};
    int h = 0;
    for(int k = 0; k < 4; ++k) {
      const std::size_t v = c.vertices[std::size_t(quads[f][std::size_t(k)])];
      if(v != a && v != b) q.halves[std::size_t(h++)] = triangle_key(a, b, v);
    }
    out.push_back(q);
  }
  return out;
}

struct Selection
{
  std::vector<Merge_candidate> cells;            // the kept cells, in the order kept
  std::vector<std::size_t> kept;                 // their numbers 0, 1, ...
  std::vector<std::size_t> owner;                // per tet: its kept cell's number, no_index if none
  std::vector<std::vector<std::size_t>> taken_in; // per kept cell: the flat tets it took in
};

/*
 * Greedy selection, in rounds: hexahedra, then prisms, then pyramids (`select()` once per
 * kind, the candidates of the later kinds made from the tets left). Within a round by
 * descending quality, ties by the candidates' order.
 */
class Conforming_selection
{
public:
  explicit Conforming_selection(const Tetrahedral_adjacency& mesh) : mesh_(mesh)
  {
    s_.owner.assign(mesh.number_of_tets(), no_index);
    // the flat tets, by their sorted corners: they may sit between two quads of these corners
    for(std::size_t t = 0; t < mesh.number_of_tets(); ++t)
      if(is_flat(mesh, t, 0.1)) {
        Quad_corners q = mesh.tets[t];
        std::sort(q.begin(), q.end());
        flat_tet_.emplace(q, t);
        flat_tets_.push_back(t);
      }
  }

  /// keeps, by descending quality, the candidates that share no tet with a kept cell and conform to them
  void select(const std::vector<Merge_candidate>& candidates)
  {
    std::vector<std::size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return candidates[a].quality > candidates[b].quality; });
    for(std::size_t i : order) {
      const Merge_candidate& c = candidates[i];
      bool ok = true;
      for(int k = 0; k < c.number_of_tets && ok; ++k) ok = s_.owner[c.tets[std::size_t(k)]] == no_index;
      if(!ok) continue;
      const std::vector<Quad_face> quads = quad_faces(c);
      std::vector<std::size_t> take_in;
      for(const Quad_face& q : quads) {
        auto d = diagonal_of_.find(q.corners);
        if(d != diagonal_of_.end() && d->second != q.diagonal) {
          auto f = flat_tet_.find(q.corners);
          if(f != flat_tet_.end() && s_.owner[f->second] == no_index && mesh_.subdomain[f->second] == mesh_.subdomain[c.tets[0]])
            take_in.push_back(f->second);
          else
            ok = false;
        }
        for(const Triangle_key& h : q.halves) {
          auto it = half_of_.find(h);
          if(it != half_of_.end() && it->second != q.corners) ok = false;
        }
        if(!ok) break;
      }
      if(!ok) continue;
      const std::size_t id = s_.kept.size();
      for(int k = 0; k < c.number_of_tets; ++k) s_.owner[c.tets[std::size_t(k)]] = id;
      for(std::size_t t : take_in) s_.owner[t] = id;
      for(const Quad_face& q : quads) {
        if(!diagonal_of_.count(q.corners)) {
          diagonal_of_[q.corners] = q.diagonal;
          cell_of_quad_[q.corners] = id;
        }
        for(const Triangle_key& h : q.halves) half_of_[h] = q.corners;
      }
      s_.cells.push_back(c);
      s_.kept.push_back(id);
      s_.taken_in.push_back(take_in);
    }
  }

  /*
   * After the last round: a flat tet still free whose corners are a kept quad's lies on that
   * quad, against the cell's two triangles (the only other tet on them); the cell takes it in
   * and its quad shows the flat tet's other diagonal, toward the boundary or the tets beyond.
   * Returns how many.
   */
  std::size_t take_in_flat_tets()
  {
    std::size_t count = 0;
    for(std::size_t t : flat_tets_) {
      if(s_.owner[t] != no_index) continue;
      Quad_corners q = mesh_.tets[t];
      std::sort(q.begin(), q.end());
      auto c = cell_of_quad_.find(q);
      if(c == cell_of_quad_.end()) continue;
      const std::size_t id = c->second;
      if(mesh_.subdomain[t] != mesh_.subdomain[s_.cells[id].tets[0]]) continue;
      Quad_diagonal& d = diagonal_of_[q];
      Quad_diagonal other{};
      int k = 0;
      for(std::size_t v : q)
        if(v != d[0] && v != d[1]) other[std::size_t(k++)] = v;
      // the flat tet's other two triangles must not be halves of another kept quad
      const std::array<Triangle_key, 2> halves = {{triangle_key(other[0], other[1], d[0]), triangle_key(other[0], other[1], d[1])}};
      bool ok = true;
      for(const Triangle_key& h : halves) {
        auto it = half_of_.find(h);
        if(it != half_of_.end() && it->second != q) ok = false;
      }
      if(!ok) continue;
      for(const Triangle_key& h : halves) half_of_[h] = q;
      d = other;
      s_.owner[t] = id;
      s_.taken_in[id].push_back(t);
      ++count;
    }
    return count;
  }

  const Selection& result() const { return s_; }

private:
  const Tetrahedral_adjacency& mesh_;
  Selection s_;
  std::unordered_map<Quad_corners, std::size_t, Array_hash> flat_tet_;
  std::vector<std::size_t> flat_tets_; // the same, in index order
  std::unordered_map<Triangle_key, Quad_corners, Array_hash> half_of_;    // a kept quad's triangles
  std::unordered_map<Quad_corners, Quad_diagonal, Array_hash> diagonal_of_; // a kept quad's diagonal
  std::unordered_map<Quad_corners, std::size_t, Array_hash> cell_of_quad_;  // the first kept cell of a quad
};

} // namespace internal
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_INTERNAL_CONFORMING_SELECTION_H
