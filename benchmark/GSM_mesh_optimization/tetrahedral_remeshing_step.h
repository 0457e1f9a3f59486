// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `remesh` step of compare_optimizers: CGAL's strongest tool on a make_mesh_3
// complex, CGAL::tetrahedral_isotropic_remeshing, as its manual runs it after
// make_mesh_3 (the triangulation taken out with convert_to_triangulation_3,
// the feature edges kept as constrained edges), then put back into the complex
// so that it is measured like the other chains.

#ifndef VVM_BENCHMARK_TETRAHEDRAL_REMESHING_STEP_H
#define VVM_BENCHMARK_TETRAHEDRAL_REMESHING_STEP_H

#include <CGAL/property_map.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace vvm_benchmark {

/// the mean length of the edges of the cells in the complex
template <class C3T3>
double mean_edge_length(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  double sum = 0;
  std::size_t n = 0;
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    auto c = tr.incident_cells(*e), done = c;
    bool in_complex = false;
    do in_complex = in_complex || c3t3.is_in_complex(c); while(++c != done && !in_complex);
    if(!in_complex) continue;
    const auto p = tr.point(e->first, e->second).point(), q = tr.point(e->first, e->third).point();
    sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
    ++n;
  }
  return n > 0 ? sum / double(n) : 0.;
}

/// `iterations` of isotropic remeshing of `c3t3` to edges of length `target`; feature edges
/// (the complex's edges) are constrained, the complex's cells and facets rebuilt from the
/// subdomain and surface patch indices the remeshing keeps
template <class C3T3>
void tetrahedral_remeshing_step(C3T3& c3t3, double target, int iterations = 3)
{
  typedef typename C3T3::Triangulation Tr;
  typedef CGAL::Triangulation_3<typename Tr::Geom_traits, typename Tr::Triangulation_data_structure> Triangulation;
  typedef std::pair<typename Triangulation::Vertex_handle, typename Triangulation::Vertex_handle> Vertex_pair;
  std::set<Vertex_pair> constraints;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) {
    const auto a = e->first->vertex(e->second), b = e->first->vertex(e->third);
    constraints.insert(std::minmax(a, b));
  }
  Triangulation tr = CGAL::convert_to_triangulation_3(std::move(c3t3));
  CGAL::tetrahedral_isotropic_remeshing(tr, target,
                                        CGAL::parameters::number_of_iterations(iterations)
                                            .edge_is_constrained_map(CGAL::Boolean_property_map<std::set<Vertex_pair>>(constraints)));
  c3t3.triangulation().Triangulation::swap(tr);
  c3t3.rescan_after_load_of_triangulation();
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_TETRAHEDRAL_REMESHING_STEP_H
