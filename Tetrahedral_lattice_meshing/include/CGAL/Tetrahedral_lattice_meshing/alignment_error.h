// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The alignment error of mesh edges with a lattice one-ring under a frame
// field (dissertation section 4.3.3): an edge mapped into the imagined space
// by the frame of its midpoint, against the nearest one-ring direction.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_ALIGNMENT_ERROR_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_ALIGNMENT_ERROR_H

#include <CGAL/Tetrahedral_lattice_meshing/Lattice.h>

#include <CGAL/VVM/internal/Eigen_conversion.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * returns \f$ \epsilon \f$, in degrees, of the edge vector `v` under the frame inverse `B`:
 * the smallest angle between \f$ B v \f$ and the one-ring vectors of `lattice`.
 */
inline double edge_alignment_error(const Lattice& lattice, const Eigen::Matrix3d& B, const Eigen::Vector3d& v)
{
  const Eigen::Vector3d u = B * v;
  const double n = u.norm();
  if(!(n > 0)) return 90.;
  double best = -1;
  for(const Eigen::Vector3d& h : lattice.one_ring) best = (std::max)(best, u.dot(h) / (n * h.norm()));
  return std::acos(std::clamp(best, -1., 1.)) * 57.295779513082320876798154814105;
}

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the alignment error over the edges of a mesh, in degrees
struct Alignment_statistics
{
  std::size_t number_of_edges = 0;
  double mean = 0;
  double standard_deviation = 0;
  double max = 0;
};

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * returns the alignment error statistics of the edges of the cells in the complex of `c3t3`,
 * each edge measured once, under `field` (a `FrameField_3`) at its midpoint.
 */
template <class C3T3, class FrameField>
Alignment_statistics alignment_statistics(const C3T3& c3t3, const FrameField& field, const Lattice& lattice)
{
  typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
  typedef typename FrameField::Point_3 Point_3;
  using VVM::internal::to_eigen;
  const auto& tr = c3t3.triangulation();
  std::set<std::pair<Vertex_handle, Vertex_handle>> seen;
  Alignment_statistics s;
  double sum = 0, sum2 = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        Vertex_handle a = c->vertex(i), b = c->vertex(j);
        if(b < a) std::swap(a, b);
        if(!seen.emplace(a, b).second) continue;
        const Eigen::Vector3d p = to_eigen(tr.point(a)), q = to_eigen(tr.point(b)), m = 0.5 * (p + q);
        const double e = edge_alignment_error(lattice, field.B(Point_3(m[0], m[1], m[2])), q - p);
        sum += e;
        sum2 += e * e;
        s.max = (std::max)(s.max, e);
      }
  s.number_of_edges = seen.size();
  if(s.number_of_edges) {
    s.mean = sum / double(s.number_of_edges);
    s.standard_deviation = std::sqrt((std::max)(0., sum2 / double(s.number_of_edges) - s.mean * s.mean));
  }
  return s;
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * returns the mean alignment error (degrees) of the six edges of each cell in the complex of
 * `c3t3`, in the order of `cells_in_complex_begin()`: a cell data array for
 * `GSM_mesh_optimization::IO::write_VTU_with_quality()`.
 */
template <class C3T3, class FrameField>
std::vector<double> cell_alignment_errors(const C3T3& c3t3, const FrameField& field, const Lattice& lattice)
{
  typedef typename FrameField::Point_3 Point_3;
  using VVM::internal::to_eigen;
  const auto& tr = c3t3.triangulation();
  std::vector<double> errors;
  errors.reserve(c3t3.number_of_cells_in_complex());
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    double sum = 0;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const Eigen::Vector3d p = to_eigen(tr.point(c, i)), q = to_eigen(tr.point(c, j)), m = 0.5 * (p + q);
        sum += edge_alignment_error(lattice, field.B(Point_3(m[0], m[1], m[2])), q - p);
      }
    errors.push_back(sum / 6.);
  }
  return errors;
}

} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_ALIGNMENT_ERROR_H
