// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The frame field used when the caller gives none: the boundary-aligned cross
// field of generate_cross_field_3() on a make_mesh_3() mesh of the domain.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_CROSS_FIELD_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_CROSS_FIELD_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Domain_boundary.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>

#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Reproducible_sampling.h>
#include <CGAL/make_mesh_3.h>

#include <stdexcept>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/*
 * The cross field of `domain` (unit frames: rotations), on a mesh of edges
 * about `size` long, with an axis on the normal of the boundary and along its
 * feature curves. It does not depend on the process's history (seeded mesher).
 * `time_limit` (seconds from the call, 0: none) stops the field's smoothing rounds;
 * the mesh and the least-squares solve always run.
 */
template <class MeshDomain>
Frame_fields::Discrete_frame_field_3<typename Kernel_traits<typename MeshDomain::R::Point_3>::Kernel>
domain_cross_field(const MeshDomain& domain, double size, double time_limit = 0)
{
  const VVM::internal::Time_limit limit(time_limit);
  namespace P = CGAL::parameters;
  typedef typename Sampling_complex<MeshDomain>::type C3T3;
  typedef CGAL::Mesh_criteria_3<typename C3T3::Triangulation> Criteria;
  if(!(size > 0) || !std::isfinite(size))
    throw std::invalid_argument("the cross field's mesh size must be positive and finite");
  Criteria criteria(P::edge_size = size, P::facet_angle = 25, P::facet_size = size,
                    P::facet_distance = 0.05 * size, P::cell_radius_edge_ratio = 3, P::cell_size = size);
  C3T3 c3t3;
  {
    const Reproducible_sampling reproducible(domain);
    c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria, P::no_perturb(), P::no_exude());
  }
  if(c3t3.number_of_cells_in_complex() == 0)
    throw std::invalid_argument("the domain is empty: no cell to carry a cross field");
  return Frame_fields::generate_cross_field_3(c3t3, P::maximum_running_time(limit.remaining())).field;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_CROSS_FIELD_H
