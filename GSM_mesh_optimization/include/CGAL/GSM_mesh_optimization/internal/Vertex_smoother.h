// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// GSM vertex smoothing (dissertation section 3.3.1 and 3.3.3): per vertex, a
// Newton direction h^-1 g of the energy of its incident cells and a
// backtracking line search from the largest move its one-ring allows. A move is
// kept only if no cell inverts (nor the convex hull stops being convex; on a
// mesh whose boundary is not a convex hull, nor two boundary facets close up
// on an edge, which would fold the boundary) and the one-ring energy
// decreases. Surface vertices move in their tangent plane and are projected
// back onto the domain's surface, on their own patch; feature
// curve vertices move along their curve; corners never move. A boundary vertex
// moves only where its facets stray from the surface no further than the
// initial mesh's did (Boundary_fidelity.h).
//
// Rings are built from a given star (the cells around the vertex) and a move
// reads and writes only the ring, without the triangulation's traversal flags,
// so vertices that are not neighbors can be smoothed in parallel.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_SMOOTHER_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_SMOOTHER_H

#include <CGAL/GSM_mesh_optimization/internal/Boundary_fidelity.h>
#include <CGAL/GSM_mesh_optimization/internal/Mesh_energy.h>

#include <CGAL/Mesh_3/Has_features.h>
#include <CGAL/enum.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <tuple>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

template <class C3T3, class MeshDomain>
class Vertex_smoother
{
public:
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Geom_traits GT;
  typedef typename GT::Point_3 Bare_point;
  typedef typename GT::Vector_3 Vector_3;
  typedef typename GT::Segment_3 Segment_3;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Facet Facet;
  typedef typename C3T3::Surface_patch_index Surface_patch_index;
  typedef typename C3T3::Curve_index Curve_index;
  typedef Mesh_energy<C3T3> Energy;
  typedef Boundary_fidelity<C3T3, MeshDomain> Fidelity;

  // A candidate vertex: where it is allowed to go and what its move is worth.
  struct Ring
  {
    Vertex_handle v;
    int dimension = 3;
    std::vector<Cell_handle> finite_cells, complex_cells, infinite_cells;
    // B of each complex cell where the ring was made, for a metric that varies: the Newton
    // step and the line search measure with these (B is a constant in the derivatives),
    // and only the move taken is measured again with B where the cells go
    std::vector<Eigen::Matrix3d> frames;
    double max_neighbor_distance = 0;
    std::vector<Facet> surface_facets;                // surface and curve vertices, each facet once
    Eigen::Vector3d normal = Eigen::Vector3d::Zero(); // surface vertices
    Surface_patch_index patch = Surface_patch_index();
    std::vector<Vertex_handle> curve_neighbors;       // feature-curve vertices
    Curve_index curve = Curve_index();

    /// empties the ring for the next vertex, keeping the vectors' memory (one ring
    /// serves a whole sweep)
    void clear()
    {
      v = Vertex_handle();
      dimension = 3;
      finite_cells.clear();
      complex_cells.clear();
      infinite_cells.clear();
      frames.clear();
      max_neighbor_distance = 0;
      surface_facets.clear();
      normal = Eigen::Vector3d::Zero();
      patch = Surface_patch_index();
      curve_neighbors.clear();
      curve = Curve_index();
    }
  };

  Vertex_smoother(C3T3& c3t3, const MeshDomain* domain, const Energy& energy, bool freeze_boundary,
                  double boundary_distance = 0)
    : c3t3_(c3t3), tr_(c3t3.triangulation()), domain_(domain), energy_(energy),
      freeze_boundary_(freeze_boundary)
  {
    if constexpr(!std::is_void<MeshDomain>::value)
      if(lowest_movable_dimension() < 3) fidelity_.emplace(c3t3, domain, boundary_distance);
    convex_hull_ = hull_is_locally_convex();
  }

  /// whether the triangulation's boundary is convex, as a Delaunay mesh's (else it is the
  /// boundary of a mesh made elsewhere, Complex_from_tetrahedra_3)
  bool convex_hull() const { return convex_hull_; }

