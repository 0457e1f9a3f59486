// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of Tetrahedral_lattice_meshing that CGAL's central list
// does not have (CGAL 5.5.1 offers no hook to add names to CGAL::parameters);
// each has an overload that appends it to an existing pack:
//
//   namespace TLM = CGAL::Tetrahedral_lattice_meshing;
//   CGAL::lattice_particles_3(domain, field,
//       TLM::parameters::lattice(TLM::Lattice_type::FCC,
//           TLM::parameters::edge_length(0.1, CGAL::parameters::random_seed(7))));

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_PARAMETERS_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_PARAMETERS_H

#include <CGAL/VVM/internal/add_named_parameter.h>
#include <CGAL/VVM/parameters.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal_np {

enum lattice_t { lattice };
enum edge_length_t { edge_length };
enum number_of_particles_t { number_of_particles };
enum kernel_width_t { kernel_width };
enum neighbor_radius_t { neighbor_radius };
enum multiresolution_levels_t { multiresolution_levels };
enum mesh_optimization_t { mesh_optimization };

} // namespace internal_np

namespace parameters {

/// `Lattice_type`: BCC (default), FCC or CUBIC
CGAL_VVM_ADD_NAMED_PARAMETER(lattice)
/// `double`: \f$ l^* \f$, the cube edge of the lattice in the imagined space
CGAL_VVM_ADD_NAMED_PARAMETER(edge_length)
/// `std::size_t`: the number of particles sought (sets \f$ l^* \f$ from the domain's imagined volume)
CGAL_VVM_ADD_NAMED_PARAMETER(number_of_particles)
/// `double`: \f$ \sigma \f$ in units of \f$ l^* \f$ (default: 0.3 \f$ l_{closest} \f$; cubic 0.3)
CGAL_VVM_ADD_NAMED_PARAMETER(kernel_width)
/// `double`: the neighbour radius \f$ R \f$ in units of \f$ l^* \f$ (default 1.3; cubic 1.5)
CGAL_VVM_ADD_NAMED_PARAMETER(neighbor_radius)
/// `int`: \f$ k \f$, the particles are first optimized at \f$ 2^k l^* \f$ (default: BCC and FCC from
/// \f$ k_0 + 1 \f$ and \f$ k_0 = \lceil \log_8 (n / 2000) \rceil \f$ levels, the lower energy kept, see
/// `lattice_particles_3()`; cubic: 2 from 3,200 particles, 1 from 400)
CGAL_VVM_ADD_NAMED_PARAMETER(multiresolution_levels)
/// `int`: the number of threads (default 0: TBB's choice); the result does not depend on it
using VVM::parameters::number_of_threads;
/// a model of `FrameField_3` (or a `std::reference_wrapper` to one): the field the lattice follows, in
/// the overloads without a positional field (default: the domain's boundary-aligned cross field)
using VVM::parameters::frame_field;
/// `Lattice_mesh_optimization`: how `make_lattice_mesh_3()` ends (default `FLIPS`)
CGAL_VVM_ADD_NAMED_PARAMETER(mesh_optimization)
/// `Lattice_mesh_report*`: receives what `make_lattice_mesh_3()` did (default: none)
using VVM::parameters::report;
/// the former name of `report`
CGAL_VVM_ADD_DEPRECATED_NAMED_PARAMETER(mesh_report, report)

} // namespace parameters
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_PARAMETERS_H
