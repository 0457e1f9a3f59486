// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangles of particles on a surface, patch by patch (the faces between
// sharp edges): the restricted Delaunay triangulation of the particles that
// touch the patch (the Delaunay facets whose dual Voronoi edge crosses the
// patch, as Mesh_3 takes its surface facets). Patch by patch, so that no
// triangle cuts across a sharp edge and the particles of a sharp edge are
// joined along it (with the particles of both sides, a particle near the edge
// on one side hides the edge between two sharp-edge particles). Each triangle
// is oriented as the surface nearest to its centroid. Particles of a patch all
// in one plane have no Voronoi edges across it: their 2D Delaunay triangles
// are kept where their centroid lies on the surface. Flat triangles (three
// particles on one straight border or sharp edge, which Delaunay joins along
// the hull) are never kept.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_RESTRICTED_DELAUNAY_SURFACE_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_RESTRICTED_DELAUNAY_SURFACE_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Surface_metric_flips.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_with_circumcenter_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/*
 * `points` on the surface of `boundary` (a Surface_boundary), each touching the patches
 * `patches[i]`; returns the restricted Delaunay triangles, as indices into `points`.
 * `tolerance`: how far off the surface a planar set's triangle centroid may lie.
 */
template <class K, class Boundary>
std::vector<std::array<std::size_t, 3>> restricted_Delaunay_triangles(const std::vector<Eigen::Vector3d>& points,
                                                                     const std::vector<std::set<int>>& patches,
                                                                     const Boundary& boundary, double tolerance)
{
  typedef CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K> Vb;
  typedef CGAL::Delaunay_triangulation_cell_base_with_circumcenter_3<K> Cb;
  typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
  typedef CGAL::Delaunay_triangulation_3<K, Tds> Dt;
  typedef typename K::Point_3 Point_3;
  const auto& triangles = boundary.triangles();
  auto is_flat = [&](const std::size_t v[3]) { return is_flat_triangle(points[v[0]], points[v[1]], points[v[2]]); };
  typedef std::array<std::size_t, 3> Key; // sorted
  auto key_of = [](std::size_t a, std::size_t b, std::size_t c) {
    Key k = {a, b, c};
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<std::array<std::size_t, 3>> out;
  std::set<Key> seen; // a triangle two patches share is kept once
  // the triangle `v` oriented as the surface nearest to its centroid
  auto add = [&](const std::size_t v[3]) {
    if(!seen.insert(key_of(v[0], v[1], v[2])).second) return;
    const Eigen::Vector3d n = boundary.closest_on_surface((points[v[0]] + points[v[1]] + points[v[2]]) / 3.).direction;
    const Eigen::Vector3d m = (points[v[1]] - points[v[0]]).cross(points[v[2]] - points[v[0]]);
    if(m.dot(n) >= 0) out.push_back({v[0], v[1], v[2]});
    else out.push_back({v[0], v[2], v[1]});
  };
  std::vector<std::vector<std::size_t>> patch_points;
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int p : patches[i]) {
      if(p >= int(patch_points.size())) patch_points.resize(std::size_t(p) + 1);
      patch_points[std::size_t(p)].push_back(i);
    }
  typedef typename Boundary::Surface_tree Tree;
  std::vector<typename Tree::template Intersection_and_primitive_id<typename K::Segment_3>::Type> crossings;
  typedef CGAL::Search_traits_3<K> Search_traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Search_traits> Neighbor_search;
  for(std::size_t patch = 0; patch < patch_points.size(); ++patch) {
    std::vector<std::pair<Point_3, std::size_t>> input;
    for(std::size_t i : patch_points[patch]) input.emplace_back(Point_3(points[i][0], points[i][1], points[i][2]), i);
    if(input.size() < 3) continue;
    const Dt dt(input.begin(), input.end());
    if(dt.dimension() < 2) continue;
    // a facet's vertices in ascending order: the tests below then do not depend on which of
    // its two cells the facet came from
    auto vertices_of = [](const typename Dt::Facet& f, std::size_t v[3]) {
      for(int k = 0, m = 0; k < 4; ++k)
        if(k != f.second) v[m++] = f.first->vertex(k)->info();
      std::sort(v, v + 3);
    };
    if(dt.dimension() == 2) {
      for(auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
        std::size_t v[3];
        vertices_of(*f, v);
        if(!is_flat(v) && boundary.closest_on_surface((points[v[0]] + points[v[1]] + points[v[2]]) / 3.).distance <= tolerance)
          add(v);
      }
      continue;
    }
    typename Neighbor_search::Tree tree;
    for(const auto& x : input) tree.insert(x.first);
    tree.build();
    for(auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      std::size_t v[3];
      vertices_of(*f, v);
      if(is_flat(v)) continue;
      // the dual: a segment between the circumcentres, or a ray from one; does it cross the
      // patch at a point that no particle is nearer to than the facet's? (the circumcentres of
      // flat tetrahedra, computed in floating point, can be far off: their duals would cross
      // the surface in other particles' Voronoi cells)
      const auto dual = dt.dual(*f);
      crossings.clear();
      if(const typename K::Segment_3* s = CGAL::object_cast<typename K::Segment_3>(&dual))
        boundary.surface_tree().all_intersections(CGAL::compare_xyz(s->source(), s->target()) == CGAL::SMALLER
                                                      ? *s : s->opposite(),
                                                  std::back_inserter(crossings));
      else if(const typename K::Ray_3* r = CGAL::object_cast<typename K::Ray_3>(&dual))
        boundary.surface_tree().all_intersections(*r, std::back_inserter(crossings));
      for(const auto& x : crossings) {
        if(boundary.triangle_patches()[std::size_t(x.second - triangles.begin())] != int(patch)) continue;
        Eigen::Vector3d at;
        if(const Point_3* q = boost::get<Point_3>(&x.first)) at = Eigen::Vector3d(q->x(), q->y(), q->z());
        else if(const typename K::Segment_3* q = boost::get<typename K::Segment_3>(&x.first)) {
          const Point_3 m = CGAL::midpoint(q->source(), q->target());
          at = Eigen::Vector3d(m.x(), m.y(), m.z());
        } else
          continue;
        const double d = (at - points[v[0]]).norm();
        const Point_3 query(at[0], at[1], at[2]);
        const Neighbor_search nearest(tree, query, 1);
        if(std::sqrt(nearest.begin()->second) >= d * (1 - 1e-6)) {
          add(v);
          break;
        }
      }
    }
  }
  // in a canonical order, each from its smallest index: the Delaunay triangulation is unique
  // but the order of its facets is not the same from run to run once other threads have
  // allocated memory, and the holes' filling and the flips depend on the order
  for(std::array<std::size_t, 3>& t : out) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_RESTRICTED_DELAUNAY_SURFACE_H