  /// the smallest angle, in radians, between two boundary facets around their edge that a
  /// move may close down to, on a boundary that is not a convex hull: smaller, and the
  /// boundary folds at the edge (or nearly: a slit of outside space)
  static constexpr double min_boundary_opening = 5. * CGAL_PI / 180.;

  /// the angle in [0, pi] between the half-planes of the triangles (a, b, c) and (a, b, d)
  /// around their edge (a, b): 0 when they close up, pi when they are flat
  static double boundary_opening(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                 const Eigen::Vector3d& d)
  {
    const Eigen::Vector3d e = (b - a).normalized();
    const Eigen::Vector3d u = (c - a) - e * e.dot(c - a), w = (d - a) - e * e.dot(d - a);
    return std::atan2(u.cross(w).norm(), u.dot(w));
  }

  /// lowest vertex dimension that may move (3: interior only)
  int lowest_movable_dimension() const
  {
    if constexpr(std::is_void<MeshDomain>::value)
      return 3; // a bare triangulation: its boundary is fixed
    else {
      if(freeze_boundary_ || domain_ == nullptr) return 3;
      return Mesh_3::internal::Has_features<MeshDomain>::value ? 1 : 2;
    }
  }

  bool is_movable(const Vertex_handle& v) const
  {
    return !tr_.is_infinite(v) && c3t3_.in_dimension(v) >= lowest_movable_dimension() &&
           c3t3_.in_dimension(v) <= 3;
  }

  /// what a vertex at a position costs the mean-angle moves (`vertex_move_cost`), in degrees
  void set_move_cost(std::function<double(const Vertex_handle&, const Eigen::Vector3d&)> cost)
  {
    move_cost_ = std::move(cost);
  }

  double move_cost(const Vertex_handle& v, const Eigen::Vector3d& x) const { return move_cost_ ? move_cost_(v, x) : 0.; }

  /// the one-ring of `v` from its `star` (all cells incident to `v`, infinite
  /// ones included); false if it has no cell in the complex or no frame
  template <class CellRange>
  bool make_ring(const Vertex_handle& v, const CellRange& star, Ring& r) const
  {
    r.clear();
    r.v = v;
    r.dimension = c3t3_.in_dimension(v);
    const Eigen::Vector3d x = energy_.position(v);
    for(const Cell_handle& c : star) {
      if(tr_.is_infinite(c)) {
        r.infinite_cells.push_back(c);
        continue;
      }
      r.finite_cells.push_back(c);
      if(c3t3_.is_in_complex(c)) r.complex_cells.push_back(c);
      for(int i = 0; i < 4; ++i)
        if(c->vertex(i) != v)
          r.max_neighbor_distance = (std::max)(r.max_neighbor_distance, (energy_.position(c->vertex(i)) - x).norm());
    }
    if(r.complex_cells.empty()) return false;
    if(energy_.has_varying_frames())
      for(const Cell_handle& c : r.complex_cells) r.frames.push_back(energy_.frame(c));
    if(r.dimension < 3) collect_surface_facets(r);
    if(r.dimension == 2) return surface_frame(r);
    if(r.dimension == 1) return curve_frame(r);
    return true;
  }

  /// the same, collecting the star with the triangulation (not thread-safe)
  bool make_ring(const Vertex_handle& v, Ring& r) const
  {
    std::vector<Cell_handle> star;
    tr_.incident_cells(v, std::back_inserter(star));
    return make_ring(v, star, r);
  }

  /// sum of the energies of the complex cells of the ring with `v` at `x`
  double ring_energy(const Ring& r, const Eigen::Vector3d& x) const
  {
    double e = 0;
    if(energy_.has_vertex_sizes()) { // the vertex takes its size at `x`: one lookup for the ring
      const double size = energy_.size_at(x);
      for(const Cell_handle& c : r.complex_cells) e += energy_.cell(c, r.v, x, energy_.frame(c, r.v, size));
      return e;
    }
    for(const Cell_handle& c : r.complex_cells) e += energy_.cell(c, r.v, x);
    return e;
  }

