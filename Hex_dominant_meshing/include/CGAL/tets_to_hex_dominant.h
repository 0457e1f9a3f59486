// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::tets_to_hex_dominant(): a tetrahedral mesh merged into hexahedra,
// prisms and pyramids (dissertation 4.4.2).

#ifndef CGAL_TETS_TO_HEX_DOMINANT_H
#define CGAL_TETS_TO_HEX_DOMINANT_H

#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Hex_dominant_meshing/internal/Conforming_selection.h>
#include <CGAL/Hex_dominant_meshing/internal/Merge_candidates.h>
#include <CGAL/Hex_dominant_meshing/internal/Tetrahedral_adjacency.h>
#include <CGAL/Hex_dominant_meshing/parameters.h>
#include <CGAL/Tetrahedral_lattice_meshing/parameters.h>
#include <CGAL/VVM/internal/Eigen_conversion.h>
#include <CGAL/VVM/internal/Stopping.h>
#include <CGAL/VVM/internal/Thread_limit.h>
#include <CGAL/VVM/internal/Vertex_numbering.h>

#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_3.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {

/// \ingroup PkgHexDominantMeshingRef
/// what `tets_to_hex_dominant()` did, for its `report` output
struct Hex_dominant_merge_report
{
  std::size_t number_of_tets = 0;               ///< in the input
  /// candidates at or above the quality bound (prisms and pyramids: of the tets the hexahedra left)
  std::size_t number_of_hexahedron_candidates = 0;
  std::size_t number_of_prism_candidates = 0;
  std::size_t number_of_pyramid_candidates = 0;
  /// flat tets left on one cell's quad (boundary side) and taken in by it
  std::size_t number_of_flat_tets_taken_in = 0;
  /// per output cell, the input tets it is made of (indices in the order of the input's
  /// `finite_cells()` or `cells_in_complex()`)
  std::vector<std::vector<std::size_t>> cell_tets;
  /// the input tets, as indices of the output's points
  std::vector<std::array<std::size_t, 4>> tets;
  double candidate_time = 0;                     ///< seconds
  double selection_time = 0;                     ///< seconds
  /// `maximum_running_time` (or `make_hex_dominant_mesh_3()`'s stop) cut the candidate search
  /// short: the tets not searched stay tetrahedra
  bool stopped = false;
};

namespace internal {

/// `v`'s number in `mesh` and `points`, where a vertex met the first time is added
template <class Tr, class Adjacency, class PointVector>
std::size_t number_vertex(typename Tr::Vertex_handle v, Adjacency& mesh, PointVector& points,
                          VVM::internal::Vertex_numbering<Tr>& number)
{
  return number(v, [&](const auto& p) {
    const Eigen::Vector3d x(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if(!x.allFinite()) throw std::invalid_argument("tets_to_hex_dominant: a vertex has a non-finite coordinate");
    mesh.points.push_back(x);
    points.push_back(p);
  });
}

/// the finite cells of a triangulation, subdomain 1
template <class GT, class TDS, class Lds, class Point>
void indexed_tets(const Triangulation_3<GT, TDS, Lds>& tr, Tetrahedral_adjacency& mesh, std::vector<Point>& points)
{
  typedef Triangulation_3<GT, TDS, Lds> Tr;
  VVM::internal::Vertex_numbering<Tr> number(tr);
  if(tr.dimension() < 3) return;
  for(auto c : tr.finite_cell_handles()) {
    std::array<std::size_t, 4> t;
    for(int k = 0; k < 4; ++k) t[std::size_t(k)] = number_vertex<Tr>(c->vertex(k), mesh, points, number);
    mesh.tets.push_back(t);
    mesh.subdomain.push_back(1);
  }
}

/// the cells in the complex, with their subdomain index
template <class Tr, class CornerIndex, class CurveIndex, class Point>
void indexed_tets(const Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>& c3t3,
                  Tetrahedral_adjacency& mesh, std::vector<Point>& points)
{
  VVM::internal::Vertex_numbering<Tr> number(c3t3.triangulation());
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<std::size_t, 4> t;
    for(int k = 0; k < 4; ++k) t[std::size_t(k)] = number_vertex<Tr>(c->vertex(k), mesh, points, number);
    mesh.tets.push_back(t);
    mesh.subdomain.push_back(int(c3t3.subdomain_index(c)));
  }
}

template <class T>
struct Triangulation_of
{
  typedef T type;
};
template <class Tr, class CornerIndex, class CurveIndex>
struct Triangulation_of<Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>>
{
  typedef Tr type;
};

} // namespace internal
} // namespace Hex_dominant_meshing

