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
// the hull) are never kept. Where the triangles are not a 2-manifold,
// remove_non_manifold_triangles() leaves holes to fill instead.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_RESTRICTED_DELAUNAY_SURFACE_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_RESTRICTED_DELAUNAY_SURFACE_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Surface_metric_flips.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
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
  typedef CGAL::Triangulation_data_structure_3<Vb> Tds;
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
    // does `query`, a piece of the facet `v`'s dual line, cross the patch at a point that no
    // particle is nearer to than the facet's vertices, a point of its Voronoi edge?
    auto crosses_own_cell = [&](const auto& query, const std::size_t v[3]) {
      crossings.clear();
      boundary.surface_tree().all_intersections(query, std::back_inserter(crossings));
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
        const Neighbor_search nearest(tree, Point_3(at[0], at[1], at[2]), 1);
        if(std::sqrt(nearest.begin()->second) >= d * (1 - 1e-6)) return true;
      }
      return false;
    };
    const double diagonal = (boundary.bbox_max() - boundary.bbox_min()).norm();
    auto to_point = [](const Eigen::Vector3d& p) { return Point_3(p[0], p[1], p[2]); };
    // the circumcentre of a cell from its vertices in ascending order (the same whichever
    // way the cell was built); not finite for a cell flat in floating point
    auto circumcentre = [&](typename Dt::Cell_handle c) {
      std::size_t u[4];
      for(int k = 0; k < 4; ++k) u[k] = c->vertex(k)->info();
      std::sort(u, u + 4);
      const Eigen::Vector3d x = points[u[1]] - points[u[0]], y = points[u[2]] - points[u[0]],
                            z = points[u[3]] - points[u[0]];
      return Eigen::Vector3d(points[u[0]] + (x.squaredNorm() * y.cross(z) + y.squaredNorm() * z.cross(x) +
                                             z.squaredNorm() * x.cross(y)) / (2 * x.dot(y.cross(z))));
    };
    for(auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      std::size_t v[3];
      vertices_of(*f, v);
      if(is_flat(v)) continue;
      typename Dt::Cell_handle c = f->first, d = c->neighbor(f->second);
      if(dt.is_infinite(c)) std::swap(c, d);
      const Eigen::Vector3d opposite = points[c->vertex(c->index(d))->info()];
      // the facet's dual line: through its circumcentre, normal to it
      const Eigen::Vector3d normal = (points[v[1]] - points[v[0]]).cross(points[v[2]] - points[v[0]]).normalized();
      const Point_3 cp = CGAL::circumcenter(to_point(points[v[0]]), to_point(points[v[1]]), to_point(points[v[2]]));
      const Eigen::Vector3d centre(cp.x(), cp.y(), cp.z());
      // the dual Voronoi edge: between the two cells' circumcentres, or from the finite one
      // away from its fourth vertex
      const Eigen::Vector3d cc = circumcentre(c), outward = normal.dot(opposite - centre) > 0 ? -normal : normal;
      bool crosses = false;
      double t1 = (cc - centre).dot(normal), t2;
      if(dt.is_infinite(d)) {
        if(cc.allFinite()) crosses = crosses_own_cell(typename K::Ray_3(to_point(cc), to_point(cc + outward)), v);
        t2 = outward.dot(normal) * diagonal;
      } else {
        const Eigen::Vector3d cd = circumcentre(d);
        if(cc.allFinite() && cd.allFinite()) {
          const Point_3 pc = to_point(cc), pd = to_point(cd);
          crosses = crosses_own_cell(CGAL::compare_xyz(pc, pd) == CGAL::SMALLER ? typename K::Segment_3(pc, pd)
                                                                                : typename K::Segment_3(pd, pc),
                                     v);
        }
        t2 = (cd - centre).dot(normal);
      }
      if(!std::isfinite(t1) || !std::isfinite(t2)) { // a flat cell: its circumcentre is anywhere on the line
        t1 = -diagonal;
        t2 = diagonal;
      }
      if(!crosses) {
        // the same span along the dual line, which the facet alone defines: a circumcentre
        // off by rounding (a near-flat cell of four particles nearly on one circle, as on an
        // input triangle much larger than the particles' spacing) moves the dual edge off the
        // line, past the surface; a flat cell's circumcentre lies anywhere along it
        t1 = (std::max)(-diagonal, (std::min)(diagonal, t1));
        t2 = (std::max)(-diagonal, (std::min)(diagonal, t2));
        if(t1 > t2) std::swap(t1, t2);
        crosses = t1 < t2 && crosses_own_cell(typename K::Segment_3(to_point(centre + t1 * normal),
                                                                    to_point(centre + t2 * normal)), v);
      }
      if(crosses) add(v);
    }
  }
  // in a canonical order, each from its smallest index: the Delaunay triangulation is unique
  // but the order of its facets is not the same from run to run once other threads have
  // allocated memory, and the holes' filling and the flips depend on the order
  for(std::array<std::size_t, 3>& t : out) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(out.begin(), out.end());
  return out;
}