  /// the same with the ring's frames (exact where the ring was made)
  double frozen_ring_energy(const Ring& r, const Eigen::Vector3d& x) const
  {
    if(r.frames.empty()) return ring_energy(r, x);
    double e = 0;
    for(std::size_t k = 0; k < r.complex_cells.size(); ++k) e += energy_.cell(r.complex_cells[k], r.v, x, r.frames[k]);
    return e;
  }

  /// the Newton step h^-1 g restricted to the vertex's degrees of freedom,
  /// clipped to the largest move of the one-ring (the paper's alpha_init); zero if none
  Eigen::Vector3d newton_step(const Ring& r, bool& is_descent) const
  {
    const Eigen::Vector3d x = energy_.position(r.v);
    Energy_derivatives d;
    if(r.frames.empty())
      for(const Cell_handle& c : r.complex_cells) d += energy_.cell_derivatives(c, r.v, x);
    else
      for(std::size_t k = 0; k < r.complex_cells.size(); ++k)
        d += energy_.cell_derivatives(r.complex_cells[k], r.v, x, r.frames[k]);
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    is_descent = false;
    if(!d.gradient.allFinite() || !d.hessian.allFinite()) return step;

    if(r.dimension == 3) {
      Eigen::LLT<Eigen::Matrix3d> llt(d.hessian);
      if(llt.info() == Eigen::Success) {
        step = llt.solve(d.gradient);
        is_descent = true;
      } else
        step = d.gradient;
    } else if(r.dimension == 2) {
      // tangent plane basis
      Eigen::Vector3d t1 = r.normal.unitOrthogonal(), t2 = r.normal.cross(t1);
      Eigen::Matrix<double, 3, 2> T;
      T << t1, t2;
      const Eigen::Vector2d g2 = T.transpose() * d.gradient;
      const Eigen::Matrix2d h2 = T.transpose() * d.hessian * T;
      Eigen::LLT<Eigen::Matrix2d> llt(h2);
      if(llt.info() == Eigen::Success) {
        step = T * llt.solve(g2);
        is_descent = true;
      } else
        step = T * g2;
    } else {
      const Eigen::Vector3d t = curve_tangent(r);
      const double g1 = t.dot(d.gradient), h1 = t.dot(d.hessian * t);
      if(h1 > 0) {
        step = (g1 / h1) * t;
        is_descent = true;
      } else
        step = g1 * t;
    }
    const double n = step.norm();
    if(!(n > 0) || !std::isfinite(n)) return Eigen::Vector3d::Zero();
    if(n > r.max_neighbor_distance) step *= r.max_neighbor_distance / n;
    return step;
  }

  /// tries to move the vertex of `r`; true if it moved, with the change of the ring energy
  bool smooth(const Ring& r, double& energy_change) const
  {
    bool is_descent;
    const Eigen::Vector3d step = newton_step(r, is_descent);
    if(step.isZero()) return false;
    const Eigen::Vector3d x0 = energy_.position(r.v);
    const double e0 = frozen_ring_energy(r, x0);
    const double tiny = 1e-12 * (std::max)(1., std::abs(e0));
    double alpha = 1;
    for(int k = 0; k < max_backtracking_steps; ++k, alpha *= 0.5) {
      for(double sign : {1., -1.}) {
        if(sign < 0 && is_descent) continue; // the Newton direction descends: no need to look back
        Bare_point p;
        if(!candidate(r, x0 - sign * alpha * step, p)) continue;
        const Eigen::Vector3d x = Energy::to_eigen(p);
        if(!is_valid_position(r, p)) continue;
        double e = frozen_ring_energy(r, x);
        if(!(e < e0 - tiny)) continue;
        if(!r.frames.empty() && !((e = ring_energy(r, x)) < e0 - tiny)) continue; // where the cells went
        if(keeps_boundary_faithful(r, p)) {
          move(r.v, p);
          energy_change = e - e0;
          return true;
        }
      }
    }
    return false;
  }

