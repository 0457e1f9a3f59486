// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A tetrahedral mesh as indices with what the tet merging walks on: the
// neighbour across each facet, the vertex neighbours N(v) (dissertation
// Alg. 6-8) and the tets around each vertex.

#ifndef CGAL_HEX_DOMINANT_MESHING_INTERNAL_TETRAHEDRAL_ADJACENCY_H
#define CGAL_HEX_DOMINANT_MESHING_INTERNAL_TETRAHEDRAL_ADJACENCY_H

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace internal {

constexpr std::size_t no_index = std::size_t(-1);

/// a triangle's vertices sorted, the key of a facet
typedef std::array<std::size_t, 3> Triangle_key;

inline Triangle_key triangle_key(std::size_t a, std::size_t b, std::size_t c)
{
  Triangle_key k = {{a, b, c}};
  std::sort(k.begin(), k.end());
  return k;
}

struct Tetrahedral_adjacency
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 4>> tets; // positively oriented
  std::vector<int> subdomain;
  std::vector<std::array<std::size_t, 4>> neighbor; // across the facet opposite vertex k; no_index on the boundary
  std::vector<std::vector<std::size_t>> vertex_neighbors; // sorted

  std::size_t number_of_tets() const { return tets.size(); }

  /// the facet of tet `t` opposite its vertex `k`, as a sorted key
  Triangle_key facet(std::size_t t, int k) const
  {
    const auto& v = tets[t];
    return triangle_key(v[std::size_t((k + 1) & 3)], v[std::size_t((k + 2) & 3)], v[std::size_t((k + 3) & 3)]);
  }

  /// the index of vertex `v` in tet `t`, -1 if it is not one of its vertices
  int index_in(std::size_t t, std::size_t v) const
  {
    for(int k = 0; k < 4; ++k)
      if(tets[t][std::size_t(k)] == v) return k;
    return -1;
  }

  bool adjacent(std::size_t a, std::size_t b) const
  {
    const auto& n = vertex_neighbors[a];
    return std::binary_search(n.begin(), n.end(), b);
  }

  /// builds `neighbor` and `vertex_neighbors`; throws if a facet has more than two tets
  void build()
  {
    const std::size_t n = tets.size();
    for(std::size_t t = 0; t < n; ++t)
      for(std::size_t v : tets[t])
        if(v >= points.size()) throw std::invalid_argument("tets_to_hex_dominant: a cell refers to no point");
    std::vector<std::tuple<Triangle_key, std::size_t, int>> facets;
    facets.reserve(4 * n);
    for(std::size_t t = 0; t < n; ++t)
      for(int k = 0; k < 4; ++k) facets.emplace_back(facet(t, k), t, k);
    std::sort(facets.begin(), facets.end());
    neighbor.assign(n, {{no_index, no_index, no_index, no_index}});
    for(std::size_t i = 0; i < facets.size();) {
      std::size_t j = i + 1;
      while(j < facets.size() && std::get<0>(facets[j]) == std::get<0>(facets[i])) ++j;
      if(j - i > 2) throw std::invalid_argument("tets_to_hex_dominant: a facet is shared by more than two cells");
      if(j - i == 2) {
        neighbor[std::get<1>(facets[i])][std::size_t(std::get<2>(facets[i]))] = std::get<1>(facets[i + 1]);
        neighbor[std::get<1>(facets[i + 1])][std::size_t(std::get<2>(facets[i + 1]))] = std::get<1>(facets[i]);
      }
      i = j;
    }
    vertex_neighbors.assign(points.size(), {});
    for(const auto& t : tets)
      for(int a = 0; a < 4; ++a)
        for(int b = 0; b < 4; ++b)
          if(a != b) vertex_neighbors[t[std::size_t(a)]].push_back(t[std::size_t(b)]);
    for(auto& v : vertex_neighbors) {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
    }
  }

  /// the tet across the facet of `t` made of `a`, `b`, `c` (no_index if none, or if they are not a facet of `t`)
  std::size_t across(std::size_t t, std::size_t a, std::size_t b, std::size_t c) const
  {
    int opposite = -1, found = 0;
    for(int k = 0; k < 4; ++k) {
      const std::size_t v = tets[t][std::size_t(k)];
      if(v == a || v == b || v == c) ++found;
      else opposite = k;
    }
    return (found == 3 && opposite >= 0) ? neighbor[t][std::size_t(opposite)] : no_index;
  }

  /// the vertex of `t` other than `a`, `b`, `c`
  std::size_t fourth(std::size_t t, std::size_t a, std::size_t b, std::size_t c) const
  {
    for(std::size_t v : tets[t])
      if(v != a && v != b && v != c) return v;
    return no_index;
  }
};

/// the sorted intersection of sorted ranges, without the values of `excluded`
template <class Range>
void intersect(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b, const Range& excluded,
               std::vector<std::size_t>& out)
{
  out.clear();
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](std::size_t v) { return std::find(excluded.begin(), excluded.end(), v) != excluded.end(); }),
            out.end());
}

} // namespace internal
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_INTERNAL_TETRAHEDRAL_ADJACENCY_H
