// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Connects lattice particles into a Mesh_complex_3_in_triangulation_3 (the
// dissertation's section 4.3.2 with CGAL in place of GEOGRAM's RVD and
// TetGen): the Delaunay triangulation of the particles, cells labelled by the
// domain's subdomain at their centroid, surface facets between cells of
// different labels with the patch of the sampled boundary there, feature
// edges along the sharp edges, corners, and vertex dimensions as Mesh_3 sets
// them, so that output_to_medit, the quality measures and GSM see it as they
// see make_mesh_3's output.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_COMPLEX_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_COMPLEX_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Thread_safe_inside.h>
#include <CGAL/Tetrahedral_lattice_meshing/lattice_particle_types.h>
#include <CGAL/VVM/internal/Eigen_conversion.h>
#include <CGAL/VVM/internal/Parallel_for.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Mesh_3/Has_features.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Time_stamper.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

struct Complex_report
{
  std::size_t number_of_vertices = 0;          ///< particles in the triangulation
  std::size_t number_of_merged_particles = 0;  ///< particles at the place of another
  std::size_t number_of_feature_edges = 0;
  std::size_t number_of_surface_facets = 0;
  std::size_t number_of_cells = 0;
  std::size_t number_of_peeled_cells = 0;       ///< flat boundary cells left outside
  std::size_t number_of_isolated_cells = 0;     ///< cells without a neighbour in the complex, left outside
  std::vector<std::size_t> exposed_free_particles; ///< free particles on a surface facet
};

/// the frame inverse \f$ B(x) \f$ of a frame field; empty for the identity
using VVM::internal::Frame_inverse_function;

/// true if the tetrahedron's smallest height is under a tenth of its longest edge
inline bool is_flat(const std::array<Eigen::Vector3d, 4>& p)
{
  const double volume6 = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
  double longest = 0, largest_face = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j) longest = (std::max)(longest, (p[i] - p[j]).norm());
  for(int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& a = p[(i + 1) & 3], &b = p[(i + 2) & 3], &c = p[(i + 3) & 3];
    largest_face = (std::max)(largest_face, (b - a).cross(c - a).norm()); // twice its area
  }
  // smallest height = 3 V / largest face area = volume6 / (2 area) = volume6 / largest_face
  return !(largest_face > 0) || volume6 / largest_face < 0.1 * longest;
}

/// the square root of the field's metric \f$ B^T B \f$ averaged over the points (each scaled
/// by its trace), of determinant 1: the Delaunay tets of the points mapped by it stay inside
/// the cells of the lattice of a constant field (boxes, parallelepipeds), and the metric flips
/// have less to do for a varying one. The identity for a field of unit frames (a cross
/// field), which `isotropic` tells: no flip can change anything then.
template <class FrameField, class Point_3>
Eigen::Matrix3d mean_metric_root(const FrameField& field, const std::vector<Point_3>& points, bool& isotropic)
{
  auto is_isotropic = [](const Eigen::Vector3d& lambda) { return lambda.maxCoeff() < (1 + 1e-3) * lambda.minCoeff(); };
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  isotropic = true;
  for(const Point_3& p : points) {
    const Eigen::Matrix3d B = field.B(typename FrameField::Point_3(p.x(), p.y(), p.z()));
    const Eigen::Matrix3d m = B.transpose() * B;
    M += m / m.trace();
    if(isotropic) isotropic = is_isotropic(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues());
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(M);
  const Eigen::Vector3d lambda = eigen.eigenvalues();
  if(!(lambda.minCoeff() > 1e-6 * lambda.maxCoeff()) || is_isotropic(lambda)) return Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d root = eigen.operatorSqrt();
  return root / std::cbrt(root.determinant());
}

/// the Delaunay tets of `points` mapped by `map` (positive determinant) put into `tr` with the
/// points at their own places: the cells stay positive, since the map keeps orientations;
/// the mapped points are exact (Epeck), since rounding them would not keep coplanar particles
/// (those of a planar face) coplanar and would leave flat cells. `vertex[i]` is the vertex of
/// `points[i]`, or null for a point at the place of an earlier one.
template <class Tr, class Bare_point>
void insert_mapped_Delaunay(Tr& tr, const std::vector<Bare_point>& points, const Eigen::Matrix3d& map,
                            std::vector<typename Tr::Vertex_handle>& vertex)
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
  typedef CGAL::Triangulation_vertex_base_with_info_3<std::size_t, EK> Vb;
  typedef CGAL::Delaunay_triangulation_3<EK, CGAL::Triangulation_data_structure_3<Vb>> Mapped;
  std::vector<std::pair<EK::Point_3, std::size_t>> mapped;
  mapped.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    const EK::FT x(points[i].x()), y(points[i].y()), z(points[i].z());
    auto row = [&](int r) { return EK::FT(map(r, 0)) * x + EK::FT(map(r, 1)) * y + EK::FT(map(r, 2)) * z; };
    mapped.emplace_back(EK::Point_3(row(0), row(1), row(2)), i);
  }
  const Mapped dt(mapped.begin(), mapped.end());
  typedef typename Tr::Vertex Vertex;
  typedef typename Tr::Cell Cell;
  typedef typename Tr::Geom_traits::Weighted_point_3 Weighted_point;
  std::unordered_map<const Vertex*, std::size_t> particle_of;
  const auto* infinite = &*dt.infinite_vertex();
  struct Convert_vertex
  {
    const std::vector<Bare_point>& points;
    const typename Mapped::Vertex* infinite;
    std::unordered_map<const Vertex*, std::size_t>& particle_of;
    Vertex operator()(const typename Mapped::Vertex& v) const
    {
      Vertex t;
      CGAL::Time_stamper<Vertex>::initialize_time_stamp(&t); // Mesh_3's default constructors leave it unset
      if(&v != infinite) t.set_point(Weighted_point(points[v.info()], 0));
      return t;
    }
    void operator()(const typename Mapped::Vertex& v, Vertex& t) const
    {
      if(&v != infinite) particle_of[&t] = v.info();
    }
  };
  struct Convert_cell
  {
    Cell operator()(const typename Mapped::Cell&) const
    {
      Cell c;
      CGAL::Time_stamper<Cell>::initialize_time_stamp(&c);
      return c;
    }
    void operator()(const typename Mapped::Cell&, Cell&) const {}
  };
  tr.clear();
  tr.set_infinite_vertex(tr.tds().copy_tds(dt.tds(), dt.infinite_vertex(), Convert_vertex{points, infinite, particle_of},
                                           Convert_cell()));
  vertex.assign(points.size(), typename Tr::Vertex_handle());
  for(auto v : tr.finite_vertex_handles()) vertex[particle_of.at(&*v)] = v;
}