namespace Hex_dominant_meshing {
namespace internal {

/// `tets_to_hex_dominant()`: the merging, then the visitor of `np` told that it is over
template <class Point_3, class NamedParameters>
Hex_dominant_mesh_3<Point_3> merge_tets_and_visit(Tetrahedral_adjacency& mesh, std::vector<Point_3>&& points,
                                                  const NamedParameters& np);

/// `stop`: a request to stop of the caller's, asked from several threads at once, besides
/// the `maximum_running_time` of `np`
template <class Point_3, class NamedParameters>
Hex_dominant_mesh_3<Point_3> merge_tets(Tetrahedral_adjacency& mesh, std::vector<Point_3>&& points,
                                        const NamedParameters& np, const std::function<bool()>& stop = {})
{
  namespace HDM = Hex_dominant_meshing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;

  const double q_bound = choose_parameter(get_parameter(np, HDM::internal_np::quality_bound), 0.5);
  if(!(q_bound >= 0 && q_bound <= 1)) throw std::invalid_argument("tets_to_hex_dominant: the quality bound must be in [0, 1]");
  const HDM::Cell_types types = choose_parameter(get_parameter(np, HDM::internal_np::cell_types), HDM::Cell_types::ALL);
  const int threads = choose_parameter(get_parameter(np, VVM::internal_np::number_of_threads), 0);
  if(threads < 0) throw std::invalid_argument("tets_to_hex_dominant: the number of threads must be non-negative");
  const double seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  if(!(seconds >= 0))
    throw std::invalid_argument("tets_to_hex_dominant: maximum_running_time must be non-negative (0: no limit)");
  const VVM::internal::Time_limit time_limit(seconds);
  const std::function<bool()> must_stop = [&]() { return time_limit.is_reached() || (stop && stop()); };
  HDM::Hex_dominant_merge_report* report = choose_parameter(get_parameter(np, VVM::internal_np::report),
                                                            static_cast<HDM::Hex_dominant_merge_report*>(nullptr));
  Merge_candidate_finder::Frame_inverse B;
  const auto& field = get_parameter_reference(np, VVM::internal_np::frame_field);
  // the field itself, also when the pack holds a std::reference_wrapper to it
  if constexpr(!std::is_same<std::decay_t<decltype(field)>, CGAL::internal_np::Param_not_found>::value)
    B = VVM::internal::frame_inverse_function(field);

  const auto thread_limit = VVM::internal::thread_limit(threads);

  Hex_dominant_mesh_3<Point_3> out;
  out.points = std::move(points);
  mesh.build();

  CGAL::Real_timer timer;
  timer.start();
  // hexahedra first; the prisms and pyramids only of the tets they leave
  const Merge_candidate_finder finder(mesh, B, q_bound);
  Conforming_selection selection(mesh);
  std::array<std::size_t, 3> number_of_candidates{};
  double candidate_time = 0;
  bool stopped = false;
  for(int kind = 0; kind < 3 && !stopped; ++kind) {
    if((kind == 1 && types == HDM::Cell_types::HEXAHEDRA) || (kind == 2 && types != HDM::Cell_types::ALL)) break;
    const double start = timer.time();
    const std::vector<Merge_candidate> candidates = finder.find(
        kind == 0, kind == 1, kind == 2, kind == 0 ? nullptr : &selection.result().owner, must_stop, &stopped);
    candidate_time += timer.time() - start;
    number_of_candidates[std::size_t(kind)] = candidates.size();
    selection.select(candidates);
  }
  const std::size_t flat_tets_taken_in = selection.take_in_flat_tets();
  const Selection& s = selection.result();

  typedef typename Hex_dominant_mesh_3<Point_3>::Cell Cell;
  std::vector<std::vector<std::size_t>> cell_tets;
  for(std::size_t k = 0; k < s.kept.size(); ++k) {
    const auto& c = s.cells[k];
    Cell cell;
    cell.type = c.type;
    cell.vertices = c.vertices;
    cell.subdomain_index = mesh.subdomain[c.tets[0]];
    out.cells.push_back(cell);
    cell_tets.emplace_back(c.tets.begin(), c.tets.begin() + c.number_of_tets);
    cell_tets.back().insert(cell_tets.back().end(), s.taken_in[k].begin(), s.taken_in[k].end());
  }
  for(std::size_t t = 0; t < mesh.number_of_tets(); ++t) {
    if(s.owner[t] != no_index) continue;
    Cell cell;
    cell.type = Hex_dominant_cell_type::TETRAHEDRON;
    for(int k = 0; k < 4; ++k) cell.vertices[std::size_t(k)] = mesh.tets[t][std::size_t(k)];
    cell.subdomain_index = mesh.subdomain[t];
    out.cells.push_back(cell);
    cell_tets.push_back({t});
  }
  if(report) {
    *report = HDM::Hex_dominant_merge_report();
    report->number_of_tets = mesh.number_of_tets();
    report->number_of_hexahedron_candidates = number_of_candidates[0];
    report->number_of_prism_candidates = number_of_candidates[1];
    report->number_of_pyramid_candidates = number_of_candidates[2];
    report->number_of_flat_tets_taken_in = flat_tets_taken_in;
    report->cell_tets = std::move(cell_tets);
    report->tets = mesh.tets;
    report->candidate_time = candidate_time;
    report->selection_time = timer.time() - candidate_time;
    report->stopped = stopped;
  }
  return out;
}

template <class Point_3, class NamedParameters>
Hex_dominant_mesh_3<Point_3> merge_tets_and_visit(Tetrahedral_adjacency& mesh, std::vector<Point_3>&& points,
                                                  const NamedParameters& np)
{
  auto visitor = CGAL::parameters::get_parameter(np, CGAL::internal_np::visitor);
  VVM::internal::check_visitor<decltype(visitor), VVM::Stage_report>();
  const VVM::internal::Time_limit clock;
  Hex_dominant_mesh_3<Point_3> out = merge_tets(mesh, std::move(points), np);
  VVM::internal::visit_stage_end(visitor, VVM::Stage::MERGING, 0, clock.elapsed());
  return out;
}

} // namespace internal
} // namespace Hex_dominant_meshing

