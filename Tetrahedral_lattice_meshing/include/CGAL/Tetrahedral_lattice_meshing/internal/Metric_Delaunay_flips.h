// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Makes the tets of lattice particles Delaunay in the frame field's space by
// 2-3 and 3-2 flips (Lawson's flips with the in-sphere test of the points
// mapped by B). A lattice is regular in the field's space only: a cubic
// lattice is a grid of cubes there, whose Delaunay tets stay inside the cubes;
// in Euclidean space the cells are boxes or parallelepipeds, and the Euclidean
// Delaunay tets of a slightly perturbed grid of long boxes or sheared cells
// cross them, so that no hexahedron can be merged there (a sheared 8^3 grid:
// 366 of 512 hexahedra from the Euclidean tets, 499 after these flips); the
// Euclidean Delaunay tets of a stretched BCC or FCC lattice are slivers in the
// field's metric.
//
// Only inside one subdomain, never across a surface facet or a feature edge;
// every flip is checked exactly in Euclidean space (CGAL's Triangulation_3::flip).
//
// For tetrahedral lattices two more rules (`Flat_boundary_cells::FORBIDDEN` and
// `break_ties_by_shape()`): no flip lays a flat cell of four surface vertices on a
// planar face (in a varying field the in-sphere test of such a cell can ask for it),
// and points that are cospherical in the field's space (the six corners of an FCC
// octahedron, up to rounding) get the triangulation of the better shapes, not the
// flat tet of the octahedron's square. The cubic lattice keeps the defaults: any
// triangulation of a cube merges, the hexahedron patterns with a flat tet included.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_METRIC_DELAUNAY_FLIPS_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_METRIC_DELAUNAY_FLIPS_H

#include <CGAL/VVM/internal/Complex_cell_replacement.h>

#include <Eigen/LU>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

template <class C3T3>
class Metric_Delaunay_flips : public VVM::internal::Complex_cell_replacement<C3T3>
{
  typedef VVM::internal::Complex_cell_replacement<C3T3> Base;

public:
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Facet Facet;
  typedef typename Base::Edge Edge;
  typedef typename Base::Subdomain_index Subdomain_index;
  /// B(x), the map into the field's space
  typedef std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> Frame_inverse;
  /// whether a flip may make a flat cell whose four vertices are on the surface
  enum class Flat_boundary_cells { ALLOWED, FORBIDDEN };

  /// points closer to cospherical than this (the lifted determinant over the fifth power
  /// of the edge length) are
  /// left as they are: the corners of a cube in the field's space are cospherical,
  /// and any of their triangulations merges
  static constexpr double tie_tolerance = 1e-4;

  /// the shape (the volume over that of the regular tet of the same root mean square edge,
  /// in the field's space) under which a cell counts as flat
  static constexpr double flat_shape = 0.05;

  Metric_Delaunay_flips(C3T3& c3t3, Frame_inverse B, Flat_boundary_cells flat = Flat_boundary_cells::ALLOWED)
    : Base(c3t3), B_(std::move(B)), flat_boundary_cells_(flat)
  {}

  /// flips until every facet inside a subdomain is Delaunay in the field's space, or no
  /// flip can fix the rest, or `max_flips` flips (a field that varies from cell to cell
  /// has no global Delaunay triangulation, and the flips could cycle); returns the flips
  std::size_t run(std::size_t max_flips) { return repeat(max_flips, false); }

  /// flips between points cospherical in the field's space (ties of the in-sphere test) that
  /// raise the worst shape of the cells they replace by a fifth, so that no flip is undone;
  /// after `run()`, which leaves ties as they are; returns the flips
  std::size_t break_ties_by_shape(std::size_t max_flips) { return repeat(max_flips, true); }

private:
  std::size_t repeat(std::size_t max_flips, bool ties)
  {
    std::size_t flips = 0;
    // a facet that no flip could fix may be fixed once its neighbours changed: passes over
    // all facets until one flips nothing
    for(std::size_t pass_start = std::size_t(-1); flips != pass_start && flips < max_flips;)
      pass_start = flips, flips += pass(max_flips - flips, ties);
    return flips;
  }

  // a facet to look at: a cell and index, and its vertices to find it again once flips
  // have freed or reused the cell
  struct Pending_facet
  {
    Cell_handle cell;
    int index;
    std::array<Vertex_handle, 3> vertices;
  };

