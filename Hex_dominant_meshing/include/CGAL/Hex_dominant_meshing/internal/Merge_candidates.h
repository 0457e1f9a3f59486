// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// All the ways tets of a mesh merge into a hexahedron, a prism or a pyramid
// (dissertation 4.4.2, Alg. 6-8, after Meshkat and Talmor 2000 and Sokolov
// et al. 2016): hexahedra of 5 or 6 tets found from a corner tet (Alg. 8,
// first loop) or from a ring of 6 tets around a diagonal (second loop), of 7
// tets from a flat tet between two rings of 4 (third loop); prisms of 3 tets;
// pyramids of 2. Each guess of corners is checked the same way: the tets
// reached from a seed tet without crossing the cell's faces must use only its
// corners and cover each quad face with two triangles along one diagonal and
// each triangle face once. The guesses are many, the checks cheap.

#ifndef CGAL_HEX_DOMINANT_MESHING_INTERNAL_MERGE_CANDIDATES_H
#define CGAL_HEX_DOMINANT_MESHING_INTERNAL_MERGE_CANDIDATES_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/cell_quality.h>
#include <CGAL/Hex_dominant_meshing/internal/Tetrahedral_adjacency.h>
#include <CGAL/VVM/internal/Parallel_for.h>


#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <cstddef>
#include <functional>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace internal {

using VVM::internal::Index_range;
using VVM::internal::parallel_for_ranges;

/// the most tets a cell is made of (a hexahedron of 7)
constexpr int max_tets_in_cell = 7;

/// a cell made of tets, with its corners in VTK order
struct Merge_candidate
{
  Hex_dominant_cell_type type = Hex_dominant_cell_type::HEXAHEDRON;
  std::array<std::size_t, 8> vertices{};
  std::array<std::size_t, max_tets_in_cell> tets{}; // sorted
  int number_of_tets = 0;
  double quality = 0;
  /// per quad face (in the order of the type's face list) the local indices of its diagonal
  std::array<std::array<int, 2>, 6> diagonals{};

  std::size_t number_of_vertices() const { return CGAL::number_of_vertices(type); }
  bool same_cell(const Merge_candidate& o) const
  {
    return type == o.type && number_of_tets == o.number_of_tets &&
           std::equal(tets.begin(), tets.begin() + number_of_tets, o.tets.begin()) &&
           (type != Hex_dominant_cell_type::PYRAMID || vertices[4] == o.vertices[4]);
  }
  bool operator<(const Merge_candidate& o) const // for sorting out duplicates
  {
    if(type != o.type) return type < o.type;
    if(number_of_tets != o.number_of_tets) return number_of_tets < o.number_of_tets;
    for(int k = 0; k < number_of_tets; ++k)
      if(tets[std::size_t(k)] != o.tets[std::size_t(k)]) return tets[std::size_t(k)] < o.tets[std::size_t(k)];
    if(type == Hex_dominant_cell_type::PYRAMID && vertices[4] != o.vertices[4]) return vertices[4] < o.vertices[4];
    return vertices < o.vertices; // the same cell from several guesses: one labelling kept
  }
};

/// the faces of each cell type, as local vertex indices (quads, then triangles)
struct Cell_faces
{
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
};

inline const Cell_faces& cell_faces(Hex_dominant_cell_type t)
{
  static const Cell_faces hex = {{{{0, 3, 2, 1}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}}, {{1, 2, 6, 5}}, {{2, 3, 7, 6}}, {{3, 0, 4, 7}}}, {}};
  static const Cell_faces prism = {{{{0, 1, 4, 3}}, {{1, 2, 5, 4}}, {{2, 0, 3, 5}}}, {{{0, 2, 1}}, {{3, 4, 5}}}};
  static const Cell_faces pyramid = {{{{0, 3, 2, 1}}}, {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}}};
  static const Cell_faces tet = {{}, {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{2, 0, 3}}}};
  switch(t) {
    case Hex_dominant_cell_type::HEXAHEDRON: return hex;
    case Hex_dominant_cell_type::PRISM: return prism;
    case Hex_dominant_cell_type::PYRAMID: return pyramid;
    default: return tet;
  }
}