  /// no finite incident cell inverts, and the convex hull stays convex around `v` (on a
  /// boundary that is not a convex hull: no two boundary facets close up on an edge)
  bool is_valid_position(const Ring& r, const Bare_point& p) const
  {
    for(const Cell_handle& c : r.finite_cells) {
      Bare_point q[4];
      for(int i = 0; i < 4; ++i) q[i] = c->vertex(i) == r.v ? p : bare(c->vertex(i));
      if(CGAL::orientation(q[0], q[1], q[2], q[3]) != CGAL::POSITIVE) return false;
    }
    for(const Cell_handle& c : r.infinite_cells) {
      // hull facet f of c, the interior witness w beyond it, and the hull
      // vertices d across its edges: no d may lie beyond f (coplanar is fine:
      // flat parts of the hull, such as a cube's faces)
      const int inf = c->index(tr_.infinite_vertex());
      Bare_point f[3];
      for(int k = 0; k < 3; ++k) {
        const Vertex_handle u = c->vertex((inf + 1 + k) & 3);
        f[k] = u == r.v ? p : bare(u);
      }
      const Cell_handle inside = c->neighbor(inf);
      const Vertex_handle w = inside->vertex(inside->index(c));
      const CGAL::Orientation side = CGAL::orientation(f[0], f[1], f[2], bare(w));
      if(side == CGAL::COPLANAR) return false;
      for(int j = 0; j < 4; ++j) {
        if(j == inf) continue;
        const Cell_handle nb = c->neighbor(j);
        const Vertex_handle d = nb->vertex(nb->index(c));
        if(convex_hull_) {
          const CGAL::Orientation o = CGAL::orientation(f[0], f[1], f[2], d == r.v ? p : bare(d));
          if(o != side && o != CGAL::COPLANAR) return false;
          continue;
        }
        // the facet's edge opposite its vertex j, and the two apexes around it
        std::array<Vertex_handle, 2> edge;
        for(int k = 0, n = 0; k < 4; ++k)
          if(k != inf && k != j) edge[std::size_t(n++)] = c->vertex(k);
        const auto at = [&](const Vertex_handle& u, bool moved) {
          return moved && u == r.v ? Energy::to_eigen(p) : energy_.position(u);
        };
        const auto opening = [&](bool moved) {
          return boundary_opening(at(edge[0], moved), at(edge[1], moved), at(c->vertex(j), moved), at(d, moved));
        };
        const double after = opening(true);
        if(after < min_boundary_opening && after < opening(false)) return false;
      }
    }
    return true;
  }

  /// moves the vertex `v` to `p`
  void move(const Vertex_handle& v, const Bare_point& p) const
  {
    set_bare_point(tr_, v, p);
    energy_.vertex_moved(v);
  }

  /// the point the vertex of `r` would take for the unconstrained target `x`: `x` itself,
  /// or its projection on the vertex's surface patch or curve; false if there is none
  bool candidate(const Ring& r, const Eigen::Vector3d& x, Bare_point& p) const
  {
    p = Bare_point(x[0], x[1], x[2]);
    if(r.dimension == 3) return true;
    if constexpr(std::is_void<MeshDomain>::value)
      return false;
    else {
      if(r.dimension == 2) return project_on_surface(r, p);
      return project_on_curve(r, p);
    }
  }

  /// the part of the direction `d` along which the vertex of `r` may move
  Eigen::Vector3d tangential(const Ring& r, const Eigen::Vector3d& d) const
  {
    if(r.dimension == 2) return d - r.normal.dot(d) * r.normal;
    if(r.dimension == 1) {
      const Eigen::Vector3d t = curve_tangent(r);
      return t.dot(d) * t;
    }
    return d;
  }

