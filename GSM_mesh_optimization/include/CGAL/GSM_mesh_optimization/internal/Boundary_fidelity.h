// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far the boundary of the mesh may stray from the domain's surface.
// Boundary vertices that move stay on the surface, but the facets between them
// can cut deeper into it (or bulge further out), most of all across creases the
// domain does not protect: the boundary's Hausdorff distance to the surface
// grows. Where vertices only move, both directions of it grow together, so one
// measure serves both; where a surface vertex goes (Surface_vertex_collapse.h), its
// point is checked against the facets that replace it too.
//
// The deviation of a surface facet is the largest distance from points of a
// grid on it to its own patch, along its normal, found with the domain's
// `Construct_intersection` (any domain: polyhedral or implicit). It is larger
// than the true distances both ways: along the facet's normal the surface is
// further than along its own, and a point of the surface beside a crease can be
// closer to the next facet. Bounds taken from the initial deviations alone let
// the boundary's Hausdorff distance to the surface grow where they overstate it,
// and a floor at a quantile of them held the vertices of thin parts, where the
// worst cells are. So the bounds come from the largest true
// distance between the initial boundary and the surface, estimated where the
// deviations are largest: from a grid point to the surface (the nearest
// intersection along a cone of directions about the normal) and from the
// surface's point on its normal to the boundary (an AABB tree of the initial
// facets). Any facet may deviate 90% of it, or a high quantile of the initial
// deviations (not their maximum: facets beside feature edges can measure far
// more than they stray) if that is more; the vertices of a facet that deviated
// more may let their facets deviate as much, up to the largest distance. A facet
// may stray as far as the largest bound of its vertices: its deviation is then at
// most the initial Hausdorff distance (or the quantile), wherever it lies. Where
// the surface has a crease the domain
// does not protect, the distance peaks on the crease, between grid points: on a
// grid with the facet's edges in 4, moves that kept the bounds let the
// boundary's Hausdorff distance to the surface grow. So the
// bounds are measured on that grid and on one with edges in 8, which contains
// it, and a moved facet that comes within a fifth of its bound on the first
// must keep its bound on the second too. A moved facet is only tested against its
// bounds: a point whose normal segment as long as the bound meets the surface is
// close enough: one short query in place of two or more of the measure, which
// looks for the nearest of the intersections within the full reach, and a
// predicate (`Do_intersect_surface`), which costs a fraction of a construction.
// A boundary that starts on the surface (a mesh made elsewhere, imported with its
// own boundary as the surface) has no initial distance to measure, and the
// surface is piecewise linear with the initial facets as its pieces: under a
// moved facet the distance along its normal then peaks where a corner or an
// edge of a piece lies, which any grid can miss. There the corners and edge
// crossings of the pieces under a moved facet are measured too; so are the
// corners next to the changed facets that lie over none of them (a ridge the
// new facets cut), and the corners of the feature curves (polylines) along a
// moved chord: the boundary then stays within its bound both ways.
// Everything is computed at the start (the facets in parallel); later
// calls only read it and the domain, so they are thread-safe.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_BOUNDARY_FIDELITY_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_BOUNDARY_FIDELITY_H

#include <CGAL/VVM/internal/Parallel_for.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

using VVM::internal::parallel_for_each_index;

template <class C3T3, class MeshDomain>
class Boundary_fidelity
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Geom_traits GT;
  typedef typename GT::Point_3 Bare_point;
  typedef typename GT::Vector_3 Vector_3;
  typedef typename GT::Segment_3 Segment_3;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename C3T3::Surface_patch_index Surface_patch_index;
  typedef typename C3T3::Curve_index Curve_index;