/*!
 * \ingroup PkgHexDominantMeshingRef
 *
 * merges the tets of `tets` into hexahedra, prisms and pyramids (dissertation 4.4.2, after
 * Meshkat and Talmor 2000 and Sokolov et al. 2016). First every candidate is found: hexahedra
 * of 5 or 6 tets (the 6 ways) and of 7 tets with one flat tet between two prisms (the 4
 * ways), prisms of 3 tets, pyramids of 2 (Alg. 6-8), each with its merging quality
 * (\f$ Q_{hex} = Q_p \min_c Q_o \f$ for hexahedra, see `hexahedron_merging_quality()`) in the
 * frame field's space; no candidate has an inverted corner. Then the hexahedra are kept
 * greedily by descending quality, then the prisms, then the pyramids, each only if it shares
 * no tet with a kept cell and its quad faces conform: a quad meets the same quad on the other
 * side, or two triangles of the tets' own facets, never half of another quad nor the same
 * corners split along the other diagonal. The tets left are tetrahedra of the result. The
 * cells partition the tets exactly.
 *
 * \tparam TetMesh a `Triangulation_3` (its finite cells, subdomain 1) or a
 *   `Mesh_complex_3_in_triangulation_3` (its cells in the complex, with their subdomain
 *   index); no cell merges across subdomains
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{Hex_dominant_meshing::parameters::quality_bound}
 *     \cgalParamDescription{\f$ Q_{bound} \f$: no cell is made under this merging quality (in [0, 1])}
 *     \cgalParamType{`double`} \cgalParamDefault{0.5}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Hex_dominant_meshing::parameters::cell_types}
 *     \cgalParamDescription{which cells the tets may merge into}
 *     \cgalParamType{`Hex_dominant_meshing::Cell_types`} \cgalParamDefault{`ALL`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Hex_dominant_meshing::parameters::frame_field}
 *     \cgalParamDescription{the qualities are measured after mapping each cell by the frame
 *       inverse \f$ B \f$ at its centroid}
 *     \cgalParamType{a model of `FrameField_3`} \cgalParamDefault{the identity}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::number_of_threads}
 *     \cgalParamDescription{threads of the candidate search; the result does not depend on it}
 *     \cgalParamType{`int`} \cgalParamDefault{0: TBB's choice}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Hex_dominant_meshing::parameters::report}
 *     \cgalParamDescription{receives the candidate counts, the tets of each cell and the times}
 *     \cgalParamType{`Hex_dominant_meshing::Hex_dominant_merge_report*`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{called once the merging is over, with a `VVM::Stage_report`}
 *     \cgalParamType{a callable taking `const VVM::Stage_report&`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_running_time}
 *     \cgalParamDescription{a time limit in seconds, from the call: the candidate search stops once
 *       it is reached, the candidates found are selected as usual and the other tets stay
 *       tetrahedra (`Hex_dominant_merge_report::stopped`); 0 for none}
 *     \cgalParamType{`double`, non-negative} \cgalParamDefault{0}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \returns the hex-dominant mesh, its points those of the tets' vertices
 * \throw std::invalid_argument if the quality bound is not in [0, 1], the time limit negative, if a vertex is not
 *   finite or a facet is shared by more than two tets
 */