  /// a point where the segment `s` meets the domain's surface, if it lies on the patch `patch`
  bool project_on_patch(const Segment_3& s, const Surface_patch_index& patch, Bare_point& p) const
  {
    if constexpr(std::is_void<MeshDomain>::value) {
      CGAL_USE(s);
      CGAL_USE(patch);
      CGAL_USE(p);
      return false;
    } else {
      const typename MeshDomain::Intersection i = domain_->construct_intersection_object()(s);
      if(std::get<2>(i) != 2) return false;
      if(!(domain_->surface_patch_index(std::get<1>(i)) == patch)) return false;
      p = std::get<0>(i);
      return true;
    }
  }

  /// the triangle `t`, a part of the surface facet `whole` of the patch `patch` (whose vertices
  /// are `v`), strays no further from the surface than the boundary may, or than `whole` does
  /// (up to a hundredth of it)
  bool is_faithful_part(const std::array<Bare_point, 3>& t, const std::array<Bare_point, 3>& whole,
                        const Surface_patch_index& patch, const std::array<Vertex_handle, 3>& v) const
  {
    if constexpr(std::is_void<MeshDomain>::value) {
      CGAL_USE(t);
      CGAL_USE(whole);
      CGAL_USE(patch);
      CGAL_USE(v);
      return false;
    } else
      return fidelity_ && (fidelity_->is_faithful(t, patch, v) || fidelity_->strays_no_further(t, whole, patch, 0.01));
  }

  /// the triangle `t` of the patch `patch`, on the vertices `v`, strays no further from the
  /// surface than the boundary may (for a new surface facet)
  bool is_faithful_triangle(const std::array<Bare_point, 3>& t, const Surface_patch_index& patch,
                            const std::array<Vertex_handle, 3>& v) const
  {
    if constexpr(std::is_void<MeshDomain>::value) {
      CGAL_USE(t);
      CGAL_USE(patch);
      CGAL_USE(v);
      return false;
    } else
      return fidelity_ && fidelity_->is_faithful(t, patch, v);
  }

  /// how far the surface near the boundary vertex `v` may be from the boundary: its facets'
  /// bound, up to the largest initial distance between the boundary and the surface
  double boundary_bound(const Vertex_handle& v) const
  {
    if constexpr(std::is_void<MeshDomain>::value) {
      CGAL_USE(v);
      return 0;
    } else
      return fidelity_ ? (std::min)(fidelity_->bound(v), fidelity_->largest_initial_distance()) : 0;
  }

  /// the boundary vertex `v` is about to be removed (its handle may come back for a new vertex)
  void boundary_vertex_removed(const Vertex_handle& v)
  {
    if constexpr(std::is_void<MeshDomain>::value)
      CGAL_USE(v);
    else if(fidelity_)
      fidelity_->forget(v);
  }

  /// whether the facets of `v` may stray further than the floor: they did at the start
  bool has_own_boundary_bound(const Vertex_handle& v) const
  {
    if constexpr(std::is_void<MeshDomain>::value) {
      CGAL_USE(v);
      return false;
    } else
      return fidelity_ && fidelity_->has_own_bound(v);
  }

  /// the facets of a boundary vertex at `p` stray no further from the surface than the initial
  /// ones, and the edges of a feature-curve vertex no further from the curve than its bound
  /// (or than they do now)
  bool keeps_boundary_faithful(const Ring& r, const Bare_point& p) const
  {
    if constexpr(std::is_void<MeshDomain>::value)
      return r.dimension == 3; // the boundary of a bare triangulation does not move
    else {
      if(r.dimension == 3) return true;
      if(r.dimension == 1 && !keeps_curve_faithful(r, p)) return false;
      std::vector<typename Fidelity::Triangle> star;
      std::vector<std::array<Vertex_handle, 3>> star_vertices;
      for(const Facet& f : r.surface_facets) {
        typename Fidelity::Triangle t;
        std::array<Vertex_handle, 3> vs;
        for(int k = 0; k < 3; ++k) {
          vs[k] = f.first->vertex((f.second + 1 + k) & 3);
          t[k] = vs[k] == r.v ? p : bare(vs[k]);
        }
        if(!fidelity_->is_faithful(t, c3t3_.surface_patch_index(f), vs)) return false;
        star.push_back(t);
        star_vertices.push_back(vs);
      }
      return fidelity_->corners_near(star, star_vertices);
    }
  }

