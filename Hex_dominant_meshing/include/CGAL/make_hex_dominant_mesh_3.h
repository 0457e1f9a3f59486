// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::make_hex_dominant_mesh_3(): cubic-lattice particles aligned with a
// frame field, their tets, merged into hexahedra, prisms and pyramids
// (dissertation 4.4).

#ifndef CGAL_MAKE_HEX_DOMINANT_MESH_3_H
#define CGAL_MAKE_HEX_DOMINANT_MESH_3_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Frame_fields/parameters.h>
#include <CGAL/Hex_dominant_meshing/parameters.h>
#include <CGAL/tets_to_hex_dominant.h>
#include <CGAL/VVM/internal/Lattice_tetrahedralization.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Hex_dominant_meshing {

/// \ingroup PkgHexDominantMeshingRef
/// the stages of `make_hex_dominant_mesh_3()`, as its deprecated `stage_visitor` sees them
/// (the `visitor` sees them as `VVM::Stage`)
enum class Hex_dominant_stage
{
  PARTICLES,   ///< the cubic-lattice particles are placed
  TETRAHEDRA,  ///< the particles are connected into tets
  MERGING      ///< the tets are merged
};

/// \ingroup PkgHexDominantMeshingRef
/// what `make_hex_dominant_mesh_3()` did, for its `report` output
struct Hex_dominant_report
{
  std::size_t number_of_particles = 0;
  double edge_length = 0;            ///< \f$ l^* \f$
  std::size_t number_of_projected_particles = 0; ///< free particles the tets left on the boundary, put onto it
  std::size_t number_of_boundary_points = 0; ///< surface points added by the boundary refinement
  std::size_t number_of_metric_flips = 0; ///< flips that made the tets Delaunay in the field's space
  double particle_time = 0;          ///< seconds
  double tetrahedra_time = 0;        ///< seconds
  double merge_time = 0;             ///< seconds
  Hex_dominant_merge_report merge;   ///< what the merging did
  /// `maximum_running_time` stopped a stage (the particles' rounds, the merging's candidate
  /// search) or left no time for one (the boundary refinement, the flips): the mesh is valid
  bool time_limit_reached = false;
  /// a visitor returned `false`: the stages after it did only what a valid mesh needs
  /// (the particles connected into tets, which stay tetrahedra)
  bool stopped_by_visitor = false;
};