template <class TetMesh, class T, class Tag, class Base>
Hex_dominant_mesh_3<typename Hex_dominant_meshing::internal::Triangulation_of<TetMesh>::type::Geom_traits::Point_3>
tets_to_hex_dominant(const TetMesh& tets, const Named_function_parameters<T, Tag, Base>& np)
{
  typedef typename Hex_dominant_meshing::internal::Triangulation_of<TetMesh>::type::Geom_traits::Point_3 Point_3;
  Hex_dominant_meshing::internal::Tetrahedral_adjacency mesh;
  std::vector<Point_3> points;
  Hex_dominant_meshing::internal::indexed_tets(tets, mesh, points);
  return Hex_dominant_meshing::internal::merge_tets_and_visit(mesh, std::move(points), np);
}

/// \ingroup PkgHexDominantMeshingRef
/// the same with the default named parameters
template <class TetMesh>
Hex_dominant_mesh_3<typename Hex_dominant_meshing::internal::Triangulation_of<TetMesh>::type::Geom_traits::Point_3>
tets_to_hex_dominant(const TetMesh& tets)
{
  return tets_to_hex_dominant(tets, parameters::default_values());
}

/*!
 * \ingroup PkgHexDominantMeshingRef
 *
 * the same on tets given as indices into `points` (each tet is oriented positively if it is
 * not), with `subdomains` the subdomain index of each tet (empty: all 1).
 *
 * \tparam Point_3 a point type with `x()`, `y()`, `z()` and a constructor from three doubles
 * \throw std::invalid_argument also if a tet refers to no point, is flat (zero volume) or if
 *   `subdomains` is not empty and not of the size of `tets`
 */
template <class Point_3, class NamedParameters = parameters::Default_named_parameters>
Hex_dominant_mesh_3<Point_3> tets_to_hex_dominant(const std::vector<Point_3>& points,
                                                  const std::vector<std::array<std::size_t, 4>>& tets,
                                                  const std::vector<int>& subdomains = {},
                                                  const NamedParameters& np = parameters::default_values())
{
  Hex_dominant_meshing::internal::Tetrahedral_adjacency mesh;
  if(!subdomains.empty() && subdomains.size() != tets.size())
    throw std::invalid_argument("tets_to_hex_dominant: one subdomain index per tet");
  for(const Point_3& p : points) {
    const Eigen::Vector3d x(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if(!x.allFinite()) throw std::invalid_argument("tets_to_hex_dominant: a vertex has a non-finite coordinate");
    mesh.points.push_back(x);
  }
  for(std::size_t t = 0; t < tets.size(); ++t) {
    std::array<std::size_t, 4> v = tets[t];
    for(std::size_t i : v)
      if(i >= points.size()) throw std::invalid_argument("tets_to_hex_dominant: a tet refers to no point");
    const double o = Hex_dominant_meshing::internal::orientation(mesh, v[0], v[1], v[2], v[3]);
    if(!(o != 0)) throw std::invalid_argument("tets_to_hex_dominant: a tet is flat (zero volume)");
    if(o < 0) std::swap(v[2], v[3]);
    mesh.tets.push_back(v);
    mesh.subdomain.push_back(subdomains.empty() ? 1 : subdomains[t]);
  }
  return Hex_dominant_meshing::internal::merge_tets_and_visit(mesh, std::vector<Point_3>(points), np);
}

} // namespace CGAL

#endif // CGAL_TETS_TO_HEX_DOMINANT_H