  Pending_facet pending(const Facet& f) const { return {f.first, f.second, facet_vertices(f)}; }

  // the facet now, if it is still one: through its cell while the cell holds it, else
  // searched around its vertices
  bool current(const Pending_facet& t, Facet& f) const
  {
    if(this->tr_.tds().cells().is_used(t.cell) && facet_vertices(Facet(t.cell, t.index)) == t.vertices) {
      f = Facet(t.cell, t.index);
      return true;
    }
    Cell_handle c;
    int i, j, k;
    if(!this->tr_.is_facet(t.vertices[0], t.vertices[1], t.vertices[2], c, i, j, k)) return false;
    f = Facet(c, 6 - i - j - k);
    return true;
  }

  std::size_t pass(std::size_t max_flips, bool ties)
  {
    std::vector<Pending_facet> stack;
    for(auto c = this->c3t3_.cells_in_complex_begin(); c != this->c3t3_.cells_in_complex_end(); ++c)
      for(int i = 0; i < 4; ++i)
        if(Cell_handle(c) < c->neighbor(i)) stack.push_back(pending(Facet(c, i)));
    std::size_t flips = 0;
    while(!stack.empty() && flips < max_flips) {
      Facet f;
      const bool found = current(stack.back(), f);
      stack.pop_back();
      if(!found) continue;
      const Cell_handle c = f.first;
      Subdomain_index s;
      if(!this->same_subdomain({c, c->neighbor(f.second)}, s) || this->c3t3_.is_in_complex(f)) continue;
      const Eigen::Matrix3d B = B_(five_point_centroid(f));
      const Sphere_test test = in_sphere(f, B);
      if(test != (ties ? Sphere_test::TIE : Sphere_test::INSIDE)) continue;
      std::vector<Cell_handle> created;
      if(!flip_2_3(f, s, B, test, created) && !flip_3_2(f, B, test, created)) continue;
      ++flips;
      for(const Cell_handle& n : created)
        for(int m = 0; m < 4; ++m) stack.push_back(pending(Facet(n, m)));
    }
    return flips;
  }

  std::array<Vertex_handle, 3> facet_vertices(const Facet& f) const
  {
    return {f.first->vertex((f.second + 1) & 3), f.first->vertex((f.second + 2) & 3),
            f.first->vertex((f.second + 3) & 3)};
  }

