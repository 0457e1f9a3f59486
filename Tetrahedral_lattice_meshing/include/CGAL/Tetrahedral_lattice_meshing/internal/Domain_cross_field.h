// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The frame field used when the caller gives none: the boundary-aligned cross
// field of generate_cross_field_3() on a make_mesh_3() mesh of the domain.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_CROSS_FIELD_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_CROSS_FIELD_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Domain_boundary.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/Frame_fields/scale_corrected_frame_field.h>

#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Random.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Reproducible_sampling.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <stdexcept>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/*
 * The share of the bounding box of `domain` that lies inside it: one point drawn at random
 * (fixed seed) in each cell of a 16^3 grid over the box, so that walls parallel to the box's
 * faces are not missed or hit as a whole; at least one point counts (a domain thinner than the
 * grid then gets the share of one cell).
 */
template <class MeshDomain>
double domain_volume_fraction(const MeshDomain& domain)
{
  typedef typename MeshDomain::R::Point_3 Point_3;
  const CGAL::Bbox_3 bb = domain.bbox();
  const auto is_in_domain = domain.is_in_domain_object();
  constexpr int n = 16;
  CGAL::Random random(0);
  auto at = [&](double lo, double hi, int i) { return lo + (i + random.get_double()) / n * (hi - lo); };
  int inside = 0;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      for(int k = 0; k < n; ++k)
        if(is_in_domain(Point_3(at(bb.xmin(), bb.xmax(), i), at(bb.ymin(), bb.ymax(), j), at(bb.zmin(), bb.zmax(), k))))
          ++inside;
  return double((std::max)(inside, 1)) / (n * n * n);
}

/*
 * The cross field of `domain` (unit frames: rotations), on a mesh of edges
 * about `size` long, with an axis on the normal of the boundary and along its
 * feature curves. It does not depend on the process's history (seeded mesher).
 * `time_limit` (seconds from the call, 0: none) stops the field's smoothing rounds;
 * the mesh and the least-squares solve always run. With `maximum_scale_ratio` > 1,
 * the frames are then scaled so that a lattice can follow the field's turning
 * (`Frame_fields::scale_corrected_frame_field()`, scales within that ratio), unless
 * the time limit is already reached: the field is then left as it is.
 */
template <class MeshDomain>
Frame_fields::Discrete_frame_field_3<typename Kernel_traits<typename MeshDomain::R::Point_3>::Kernel>
domain_cross_field(const MeshDomain& domain, double size, double time_limit = 0, double maximum_scale_ratio = 1)
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
  auto field = Frame_fields::generate_cross_field_3(c3t3, P::maximum_running_time(limit.remaining())).field;
  if(maximum_scale_ratio > 1 && !limit.is_reached())
    field = Frame_fields::scale_corrected_frame_field(field, Frame_fields::parameters::maximum_size_ratio(maximum_scale_ratio))
                .field;
  return field;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_CROSS_FIELD_H
