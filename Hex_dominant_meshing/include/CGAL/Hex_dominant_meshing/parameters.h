// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of Hex_dominant_meshing that CGAL's central list does not
// have; each has an overload that appends it to an existing pack:
//
//   namespace HDM = CGAL::Hex_dominant_meshing;
//   CGAL::tets_to_hex_dominant(c3t3, HDM::parameters::quality_bound(0.6,
//       HDM::parameters::cell_types(HDM::Cell_types::HEXAHEDRA_AND_PRISMS)));
//
// make_hex_dominant_mesh_3() also takes those of Tetrahedral_lattice_meshing
// (edge_length, number_of_particles, number_of_threads, ...).

#ifndef CGAL_HEX_DOMINANT_MESHING_PARAMETERS_H
#define CGAL_HEX_DOMINANT_MESHING_PARAMETERS_H

#include <CGAL/VVM/internal/add_named_parameter.h>
#include <CGAL/VVM/parameters.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Hex_dominant_meshing {

/// \ingroup PkgHexDominantMeshingRef
/// which cells the tets may merge into (the rest stay tetrahedra)
enum class Cell_types
{
  HEXAHEDRA,             ///< hexahedra only
  HEXAHEDRA_AND_PRISMS,  ///< hexahedra, then prisms
  ALL                    ///< hexahedra, then prisms, then pyramids (default)
};

namespace internal_np {

enum quality_bound_t { quality_bound };
enum cell_types_t { cell_types };
enum stage_visitor_t { stage_visitor };
enum tetrahedral_mesh_t { tetrahedral_mesh };
enum boundary_distance_t { boundary_distance };

} // namespace internal_np

namespace parameters {

/// `double`: \f$ Q_{bound} \f$, the merging quality under which no cell is made (default 0.5)
CGAL_VVM_ADD_NAMED_PARAMETER(quality_bound)
/// `Cell_types`: which cells the tets merge into (default `ALL`)
CGAL_VVM_ADD_NAMED_PARAMETER(cell_types)
/// a `FrameField_3`: the qualities are measured in its space (default: the identity); the
/// field of the lattice in `make_hex_dominant_mesh_3()` (default: the domain's cross field)
using VVM::parameters::frame_field;
/// `Hex_dominant_report*` (`make_hex_dominant_mesh_3()`) or `Hex_dominant_merge_report*`
/// (`tets_to_hex_dominant()`): receives what the call did (default: none)
using VVM::parameters::report;
/// the former names of `report`
CGAL_VVM_ADD_DEPRECATED_NAMED_PARAMETER(merge_report, report)
CGAL_VVM_ADD_DEPRECATED_NAMED_PARAMETER(hex_dominant_report, report)
/// deprecated, use `visitor` (its `VVM::Stage_report`s): a callable
/// `void(Hex_dominant_stage, double seconds)` called after each stage of `make_hex_dominant_mesh_3()`
CGAL_VVM_ADD_NAMED_PARAMETER(stage_visitor)
/// `C3T3*`: receives the tets `make_hex_dominant_mesh_3()` merged (default: none)
CGAL_VVM_ADD_NAMED_PARAMETER(tetrahedral_mesh)
/// `double`: the boundary refinement's threshold on the distance between the tets' boundary and
/// the domain's surface (default 0: no refinement)
CGAL_VVM_ADD_NAMED_PARAMETER(boundary_distance)

} // namespace parameters
} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_PARAMETERS_H