namespace internal {

template <class C3T3, class MeshDomain, class FrameField, class NamedParameters>
Hex_dominant_mesh_3<typename MeshDomain::R::Point_3>
make_hex_dominant_mesh(const MeshDomain& domain, const FrameField& field, const VVM::internal::Lattice_request& request,
                       const NamedParameters& np)
{
  namespace HDM = Hex_dominant_meshing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  HDM::Hex_dominant_report* report = choose_parameter(get_parameter(np, VVM::internal_np::report),
                                                      static_cast<HDM::Hex_dominant_report*>(nullptr));
  HDM::Hex_dominant_report local;
  HDM::Hex_dominant_report& r = report ? *report : local;
  r = HDM::Hex_dominant_report();
  const VVM::internal::Time_limit time_limit(request.options.maximum_running_time);
  auto visitor = get_parameter(np, CGAL::internal_np::visitor);
  VVM::internal::check_visitor<decltype(visitor), Tetrahedral_lattice_meshing::Lattice_round_report>();
  auto v = get_parameter(np, HDM::internal_np::stage_visitor); // deprecated
  // the end of a stage, for the visitor (not after a stop) and the stage visitor (after
  // each stage, as it always was); false: one asks to stop
  auto visit_stage = [&](HDM::Hex_dominant_stage s, VVM::Stage stage, int rounds, double t, bool stopped) {
    bool go = stopped || VVM::internal::visit_stage_end(visitor, stage, rounds, time_limit.elapsed());
    if constexpr(!std::is_same<decltype(v), CGAL::internal_np::Param_not_found>::value)
      go = VVM::internal::visit(v, s, t) && go;
    return go;
  };

  VVM::internal::Lattice_tetrahedralization_options options;
  options.caller = "make_hex_dominant_mesh_3";
  options.boundary_distance = choose_parameter(get_parameter(np, HDM::internal_np::boundary_distance), 0.);
  options.for_tetrahedral_lattice = false;
  // the cells of the lattice are cubes in the field's space: the tets are made Delaunay there
  C3T3 c3t3;
  const VVM::internal::Lattice_tetrahedralization<MeshDomain> t = VVM::internal::lattice_tetrahedralization(
      c3t3, domain, field, request, time_limit, options,
      [&](const VVM::internal::Lattice_tetrahedralization_report& tr) {
        return visit_stage(HDM::Hex_dominant_stage::PARTICLES, VVM::Stage::PARTICLES, tr.number_of_particle_rounds,
                           tr.particle_time, tr.stopped_by_visitor);
      });
  VVM::internal::copy_shared_fields(t.report, r);
  r.tetrahedra_time = t.report.connection_time;
  r.number_of_boundary_points = t.report.number_of_boundary_points;
  if(!visit_stage(HDM::Hex_dominant_stage::TETRAHEDRA, VVM::Stage::TETRAHEDRA, 0, r.tetrahedra_time, r.stopped_by_visitor))
    r.stopped_by_visitor = true;
  // read from the merging's threads: no write to `r` here
  const std::function<bool()> must_stop = [&]() { return r.stopped_by_visitor || time_limit.is_reached(); };

  CGAL::Real_timer timer;
  timer.start();
  Tetrahedral_adjacency adjacency;
  std::vector<typename MeshDomain::R::Point_3> points;
  indexed_tets(c3t3, adjacency, points);
  // the merging's own time limit is the whole call's (`must_stop`)
  auto mesh = merge_tets(adjacency, std::move(points),
                         HDM::parameters::frame_field(std::cref(field), HDM::parameters::report(&r.merge, np)),
                         must_stop);
  if(r.merge.stopped && !r.stopped_by_visitor) r.time_limit_reached = true;
  r.merge_time = timer.time();
  if(!visit_stage(HDM::Hex_dominant_stage::MERGING, VVM::Stage::MERGING, 0, r.merge_time, r.stopped_by_visitor))
    r.stopped_by_visitor = true;
  C3T3* tets = choose_parameter(get_parameter(np, HDM::internal_np::tetrahedral_mesh), static_cast<C3T3*>(nullptr));
  if(tets) *tets = std::move(c3t3);
  return mesh;
}

template <class NamedParameters>
VVM::internal::Lattice_request read_hex_dominant_request(const NamedParameters& np)
{
  namespace TLM = Tetrahedral_lattice_meshing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(choose_parameter(get_parameter(np, TLM::internal_np::lattice), TLM::Lattice_type::CUBIC) != TLM::Lattice_type::CUBIC)
    throw std::invalid_argument("make_hex_dominant_mesh_3: hexahedra come from the cubic lattice (no BCC or FCC)");
  const double q_bound = choose_parameter(get_parameter(np, internal_np::quality_bound), 0.5);
  if(!(q_bound >= 0 && q_bound <= 1)) throw std::invalid_argument("make_hex_dominant_mesh_3: the quality bound must be in [0, 1]");
  const double boundary_distance = choose_parameter(get_parameter(np, internal_np::boundary_distance), 0.);
  if(!(boundary_distance >= 0) || !std::isfinite(boundary_distance))
    throw std::invalid_argument("make_hex_dominant_mesh_3: the boundary distance must be non-negative and finite");
  VVM::internal::Lattice_request r = VVM::internal::read_lattice_request(TLM::parameters::lattice(TLM::Lattice_type::CUBIC, np));
  r.maximum_scale_ratio = choose_parameter(get_parameter(np, Frame_fields::internal_np::maximum_size_ratio), 2.);
  if(!(r.maximum_scale_ratio >= 1) || !std::isfinite(r.maximum_scale_ratio))
    throw std::invalid_argument("make_hex_dominant_mesh_3: maximum_size_ratio must be at least 1 and finite");
  return r;
}

} // namespace internal
} // namespace Hex_dominant_meshing