/*
 * Removes the triangles that keep `triangles` from being a 2-manifold: all those on an edge
 * of more than two, then, at each vertex whose triangles make several fans, those of every fan
 * but the largest; again until none is left. Returns how many were removed. The holes this
 * leaves are filled between the particles around them; splitting the vertices instead (as
 * `orient_polygon_soup()` does) leaves holes between copies of one point, which are filled
 * with triangles of zero angle.
 */
inline std::size_t remove_non_manifold_triangles(std::vector<std::array<std::size_t, 3>>& triangles)
{
  std::size_t removed = 0;
  for(;;) {
    std::vector<char> remove(triangles.size(), 0);
    // the triangles of each edge: (smaller vertex, larger vertex, triangle), sorted
    std::vector<std::array<std::size_t, 3>> edges;
    for(std::size_t t = 0; t < triangles.size(); ++t)
      for(int k = 0; k < 3; ++k)
        edges.push_back({(std::min)(triangles[t][k], triangles[t][(k + 1) % 3]),
                         (std::max)(triangles[t][k], triangles[t][(k + 1) % 3]), t});
    std::sort(edges.begin(), edges.end());
    for(std::size_t i = 0, j; i < edges.size(); i = j) {
      for(j = i; j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]; ++j) {}
      if(j - i > 2)
        for(std::size_t k = i; k < j; ++k) remove[edges[k][2]] = 1;
    }
    // the fans at each vertex: its triangles joined across the edges they share there
    std::size_t n = 0;
    for(const auto& t : triangles) n = (std::max)(n, *std::max_element(t.begin(), t.end()) + 1);
    std::vector<std::vector<std::size_t>> around(n);
    for(std::size_t t = 0; t < triangles.size(); ++t)
      if(!remove[t])
        for(std::size_t v : triangles[t]) around[v].push_back(t);
    for(std::size_t v = 0; v < n; ++v) {
      const std::vector<std::size_t>& ts = around[v];
      std::vector<std::size_t> fan(ts.size());
      for(std::size_t i = 0; i < ts.size(); ++i) fan[i] = i;
      std::function<std::size_t(std::size_t)> root = [&](std::size_t i) { return fan[i] == i ? i : fan[i] = root(fan[i]); };
      for(std::size_t i = 0; i < ts.size(); ++i)
        for(std::size_t j = i + 1; j < ts.size(); ++j) {
          int shared = 0;
          for(std::size_t a : triangles[ts[i]])
            for(std::size_t b : triangles[ts[j]]) shared += a == b && a != v;
          if(shared > 0) fan[root(i)] = root(j);
        }
      std::vector<std::size_t> size(ts.size(), 0);
      for(std::size_t i = 0; i < ts.size(); ++i) ++size[root(i)];
      const std::size_t largest = std::size_t(std::max_element(size.begin(), size.end()) - size.begin());
      for(std::size_t i = 0; i < ts.size(); ++i)
        if(root(i) != largest) remove[ts[i]] = 1;
    }
    const std::size_t before = triangles.size();
    std::size_t k = 0;
    for(std::size_t t = 0; t < before; ++t)
      if(!remove[t]) triangles[k++] = triangles[t];
    triangles.resize(k);
    if(k == before) return removed;
    removed += before - k;
  }
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_RESTRICTED_DELAUNAY_SURFACE_H
