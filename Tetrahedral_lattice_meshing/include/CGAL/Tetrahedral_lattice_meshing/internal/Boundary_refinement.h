// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The boundary refinement of dissertation section 4.4.2: surface points are
// added to the particles where the tets' boundary is farther than a threshold
// from the domain's surface (facets cutting a curved patch or a sharp edge) or
// the surface farther than it from the tets' boundary (cut corners and edges),
// and the particles are connected again, until the distance is under the
// threshold both ways or a few rounds are done.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_BOUNDARY_REFINEMENT_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_BOUNDARY_REFINEMENT_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Lattice_connection.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/// adds surface points and connects the particles again (see above), `cr` the last connection's
/// report; returns the points added
template <class C3T3, class MeshDomain>
std::size_t refine_boundary(C3T3& c3t3, const MeshDomain& domain, Particles_in_domain<MeshDomain>& pd,
                            double threshold, const Eigen::Matrix3d& delaunay_map,
                            const Frame_inverse_function& frame_inverse, std::size_t& number_of_projected_particles,
                            Complex_report& cr, int max_rounds = 4)
{
  namespace TLM = Tetrahedral_lattice_meshing;
  typedef typename MeshDomain::R K;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Triangle_3 Triangle_3;
  typedef typename std::vector<Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator>>> Tree;
  const auto& boundary = *pd.boundary;
  auto& particles = pd.particles;
  auto eig = [](const Point_3& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); };
  std::size_t added_total = 0;
  for(int round = 0; round < max_rounds; ++round) {
    // the tets' boundary facets, and the gap kept between added points: a third of their edges
    std::vector<Triangle_3> facets;
    double edge_sum = 0;
    const auto& tr = c3t3.triangulation();
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
      std::array<Point_3, 3> p;
      for(int k = 0; k < 3; ++k)
        p[std::size_t(k)] = tr.geom_traits().construct_point_3_object()(tr.point(f->first->vertex((f->second + k + 1) & 3)));
      facets.emplace_back(p[0], p[1], p[2]);
      edge_sum += std::sqrt(CGAL::squared_distance(p[0], p[1]));
    }
    if(facets.empty()) break;
    const double gap = edge_sum / double(facets.size()) / 3.;
    // a hash grid of cell `gap` over the particles and the points added, to keep them apart
    std::unordered_map<std::int64_t, std::vector<Eigen::Vector3d>> grid;
    auto key = [gap](const Eigen::Vector3d& p, int dx, int dy, int dz) {
      const std::int64_t i = std::int64_t(std::floor(p[0] / gap)) + dx, j = std::int64_t(std::floor(p[1] / gap)) + dy,
                         k = std::int64_t(std::floor(p[2] / gap)) + dz;
      return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
    };
    for(const Point_3& p : particles.points) grid[key(eig(p), 0, 0, 0)].push_back(eig(p));
    std::size_t added = 0;
    auto add = [&](const Eigen::Vector3d& x) {
      for(int dx = -1; dx <= 1; ++dx)
        for(int dy = -1; dy <= 1; ++dy)
          for(int dz = -1; dz <= 1; ++dz) {
            auto it = grid.find(key(x, dx, dy, dz));
            if(it == grid.end()) continue;
            for(const Eigen::Vector3d& q : it->second)
              if((q - x).norm() < gap) return;
          }
      grid[key(x, 0, 0, 0)].push_back(x);
      // on a sharp edge if the surface point is one of its points, else on the surface
      TLM::Particle_kind kind = TLM::Particle_kind::BOUNDARY;
      int feature = boundary.closest_on_surface(x).feature;
      if(boundary.has_sharp_edges()) {
        const auto e = boundary.closest_on_sharp_edge(x);
        if(e.distance < 1e-3 * gap) kind = TLM::Particle_kind::SHARP_EDGE, feature = e.feature;
      }
      particles.points.emplace_back(x[0], x[1], x[2]);
      particles.kinds.push_back(kind);
      particles.features.push_back(feature);
      ++added;
    };
    // the tets' boundary far from the surface: the surface point nearest to the facet's centroid
    // or edge midpoints
    for(const Triangle_3& t : facets) {
      const Eigen::Vector3d a = eig(t[0]), b = eig(t[1]), c = eig(t[2]);
      for(const Eigen::Vector3d& x : {Eigen::Vector3d((a + b + c) / 3.), Eigen::Vector3d((a + b) / 2.),
                                      Eigen::Vector3d((b + c) / 2.), Eigen::Vector3d((c + a) / 2.)}) {
        const auto s = boundary.closest_on_surface(x);
        if(s.distance > threshold) add(s.point);
      }
    }
    // the surface far from the tets' boundary: points of the sampled surface's triangles, of its
    // sharp edges and corners
    Tree tree(facets.cbegin(), facets.cend());
    tree.accelerate_distance_queries();
    auto far = [&](const Eigen::Vector3d& x) {
      return tree.squared_distance(Point_3(x[0], x[1], x[2])) > threshold * threshold;
    };
    for(const auto& t : boundary.triangles()) { // corners, edge midpoints, centroid, and between
      const Eigen::Vector3d a = eig(t[0]), b = eig(t[1]), c = eig(t[2]), g = (a + b + c) / 3.;
      for(const Eigen::Vector3d& x : {a, b, c, Eigen::Vector3d((a + b) / 2.), Eigen::Vector3d((b + c) / 2.),
                                      Eigen::Vector3d((c + a) / 2.), g, Eigen::Vector3d((a + g) / 2.),
                                      Eigen::Vector3d((b + g) / 2.), Eigen::Vector3d((c + g) / 2.)})
        if(far(x)) add(boundary.closest_on_surface(x).point);
    }
    for(const auto& s : boundary.segments())
      for(const Eigen::Vector3d& x : {eig(s[0]), eig(s[1]), Eigen::Vector3d((eig(s[0]) + eig(s[1])) / 2.)})
        if(far(x)) add(x);
    if(added == 0) break;
    added_total += added;
    cr = connect_lattice_particles(c3t3, domain, pd, number_of_projected_particles, delaunay_map, frame_inverse);
  }
  return added_total;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_BOUNDARY_REFINEMENT_H