/// true if the tet's smallest height is under `ratio` times its longest edge
inline bool is_flat(const std::array<Eigen::Vector3d, 4>& p, double ratio)
{
  const double volume6 = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
  double longest = 0, largest_face = 0;
  for(int i = 0; i < 4; ++i) {
    for(int j = i + 1; j < 4; ++j) longest = (std::max)(longest, (p[std::size_t(i)] - p[std::size_t(j)]).norm());
    const Eigen::Vector3d& a = p[std::size_t((i + 1) & 3)], &b = p[std::size_t((i + 2) & 3)], &c = p[std::size_t((i + 3) & 3)];
    largest_face = (std::max)(largest_face, (b - a).cross(c - a).norm());
  }
  return !(largest_face > 0) || volume6 / largest_face < ratio * longest;
}

inline bool is_flat(const Tetrahedral_adjacency& mesh, std::size_t t, double ratio)
{
  std::array<Eigen::Vector3d, 4> p;
  for(int k = 0; k < 4; ++k) p[std::size_t(k)] = mesh.points[mesh.tets[t][std::size_t(k)]];
  return is_flat(p, ratio);
}

/*
 * Checks that the corners `c` (VTK order for `type`) bound a cell made of tets of `mesh`
 * reached from `seed`, with no inverted corner, and fills `out` (tets, diagonals) if so.
 */
inline bool collect_cell(const Tetrahedral_adjacency& mesh, Hex_dominant_cell_type type,
                         const std::array<std::size_t, 8>& c, std::size_t seed, int max_tets, Merge_candidate& out)
{
  const std::size_t n = CGAL::number_of_vertices(type);
  auto local = [&](std::size_t v) {
    for(std::size_t k = 0; k < n; ++k)
      if(c[k] == v) return int(k);
    return -1;
  };
  for(std::size_t a = 0; a < n; ++a)
    for(std::size_t b = a + 1; b < n; ++b)
      if(c[a] == c[b]) return false;
  const Cell_faces& faces = cell_faces(type);
  std::array<unsigned, 6> quad_mask{};
  std::array<unsigned, 4> triangle_mask{};
  for(std::size_t f = 0; f < faces.quads.size(); ++f)
    for(int k : faces.quads[f]) quad_mask[f] |= 1u << k;
  for(std::size_t f = 0; f < faces.triangles.size(); ++f)
    for(int k : faces.triangles[f]) triangle_mask[f] |= 1u << k;
  // BFS from the seed, not crossing the faces
  std::array<std::size_t, max_tets_in_cell> tets{};
  int count = 0;
  std::array<unsigned, 6> quad_cover{};      // the triangles met on each quad, as masks
  std::array<unsigned, 6> quad_second{};
  std::array<int, 6> quad_hits{};
  std::array<int, 4> triangle_hits{};
  tets[std::size_t(count++)] = seed;
  for(int head = 0; head < count; ++head) {
    const std::size_t t = tets[std::size_t(head)];
    std::array<int, 4> l;
    for(int k = 0; k < 4; ++k)
      if((l[std::size_t(k)] = local(mesh.tets[t][std::size_t(k)])) < 0) return false;
    for(int k = 0; k < 4; ++k) {
      const unsigned m = (1u << l[std::size_t((k + 1) & 3)]) | (1u << l[std::size_t((k + 2) & 3)]) |
                         (1u << l[std::size_t((k + 3) & 3)]);
      bool on_face = false;
      for(std::size_t f = 0; f < faces.quads.size() && !on_face; ++f)
        if((m & ~quad_mask[f]) == 0) {
          on_face = true;
          if(quad_hits[f] == 0) quad_cover[f] = m;
          else quad_second[f] = m;
          if(++quad_hits[f] > 2) return false;
        }
      for(std::size_t f = 0; f < faces.triangles.size() && !on_face; ++f)
        if(m == triangle_mask[f]) {
          on_face = true;
          if(++triangle_hits[f] > 1) return false;
        }
      if(on_face) continue;
      const std::size_t nb = mesh.neighbor[t][std::size_t(k)];
      if(nb == no_index || mesh.subdomain[nb] != mesh.subdomain[seed]) return false;
      if(std::find(tets.begin(), tets.begin() + count, nb) != tets.begin() + count) continue;
      if(count == max_tets) return false;
      tets[std::size_t(count++)] = nb;
    }
  }
  for(std::size_t f = 0; f < faces.triangles.size(); ++f)
    if(triangle_hits[f] != 1) return false;
  for(std::size_t f = 0; f < faces.quads.size(); ++f) {
    // two triangles along a diagonal: together the quad, in common two opposite corners
    if(quad_hits[f] != 2 || (quad_cover[f] | quad_second[f]) != quad_mask[f]) return false;
    const unsigned common = quad_cover[f] & quad_second[f];
    const auto& q = faces.quads[f];
    if(common == ((1u << q[0]) | (1u << q[2]))) out.diagonals[f] = {{q[0], q[2]}};
    else if(common == ((1u << q[1]) | (1u << q[3]))) out.diagonals[f] = {{q[1], q[3]}};
    else return false;
  }
  // no inverted corner (the quality in the field's space comes later, once per distinct cell)
  if(type == Hex_dominant_cell_type::HEXAHEDRON) {
    std::array<Eigen::Vector3d, 8> p;
    for(std::size_t k = 0; k < 8; ++k) p[k] = mesh.points[c[k]];
    if(!(hexahedron_scaled_jacobian(p) > 0)) return false;
  } else if(type == Hex_dominant_cell_type::PRISM) {
    std::array<Eigen::Vector3d, 6> p;
    for(std::size_t k = 0; k < 6; ++k) p[k] = mesh.points[c[k]];
    if(!(internal::min_corner_scaled_jacobian(p, prism_corner_neighbors(), Eigen::Matrix3d::Identity()) > 0)) return false;
  } else {
    std::array<Eigen::Vector3d, 5> p;
    for(std::size_t k = 0; k < 5; ++k) p[k] = mesh.points[c[k]];
    if(!(internal::min_corner_scaled_jacobian(p, pyramid_corner_neighbors(), Eigen::Matrix3d::Identity()) > 0)) return false;
  }
  out.type = type;
  out.vertices = c;
  out.number_of_tets = count;
  std::sort(tets.begin(), tets.begin() + count);
  out.tets = tets;
  return true;
}

