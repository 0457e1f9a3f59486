// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A bare Triangulation_3 seen through the part of the
// Mesh_complex_3_in_triangulation_3 interface that GSM uses: every finite cell
// is in the complex (subdomain 1), the convex hull facets are the surface
// (patch 1), the hull vertices are surface vertices, and there is no feature
// curve. With the boundary frozen this lets `gsm_optimize_triangulation_3()`
// run the same optimizer as `gsm_optimize_mesh_3()`.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_TRIANGULATION_COMPLEX_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_TRIANGULATION_COMPLEX_H

#include <CGAL/VVM/internal/Complex_cell_replacement.h>

#include <type_traits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class Triangulation_3>
class Triangulation_complex
{
public:
  typedef Triangulation_3 Triangulation;
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  typedef typename Triangulation::Cell_handle Cell_handle;
  typedef typename Triangulation::Facet Facet;
  typedef int Subdomain_index;
  typedef int Surface_patch_index;
  typedef int Curve_index;
  typedef int Corner_index;
  typedef typename Triangulation::Finite_cells_iterator Cells_in_complex_iterator;
  typedef typename std::vector<Facet>::const_iterator Facets_in_complex_iterator;

  // the hull does not change: flips never cross a surface facet and hull vertices never move
  explicit Triangulation_complex(Triangulation& tr) : tr_(tr)
  {
    for(Cell_handle c : tr_.all_cell_handles()) {
      if(!tr_.is_infinite(c)) continue;
      const int i = c->index(tr_.infinite_vertex());
      hull_facets_.push_back(tr_.mirror_facet(Facet(c, i)));
      for(int k = 0; k < 4; ++k)
        if(k != i) hull_vertices_.insert(&*c->vertex(k));
    }
  }

  Triangulation& triangulation() { return tr_; }
  const Triangulation& triangulation() const { return tr_; }

  Cells_in_complex_iterator cells_in_complex_begin() const { return tr_.finite_cells_begin(); }
  Cells_in_complex_iterator cells_in_complex_end() const { return tr_.finite_cells_end(); }
  std::size_t number_of_cells_in_complex() const { return tr_.number_of_finite_cells(); }
  Facets_in_complex_iterator facets_in_complex_begin() const { return hull_facets_.begin(); }
  Facets_in_complex_iterator facets_in_complex_end() const { return hull_facets_.end(); }

  bool is_in_complex(const Cell_handle& c) const { return !tr_.is_infinite(c); }
  bool is_in_complex(const Cell_handle& c, int i) const
  {
    return tr_.is_infinite(c) != tr_.is_infinite(c->neighbor(i));
  }
  bool is_in_complex(const Facet& f) const { return is_in_complex(f.first, f.second); }
  bool is_in_complex(const Vertex_handle&, const Vertex_handle&) const { return false; }

  Subdomain_index subdomain_index(const Cell_handle& c) const { return tr_.is_infinite(c) ? 0 : 1; }
  Surface_patch_index surface_patch_index(const Cell_handle& c, int i) const
  {
    return is_in_complex(c, i) ? 1 : 0;
  }
  Surface_patch_index surface_patch_index(const Facet& f) const { return surface_patch_index(f.first, f.second); }
  Curve_index curve_index(const Vertex_handle&, const Vertex_handle&) const { return 0; }
  int in_dimension(const Vertex_handle& v) const { return hull_vertices_.count(&*v) ? 2 : 3; }

  // membership follows from finiteness: nothing to record
  void add_to_complex(const Cell_handle&, const Subdomain_index&) {}
  void remove_from_complex(const Cell_handle&) {}
  void add_to_complex(const Facet&, const Surface_patch_index&) {}
  void remove_from_complex(const Facet&) {}
  // a vertex inserted by an edge split is interior: not a hull vertex
  void set_dimension(const Vertex_handle&, int) {}
  void set_index(const Vertex_handle&, const Subdomain_index&) {}

private:
  Triangulation& tr_;
  std::vector<Facet> hull_facets_;
  std::unordered_set<const void*> hull_vertices_;
};

// Mesh_3 cells carry per-facet surface data that flips must restore; bare cells have none.
template <class C3T3>
struct Is_triangulation_complex : std::false_type {};
template <class Tr>
struct Is_triangulation_complex<Triangulation_complex<Tr>> : std::true_type {};

} // namespace internal
} // namespace GSM_mesh_optimization

namespace VVM {
namespace internal {

template <class Tr>
struct Has_facet_surface_data<GSM_mesh_optimization::internal::Triangulation_complex<Tr>> : std::false_type {};

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_TRIANGULATION_COMPLEX_H
