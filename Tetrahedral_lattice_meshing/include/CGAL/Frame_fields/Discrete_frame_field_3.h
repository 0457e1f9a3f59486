// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A frame field known at the vertices or at the cells of a tetrahedral mesh,
// looked up in constant time through a uniform grid (dissertation 4.4.3).

#ifndef CGAL_FRAME_FIELDS_DISCRETE_FRAME_FIELD_3_H
#define CGAL_FRAME_FIELDS_DISCRETE_FRAME_FIELD_3_H

#include <CGAL/Frame_fields/frame_inverse.h>
#include <CGAL/Frame_fields/internal/Uniform_grid_3.h>

#include <CGAL/assertions.h>
#include <CGAL/VVM/internal/Eigen_conversion.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Frame_fields {

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// where the frames of a `Discrete_frame_field_3` are known
enum class Frame_location
{
  VERTICES, ///< one frame per vertex; a point takes the frame of its nearest vertex
  CELLS     ///< one frame per tetrahedron; a point takes the frame of the cell containing it
};

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * A frame field given by one frame per vertex or per cell of a tetrahedral mesh
 * (points and index quadruples), as produced by external cross-field generators or
 * by `generate_cross_field_3()`.
 *
 * With `Frame_location::VERTICES`, \f$ T(x) \f$ is the frame of the vertex nearest to
 * \f$ x \f$ (the smallest index among equally near ones). With `Frame_location::CELLS`,
 * it is the frame of the cell containing \f$ x \f$ (the smallest index if \f$ x \f$ is on
 * a shared face); outside the mesh, that of the cell whose centroid is nearest.
 * Both lookups go through a uniform grid over the mesh with about one element per grid
 * cell, so they take constant time on meshes of bounded element size ratio.
 *
 * \tparam GeomTraits a model of `Kernel`
 * \cgalModels `FrameField_3`
 */
