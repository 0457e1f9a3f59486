// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The particles of a lattice connected into a complex (`connect_particles()`),
// with the free particles that the complex leaves on its boundary put onto the
// surface first.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_LATTICE_CONNECTION_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_LATTICE_CONNECTION_H

#include <CGAL/lattice_particles_3.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_complex.h>

#include <Eigen/Core>

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/// the particles connected into `c3t3` (`connect_particles()`); free particles the complex
/// leaves on its boundary (under a hole of the boundary layer) would make tents off the
/// surface: they go onto the surface and the particles are connected again
template <class C3T3, class MeshDomain>
Complex_report connect_lattice_particles(C3T3& c3t3, const MeshDomain& domain, Particles_in_domain<MeshDomain>& pd,
                                         std::size_t& number_of_projected_particles,
                                         const Eigen::Matrix3d& delaunay_map = Eigen::Matrix3d::Identity(),
                                         const Frame_inverse_function& frame_inverse = Frame_inverse_function())
{
  Complex_report cr = connect_particles(c3t3, domain, *pd.boundary, pd.particles, delaunay_map, frame_inverse);
  for(int pass = 0; pass < 3 && !cr.exposed_free_particles.empty(); ++pass) {
    for(std::size_t i : cr.exposed_free_particles) {
      auto& p = pd.particles.points[i];
      const auto c = pd.boundary->closest_on_surface(Eigen::Vector3d(p.x(), p.y(), p.z()));
      p = std::decay_t<decltype(p)>(c.point[0], c.point[1], c.point[2]);
      pd.particles.kinds[i] = Particle_kind::BOUNDARY;
      pd.particles.features[i] = c.feature;
    }
    number_of_projected_particles += cr.exposed_free_particles.size();
    cr = connect_particles(c3t3, domain, *pd.boundary, pd.particles, delaunay_map, frame_inverse);
  }
  return cr;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_LATTICE_CONNECTION_H
