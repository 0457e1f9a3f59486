// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters shared by the three VVM packages that CGAL's central list
// does not have: each is declared here once, and the packages' own
// `parameters` namespaces re-export those they take, so that one pack serves
// every entry point (`number_of_threads`, `frame_field`, `report`). Also those of the
// local thickness of a surface and of the sizing field made from it.
//
//   namespace VVM = CGAL::VVM;
//   CGAL::Thickness_sizing_field_3<K> size(thickness,
//       VVM::parameters::cells_across(3, VVM::parameters::gradation(0.3)));

#ifndef CGAL_VVM_PARAMETERS_H
#define CGAL_VVM_PARAMETERS_H

#include <CGAL/VVM/internal/add_named_parameter.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace VVM {
namespace internal_np {

enum number_of_threads_t { number_of_threads };
enum report_t { report };
enum frame_field_t { frame_field };
enum cells_across_t { cells_across };
enum minimum_size_t { minimum_size };
enum maximum_size_t { maximum_size };
enum gradation_t { gradation };
enum sample_spacing_t { sample_spacing };
enum cone_angle_t { cone_angle };

} // namespace internal_np

namespace parameters {

/// `int`: the number of threads of the parallel loops (default 0: TBB's choice); the results do not
/// depend on it
CGAL_VVM_ADD_NAMED_PARAMETER(number_of_threads)
/// a model of `FrameField_3`, or a `std::reference_wrapper` to one: the frame field that a lattice
/// follows or in whose space cells are measured
CGAL_VVM_ADD_NAMED_PARAMETER(frame_field)
/// a pointer to the entry point's report struct (`GSM_mesh_optimization::Optimization_report*`,
/// `Tetrahedral_lattice_meshing::Lattice_mesh_report*`, `Hex_dominant_meshing::Hex_dominant_report*`,
/// `Hex_dominant_meshing::Hex_dominant_merge_report*`): receives what the call did
CGAL_VVM_ADD_NAMED_PARAMETER(report)
/// `double`: the number of cells a wall (or a gap) holds across its thickness
CGAL_VVM_ADD_NAMED_PARAMETER(cells_across)
/// `double`: the smallest size a sizing field gives
CGAL_VVM_ADD_NAMED_PARAMETER(minimum_size)
/// `double`: the largest size a sizing field gives
CGAL_VVM_ADD_NAMED_PARAMETER(maximum_size)
/// `double`: how fast a size may grow with the distance (the size's Lipschitz constant)
CGAL_VVM_ADD_NAMED_PARAMETER(gradation)
/// `double`: the distance between two points where a surface is sampled
CGAL_VVM_ADD_NAMED_PARAMETER(sample_spacing)
/// `double`: the opening angle, in degrees, of the cone of rays cast from a surface point
CGAL_VVM_ADD_NAMED_PARAMETER(cone_angle)

} // namespace parameters
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_PARAMETERS_H