  /// the new surface facets `t` on the vertices `v` keep the corners of the surface near
  /// them within the boundary's bound (Boundary_fidelity::corners_near)
  bool keeps_corners_near(const std::vector<std::array<Bare_point, 3>>& t,
                          const std::vector<std::array<Vertex_handle, 3>>& v) const
  {
    if constexpr(std::is_void<MeshDomain>::value) {
      CGAL_USE(t);
      CGAL_USE(v);
      return false;
    } else
      return fidelity_ && fidelity_->corners_near(t, v);
  }

  /// the new surface facets `f` keep the corners of the surface near them within the
  /// boundary's bound
  bool keeps_corners_near(const std::vector<Facet>& f) const
  {
    std::vector<std::array<Bare_point, 3>> t;
    std::vector<std::array<Vertex_handle, 3>> v;
    for(const Facet& g : f) {
      v.emplace_back();
      t.emplace_back();
      for(int k = 0; k < 3; ++k) {
        v.back()[k] = g.first->vertex((g.second + 1 + k) & 3);
        t.back()[k] = bare(v.back()[k]);
      }
    }
    return keeps_corners_near(t, v);
  }

  /// the facet `f`, on the patch `patch`, strays no further from the surface than
  /// the initial facets around its vertices (for a change of the surface triangulation)
  bool is_faithful(const Facet& f, const Surface_patch_index& patch) const
  {
    if constexpr(std::is_void<MeshDomain>::value)
      return false; // the boundary of a bare triangulation does not change
    else {
      if(!fidelity_) return false;
      typename Fidelity::Triangle t;
      std::array<Vertex_handle, 3> vs;
      for(int k = 0; k < 3; ++k) {
        vs[k] = f.first->vertex((f.second + 1 + k) & 3);
        t[k] = bare(vs[k]);
      }
      return fidelity_->is_faithful(t, patch, vs);
    }
  }

private:
  static constexpr int max_backtracking_steps = 12;

  Bare_point bare(const Vertex_handle& v) const
  {
    return tr_.geom_traits().construct_point_3_object()(tr_.point(v));
  }

  // the surface facets around the vertex of `r`, each once, seen from the cell
  // of larger subdomain index
  void collect_surface_facets(Ring& r) const
  {
    for(const Cell_handle& c : r.finite_cells) {
      const int iv = c->index(r.v);
      for(int i = 0; i < 4; ++i) {
        if(i == iv || !c3t3_.is_in_complex(c, i)) continue;
        const Cell_handle m = c->neighbor(i);
        if(!tr_.is_infinite(m)) {
          const auto sc = c3t3_.subdomain_index(c), sm = c3t3_.subdomain_index(m);
          if(sc < sm || (sc == sm && &*c < &*m)) continue;
        }
        r.surface_facets.push_back(Facet(c, i));
      }
    }
  }

  // --- surface vertices -------------------------------------------------------

  // normal of the vertex: area-weighted normals of its surface facets, all
  // oriented from the cell of larger subdomain index
  bool surface_frame(Ring& r) const
  {
    bool has_patch = false;
    for(const Facet& f : r.surface_facets) {
      const Cell_handle& c = f.first;
      const int i = f.second;
      const Surface_patch_index patch = c3t3_.surface_patch_index(c, i);
      if(!has_patch) {
        r.patch = patch;
        has_patch = true;
      } else if(!(patch == r.patch))
        return false; // on two patches: it sits on a feature the domain did not protect
      const Eigen::Vector3d a = energy_.position(c->vertex((i + 1) & 3));
      const Eigen::Vector3d b = energy_.position(c->vertex((i + 2) & 3));
      const Eigen::Vector3d d = energy_.position(c->vertex((i + 3) & 3));
      const Eigen::Vector3d inner = energy_.position(c->vertex(i));
      Eigen::Vector3d n = (b - a).cross(d - a);
      if(n.dot(inner - a) > 0) n = -n;
      r.normal += n;
    }
    const double len = r.normal.norm();
    if(!has_patch || !(len > 0)) return false;
    r.normal /= len;
    return true;
  }