public:
  typedef std::array<Bare_point, 3> Triangle;

  /// the quantile of the initial deviations below which any facet may stray
  static constexpr double floor_quantile = 0.95;
  /// any facet may also stray this share of the largest distance between the initial boundary
  /// and the surface
  static constexpr double floor_share = 0.9;
  /// the grids of a facet: its edges split in this many parts, plus its centroid
  static constexpr int coarse_grid = 4;
  static constexpr int fine_grid = 8;
  /// a moved facet whose coarse measure is over this share of its coarse bound is measured on
  /// the fine grid too
  static constexpr double fine_check_share = 0.8;
  /// the boundary started on the surface if this share of its facets lay on it
  static constexpr double started_on_surface_share = 0.99;
  /// two pieces of a surface the boundary started on meet at a kink if the sine of their angle
  /// is over the square root of this (over the rounding noise of a flat part)
  static constexpr double kink_sin2 = 1e-18;

  /// `least_bound`: any facet may stray at least this far (a caller's tolerance)
  Boundary_fidelity(const C3T3& c3t3, const MeshDomain* domain, double least_bound = 0) : domain_(domain)
  {
    const Tr& tr = c3t3.triangulation();
    std::vector<Initial_facet> facets;
    std::array<std::vector<double>, 2> deviations;
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
      Initial_facet e;
      for(int k = 0; k < 3; ++k) {
        e.v[k] = f->first->vertex((f->second + 1 + k) & 3);
        e.t[k] = tr.geom_traits().construct_point_3_object()(tr.point(e.v[k]));
      }
      e.patch = c3t3.surface_patch_index(*f);
      facets.push_back(e);
    }
    if(facets.empty()) return;
    parallel_for_each_index(facets.size(), [&](std::size_t i) {
      Initial_facet& e = facets[i];
      e.d[0] = deviation(e.t, e.patch, coarse_grid);
      e.d[1] = (std::max)(e.d[0], deviation(e.t, e.patch, fine_grid, coarse_grid));
    }, 64);
    for(const Initial_facet& e : facets)
      for(int g = 0; g < 2; ++g) deviations[g].push_back(e.d[g]);

    std::vector<Triangle_3> triangles;
    for(const Initial_facet& e : facets) triangles.emplace_back(e.t[0], e.t[1], e.t[2]);
    Boundary_tree boundary(triangles.begin(), triangles.end());
    boundary.accelerate_distance_queries();
    // (a few facets may measure more: the nearest of the intersections along a normal is not
    // always found)
    const auto on_surface = std::count_if(facets.begin(), facets.end(), [](const Initial_facet& e) { return lies_on_surface(e); });
    // of the pieces, only those with a kink matter: the distance to a facet along its normal
    // is linear over a flat part (none on a flat model, where the pieces are not needed)
    std::vector<Triangle_3> kinked;
    if(double(on_surface) >= started_on_surface_share * double(facets.size())) {
      std::map<std::pair<Vertex_handle, Vertex_handle>, std::vector<std::size_t>> edge_facets;
      for(std::size_t i = 0; i < facets.size(); ++i)
        for(int k = 0; k < 3; ++k) {
          const Vertex_handle a = facets[i].v[k], b = facets[i].v[(k + 1) % 3];
          edge_facets[a < b ? std::make_pair(a, b) : std::make_pair(b, a)].push_back(i);
        }
      std::vector<bool> has_kink(facets.size(), false);
      for(const auto& ef : edge_facets) {
        if(ef.second.size() != 2 || !(facets[ef.second[0]].patch == facets[ef.second[1]].patch)) continue;
        const Vector_3 n = triangles[ef.second[0]].supporting_plane().orthogonal_vector();
        const Vector_3 m = triangles[ef.second[1]].supporting_plane().orthogonal_vector();
        const double sin2 = CGAL::to_double(CGAL::cross_product(n, m).squared_length()) /
                            CGAL::to_double(n.squared_length() * m.squared_length());
        if(sin2 > kink_sin2) has_kink[ef.second[0]] = has_kink[ef.second[1]] = true;
      }
      for(std::size_t i = 0; i < facets.size(); ++i)
        if(has_kink[i]) kinked.push_back(triangles[i]);
    }
    if(!kinked.empty()) {
      auto pieces = std::make_shared<Pieces>();
      pieces->triangles = std::move(kinked);
      pieces->tree.rebuild(pieces->triangles.begin(), pieces->triangles.end());
      for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) {
        const Vertex_handle a = e->first->vertex(e->second), b = e->first->vertex(e->third);
        auto& points = pieces->curve_points[c3t3.curve_index(*e)];
        for(const Vertex_handle& v : {a, b}) points.push_back(tr.geom_traits().construct_point_3_object()(tr.point(v)));
      }
      pieces_ = pieces;
    }

    // the largest distance: only facets that measure more along their normal can raise it
    std::sort(facets.begin(), facets.end(), [](const Initial_facet& a, const Initial_facet& b) { return a.d[1] > b.d[1]; });
    double& largest = largest_;
    for(const Initial_facet& e : facets) {
      if(!(e.d[1] > largest)) break;
      largest = (std::max)(largest, distance_between(e, fine_grid, boundary, largest));
    }
    for(int g = 0; g < 2; ++g) {
      const auto q = deviations[g].begin() + std::ptrdiff_t(floor_quantile * double(deviations[g].size() - 1));
      std::nth_element(deviations[g].begin(), q, deviations[g].end());
      floors_[g] = (std::max)({*q, floor_share * largest, least_bound});
    }
    largest = (std::max)(largest, least_bound);
    // the vertices of the facets over the floor may let their facets stray as far as these did,
    // up to the largest distance
    for(const Initial_facet& e : facets)
      for(int g = 0; g < 2; ++g) {
        if(!(e.d[g] > floors_[g])) continue;
        for(int k = 0; k < 3; ++k) {
          double& b = vertex_bounds_[e.v[k]][g];
          b = (std::max)(b, (std::min)(e.d[g], largest));
        }
      }
  }

  /// how far the facets around `v` may stray, measured on the coarse grid (`fine` false) or
  /// the fine one: as far as they did at the start, up to the largest initial distance, or
  /// the floor
  double bound(const Vertex_handle& v, bool fine = false) const
  {
    const auto it = vertex_bounds_.find(v);
    return it == vertex_bounds_.end() ? floors_[fine] : (std::max)(floors_[fine], it->second[fine]);
  }

  /// whether `v` has a bound of its own, over the floor
  bool has_own_bound(const Vertex_handle& v) const { return vertex_bounds_.count(v) != 0; }

  /// `v` is about to be removed: a vertex made later in its place (the same handle) has
  /// no bound of its own
  void forget(const Vertex_handle& v) { vertex_bounds_.erase(v); }

  /// the estimate of the largest distance between the initial boundary and the surface (in
  /// either direction) that caps the bounds
  double largest_initial_distance() const { return largest_; }

  /// whether the facet `t` of the patch `patch`, on the vertices `v`, strays no further than they allow
  bool is_faithful(const Triangle& t, const Surface_patch_index& patch, const std::array<Vertex_handle, 3>& v) const
  {
    const auto allowed = [&](bool fine) { return (std::max)({bound(v[0], fine), bound(v[1], fine), bound(v[2], fine)}); };
    const double coarse_bound = allowed(false);
    if(deviates_at_most(t, patch, coarse_grid, 0, fine_check_share * coarse_bound))
      return pieces_deviate_at_most(t, patch, allowed(true));
    return deviates_at_most(t, patch, coarse_grid, 0, coarse_bound) &&
           deviates_at_most(t, patch, fine_grid, coarse_grid, allowed(true)) &&
           pieces_deviate_at_most(t, patch, allowed(true));
  }

  /// whether the part `t` of the facet `whole` (of the patch `patch`) strays from the surface
  /// no further than `whole` does, on both grids, up to the share `slack` (a part's normal
  /// turns a little: where it keeps the edge of the whole that sets the whole's deviation,
  /// it measures a hair more than the whole on the same points)
  bool strays_no_further(const Triangle& t, const Triangle& whole, const Surface_patch_index& patch,
                         double slack) const
  {
    const double coarse = deviation(whole, patch, coarse_grid);
    if(!deviates_at_most(t, patch, coarse_grid, 0, (1 + slack) * coarse)) return false;
    const double fine = (std::max)(coarse, deviation(whole, patch, fine_grid, coarse_grid));
    return deviates_at_most(t, patch, fine_grid, coarse_grid, (1 + slack) * fine) &&
           pieces_deviate_at_most(t, patch, (std::max)((1 + slack) * fine, floors_[1]));
  }

  /// on a boundary that started on the surface, whether the corners of the surface's pieces
  /// near the new facets `star` (the facets around a changed part of the boundary, whose
  /// outer edges stay) lie within the bound of their vertices `v` of them; true on others.
  /// A corner over a ridge that the new facets cut lies over no facet's interior (each facet
  /// alone cannot tell): its distance to the nearest point of `star` counts, unless that point
  /// is on an outer edge (a facet outside is nearer) or the surface comes within the bound of
  /// it on the line to the corner (the corner is on the far side of a thin part)
  bool corners_near(const std::vector<Triangle>& star, const std::vector<std::array<Vertex_handle, 3>>& v) const
  {
    if(!pieces_ || star.empty()) return true;
    double limit = 0, longest2 = 0;
    for(const auto& w : v)
      for(const Vertex_handle& u : w) limit = (std::max)(limit, bound(u, true));
    std::map<std::pair<Bare_point, Bare_point>, int> edges;
    CGAL::Bbox_3 box;
    for(const Triangle& t : star)
      for(int k = 0; k < 3; ++k) {
        const Bare_point &a = t[k], &b = t[(k + 1) % 3];
        ++edges[a < b ? std::make_pair(a, b) : std::make_pair(b, a)];
        longest2 = (std::max)(longest2, CGAL::to_double(CGAL::squared_distance(a, b)));
        box += a.bbox();
      }
    const double margin = 0.5 * std::sqrt(longest2);
    const double tolerance = (std::max)(limit, noise_share * margin);
    box = CGAL::Bbox_3(box.xmin() - margin, box.ymin() - margin, box.zmin() - margin, box.xmax() + margin,
                       box.ymax() + margin, box.zmax() + margin);
    std::vector<Segment_3> outer;
    for(const auto& e : edges)
      if(e.second == 1) outer.emplace_back(e.first.first, e.first.second);
    const double limit2 = tolerance * tolerance;
    for(const Triangle_3* near : pieces_near(box))
      for(int k = 0; k < 3; ++k) {
        const Bare_point& x = (*near)[k];
        double d2 = HUGE_VAL;
        const Triangle* nearest = nullptr;
        for(const Triangle& t : star) {
          const double e2 = CGAL::to_double(CGAL::squared_distance(x, Triangle_3(t[0], t[1], t[2])));
          if(e2 < d2) {
            d2 = e2;
            nearest = &t;
          }
        }
        if(!(d2 > limit2) || d2 > margin * margin) continue;
        bool on_outer_edge = false;
        for(const Segment_3& s : outer)
          if(!(CGAL::to_double(CGAL::squared_distance(x, s)) > d2 * (1 + 1e-9))) on_outer_edge = true;
        if(on_outer_edge) continue;
        // the nearest point: x's projection to the facet's plane, if inside it, else on its edges
        const Triangle& t = *nearest;
        const Triangle_3 facet(t[0], t[1], t[2]);
        Bare_point y = facet.supporting_plane().projection(x);
        if(CGAL::to_double(CGAL::squared_distance(x, y)) < d2 * (1 - 1e-9)) { // not inside the facet
          double best = HUGE_VAL;
          for(int i = 0; i < 3; ++i) {
            const Segment_3 s(t[i], t[(i + 1) % 3]);
            const Vector_3 ab = s.target() - s.source();
            const double l2 = CGAL::to_double(ab.squared_length());
            const double u = l2 > 0 ? std::clamp(CGAL::to_double((x - s.source()) * ab) / l2, 0., 1.) : 0.;
            const Bare_point z = s.source() + ab * u;
            const double e2 = CGAL::to_double(CGAL::squared_distance(x, z));
            if(e2 < best) {
              best = e2;
              y = z;
            }
          }
        }
        const Vector_3 r = (x - y) * (tolerance / std::sqrt(d2));
        if(!domain_->do_intersect_surface_object()(Segment_3(y - r, y + r))) return false;
      }
    return true;
  }

  /// on a boundary that started on the surface, the largest distance to the chord from `o` to
  /// `q` of the curve `curve`'s initial vertices that lie along it, the corners of the curve
  /// (a polyline) between them; 0 on others. A vertex further from the chord than half its
  /// length belongs to another part of the curve (or the chord is far off the arc, which
  /// sampling the arc shows)
  double curve_corners_deviation(const Curve_index& curve, const Bare_point& o, const Bare_point& q) const
  {
    if(!pieces_) return 0;
    const auto it = pieces_->curve_points.find(curve);
    if(it == pieces_->curve_points.end()) return 0;
    const Vector_3 chord = q - o;
    const double length2 = CGAL::to_double(chord.squared_length());
    if(!(length2 > 0)) return 0;
    double d2 = 0;
    for(const Bare_point& x : it->second) {
      const Vector_3 ox = x - o;
      const double t = CGAL::to_double(ox * chord);
      if(!(t > 0 && t < length2)) continue;
      const double e2 = CGAL::to_double(ox.squared_length()) - t * t / length2;
      if(e2 < 0.25 * length2) d2 = (std::max)(d2, e2);
    }
    return std::sqrt(d2);
  }

  /// on a boundary that started on the surface, whether the corners of the surface's pieces
  /// under `t` and the crossings of their edges with the edges of `t` are within `limit` of
  /// `t` along its normal, as `deviates_at_most()` measures its grid points; true on others.
  /// With the facet's vertices, these are the points where the distance along the normal to
  /// a piecewise linear surface peaks
  bool pieces_deviate_at_most(const Triangle& t, const Surface_patch_index& patch, double limit) const
  {
    if(!pieces_) return true;
    Vector_3 reach;
    if(!measuring_reach(t, reach)) return true;
    const double length = std::sqrt(CGAL::to_double(reach.squared_length()));
    const double tolerance = (std::max)(limit, noise_share * length);
    if(!(tolerance < length)) return true;
    // the facet in a frame of its plane: u, w along it, h along its unit normal
    const Vector_3 unit = reach / length;
    Vector_3 e1 = t[1] - t[0];
    e1 = e1 / std::sqrt(CGAL::to_double(e1.squared_length()));
    const Vector_3 e2 = CGAL::cross_product(unit, e1);
    const auto coordinates = [&](const Bare_point& p) {
      const Vector_3 d = p - t[0];
      return std::array<double, 3>{{CGAL::to_double(d * e1), CGAL::to_double(d * e2), CGAL::to_double(d * unit)}};
    };
    const auto at = [&](double u, double w) { return t[0] + e1 * u + e2 * w; };
    std::array<std::array<double, 3>, 3> c;
    for(int k = 0; k < 3; ++k) c[k] = coordinates(t[k]);
    // a point over which the surface lies at height `h`: close enough if that is within the
    // tolerance, else measured as a grid point is (a nearer part of the surface may lie there)
    const auto is_close = [&](double u, double w, double h) {
      if(std::abs(h) <= tolerance) return true;
      const Bare_point s = at(u, w);
      const Vector_3 r = reach * (tolerance / length);
      if(domain_->do_intersect_surface_object()(Segment_3(s - r, s + r))) return true;
      return distance_along(s, reach, patch) <= tolerance;
    };
    const double margin = length;
    CGAL::Bbox_3 box = t[0].bbox() + t[1].bbox() + t[2].bbox();
    box = CGAL::Bbox_3(box.xmin() - margin, box.ymin() - margin, box.zmin() - margin, box.xmax() + margin,
                       box.ymax() + margin, box.zmax() + margin);
    for(const Triangle_3* near : pieces_near(box)) {
      const Triangle_3& piece = *near;
      std::array<std::array<double, 3>, 3> p;
      bool is_within = true;
      for(int k = 0; k < 3; ++k) {
        p[k] = coordinates(piece[k]);
        is_within = is_within && std::abs(p[k][2]) <= tolerance;
      }
      if(is_within) continue; // the height is linear over the piece
      for(int k = 0; k < 3; ++k) {
        // a corner over the facet's interior: on the left of its three edges (counterclockwise
        // in the frame)
        const std::array<double, 3>& a = p[k];
        double b[3];
        for(int i = 0; i < 3; ++i) {
          const auto& q = c[(i + 1) % 3];
          const auto& r = c[(i + 2) % 3];
          b[i] = (q[0] - a[0]) * (r[1] - a[1]) - (q[1] - a[1]) * (r[0] - a[0]);
        }
        if(b[0] > 0 && b[1] > 0 && b[2] > 0 && std::abs(a[2]) <= length && !is_close(a[0], a[1], a[2])) return false;
        // the crossings of the piece's edge with the facet's edges
        const std::array<double, 3>& d = p[(k + 1) % 3];
        for(int i = 0; i < 3; ++i) {
          const auto& q = c[i];
          const auto& r = c[(i + 1) % 3];
          const double den = (d[0] - a[0]) * (r[1] - q[1]) - (d[1] - a[1]) * (r[0] - q[0]);
          if(den == 0) continue;
          const double s = ((q[0] - a[0]) * (r[1] - q[1]) - (q[1] - a[1]) * (r[0] - q[0])) / den; // along the piece
          const double v = ((q[0] - a[0]) * (d[1] - a[1]) - (q[1] - a[1]) * (d[0] - a[0])) / den; // along the facet
          if(!(s > 0 && s < 1 && v > 0 && v < 1)) continue;
          const double h = a[2] + s * (d[2] - a[2]);
          if(std::abs(h) <= length && !is_close(q[0] + v * (r[0] - q[0]), q[1] + v * (r[1] - q[1]), h)) return false;
        }
      }
    }
    return true;
  }

  /// the largest distance from the points of the grid of `t` with `m` subdivisions (and its
  /// centroid) to the patch `patch` along the normal of `t`, within half its longest edge (far
  /// beyond a chord's sag, short of the far side of thin parts); a point whose normal line meets
  /// another patch first, or none (beside a feature edge), or within the rounding noise (where
  /// the centroid is), does not count. With `known`, a
  /// divisor of `m`, the points of the grid with `known` subdivisions are skipped but for the
  /// centroid: the caller has measured them
  double deviation(const Triangle& t, const Surface_patch_index& patch, int m, int known = 0) const
  {
    double d = 0;
    bool is_centroid = true, centroid_on_surface = false;
    for_each_grid_point(t, m, known, [&](const Bare_point& s, const Vector_3& reach) {
      // a facet whose centroid lies on the surface (up to `noise_share`) lies in a flat part of it,
      // most often: its points are tried with a predicate first, which costs less
      if(is_centroid || centroid_on_surface) {
        const Vector_3 noise = reach * noise_share;
        const bool on_surface = bool(domain_->do_intersect_surface_object()(Segment_3(s - noise, s + noise)));
        if(is_centroid) centroid_on_surface = on_surface;
        is_centroid = false;
        if(on_surface) return true;
      }
      d = (std::max)(d, distance_along(s, reach, patch));
      return true;
    });
    return d;
  }

  /// whether `deviation(t, patch, m, known)` is at most `limit`, found with fewer and shorter
  /// queries: a point whose normal segment within `limit` meets the surface is close enough
  bool deviates_at_most(const Triangle& t, const Surface_patch_index& patch, int m, int known, double limit) const
  {
    return for_each_grid_point(t, m, known, [&](const Bare_point& s, const Vector_3& reach) {
      const double length = std::sqrt(CGAL::to_double(reach.squared_length()));
      // deviations under the rounding noise count as none: on a flat patch, the bounds are
      // themselves rounding noise, and a moved facet's points are off its plane by as much
      const double tolerance = (std::max)(limit, noise_share * length);
      if(!(tolerance < length)) return true; // no point of the segment is further
      // a predicate, not a construction: whether the segment within `tolerance` meets the surface
      const Vector_3 r = reach * (tolerance / length);
      if(domain_->do_intersect_surface_object()(Segment_3(s - r, s + r)))
        return true; // the nearest intersection is within `tolerance`
      return distance_along(s, reach, patch) <= tolerance;
    });
  }

  /// the share of half a facet's longest edge under which a deviation counts as rounding noise
  static constexpr double noise_share = 1e-6;