/// the merging quality of a candidate in the space of `B` at its centroid (the identity if `B` is empty)
inline double merging_quality(const Tetrahedral_adjacency& mesh, const Merge_candidate& m,
                              const std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>& B)
{
  const std::size_t n = m.number_of_vertices();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for(std::size_t k = 0; k < n; ++k) centroid += mesh.points[m.vertices[k]];
  Eigen::Matrix3d b = B ? B(centroid / double(n)) : Eigen::Matrix3d::Identity();
  if(b.determinant() < 0) b = -b; // a left-handed frame measures the same cell
  if(m.type == Hex_dominant_cell_type::HEXAHEDRON) {
    std::array<Eigen::Vector3d, 8> p;
    for(std::size_t k = 0; k < 8; ++k) p[k] = mesh.points[m.vertices[k]];
    return hexahedron_merging_quality(p, b);
  }
  if(m.type == Hex_dominant_cell_type::PRISM) {
    std::array<Eigen::Vector3d, 6> p;
    for(std::size_t k = 0; k < 6; ++k) p[k] = mesh.points[m.vertices[k]];
    return prism_merging_quality(p, b);
  }
  std::array<Eigen::Vector3d, 5> p;
  for(std::size_t k = 0; k < 5; ++k) p[k] = mesh.points[m.vertices[k]];
  return pyramid_merging_quality(p, b);
}

inline double orientation(const Tetrahedral_adjacency& mesh, std::size_t a, std::size_t b, std::size_t c, std::size_t d)
{
  const Eigen::Vector3d& p = mesh.points[a];
  return (mesh.points[b] - p).dot((mesh.points[c] - p).cross(mesh.points[d] - p));
}

