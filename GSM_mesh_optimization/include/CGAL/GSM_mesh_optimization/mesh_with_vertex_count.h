// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mesh at about a requested number of vertices: make_mesh_3 takes sizes,
// not counts, so the size is searched for, each guess corrected by the power
// law n ~ s^-alpha fitted to the last two meshes.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_MESH_WITH_VERTEX_COUNT_H
#define CGAL_GSM_MESH_OPTIMIZATION_MESH_WITH_VERTEX_COUNT_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace GSM_mesh_optimization {

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * The result of `mesh_with_vertex_count()`: the mesh nearest to the requested number of
 * vertices among those made, and how it was made.
 *
 * \tparam C3T3 a `Mesh_complex_3_in_triangulation_3`
 */
template <class C3T3>
struct Mesh_with_vertex_count_result
{
  C3T3 c3t3;                          ///< the mesh
  double size = 0;                    ///< the size it was made with
  double time_s = 0;                  ///< the time taken to make it (seconds)
  std::size_t number_of_vertices = 0; ///< its vertices incident to a cell in the complex
  double relative_error = 0;          ///< \f$ |n - n_{target}| / n_{target} \f$
  int number_of_meshes = 0;           ///< the number of meshes made by the search
};

/// \ingroup PkgGSMMeshOptimizationIO
/// the number of vertices of the cells in the complex of `c3t3`
template <class C3T3>
std::size_t number_of_vertices_in_complex(const C3T3& c3t3)
{
  std::set<typename C3T3::Triangulation::Vertex_handle> vertices;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i) vertices.insert(c->vertex(i));
  return vertices.size();
}

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * makes meshes of a domain with the sizes \f$ s_0, s_1, \dots \f$ until one has a number
 * \f$ n \f$ of vertices (incident to a cell in the complex) within `tolerance` of
 * `number_of_vertices` (\f$ |n - n_{target}| \le \f$ `tolerance` \f$ n_{target} \f$), or
 * `number_of_iterations` meshes were made, and returns the one nearest to the target.
 * \f$ s_0 \f$ is `first_size`; each next size assumes \f$ n \sim s^{-\alpha} \f$, with
 * \f$ \alpha = 3 \f$ at first, then fitted to the last two meshes and clamped to
 * \f$ [1.5, 3.5] \f$ (between surface- and volume-dominated meshes):
 * \f$ s_{k+1} = s_k (n_k / n_{target})^{1/\alpha} \f$.
 *
 * \tparam MeshWithSize a callable `C3T3(double size)`, e.g. calling `make_mesh_3()` with
 *   the edge, facet and cell sizes set to `size`; it should be deterministic (set the
 *   random seed inside)
 * \tparam NamedParameters a sequence of named parameters
 *
 * \param mesh_with_size makes a mesh with a given size
 * \param number_of_vertices the target, positive
 * \param first_size the first size tried, positive and finite
 * \param tolerance the relative tolerance on the number of vertices, non-negative
 * \param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the largest number of meshes made}
 *     \cgalParamType{`int`}
 *     \cgalParamDefault{8}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{one line per mesh on `std::cerr`: its size, vertex count and time}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{false}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \returns the mesh nearest to the target, its size, the time it took and its error
 * \throws std::invalid_argument if an argument is out of range, or if a mesh has no
 *   vertex (the domain is empty or the size far too large)
 */
template <class MeshWithSize, class NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_with_vertex_count_result<std::decay_t<std::invoke_result_t<const MeshWithSize&, double>>>
mesh_with_vertex_count(const MeshWithSize& mesh_with_size, std::size_t number_of_vertices, double first_size,
                       double tolerance = 0.05,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::decay_t<std::invoke_result_t<const MeshWithSize&, double>> C3T3;
  const int max_meshes = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 8);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  if(number_of_vertices == 0)
    throw std::invalid_argument("mesh_with_vertex_count: the number of vertices must be positive");
  if(!(first_size > 0) || !std::isfinite(first_size))
    throw std::invalid_argument("mesh_with_vertex_count: the first size must be positive and finite");
  if(!(tolerance >= 0)) throw std::invalid_argument("mesh_with_vertex_count: the tolerance must be non-negative");
  if(max_meshes < 1) throw std::invalid_argument("mesh_with_vertex_count: number_of_iterations must be at least 1");

  const double target = double(number_of_vertices);
  Mesh_with_vertex_count_result<C3T3> best;
  double s = first_size, prev_s = 0, prev_n = 0, best_error = 1e300;
  for(int attempt = 0; attempt < max_meshes; ++attempt) {
    CGAL::Real_timer timer;
    timer.start();
    C3T3 c3t3 = mesh_with_size(s);
    timer.stop();
    const std::size_t count = number_of_vertices_in_complex(c3t3);
    const double n = double(count);
    if(verbose) std::cerr << "  make_mesh_3 size " << s << ": " << n << " vertices (" << timer.time() << " s)\n";
    ++best.number_of_meshes;
    if(count == 0)
      throw std::invalid_argument("mesh_with_vertex_count: the mesh of size " + std::to_string(s) +
                                  " has no vertex");
    const double error = std::abs(n - target) / target;
    if(error < best_error) {
      best_error = error;
      best.c3t3 = std::move(c3t3);
      best.size = s;
      best.time_s = timer.time();
      best.number_of_vertices = count;
      best.relative_error = error;
    }
    if(error <= tolerance) break;
    double alpha = 3;
    if(prev_n > 0 && prev_s != s && prev_n != n)
      alpha = std::clamp(-std::log(n / prev_n) / std::log(s / prev_s), 1.5, 3.5);
    prev_s = s;
    prev_n = n;
    s *= std::pow(n / target, 1. / alpha);
  }
  return best;
}

} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_MESH_WITH_VERTEX_COUNT_H