  // intersection of the domain's surface with the normal segment through `p`,
  // accepted only on the vertex's own patch
  bool project_on_surface(const Ring& r, Bare_point& p) const
  {
    // as long as the move: the surface is that close to the tangent plane over the
    // move, and a longer segment could reach across a thin part to the other side
    const double h = (std::min)(r.max_neighbor_distance,
                                (Energy::to_eigen(p) - energy_.position(r.v)).norm());
    const Vector_3 n(r.normal[0] * h, r.normal[1] * h, r.normal[2] * h);
    return project_on_patch(Segment_3(p - n, p + n), r.patch, p);
  }

  // --- feature-curve vertices -------------------------------------------------

  bool curve_frame(Ring& r) const
  {
    if constexpr(Mesh_3::internal::Has_features<MeshDomain>::value) {
      for(const Cell_handle& c : r.finite_cells)
        for(int i = 0; i < 4; ++i) {
          const Vertex_handle w = c->vertex(i);
          if(w != r.v && c3t3_.is_in_complex(r.v, w) &&
             std::find(r.curve_neighbors.begin(), r.curve_neighbors.end(), w) == r.curve_neighbors.end())
            r.curve_neighbors.push_back(w);
        }
      if(r.curve_neighbors.size() != 2) return false;
      r.curve = c3t3_.curve_index(r.v, r.curve_neighbors[0]);
      return r.curve == c3t3_.curve_index(r.v, r.curve_neighbors[1]);
    } else
      return false;
  }

  Eigen::Vector3d curve_tangent(const Ring& r) const
  {
    const Eigen::Vector3d t =
        energy_.position(r.curve_neighbors[1]) - energy_.position(r.curve_neighbors[0]);
    return t.normalized();
  }

  // the point of the curve at the arc length from the vertex that matches the
  // displacement to `p` along the tangent, strictly between the two neighbors.
  // The neighbors' distances along the curve are bounded by their chords, and the
  // curve's direction at the vertex is found with `construct_point_on_curve()`:
  // CGAL 5.5.1's `signed_geodesic_distance()` can loop forever on points that its
  // two ways of locating a point on a polyline place on different segments.
  bool project_on_curve(const Ring& r, Bare_point& p) const
  {
    if constexpr(Mesh_3::internal::Has_features<MeshDomain>::value) {
      const Bare_point o = bare(r.v);
      const Eigen::Vector3d eo = Energy::to_eigen(o), t = curve_tangent(r);
      const Eigen::Vector3d v0 = Energy::to_eigen(bare(r.curve_neighbors[0])) - eo,
                            v1 = Energy::to_eigen(bare(r.curve_neighbors[1])) - eo;
      const double step = 0.01 * (std::min)(v0.norm(), v1.norm());
      if(!(step > 0)) return false;
      // the neighbors' sides along the curve's orientation: a step along a loop (distances
      // wrap around), the order along an open curve
      double s0, s1;
      if(domain_->is_loop(r.curve)) {
        const Eigen::Vector3d forward = Energy::to_eigen(domain_->construct_point_on_curve(o, r.curve, step)) - eo;
        s0 = forward.dot(v0);
        s1 = forward.dot(v1);
      } else {
        s0 = double(int(domain_->distance_sign(o, bare(r.curve_neighbors[0]), r.curve)));
        s1 = double(int(domain_->distance_sign(o, bare(r.curve_neighbors[1]), r.curve)));
      }
      if(!(s0 * s1 < 0)) return false; // the neighbors must be on both sides
      const double d0 = s0 > 0 ? v0.norm() : -v0.norm(), d1 = s1 > 0 ? v1.norm() : -v1.norm();
      const double lo = (std::min)(d0, d1), hi = (std::max)(d0, d1);
      const double s = t.dot(Energy::to_eigen(p) - eo);
      // the tangent points from neighbor 0 to neighbor 1: orient s with the curve
      const double arc = d1 > d0 ? s : -s;
      if(!(arc > 0.9 * lo && arc < 0.9 * hi)) return false;
      p = domain_->construct_point_on_curve(o, r.curve, arc);
      return true;
    } else {
      CGAL_USE(r);
      CGAL_USE(p);
      return false;
    }
  }