/// finds the ring of `n` tets around the edge `i j` of tet `t`, from its vertices `k`, `l` on (Alg. 7)
inline bool find_ring(const Tetrahedral_adjacency& mesh, std::size_t t, std::size_t i, std::size_t j,
                      std::size_t k, std::size_t l, std::size_t n, std::array<std::size_t, 6>& ring)
{
  ring[0] = k;
  ring[1] = l;
  std::size_t current = t;
  for(std::size_t m = 2;; ++m) {
    const std::size_t next = mesh.across(current, i, j, ring[m - 1]);
    if(next == no_index || mesh.subdomain[next] != mesh.subdomain[t]) return false;
    const std::size_t v = mesh.fourth(next, i, j, ring[m - 1]);
    if(v == ring[0]) return m == n;
    if(m == n) return false;
    ring[m] = v;
    current = next;
  }
}

class Merge_candidate_finder
{
public:
  typedef std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> Frame_inverse;

  /// candidates under `quality_bound` are not kept (they would never be chosen)
  Merge_candidate_finder(const Tetrahedral_adjacency& mesh, const Frame_inverse& B, double quality_bound = 0)
    : mesh_(mesh), B_(B), bound_(quality_bound)
  {
    // the frame inverse at each tet's centroid: what prunes the guesses made from it
    tet_B_.assign(B ? mesh.number_of_tets() : 0, Eigen::Matrix3d::Identity());
    parallel_for_ranges(tet_B_.size(), 256, [&](const Index_range& r) {
      for(std::size_t t = r.begin(); t != r.end(); ++t) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for(std::size_t v : mesh.tets[t]) c += mesh.points[v];
        tet_B_[t] = B(0.25 * c);
        if(tet_B_[t].determinant() < 0) tet_B_[t] = -tet_B_[t]; // left-handed frames measure the same cells
      }
    });
  }

  /// the candidates of the kinds asked for, without duplicates, in a fixed order; with
  /// `owner`, only of the tets still free (owner no_index)
  /// the candidates of the tets free in `owner` (all if null); once `must_stop()` (called from
  /// several threads at once) returns true, the tets not yet searched are skipped and `*stopped`
  /// is set
  std::vector<Merge_candidate> find(bool hexahedra, bool prisms, bool pyramids,
                                    const std::vector<std::size_t>* owner = nullptr,
                                    const std::function<bool()>& must_stop = {}, bool* stopped = nullptr) const
  {
    const std::size_t n = mesh_.number_of_tets();
    owner_ = owner;
    std::vector<std::vector<Merge_candidate>> per_tet(n);
    std::atomic<bool> cut(false);
    parallel_for_ranges(n, 64, [&](const Index_range& r) {
      if(cut.load(std::memory_order_relaxed) || (must_stop && must_stop())) {
        cut = true;
        return;
      }
      std::vector<std::size_t> pij, pik, pjk, pq, s;
      for(std::size_t t = r.begin(); t != r.end(); ++t) {
        if(!is_free(t)) continue;
        auto& out = per_tet[t];
        if(hexahedra) {
          corner_tet_hexahedra(t, out, pij, pik, pjk, pq, s);
          diagonal_ring_hexahedra(t, out);
          flat_tet_hexahedra(t, out, pij, pik);
        }
        if(prisms) tet_prisms(t, out);
        if(pyramids) tet_pyramids(t, out);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end(),
                              [](const Merge_candidate& a, const Merge_candidate& b) { return a.same_cell(b); }),
                  out.end());
      }
    });
    std::vector<Merge_candidate> all;
    for(auto& v : per_tet) all.insert(all.end(), v.begin(), v.end());
    per_tet.clear();
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end(),
                          [](const Merge_candidate& a, const Merge_candidate& b) { return a.same_cell(b); }),
              all.end());
    parallel_for_ranges(all.size(), 256, [&](const Index_range& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i) all[i].quality = merging_quality(mesh_, all[i], B_);
    });
    all.erase(std::remove_if(all.begin(), all.end(), [this](const Merge_candidate& m) { return m.quality < bound_; }), all.end());
    if(stopped && cut) *stopped = true;
    return all;
  }