/*!
 * \ingroup PkgHexDominantMeshingRef
 *
 * makes a hex-dominant mesh of `domain` aligned with the frame field `field` (dissertation
 * 4.4): particles placed by `lattice_particles_3()` with the cubic lattice (eq. 4.6, \f$ w = 1 \f$,
 * \f$ \sigma = 0.3 l^* \f$, \f$ R = 1.5 l^* \f$, the thresholds of Table 4.5; the number of
 * particles estimated from the domain's volume in the field's space), connected into tets as
 * `make_lattice_mesh_3()` does (CGAL's Delaunay triangulation, cells labelled by subdomain,
 * boundary facets, feature edges; the Delaunay tets of the particles mapped by the square
 * root of the field's mean metric), made Delaunay in the field's space by flips inside each
 * subdomain (the lattice's cells are cubes there, boxes or parallelepipeds in Euclidean space),
 * then merged by `tets_to_hex_dominant()` with the qualities measured in the field's space.
 *
 * \tparam C3T3 a `Mesh_complex_3_in_triangulation_3` of a `Mesh_triangulation_3` of `MeshDomain`,
 *   for the tets
 * \tparam MeshDomain a model of `MeshDomain_3` (or `MeshDomainWithFeatures_3`) with `bbox()`
 * \tparam FrameField a model of `FrameField_3`
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{the named parameters of `lattice_particles_3()`}
 *     \cgalParamDescription{`edge_length` or `number_of_particles`, `random_seed`,
 *       `number_of_threads`, `maximum_running_time` (see below), ...; the lattice is the cubic one}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{the named parameters of `tets_to_hex_dominant()`}
 *     \cgalParamDescription{`quality_bound`, `cell_types`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Hex_dominant_meshing::parameters::boundary_distance}
 *     \cgalParamDescription{the boundary refinement of dissertation 4.4.2: where the tets'
 *       boundary is farther than this from the domain's surface, or the surface (its samples,
 *       sharp edges) farther than this from the tets' boundary, surface points are added to
 *       the particles (kept a third of the boundary edge length apart) and the particles are
 *       connected again, for at most four rounds. The cells at the added points are seldom
 *       hexahedra: the refinement trades hexahedra near the boundary for a closer boundary}
 *     \cgalParamType{`double`} \cgalParamDefault{0: no refinement}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{called with the particles' rounds
 *       (`Tetrahedral_lattice_meshing::Lattice_round_report`) and each stage's end
 *       (`VVM::Stage_report`: `PARTICLES`, `TETRAHEDRA`, `MERGING`); if it returns `false`, the
 *       stages after it do only what a valid mesh needs (see below)}
 *     \cgalParamType{a callable taking `const VVM::Stage_report&` or
 *       `const Tetrahedral_lattice_meshing::Lattice_round_report&`, returning `void` or `bool`}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Hex_dominant_meshing::parameters::tetrahedral_mesh}
 *     \cgalParamDescription{receives the tets that were merged (e.g. to merge them again with
 *       another quality bound by `tets_to_hex_dominant()`)}
 *     \cgalParamType{`C3T3*`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Hex_dominant_meshing::parameters::report}
 *     \cgalParamDescription{receives the counts and times of each stage}
 *     \cgalParamType{`Hex_dominant_meshing::Hex_dominant_report*`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * `maximum_running_time` (seconds from the call, 0: none) is shared by the stages: the
 * particles' rounds and the merging's candidate search stop once it is reached, the boundary
 * refinement and the flips do not start after it, and the result is a valid mesh whose tets
 * not merged stay tetrahedra (`Hex_dominant_report::time_limit_reached`). The stages without
 * which there is no mesh always run: the boundary's sampling, the first particles and their
 * connection into tets (and, in the overload without a field, the cross field's mesh and
 * least-squares solve). A visitor that returns `false` stops the same way
 * (`Hex_dominant_report::stopped_by_visitor`). The former `stage_visitor`, called as
 * `stage_visitor(Hex_dominant_stage, seconds)`, still works but is deprecated.
 *
 * \throw std::invalid_argument before any work on bad input (as `lattice_particles_3()`:
 *   empty domain, bad sizes or counts, degenerate field; a lattice other than cubic; a quality
 *   bound outside [0, 1]); and if the particles give no cell inside the domain
 */
template <class C3T3, class MeshDomain, class FrameField, class NamedParameters = parameters::Default_named_parameters>
Hex_dominant_mesh_3<typename MeshDomain::R::Point_3>
make_hex_dominant_mesh_3(const MeshDomain& domain, const FrameField& field,
                         const NamedParameters& np = parameters::default_values())
{
  namespace HDM_internal = Hex_dominant_meshing::internal;
  return HDM_internal::make_hex_dominant_mesh<C3T3>(domain, field, HDM_internal::read_hex_dominant_request(np), np);
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 *
 * the same with the frame field of the named parameter `Hex_dominant_meshing::parameters::frame_field`
 * or, without it, the boundary-aligned cross field of `Frame_fields::generate_cross_field_3()`
 * (unit frames, one axis on the surface normal and along the feature curves), computed on a
 * `make_mesh_3()` mesh of `domain` whose edges are about \f$ l^* \f$ long, then scale-corrected
 * by `Frame_fields::scale_corrected_frame_field()` so that the lattice's layers can follow its
 * turning (fewer prisms and pyramids filling the gaps of a fraction of a layer).
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{the named parameters of the overload above}
 *     \cgalParamDescription{`frame_field` here, and those of `lattice_particles_3()` and
 *       `tets_to_hex_dominant()`, `boundary_distance`, `visitor`, ...}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::maximum_size_ratio}
 *     \cgalParamDescription{the largest ratio of two scales of the generated cross field's scale
 *       correction; 1 for none. Ignored with `frame_field`; skipped once `maximum_running_time` is reached}
 *     \cgalParamType{`double`, at least 1} \cgalParamDefault{2}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 */
template <class C3T3, class MeshDomain, class T, class Tag, class Base>
Hex_dominant_mesh_3<typename MeshDomain::R::Point_3>
make_hex_dominant_mesh_3(const MeshDomain& domain, const Named_function_parameters<T, Tag, Base>& np)
{
  namespace HDM_internal = Hex_dominant_meshing::internal;
  return VVM::internal::with_frame_field(domain, HDM_internal::read_hex_dominant_request(np), np,
                                        [&](const auto& field, const VVM::internal::Lattice_request& r) {
                                          return HDM_internal::make_hex_dominant_mesh<C3T3>(domain, field, r, np);
                                        });
}

} // namespace CGAL

#endif // CGAL_MAKE_HEX_DOMINANT_MESH_3_H