/// `delaunay_map`: the tets are the Delaunay tets of the particles mapped by this linear map
/// (with a positive determinant; e.g. the square root of the field's mean metric, so that the
/// cells of a sheared or stretched lattice are not crossed), back at their own places.
/// `frame_inverse`: the field's \f$ B \f$, in whose space a boundary cell is flat or not (a
/// lattice cell stretched 80 times along x is flat in Euclidean space, not in the field's).
template <class C3T3, class MeshDomain, class Boundary, class Point_3>
Complex_report connect_particles(C3T3& c3t3, const MeshDomain& domain, const Boundary& boundary,
                                 const Lattice_particles_3<Point_3>& particles,
                                 const Eigen::Matrix3d& delaunay_map = Eigen::Matrix3d::Identity(),
                                 const Frame_inverse_function& frame_inverse = Frame_inverse_function())
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Geom_traits::Weighted_point_3 Weighted_point;
  typedef typename Tr::Geom_traits::Point_3 Bare_point;
  typedef typename MeshDomain::Subdomain_index Subdomain_index;

  Complex_report report;
  c3t3.clear();
  Tr& tr = c3t3.triangulation();
  const std::size_t n = particles.size();
  // Hilbert order for insertion speed, handles kept per particle
  std::vector<Bare_point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d p(particles.points[i].x(), particles.points[i].y(), particles.points[i].z());
    // sharp-edge particles sit on the sampled chords: put them on the domain's curve itself
    if(particles.kinds[i] == Particle_kind::SHARP_EDGE) p = boundary.point_on_curve(p);
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  typedef CGAL::Spatial_sort_traits_adapter_3<typename Tr::Geom_traits,
      typename CGAL::Pointer_property_map<Bare_point>::const_type> Sort_traits;
  const std::vector<Bare_point>& cpoints = points;
  CGAL::spatial_sort(order.begin(), order.end(), Sort_traits(CGAL::make_property_map(cpoints)));
  std::vector<Vertex_handle> vertex(n);
  const bool mapped = !delaunay_map.isIdentity(0);
  if(mapped)
    insert_mapped_Delaunay(tr, points, delaunay_map, vertex);
  else {
    Cell_handle hint;
    for(std::size_t i : order) {
      vertex[i] = tr.insert(Weighted_point(points[i], 0), hint);
      if(vertex[i] != Vertex_handle()) hint = vertex[i]->cell();
    }
  }
  std::map<Vertex_handle, std::size_t> particle_of;
  for(std::size_t i = 0; i < n; ++i) {
    if(vertex[i] == Vertex_handle()) { // left out by the mapped Delaunay: at the place of another
      ++report.number_of_merged_particles;
      continue;
    }
    if(!particle_of.emplace(vertex[i], i).second) ++report.number_of_merged_particles;
  }
  report.number_of_vertices = tr.number_of_vertices();
  if(tr.dimension() < 3) return report;

  auto eig = [&](const Vertex_handle& v) {
    const auto& p = tr.geom_traits().construct_point_3_object()(tr.point(v));
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  auto kind = [&](const Vertex_handle& v) {
    auto it = particle_of.find(v);
    return it == particle_of.end() ? Particle_kind::FREE : particles.kinds[it->second];
  };
  auto is_flat_in_field = [&](std::array<Eigen::Vector3d, 4> p) {
    if(frame_inverse) {
      const Eigen::Matrix3d B = frame_inverse(0.25 * (p[0] + p[1] + p[2] + p[3]));
      for(Eigen::Vector3d& q : p) q = B * q;
    }
    return is_flat(p);
  };
  // cells: the subdomain at the centroid, except the flat cells of boundary particles lying
  // on the surface (four particles of a planar patch), whose centroid is on it too
  const auto is_in = domain.is_in_domain_object();
  std::vector<Cell_handle> cells;
  for(Cell_handle c : tr.finite_cell_handles()) cells.push_back(c);
  std::vector<Eigen::Vector3d> centroid(cells.size());
  std::vector<char> flat_on_surface(cells.size(), 0);
  VVM::internal::parallel_for_each_index(cells.size(), [&](std::size_t i) {
    const Cell_handle c = cells[i];
    std::array<Eigen::Vector3d, 4> p;
    bool all_boundary = true;
    for(int k = 0; k < 4; ++k) {
      p[k] = eig(c->vertex(k));
      all_boundary = all_boundary && kind(c->vertex(k)) != Particle_kind::FREE;
    }
    const Eigen::Vector3d g = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    centroid[i] = g;
    if(all_boundary && is_flat_in_field(p)) {
      double longest = 0;
      for(int a = 0; a < 4; ++a)
        for(int b = a + 1; b < 4; ++b) longest = (std::max)(longest, (p[a] - p[b]).norm());
      flat_on_surface[i] = boundary.closest_on_surface(g).distance < 0.05 * longest;
    }
  });
  std::vector<Subdomain_index> subdomain(cells.size(), Subdomain_index());
  auto subdomain_of_cell = [&](std::size_t i) {
    if(flat_on_surface[i]) return;
    const Eigen::Vector3d& g = centroid[i];
    const auto s = is_in(typename MeshDomain::Point_3(g[0], g[1], g[2]));
    if(s) subdomain[i] = *s;
  };
  if constexpr(has_thread_safe_inside<MeshDomain>)
    VVM::internal::parallel_for_each_index(cells.size(), subdomain_of_cell);
  else
    for(std::size_t i = 0; i < cells.size(); ++i) subdomain_of_cell(i);
  for(std::size_t i = 0; i < cells.size(); ++i)
    if(subdomain[i] != Subdomain_index()) {
      c3t3.add_to_complex(cells[i], subdomain[i]);
      ++report.number_of_cells;
    }
  // Flat cells of boundary particles (four particles of a planar face, or a sliver across
  // a curved boundary) with a facet on the boundary are outside: peel them, layer by layer.
  auto label = [&](const Cell_handle& c) {
    return (!tr.is_infinite(c) && c3t3.is_in_complex(c)) ? c3t3.subdomain_index(c) : Subdomain_index();
  };
  for(int pass = 0; pass < 100; ++pass) {
    std::vector<Cell_handle> peel;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      bool all_boundary = true, on_boundary = false;
      for(int k = 0; k < 4; ++k) {
        all_boundary = all_boundary && kind(c->vertex(k)) != Particle_kind::FREE;
        on_boundary = on_boundary || label(c->neighbor(k)) != c3t3.subdomain_index(c);
      }
      if(!all_boundary || !on_boundary) continue;
      std::array<Eigen::Vector3d, 4> p;
      for(int k = 0; k < 4; ++k) p[k] = eig(c->vertex(k));
      if(is_flat_in_field(p)) peel.push_back(c);
    }
    for(const Cell_handle& c : peel) c3t3.remove_from_complex(c);
    report.number_of_peeled_cells += peel.size();
    report.number_of_cells -= peel.size();
    if(peel.empty()) break;
  }
  // a cell whose four neighbours are all outside hangs on the mesh by an edge or a vertex
  // (a non-manifold boundary): outside too
  {
    std::vector<Cell_handle> isolated;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      int outside = 0;
      for(int k = 0; k < 4; ++k) outside += label(c->neighbor(k)) != c3t3.subdomain_index(c);
      if(outside == 4) isolated.push_back(c);
    }
    for(const Cell_handle& c : isolated) c3t3.remove_from_complex(c);
    report.number_of_isolated_cells = isolated.size();
    report.number_of_cells -= isolated.size();
  }
  // surface facets: between cells of different subdomains (outside included)
  std::vector<typename Tr::Facet> surface_facets;
  for(auto f : tr.finite_facets())
    if(label(f.first) != label(f.first->neighbor(f.second))) surface_facets.push_back(f);
  std::vector<int> patch(surface_facets.size());
  VVM::internal::parallel_for_each_index(surface_facets.size(), [&](std::size_t i) {
    const auto& f = surface_facets[i];
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for(int k = 1; k <= 3; ++k) g += eig(f.first->vertex((f.second + k) & 3)) / 3.;
    patch[i] = boundary.closest_on_surface(g).feature;
  });
  for(std::size_t i = 0; i < surface_facets.size(); ++i)
    c3t3.add_to_complex(surface_facets[i], boundary.patch_indices()[std::size_t(patch[i])]);
  report.number_of_surface_facets += surface_facets.size();
  // feature edges: Delaunay edges between sharp-edge or corner particles along a sharp edge
  auto on_feature = [&](Particle_kind k) { return k == Particle_kind::SHARP_EDGE || k == Particle_kind::CORNER; };
  std::map<Vertex_handle, int> curve_of;
  if constexpr(CGAL::Mesh_3::internal::Has_features<MeshDomain>::value)
  if(boundary.has_sharp_edges()) {
    for(auto e : tr.finite_edges()) {
      const Vertex_handle u = e.first->vertex(e.second), v = e.first->vertex(e.third);
      if(!on_feature(kind(u)) || !on_feature(kind(v))) continue;
      const Eigen::Vector3d a = eig(u), b = eig(v);
      const auto c = boundary.closest_on_sharp_edge(0.5 * (a + b));
      if(c.distance > 0.1 * (b - a).norm()) continue;
      // the edge's curve must be the sharp-edge endpoints' own
      bool same = true;
      for(const Vertex_handle& w : {u, v})
        if(kind(w) == Particle_kind::SHARP_EDGE && particles.features[particle_of[w]] != c.feature) same = false;
      if(!same) continue;
      // and it must be on the boundary: two surface facets around it, at least
      int facets = 0;
      auto first = tr.incident_cells(e), cell = first;
      do {
        auto next = cell;
        ++next;
        if(label(cell) != label(next)) ++facets;
        cell = next;
      } while(cell != first);
      if(facets < 2) continue;
      c3t3.add_to_complex(u, v, boundary.curve_indices()[std::size_t(c.feature)]);
      curve_of[u] = curve_of[v] = c.feature;
      ++report.number_of_feature_edges;
    }
  }
  // vertex dimensions and indices, as Mesh_3 sets them
  std::set<Vertex_handle> on_surface;
  std::map<Vertex_handle, Subdomain_index> subdomain_of;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int k = 0; k < 4; ++k) subdomain_of.emplace(c->vertex(k), c3t3.subdomain_index(c));
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    const auto spi = c3t3.surface_patch_index(*f);
    for(int k = 1; k <= 3; ++k) {
      const Vertex_handle v = f->first->vertex((f->second + k) & 3);
      on_surface.insert(v);
      c3t3.set_dimension(v, 2);
      c3t3.set_index(v, domain.index_from_surface_patch_index(spi));
    }
  }
  for(const Vertex_handle& v : on_surface) {
    auto it = particle_of.find(v);
    if(it != particle_of.end() && particles.kinds[it->second] == Particle_kind::FREE)
      report.exposed_free_particles.push_back(it->second);
  }
  std::sort(report.exposed_free_particles.begin(), report.exposed_free_particles.end());
  for(Vertex_handle v : tr.finite_vertex_handles()) {
    if(on_surface.count(v)) continue;
    c3t3.set_dimension(v, 3);
    auto it = subdomain_of.find(v);
    c3t3.set_index(v, domain.index_from_subdomain_index(it == subdomain_of.end() ? Subdomain_index() : it->second));
  }
  if constexpr(CGAL::Mesh_3::internal::Has_features<MeshDomain>::value) {
    for(const auto& vc : curve_of) {
      c3t3.set_dimension(vc.first, 1);
      c3t3.set_index(vc.first, domain.index_from_curve_index(boundary.curve_indices()[std::size_t(vc.second)]));
    }
    for(const auto& vp : particle_of) {
      if(particles.kinds[vp.second] != Particle_kind::CORNER || !on_surface.count(vp.first)) continue;
      const auto ci = boundary.corner_indices()[std::size_t(particles.features[vp.second])];
      c3t3.add_to_complex(vp.first, ci);
      c3t3.set_dimension(vp.first, 0);
      c3t3.set_index(vp.first, domain.index_from_corner_index(ci));
    }
  }
  return report;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_PARTICLE_COMPLEX_H