private:
  // the half normal segment of `t` along which its points are measured: along its normal, half
  // its longest edge long (far beyond a chord's sag, short of the far side of thin parts);
  // false if `t` is flat
  static bool measuring_reach(const Triangle& t, Vector_3& reach)
  {
    const Vector_3 n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    const double area2 = CGAL::to_double(n.squared_length());
    if(!(area2 > 0)) return false;
    double longest2 = 0;
    for(int k = 0; k < 3; ++k)
      longest2 = (std::max)(longest2, CGAL::to_double(CGAL::squared_distance(t[k], t[(k + 1) % 3])));
    reach = n * (0.5 * std::sqrt(longest2 / area2));
    return true;
  }

  // calls `f(point, reach)` on the points of `deviation()`'s grid, with the half normal segment
  // along which they are measured, while it returns true; false if it returned false
  template <class F>
  static bool for_each_grid_point(const Triangle& t, int m, int known, const F& f)
  {
    Vector_3 reach;
    if(!measuring_reach(t, reach)) return true;
    if(!f(CGAL::centroid(t[0], t[1], t[2]), reach)) return false;
    const int step = known > 0 ? m / known : 0;
    for(int i = 0; i < m; ++i)
      for(int j = 0; i + j <= m; ++j) {
        const int k = m - i - j;
        if(j == m || k == m) continue; // the vertices lie on the surface
        if(step > 0 && i % step == 0 && j % step == 0) continue;
        if(!f(CGAL::barycenter(t[0], double(i) / m, t[1], double(j) / m, t[2], double(k) / m), reach)) return false;
      }
    return true;
  }

  // the domain returns any intersection of a segment: shrink it past each one
  // found, down to the nearest (or give up after a few)
  static constexpr int max_shrinks = 4;

  // distance from `s` to the nearest intersection of the surface with the
  // segment from `s - reach` to `s + reach`, if it lies on `patch`; else 0
  double distance_along(const Bare_point& s, Vector_3 reach, const Surface_patch_index& patch,
                        Bare_point* hit = nullptr) const
  {
    const double length = std::sqrt(CGAL::to_double(reach.squared_length()));
    const Vector_3 unit = reach / length;
    double d = 0;
    bool on_patch = false;
    for(int k = 0; k < max_shrinks; ++k) {
      const Segment_3 segment(s - reach, s + reach);
      // after the first hit, most shrunk segments meet nothing: the predicate says so for less
      if(k > 0 && !domain_->do_intersect_surface_object()(segment)) break;
      const typename MeshDomain::Intersection i = domain_->construct_intersection_object()(segment);
      if(std::get<2>(i) != 2) break;
      d = std::sqrt(CGAL::to_double(CGAL::squared_distance(s, std::get<0>(i))));
      on_patch = domain_->surface_patch_index(std::get<1>(i)) == patch;
      if(hit != nullptr) *hit = std::get<0>(i);
      if(!(d > 1e-9 * length)) break; // a shorter segment would be a point
      reach = unit * (0.99 * d);
    }
    return on_patch ? d : 0;
  }

  struct Initial_facet
  {
    Triangle t;
    std::array<Vertex_handle, 3> v;
    Surface_patch_index patch;
    std::array<double, 2> d; // deviations on the coarse grid and on both
  };

  // whether the facet's deviation is rounding noise
  static bool lies_on_surface(const Initial_facet& e)
  {
    double longest2 = 0;
    for(int k = 0; k < 3; ++k)
      longest2 = (std::max)(longest2, CGAL::to_double(CGAL::squared_distance(e.t[k], e.t[(k + 1) % 3])));
    return e.d[1] <= noise_share * 0.5 * std::sqrt(longest2);
  }

  typedef typename CGAL::Kernel_traits<Bare_point>::Kernel Kernel;
  typedef typename Kernel::Triangle_3 Triangle_3;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<
      Kernel, CGAL::AABB_triangle_primitive<Kernel, typename std::vector<Triangle_3>::const_iterator>>>
      Boundary_tree;

  // The largest distance, over the points of the grid of `e` with `m` subdivisions that
  // deviate more than `above`, from the point to the surface and from the surface's point on
  // its normal to the boundary `boundary`; `above` if none is further. The deviation of a
  // point is larger than both: along the facet's normal, the surface is further than along
  // its own normal, and a point of the surface beside a crease can be closer to the next facet
  double distance_between(const Initial_facet& e, int m, const Boundary_tree& boundary, double above) const
  {
    double largest = above;
    for_each_grid_point(e.t, m, 0, [&](const Bare_point& s, const Vector_3& reach) {
      Bare_point x;
      const double along = distance_along(s, reach, e.patch, &x);
      if(!(along > largest)) return true;
      const double to_boundary = std::sqrt(CGAL::to_double(boundary.squared_distance(x)));
      largest = (std::max)(largest, (std::max)(to_boundary, nearest_in_cone(s, reach, along)));
      return true;
    });
    return largest;
  }

  // the distance from `s` to the surface: the nearest of its points along the directions of a
  // cone of half angle 60 degrees about `reach`, up to `limit`
  double nearest_in_cone(const Bare_point& s, const Vector_3& reach, double limit) const
  {
    const double length = std::sqrt(CGAL::to_double(reach.squared_length()));
    // a distance of the rounding noise (a flat face not along the axes): no shorter one to look
    // for, and segments that short would be points
    if(!(limit > noise_share * length)) return limit;
    const Vector_3 n = reach / length;
    Vector_3 e1 = CGAL::cross_product(n, std::abs(CGAL::to_double(n.x())) < 0.6 ? Vector_3(1, 0, 0) : Vector_3(0, 1, 0));
    e1 = e1 / std::sqrt(CGAL::to_double(e1.squared_length()));
    const Vector_3 e2 = CGAL::cross_product(n, e1);
    double nearest = limit;
    for(int a = 1; a <= cone_rings; ++a)
      for(int b = 0; b < cone_ring_rays; ++b) {
        const double alpha = a * (CGAL_PI / 3) / cone_rings, beta = b * (2 * CGAL_PI) / cone_ring_rays;
        const Vector_3 u = n * std::cos(alpha) + (e1 * std::cos(beta) + e2 * std::sin(beta)) * std::sin(alpha);
        Vector_3 r = u * nearest;
        for(int k = 0; k < max_shrinks; ++k) {
          const Segment_3 segment(s - r, s + r);
          if(k > 0 && !domain_->do_intersect_surface_object()(segment)) break;
          const typename MeshDomain::Intersection i = domain_->construct_intersection_object()(segment);
          if(std::get<2>(i) != 2) break;
          const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(s, std::get<0>(i))));
          nearest = (std::min)(nearest, d);
          if(!(d > 1e-9 * length)) return 0;
          r = u * (0.99 * d);
        }
      }
    return nearest;
  }
  static constexpr int cone_rings = 3;
  static constexpr int cone_ring_rays = 8;

  // collects the primitives whose boxes overlap a box: their triangles need not meet it (an
  // exact test costs more than the few extra pieces)
  struct Overlapping_boxes
  {
    const CGAL::Bbox_3& box;
    std::vector<const Triangle_3*>& out;
    bool go_further() const { return true; }
    template <class Primitive>
    void intersection(const CGAL::Bbox_3&, const Primitive& p)
    {
      if(CGAL::do_overlap(box, p.datum().bbox())) out.push_back(&*p.id());
    }
    template <class Node>
    bool do_intersect(const CGAL::Bbox_3&, const Node& node) const { return CGAL::do_overlap(box, node.bbox()); }
  };

  std::vector<const Triangle_3*> pieces_near(const CGAL::Bbox_3& box) const
  {
    std::vector<const Triangle_3*> near;
    Overlapping_boxes traits{box, near};
    pieces_->tree.traversal(box, traits);
    return near;
  }

  // the initial facets, the pieces of a surface the boundary started on
  struct Pieces
  {
    std::vector<Triangle_3> triangles;
    Boundary_tree tree;
    std::map<Curve_index, std::vector<Bare_point>> curve_points; // the feature curves' vertices
  };

  const MeshDomain* domain_;
  std::shared_ptr<const Pieces> pieces_;
  std::unordered_map<Vertex_handle, std::array<double, 2>> vertex_bounds_; // coarse, fine
  std::array<double, 2> floors_ = {{0, 0}};
  double largest_ = 0;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_BOUNDARY_FIDELITY_H