template <class GeomTraits>
class Discrete_frame_field_3
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef Eigen::Matrix3d Matrix;
  typedef std::array<std::size_t, 4> Cell;

  Discrete_frame_field_3() = default;

  /*!
   * \param points the mesh vertices
   * \param cells the tetrahedra, as indices into `points` (may be empty with
   *   `Frame_location::VERTICES`)
   * \param frames one frame \f$ T \f$ per vertex or per cell, as `location` says
   * \param location whether `frames` are given at the vertices or at the cells
   * \throws std::invalid_argument on an empty mesh, a count of frames that does not
   *   match, a cell index out of range, a non-finite point or one beyond 1e100 in magnitude,
   *   or a degenerate frame
   */
  Discrete_frame_field_3(std::vector<Point_3> points, std::vector<Cell> cells,
                         std::vector<Matrix> frames, Frame_location location)
    : points_(std::move(points)), cells_(std::move(cells)), T_(std::move(frames)), location_(location)
  {
    const char* who = "Discrete_frame_field_3: ";
    if(points_.empty()) throw std::invalid_argument(std::string(who) + "the mesh has no vertex");
    if(location_ == Frame_location::CELLS && cells_.empty())
      throw std::invalid_argument(std::string(who) + "a field on cells needs at least one cell");
    const std::size_t expected = location_ == Frame_location::VERTICES ? points_.size() : cells_.size();
    if(T_.size() != expected)
      throw std::invalid_argument(std::string(who) + std::to_string(T_.size()) + " frames for " +
                                  std::to_string(expected) +
                                  (location_ == Frame_location::VERTICES ? " vertices" : " cells"));
    xyz_.reserve(points_.size());
    for(const Point_3& p : points_) {
      xyz_.push_back(VVM::internal::to_eigen(p));
      if(!xyz_.back().allFinite())
        throw std::invalid_argument(std::string(who) + "a vertex has a non-finite coordinate");
    }
    // the point location grids sum and multiply coordinates: keep them far from overflow
    for(const Eigen::Vector3d& x : xyz_)
      if(!(x.cwiseAbs().maxCoeff() <= 1e100))
        throw std::invalid_argument(std::string(who) + "a vertex has a coordinate beyond 1e100 in magnitude");
    for(const Cell& c : cells_)
      for(std::size_t v : c)
        if(v >= points_.size())
          throw std::invalid_argument(std::string(who) + "a cell refers to vertex " + std::to_string(v) +
                                      " of " + std::to_string(points_.size()));
    B_.reserve(T_.size());
    for(std::size_t i = 0; i < T_.size(); ++i)
      B_.push_back(frame_inverse(T_[i], std::string(location_ == Frame_location::VERTICES ? "of vertex " : "of cell ") +
                                            std::to_string(i)));
    build_grids();
  }

  /// the frame \f$ T \f$ at `p`
  /// \throws std::invalid_argument as `index_of()`
  Matrix T(const Point_3& p) const { return T_[index_of(p)]; }
  /// its inverse \f$ B \f$ at `p`
  /// \throws std::invalid_argument as `index_of()`
  Matrix B(const Point_3& p) const { return B_[index_of(p)]; }

  /// the index of the vertex or cell whose frame is used at `p`. Far from the mesh
  /// (beyond about \f$ 10^{154} \f$, where squared distances overflow) every vertex or
  /// centroid is equally near and the smallest index is returned.
  /// \throws std::invalid_argument if the field is empty (default constructed) or a
  ///   coordinate of `p` is NaN or infinite
  std::size_t index_of(const Point_3& p) const
  {
    if(T_.empty()) throw std::invalid_argument("Discrete_frame_field_3: the field is empty");
    const Eigen::Vector3d x = VVM::internal::to_eigen(p);
    if(!x.allFinite()) {
      std::ostringstream os;
      os << "Discrete_frame_field_3: the query point (" << x.transpose() << ") is not finite";
      throw std::invalid_argument(os.str());
    }
    std::ptrdiff_t found = -1;
    if(location_ == Frame_location::VERTICES) {
      found = vertex_grid_.nearest(x);
    } else {
      std::size_t inside = cells_.size();
      cell_grid_.for_each_in_cell(x, [&](std::size_t c) {
        if(c < inside && contains(c, x)) inside = c;
      });
      found = inside < cells_.size() ? std::ptrdiff_t(inside) : centroid_grid_.nearest(x);
    }
    CGAL_assertion(found >= 0 && std::size_t(found) < T_.size());
    return std::size_t(found);
  }

  /// `true` if cell `c` contains `x` (boundary included, up to rounding)
  bool contains(std::size_t c, const Eigen::Vector3d& x) const
  {
    const Eigen::Vector3d& p0 = xyz_[cells_[c][0]];
    Eigen::Matrix3d E;
    for(int i = 0; i < 3; ++i) E.col(i) = xyz_[cells_[c][i + 1]] - p0;
    const Eigen::Vector3d l = E.partialPivLu().solve(x - p0);
    const double eps = 1e-12;
    return l.allFinite() && l.minCoeff() >= -eps && l.sum() <= 1 + eps;
  }

  Frame_location location() const { return location_; }
  const std::vector<Point_3>& points() const { return points_; }
  const std::vector<Cell>& cells() const { return cells_; }
  /// the frames \f$ T \f$, one per vertex or per cell
  const std::vector<Matrix>& frames() const { return T_; }
  /// their inverses \f$ B \f$
  const std::vector<Matrix>& inverse_frames() const { return B_; }

private:
  void build_grids()
  {
    if(location_ == Frame_location::VERTICES) {
      vertex_grid_ = internal::Uniform_grid_3(xyz_, xyz_);
      return;
    }
    std::vector<Eigen::Vector3d> lo, hi;
    for(const Cell& c : cells_) {
      Eigen::Vector3d a = xyz_[c[0]], b = a, s = a;
      for(int i = 1; i < 4; ++i) {
        a = a.cwiseMin(xyz_[c[i]]);
        b = b.cwiseMax(xyz_[c[i]]);
        s += xyz_[c[i]];
      }
      // widened a little: a point on a face must find the cell through either grid cell
      const Eigen::Vector3d margin = Eigen::Vector3d::Constant(1e-9 * (b - a).norm());
      lo.push_back(a - margin);
      hi.push_back(b + margin);
      centroids_.push_back(0.25 * s);
    }
    cell_grid_ = internal::Uniform_grid_3(lo, hi);
    centroid_grid_ = internal::Uniform_grid_3(centroids_, centroids_);
  }

  std::vector<Point_3> points_;
  std::vector<Cell> cells_;
  std::vector<Matrix> T_, B_;
  Frame_location location_ = Frame_location::VERTICES;
  std::vector<Eigen::Vector3d> xyz_, centroids_;
  internal::Uniform_grid_3 vertex_grid_, cell_grid_, centroid_grid_;
};

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_DISCRETE_FRAME_FIELD_3_H