  Eigen::Vector3d position(const Vertex_handle& v) const
  {
    const auto p = this->bare(v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  enum class Sphere_test { INSIDE, TIE, OUTSIDE };

  Eigen::Vector3d five_point_centroid(const Facet& f) const
  {
    const Cell_handle c = f.first, n = c->neighbor(f.second);
    Eigen::Vector3d centroid = position(n->vertex(n->index(c))) / 5.;
    for(int k = 0; k < 4; ++k) centroid += position(c->vertex(k)) / 5.;
    return centroid;
  }

  // whether the vertex of the neighbour beyond f lies inside the sphere through f's cell, in
  // the field's space at the centroid of the five points (`B`): the sign of the lifted
  // determinant, one number for the five points whichever of their triangulations is
  // tested, so that a flip is never undone by the reverse one, ties included
  Sphere_test in_sphere(const Facet& f, const Eigen::Matrix3d& B) const
  {
    const Cell_handle c = f.first, n = c->neighbor(f.second);
    std::array<Eigen::Vector3d, 4> x; // the cell's vertices (positively oriented), from the one beyond
    const Eigen::Vector3d t = position(n->vertex(n->index(c)));
    for(int k = 0; k < 4; ++k) x[k] = position(c->vertex(k));
    Eigen::Matrix4d lifted;
    double edge2 = 0;
    for(int k = 0; k < 4; ++k) {
      const Eigen::Vector3d y = B * (x[k] - t);
      lifted.row(k) << y.transpose(), y.squaredNorm();
      for(int m = k + 1; m < 4; ++m) edge2 += (B * (x[k] - x[m])).squaredNorm() / 6.;
    }
    // B keeps the orientation or reverses it; inside when the determinant has the other sign
    const double inside = -lifted.determinant() * (B.determinant() > 0 ? 1. : -1.);
    if(!std::isfinite(inside)) return Sphere_test::OUTSIDE;
    const double tie = tie_tolerance * edge2 * edge2 * std::sqrt(edge2);
    return inside > tie ? Sphere_test::INSIDE : inside < -tie ? Sphere_test::OUTSIDE : Sphere_test::TIE;
  }

  // the cell's volume over that of the regular one of the same root mean square edge, in
  // the field's space: 1 for a regular tet, 0 for a flat one
  double shape(const std::array<Vertex_handle, 4>& v, const Eigen::Matrix3d& B) const
  {
    std::array<Eigen::Vector3d, 4> y;
    for(int k = 0; k < 4; ++k) y[k] = B * position(v[k]);
    double edge2 = 0;
    for(int k = 0; k < 4; ++k)
      for(int m = k + 1; m < 4; ++m) edge2 += (y[k] - y[m]).squaredNorm() / 6.;
    const double volume6 = std::abs((y[1] - y[0]).dot((y[2] - y[0]).cross(y[3] - y[0])));
    return edge2 > 0 ? volume6 / (std::sqrt(2.) * edge2 * std::sqrt(edge2)) : 0.;
  }

  double worst_shape(const std::vector<std::array<Vertex_handle, 4>>& cells, const Eigen::Matrix3d& B) const
  {
    double worst = 1;
    for(const auto& c : cells) worst = (std::min)(worst, shape(c, B));
    return worst;
  }

  std::array<Vertex_handle, 4> cell_vertices(const Cell_handle& c) const
  {
    return {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
  }

  // whether replacing the cells `before` by `after` is wanted: an in-sphere violation is
  // fixed unless that makes a forbidden flat cell; a tie is broken if that raises the worst
  // shape by a fifth (and makes no such cell)
  bool wanted(const std::vector<std::array<Vertex_handle, 4>>& before,
              const std::vector<std::array<Vertex_handle, 4>>& after, const Eigen::Matrix3d& B, Sphere_test test) const
  {
    if(flat_boundary_cells_ == Flat_boundary_cells::FORBIDDEN)
      for(const auto& c : after) {
        bool on_surface = true;
        for(const Vertex_handle& v : c) on_surface = on_surface && this->c3t3_.in_dimension(v) < 3;
        if(on_surface && !(shape(c, B) > flat_shape)) return false;
      }
    return test == Sphere_test::INSIDE || worst_shape(after, B) > 1.2 * worst_shape(before, B);
  }

  // the facet's two cells become three around the edge between their apexes
  bool flip_2_3(const Facet& f, const Subdomain_index& s, const Eigen::Matrix3d& B, Sphere_test test,
                std::vector<Cell_handle>& created)
  {
    const Cell_handle c = f.first, n = c->neighbor(f.second);
    const Vertex_handle a = c->vertex(f.second), b = n->vertex(n->index(c));
    const std::array<Vertex_handle, 3> t = facet_vertices(f);
    if(!wanted({cell_vertices(c), cell_vertices(n)},
               {{a, b, t[0], t[1]}, {a, b, t[1], t[2]}, {a, b, t[2], t[0]}}, B, test))
      return false;
    this->release({c, n});
    if(!this->tr_.flip(c, f.second)) { // not convex: CGAL checks it exactly
      this->claim({c, n}, s);
      return false;
    }
    created = this->cells_around(a, b);
    this->claim(created, s);
    return true;
  }

  // the three cells around an edge of the facet become two
  bool flip_3_2(const Facet& f, const Eigen::Matrix3d& B, Sphere_test test, std::vector<Cell_handle>& created)
  {
    const std::array<Vertex_handle, 3> t = facet_vertices(f);
    for(int k = 0; k < 3; ++k) {
      const Vertex_handle p = t[k], q = t[(k + 1) % 3];
      const Cell_handle c = f.first;
      const Edge e(c, c->index(p), c->index(q));
      std::vector<Cell_handle> ring;
      std::vector<Vertex_handle> others;
      Subdomain_index s;
      if(!this->removable_edge(e, ring, others, s, 3) || ring.size() != 3) continue;
      if(!wanted({cell_vertices(ring[0]), cell_vertices(ring[1]), cell_vertices(ring[2])},
                 {{others[0], others[1], others[2], p}, {others[0], others[1], others[2], q}}, B, test))
        continue;
      this->release(ring);
      if(!this->tr_.flip(e)) {
        this->claim(ring, s);
        continue;
      }
      created = this->cells_on(others[0], others[1], others[2]);
      this->claim(created, s);
      return true;
    }
    return false;
  }

  Frame_inverse B_;
  Flat_boundary_cells flat_boundary_cells_;
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_METRIC_DELAUNAY_FLIPS_H
