// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The vertices of a triangulation numbered 0, 1, ... in the order its cells are
// read, as the indexed meshes of the frame fields and of the hex-dominant
// merging hold them.

#ifndef CGAL_VVM_INTERNAL_VERTEX_NUMBERING_H
#define CGAL_VVM_INTERNAL_VERTEX_NUMBERING_H

#include <cstddef>
#include <unordered_map>

namespace CGAL {
namespace VVM {
namespace internal {

/// the numbers of the vertices of a triangulation `Tr`, given as they are first met
template <class Tr>
class Vertex_numbering
{
public:
  typedef typename Tr::Vertex_handle Vertex_handle;

  explicit Vertex_numbering(const Tr& tr) : tr_(tr) {}

  /// the number of `v`; for a vertex met the first time, the next number, after
  /// `on_new_vertex(p)` with its bare point `p`
  template <class OnNewVertex>
  std::size_t operator()(Vertex_handle v, const OnNewVertex& on_new_vertex)
  {
    auto it = index_.find(v);
    if(it != index_.end()) return it->second;
    on_new_vertex(tr_.geom_traits().construct_point_3_object()(tr_.point(v)));
    const std::size_t n = index_.size();
    index_.emplace(v, n);
    return n;
  }

private:
  const Tr& tr_;
  std::unordered_map<Vertex_handle, std::size_t> index_;
};

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_VERTEX_NUMBERING_H
