// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Aggregated element quality of a tetrahedral mesh: the cells of a
// Mesh_complex_3_in_triangulation_3 that are in the complex, or the finite
// cells of a Triangulation_3. The figures are those of the dissertation's
// tables (section 3.4.1) plus counts of inverted tets and histograms.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_MESH_QUALITY_STATISTICS_H
#define CGAL_GSM_MESH_OPTIMIZATION_MESH_QUALITY_STATISTICS_H

#include <CGAL/GSM_mesh_optimization/tetrahedron_quality.h>

#include <CGAL/Kernel/global_functions_3.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <limits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {

/*!
 * \ingroup PkgGSMMeshOptimizationQuality
 * Quality figures of a set of tetrahedra. Angles are in degrees.
 */
struct Mesh_quality_statistics
{
  /// thresholds (degrees) of the counts `n_min_dihedral_below`
  static constexpr std::array<double, 4> dihedral_thresholds{{10., 20., 30., 40.}};

  std::size_t number_of_vertices = 0; ///< vertices incident to at least one measured cell
  std::size_t number_of_cells = 0;
  std::size_t number_of_inverted_cells = 0; ///< cells of non-positive signed volume
  double min_dihedral_angle = 0;      ///< theta_min
  double max_dihedral_angle = 0;      ///< theta_max
  double mean_min_dihedral_angle = 0; ///< mean over the cells of their smallest dihedral angle
  double mean_max_dihedral_angle = 0; ///< mean over the cells of their largest dihedral angle
  /// number of cells whose smallest dihedral angle is below 10, 20, 30 and 40 degrees
  std::array<std::size_t, 4> n_min_dihedral_below{{0, 0, 0, 0}};
  double min_radius_ratio = 0;  ///< gamma_min
  double mean_radius_ratio = 0; ///< gamma_mean
  double min_edge_radius_ratio = 0;
  double mean_edge_radius_ratio = 0;
  double min_condition = 0;
  double mean_condition = 0;
  /// all six dihedral angles of every cell, in 180 bins of one degree
  std::array<std::size_t, 180> dihedral_angle_histogram{};
  /// the smallest dihedral angle of every cell, in 180 bins of one degree
  std::array<std::size_t, 180> min_dihedral_angle_histogram{};
  /// radius ratios, in 100 bins of width 0.01 over [0, 1] (inverted cells in bin 0)
  std::array<std::size_t, 100> radius_ratio_histogram{};

  /// accumulates one cell; call `finish()` once all cells were added
  void add(const Tetrahedron_quality& q)
  {
    const double tmin = q.min_dihedral_angle(), tmax = q.max_dihedral_angle();
    if(number_of_cells == 0) {
      min_dihedral_angle = tmin;
      max_dihedral_angle = tmax;
      min_radius_ratio = q.radius_ratio;
      min_edge_radius_ratio = q.edge_radius_ratio;
      min_condition = q.condition;
    }
    ++number_of_cells;
    if(q.is_inverted()) ++number_of_inverted_cells;
    min_dihedral_angle = (std::min)(min_dihedral_angle, tmin);
    max_dihedral_angle = (std::max)(max_dihedral_angle, tmax);
    mean_min_dihedral_angle += tmin;
    mean_max_dihedral_angle += tmax;
    for(std::size_t i = 0; i < dihedral_thresholds.size(); ++i)
      if(tmin < dihedral_thresholds[i]) ++n_min_dihedral_below[i];
    min_radius_ratio = (std::min)(min_radius_ratio, q.radius_ratio);
    mean_radius_ratio += q.radius_ratio;
    min_edge_radius_ratio = (std::min)(min_edge_radius_ratio, q.edge_radius_ratio);
    mean_edge_radius_ratio += q.edge_radius_ratio;
    min_condition = (std::min)(min_condition, q.condition);
    mean_condition += q.condition;
    for(double t : q.dihedral_angles) ++dihedral_angle_histogram[bin(t, 1., 180)];
    ++min_dihedral_angle_histogram[bin(tmin, 1., 180)];
    ++radius_ratio_histogram[bin(q.radius_ratio, 0.01, 100)];
  }

  /// turns the accumulated sums into means
  void finish()
  {
    if(number_of_cells == 0) return;
    const double n = double(number_of_cells);
    mean_min_dihedral_angle /= n;
    mean_max_dihedral_angle /= n;
    mean_radius_ratio /= n;
    mean_edge_radius_ratio /= n;
    mean_condition /= n;
  }

private:
  static std::size_t bin(double x, double width, std::size_t n)
  {
    if(!(x > 0)) return 0;
    const std::size_t b = std::size_t(x / width);
    return b < n ? b : n - 1;
  }
};

namespace internal {

struct Identity_metric
{
  template <class Point_3>
  Eigen::Matrix3d operator()(const Point_3&) const { return Eigen::Matrix3d::Identity(); }
};

template <class Tr, class CellRange, class MetricB>
Mesh_quality_statistics
quality_statistics_of_cells(const Tr& tr, const CellRange& cells, const MetricB& B)
{
  typedef typename Tr::Geom_traits::Point_3 Bare_point;
  typename Tr::Geom_traits::Construct_point_3 cp = tr.geom_traits().construct_point_3_object();

  Mesh_quality_statistics s;
  std::unordered_set<const void*> vertices;
  for(auto c : cells) {
    const Bare_point p0 = cp(tr.point(c, 0)), p1 = cp(tr.point(c, 1)),
                     p2 = cp(tr.point(c, 2)), p3 = cp(tr.point(c, 3));
    const Bare_point centroid = CGAL::centroid(p0, p1, p2, p3);
    s.add(tetrahedron_quality(p0, p1, p2, p3, B(centroid)));
    for(int i = 0; i < 4; ++i) vertices.insert(&*c->vertex(i));
  }
  s.number_of_vertices = vertices.size();
  s.finish();
  return s;
}

} // namespace internal

/*!
 * \ingroup PkgGSMMeshOptimizationQuality
 * computes the quality of the cells of `c3t3` that are in the complex.
 *
 * \tparam C3T3 a model of `MeshComplex_3InTriangulation_3`
 * \tparam MetricB a callable `Eigen::Matrix3d(const Point_3&)` returning the matrix B
 *   that maps a cell (evaluated at its centroid) to the isotropic space.
 *   With the default, the quality is the isotropic one.
 */
template <class C3T3, class MetricB = internal::Identity_metric>
Mesh_quality_statistics
mesh_quality_statistics(const C3T3& c3t3, const MetricB& B = MetricB())
{
  std::vector<typename C3T3::Triangulation::Cell_handle> cells;
  cells.reserve(c3t3.number_of_cells_in_complex());
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    cells.push_back(c);
  return internal::quality_statistics_of_cells(c3t3.triangulation(), cells, B);
}

/*!
 * \ingroup PkgGSMMeshOptimizationQuality
 * computes the quality of all finite cells of the triangulation `tr`.
 *
 * \tparam Triangulation_3 a CGAL 3D triangulation (weighted points are allowed)
 * \tparam MetricB as in `mesh_quality_statistics()`
 */
template <class Triangulation_3, class MetricB = internal::Identity_metric>
Mesh_quality_statistics
triangulation_quality_statistics(const Triangulation_3& tr, const MetricB& B = MetricB())
{
  std::vector<typename Triangulation_3::Cell_handle> cells;
  cells.reserve(tr.number_of_finite_cells());
  for(auto c : tr.finite_cell_handles())
    cells.push_back(c);
  return internal::quality_statistics_of_cells(tr, cells, B);
}

} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_MESH_QUALITY_STATISTICS_H