private:
  bool is_free(std::size_t t) const { return !owner_ || (*owner_)[t] == no_index; }

  const Eigen::Matrix3d& B_at(std::size_t t) const
  {
    static const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
    return tet_B_.empty() ? identity : tet_B_[t];
  }

  // a guess kept if its tets check out and its quality, with the frame of the seed tet, is
  // near the bound (the exact quality at the cell's centroid decides later)
  void keep_if_good(const Merge_candidate& m, std::size_t seed, std::vector<Merge_candidate>& out) const
  {
    const Eigen::Matrix3d& b = B_at(seed);
    if(bound_ > 0 && merging_quality(mesh_, m, [&b](const Eigen::Vector3d&) { return b; }) < prune_factor * bound_) return;
    out.push_back(m);
  }

  void try_cell(Hex_dominant_cell_type type, std::array<std::size_t, 8> c, std::size_t seed, int max_tets,
                std::vector<Merge_candidate>& out) const
  {
    // a mirrored guess: swap to the other handedness
    if(type == Hex_dominant_cell_type::HEXAHEDRON && orientation(mesh_, c[0], c[1], c[3], c[4]) < 0) {
      std::swap(c[1], c[3]);
      std::swap(c[5], c[7]);
    }
    Merge_candidate m;
    if(collect_cell(mesh_, type, c, seed, max_tets, m)) keep_if_good(m, seed, out);
  }

  // Q_o of the corner a with edges to b, c, d (right-handed) in the seed tet's frame: a
  // hexahedron with a corner under the bound is under it too (Q_hex <= min Q_o)
  bool corner_may_pass(std::size_t seed, std::size_t a, std::size_t b, std::size_t c, std::size_t d) const
  {
    if(!(bound_ > 0)) return true;
    const Eigen::Matrix3d& B = B_at(seed);
    const Eigen::Vector3d& p = mesh_.points[a];
    const double q = std::abs(corner_orthogonality_unsigned(B * (mesh_.points[b] - p), B * (mesh_.points[c] - p),
                                                            B * (mesh_.points[d] - p)));
    return q >= prune_factor * bound_;
  }

  // the corner a of a hexahedron with edges to b, c, d (right-handed) not inverted, as
  // collect_cell's test of the same corner computes it
  bool is_positive_corner(std::size_t a, std::size_t b, std::size_t c, std::size_t d) const
  {
    const Eigen::Vector3d& p = mesh_.points[a];
    return corner_scaled_jacobian(mesh_.points[b] - p, mesh_.points[c] - p, mesh_.points[d] - p) > 0;
  }

  static double corner_orthogonality_unsigned(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& d)
  {
    // either handedness: the guesses of the first loop are right-handed only after the check
    return (std::max)(internal::corner_orthogonality(a, b, d), internal::corner_orthogonality(b, a, d));
  }

  // Alg. 8, first loop: the tet (l; i, j, k) is the corner 000 of a hexahedron
  void corner_tet_hexahedra(std::size_t t, std::vector<Merge_candidate>& out, std::vector<std::size_t>& pij,
                            std::vector<std::size_t>& pik, std::vector<std::size_t>& pjk, std::vector<std::size_t>& pq,
                            std::vector<std::size_t>& s) const
  {
    static const int corner[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 0, 1, 3}, {3, 0, 2, 1}}; // positive (l; i, j, k)
    const auto& v = mesh_.tets[t];
    const auto& N = mesh_.vertex_neighbors;
    for(const auto& o : corner) {
      const std::size_t l = v[std::size_t(o[0])], i = v[std::size_t(o[1])], j = v[std::size_t(o[2])], k = v[std::size_t(o[3])];
      intersect(N[i], N[j], v, pij);
      intersect(N[i], N[k], v, pik);
      intersect(N[j], N[k], v, pjk);
      if(!corner_may_pass(t, l, i, j, k)) continue;
      // try_cell keeps these labels (it mirrors a guess whose corner l is inverted), so that
      // collect_cell will ask every corner to be positive: the inverted ones end a guess early
      const bool kept = !(orientation(mesh_, l, i, j, k) < 0);
      auto positive = [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
        return !kept || is_positive_corner(a, b, c, d);
      };
      for(std::size_t p : pij)
        for(std::size_t q : pik) {
          if(q == p || !corner_may_pass(t, i, p, l, q) || !positive(i, p, l, q)) continue;
          intersect(N[p], N[q], v, pq);
          if(pq.empty()) continue;
          for(std::size_t r : pjk) {
            if(r == p || r == q || !corner_may_pass(t, j, l, p, r) || !corner_may_pass(t, k, q, l, r) ||
               !positive(j, l, p, r) || !positive(k, r, q, l))
              continue;
            intersect(pq, N[r], std::array<std::size_t, 3>{{p, q, r}}, s);
            for(std::size_t x : s)
              if(positive(p, j, i, x) && positive(q, k, x, i) && positive(x, q, r, p) && positive(r, x, k, j))
                try_cell(Hex_dominant_cell_type::HEXAHEDRON, {{l, i, p, j, k, q, x, r}}, t, 7, out);
          }
        }
    }
  }

  // Alg. 8, second loop: six tets around a diagonal i j of the hexahedron
  void diagonal_ring_hexahedra(std::size_t t, std::vector<Merge_candidate>& out) const
  {
    const auto& v = mesh_.tets[t];
    std::array<std::size_t, 6> V;
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b) {
        int rest[2], r = 0;
        for(int x = 0; x < 4; ++x)
          if(x != a && x != b) rest[r++] = x;
        const std::size_t i = v[std::size_t(a)], j = v[std::size_t(b)];
        if(!find_ring(mesh_, t, i, j, v[std::size_t(rest[0])], v[std::size_t(rest[1])], 6, V)) continue;
        try_cell(Hex_dominant_cell_type::HEXAHEDRON, {{i, V[0], V[1], V[2], V[4], V[5], j, V[3]}}, t, 7, out);
        try_cell(Hex_dominant_cell_type::HEXAHEDRON, {{i, V[1], V[2], V[3], V[5], V[0], j, V[4]}}, t, 7, out);
      }
  }

  // Alg. 8, third loop, generalized: a flat tet i j k l whose opposite edges i j and k l are
  // diagonals of the hexahedron (i 000, j 111, k 110, l 001), between two prisms of three tets
  // each, whatever their triangulation (Alg. 8 finds those made of rings of 4 around i j and
  // k l only): the other corners a, c next to i and k, b, d next to j and l
  void flat_tet_hexahedra(std::size_t t, std::vector<Merge_candidate>& out, std::vector<std::size_t>& A,
                          std::vector<std::size_t>& Bs) const
  {
    const auto& v = mesh_.tets[t];
    if(!is_flat(mesh_, t, 0.25)) return; // the flat tet inside a hexahedron of 7 tets
    const auto& N = mesh_.vertex_neighbors;
    static const int pairs[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}};
    for(const auto& pr : pairs)
      for(int roles = 0; roles < 4; ++roles) {
        std::size_t i = v[std::size_t(pr[0])], j = v[std::size_t(pr[1])], k = v[std::size_t(pr[2])], l = v[std::size_t(pr[3])];
        if(roles & 1) std::swap(i, j);
        if(roles & 2) std::swap(k, l);
        intersect(N[i], N[k], v, A);
        intersect(N[j], N[l], v, Bs);
        for(std::size_t a : A)
          for(std::size_t b : Bs) {
            if(b == a || !mesh_.adjacent(a, b)) continue;
            for(std::size_t c : A) {
              if(c == a || c == b) continue;
              for(std::size_t d : Bs) {
                if(d == a || d == b || d == c || !mesh_.adjacent(c, d)) continue;
                try_cell(Hex_dominant_cell_type::HEXAHEDRON, {{i, c, k, a, l, d, j, b}}, t, 7, out);
              }
            }
          }
      }
  }

  // prisms: tet t in the middle, two of its neighbours; the caps are two disjoint boundary triangles
  void tet_prisms(std::size_t t, std::vector<Merge_candidate>& out) const
  {
    const auto& v = mesh_.tets[t];
    for(int f1 = 0; f1 < 4; ++f1)
      for(int f2 = f1 + 1; f2 < 4; ++f2) {
        const std::size_t n1 = mesh_.neighbor[t][std::size_t(f1)], n2 = mesh_.neighbor[t][std::size_t(f2)];
        if(n1 == no_index || n2 == no_index || !is_free(n1) || !is_free(n2)) continue;
        if(mesh_.subdomain[n1] != mesh_.subdomain[t] || mesh_.subdomain[n2] != mesh_.subdomain[t]) continue;
        // the boundary triangles of the three tets
        std::vector<Triangle_key> boundary;
        for(std::size_t u : {t, n1, n2})
          for(int k = 0; k < 4; ++k) {
            const std::size_t nb = mesh_.neighbor[u][std::size_t(k)];
            if(nb == t || nb == n1 || nb == n2) continue;
            boundary.push_back(mesh_.facet(u, k));
          }
        if(boundary.size() != 8) continue;
        std::vector<Merge_candidate> found;
        for(std::size_t A = 0; A < 8; ++A)
          for(std::size_t Bi = A + 1; Bi < 8; ++Bi) {
            const auto& a = boundary[A];
            const auto& b = boundary[Bi];
            bool disjoint = true;
            for(std::size_t x : a) disjoint = disjoint && std::find(b.begin(), b.end(), x) == b.end();
            if(!disjoint) continue;
            static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
            for(const auto& p : perm) {
              std::array<std::size_t, 8> c = {{a[0], a[1], a[2], b[std::size_t(p[0])], b[std::size_t(p[1])], b[std::size_t(p[2])], 0, 0}};
              if(orientation(mesh_, c[0], c[1], c[2], c[3]) < 0) {
                std::swap(c[1], c[2]);
                std::swap(c[4], c[5]);
              }
              Merge_candidate m;
              if(collect_cell(mesh_, Hex_dominant_cell_type::PRISM, c, t, 3, m)) found.push_back(m);
            }
          }
        if(found.empty()) continue;
        const Eigen::Matrix3d& b = B_at(t);
        for(auto& m : found) m.quality = merging_quality(mesh_, m, [&b](const Eigen::Vector3d&) { return b; });
        const auto best = std::max_element(found.begin(), found.end(),
            [](const Merge_candidate& x, const Merge_candidate& y) { return x.quality < y.quality; });
        if(!(bound_ > 0) || best->quality >= prune_factor * bound_) out.push_back(*best);
      }
  }

  // pyramids: two tets sharing a facet; the apex one of its vertices, the other two a base diagonal
  void tet_pyramids(std::size_t t, std::vector<Merge_candidate>& out) const
  {
    const auto& v = mesh_.tets[t];
    for(int k = 0; k < 4; ++k) {
      const std::size_t nb = mesh_.neighbor[t][std::size_t(k)];
      if(nb == no_index || nb < t || !is_free(nb) || mesh_.subdomain[nb] != mesh_.subdomain[t]) continue; // each pair once
      const std::size_t b = v[std::size_t(k)];
      const Triangle_key f = mesh_.facet(t, k);
      const std::size_t d = mesh_.fourth(nb, f[0], f[1], f[2]);
      for(int e = 0; e < 3; ++e) {
        const std::size_t apex = f[std::size_t(e)], a = f[std::size_t((e + 1) % 3)], c = f[std::size_t((e + 2) % 3)];
        std::array<std::size_t, 8> corners = {{a, b, c, d, apex, 0, 0, 0}};
        if(orientation(mesh_, a, b, d, apex) < 0) std::swap(corners[1], corners[3]);
        Merge_candidate m;
        if(collect_cell(mesh_, Hex_dominant_cell_type::PYRAMID, corners, t, 2, m)) keep_if_good(m, t, out);
      }
    }
  }

  // the frames at a tet and at a cell's centroid differ a little in a varying field
  static constexpr double prune_factor = 0.9;

  const Tetrahedral_adjacency& mesh_;
  Frame_inverse B_;
  std::vector<Eigen::Matrix3d> tet_B_;
  double bound_;
  mutable const std::vector<std::size_t>* owner_ = nullptr; // set for the duration of find(): one find() at a time
};

} // namespace internal
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_INTERNAL_MERGE_CANDIDATES_H