  // The edges of a feature-curve vertex are chords of the curve: where the curve bends between
  // two vertices, the chord cuts the corner, and the facets' measure along their normals misses
  // it (beside a feature edge the normal lines leave the patch). So the arc between the vertex
  // and each curve neighbour is sampled, and its distance to the chord bounded (with the
  // polyline's own corners where the boundary started on the surface).
  static constexpr int curve_samples = 8;

  // the largest distance from the curve between `o` and `q` (its arc, sampled) to the chord
  double chord_deviation(const Curve_index& curve, const Bare_point& o, const Bare_point& q) const
  {
    if constexpr(Mesh_3::internal::Has_features<MeshDomain>::value) {
      const Eigen::Vector3d eo = Energy::to_eigen(o), eq = Energy::to_eigen(q);
      const double chord = (eq - eo).norm();
      if(!(chord > 0)) return 0;
      double sign;
      if(domain_->is_loop(curve))
        sign = (Energy::to_eigen(domain_->construct_point_on_curve(o, curve, 0.01 * chord)) - eo).dot(eq - eo) > 0 ? 1 : -1;
      else
        sign = double(int(domain_->distance_sign(o, q, curve)));
      if(sign == 0) return 0;
      double d = 0;
      const Eigen::Vector3d u = (eq - eo) / chord;
      for(int k = 1; k < curve_samples; ++k) {
        const Eigen::Vector3d x =
            Energy::to_eigen(domain_->construct_point_on_curve(o, curve, sign * chord * k / curve_samples)) - eo;
        const double t = std::clamp(x.dot(u), 0., chord);
        d = (std::max)(d, (x - t * u).norm());
      }
      return fidelity_ ? (std::max)(d, fidelity_->curve_corners_deviation(curve, o, q)) : d;
    } else {
      CGAL_USE(curve);
      CGAL_USE(o);
      CGAL_USE(q);
      return 0;
    }
  }

  bool keeps_curve_faithful(const Ring& r, const Bare_point& p) const
  {
    const double bound = boundary_bound(r.v);
    for(const Vertex_handle& n : r.curve_neighbors) {
      const double after = chord_deviation(r.curve, p, bare(n));
      if(after > bound && after > chord_deviation(r.curve, bare(r.v), bare(n))) return false;
    }
    return true;
  }

  // every hull vertex next to a hull facet is on its cell's side or on its plane
  bool hull_is_locally_convex() const
  {
    for(auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
      if(!tr_.is_infinite(c)) continue;
      const int inf = c->index(tr_.infinite_vertex());
      Bare_point f[3];
      for(int k = 0; k < 3; ++k) f[k] = bare(c->vertex((inf + 1 + k) & 3));
      const Cell_handle inside = c->neighbor(inf);
      const CGAL::Orientation side = CGAL::orientation(f[0], f[1], f[2], bare(inside->vertex(inside->index(c))));
      for(int j = 0; j < 4; ++j) {
        if(j == inf) continue;
        const Cell_handle nb = c->neighbor(j);
        const CGAL::Orientation o = CGAL::orientation(f[0], f[1], f[2], bare(nb->vertex(nb->index(c))));
        if(o != side && o != CGAL::COPLANAR) return false;
      }
    }
    return true;
  }

  C3T3& c3t3_;
  Tr& tr_;
  const MeshDomain* domain_;
  const Energy& energy_;
  bool freeze_boundary_;
  bool convex_hull_ = true;
  std::function<double(const Vertex_handle&, const Eigen::Vector3d&)> move_cost_;
  std::optional<Fidelity> fidelity_; // when the boundary may move
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_VERTEX_SMOOTHER_H
