// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A frame field on a surface: tangent frames (two directions in the tangent
// plane with their lengths, the normal third) at the corners of a triangle
// mesh's faces, interpolated at the point of the face nearest to the query
// (found through a uniform grid of the faces, the AABB tree where the grid
// cannot tell).

#ifndef CGAL_FRAME_FIELDS_SURFACE_FRAME_FIELD_3_H
#define CGAL_FRAME_FIELDS_SURFACE_FRAME_FIELD_3_H

#include <CGAL/Frame_fields/frame_inverse.h>
#include <CGAL/Frame_fields/internal/Triangle_mesh_features.h>
#include <CGAL/Frame_fields/internal/Uniform_grid_3.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Frame_fields {

/// \ingroup PkgTetrahedralLatticeMeshingFrameFields
/// a tangent frame: a direction (projected onto the tangent plane) and the lengths along it
/// and along the tangent direction perpendicular to it
struct Tangent_frame
{
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  double length_1 = 1;
  double length_2 = 1;
};

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * returns the frame \f$ T = (l_1 d_1, l_2 d_2, \sqrt{l_1 l_2}\, n) \f$ of a surface with the unit
 * normal `n`: \f$ d_1 \f$ is `t.direction` projected onto the tangent plane and normalized,
 * \f$ d_2 = n \times d_1 \f$. A direction along the normal is replaced by one perpendicular to it.
 * \throws std::invalid_argument if a length is not positive and finite or `n` is zero
 */
inline Eigen::Matrix3d tangent_frame_matrix(const Eigen::Vector3d& n, const Tangent_frame& t)
{
  if(!(t.length_1 > 0 && t.length_2 > 0 && std::isfinite(t.length_1) && std::isfinite(t.length_2)))
    throw std::invalid_argument("tangent frame: the lengths must be positive and finite");
  if(!(n.norm() > 0) || !n.allFinite()) throw std::invalid_argument("tangent frame: the normal is zero or not finite");
  const Eigen::Vector3d u = n.normalized();
  Eigen::Vector3d d1 = t.direction - t.direction.dot(u) * u;
  if(!(d1.norm() > 1e-9 * t.direction.norm())) d1 = u.unitOrthogonal();
  d1.normalize();
  Eigen::Matrix3d T;
  T.col(0) = t.length_1 * d1;
  T.col(1) = t.length_2 * u.cross(d1);
  T.col(2) = std::sqrt(t.length_1 * t.length_2) * u;
  return T;
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingFrameFields
 * A frame field on a triangle mesh, given by a tangent frame and a unit normal at each corner of
 * each face (a vertex on a sharp edge has one per side): \f$ T(x) \f$ is interpolated at the
 * point of the face nearest to \f$ x \f$ (a uniform grid over the faces, or an AABB tree where the
 * grid cannot tell) from its three corners,
 * by barycentric weights, the directions turned to agree with the heaviest corner's (a
 * direction and its opposite are one lattice direction, and where the three frames are
 * isotropic, so are directions 60 degrees apart), then `tangent_frame_matrix()` of the
 * interpolated normal. The frames' first two axes span the tangent plane, so that a hexagonal
 * lattice in them lies on the surface (`make_lattice_surface_mesh()`).
 *
 * \tparam GeomTraits a model of `Kernel`
 * \cgalModels `FrameField_3`
 */
template <class GeomTraits>
class Surface_frame_field_3
{
  typedef typename GeomTraits::Triangle_3 Triangle_3;
  typedef typename std::vector<Triangle_3>::const_iterator Triangle_iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GeomTraits, CGAL::AABB_triangle_primitive<GeomTraits, Triangle_iterator>>> Tree;

public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef Eigen::Matrix3d Matrix;
  typedef std::array<std::size_t, 3> Face;
  /// the frames at a face's three corners, and their unit normals
  struct Corner_frames
  {
    std::array<Tangent_frame, 3> frames;
    std::array<Eigen::Vector3d, 3> normals;
  };

  /*!
   * \param points the mesh's vertices
   * \param faces its triangles, as indices into `points`
   * \param corners the frames and normals at each face's corners
   * \throws std::invalid_argument on no face, a count that does not match, an index out of
   *   range, a degenerate face, a zero or non-finite normal or direction, a length that is not
   *   positive and finite
   */
  Surface_frame_field_3(const std::vector<Point_3>& points, const std::vector<Face>& faces, std::vector<Corner_frames> corners)
    : corners_(std::move(corners)), data_(std::make_shared<Data>())
  {
    const std::string who = "Surface_frame_field_3: ";
    if(faces.empty()) throw std::invalid_argument(who + "the mesh has no face");
    if(corners_.size() != faces.size())
      throw std::invalid_argument(who + std::to_string(corners_.size()) + " corner frames for " + std::to_string(faces.size()) + " faces");
    for(const Face& f : faces) {
      for(std::size_t v : f)
        if(v >= points.size()) throw std::invalid_argument(who + "a face refers to vertex " + std::to_string(v));
      data_->triangles.emplace_back(points[f[0]], points[f[1]], points[f[2]]);
      if(data_->triangles.back().is_degenerate()) throw std::invalid_argument(who + "a face is degenerate");
    }
    for(const Corner_frames& c : corners_)
      for(int k = 0; k < 3; ++k) {
        if(!(c.normals[k].norm() > 0) || !c.normals[k].allFinite() || !(c.frames[k].direction.norm() > 0) ||
           !c.frames[k].direction.allFinite())
          throw std::invalid_argument(who + "a corner's normal or direction is zero or not finite");
        tangent_frame_matrix(c.normals[k], c.frames[k]); // checks the lengths
      }
    data_->tree.insert(data_->triangles.begin(), data_->triangles.end());
    data_->tree.build();
    data_->tree.accelerate_distance_queries();
    std::vector<Eigen::Vector3d> lo, hi;
    for(const Triangle_3& t : data_->triangles) {
      data_->corners.push_back({to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2])});
      const auto& c = data_->corners.back();
      lo.push_back(c[0].cwiseMin(c[1]).cwiseMin(c[2]));
      hi.push_back(c[0].cwiseMax(c[1]).cwiseMax(c[2]));
    }
    data_->grid = internal::Uniform_grid_3(lo, hi);
  }

  /*!
   * the field of the frames `frame(p, n)` at the mesh's vertices \f$ p \f$, where \f$ n \f$ is the
   * unit normal of the faces around the vertex on the side of each face: the mean of the normals of
   * the faces around it that turn by at most `features_angle` degrees from that face (so a vertex on
   * a sharp edge has a normal per side)
   * \tparam Frame a callable `Tangent_frame(const Eigen::Vector3d& p, const Eigen::Vector3d& unit_normal)`
   */
  template <class Frame>
  static Surface_frame_field_3 from_tangent_frames(const std::vector<Point_3>& points, const std::vector<Face>& faces,
                                                  const Frame& frame, double features_angle = 60)
  {
    const std::vector<std::array<Eigen::Vector3d, 3>> normals = corner_normals(points, faces, features_angle);
    std::vector<Corner_frames> corners(faces.size());
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k) {
        corners[f].normals[k] = normals[f][k];
        corners[f].frames[k] = frame(to_eigen(points[faces[f][k]]), normals[f][k]);
      }
    return Surface_frame_field_3(points, faces, std::move(corners));
  }

  /*!
   * the field `field` (a model of `FrameField_3`, such as a `Discrete_frame_field_3` read from the
   * frame-field text format: a frame per vertex of the surface, or a volume field) on the tangent
   * planes: at each corner, of the three axes of \f$ T(p) \f$ at its vertex \f$ p \f$, the one
   * nearest to the corner's normal (as `from_tangent_frames()` takes it) is dropped; the first of
   * the two others is the direction, and their lengths are \f$ l_1 \f$ and \f$ l_2 \f$. A field
   * written as \f$ (l_1 d_1, l_2 d_2, \sqrt{l_1 l_2}\, n) \f$ comes back as it was.
   * \throws std::invalid_argument as the constructor, or if `field` throws it at a vertex
   */
  template <class FrameField>
  static Surface_frame_field_3 from_frame_field(const std::vector<Point_3>& points, const std::vector<Face>& faces,
                                               const FrameField& field, double features_angle = 60)
  {
    return from_tangent_frames(points, faces, [&](const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
      const Matrix T = field.T(Point_3(p[0], p[1], p[2]));
      int normal = 0;
      for(int k = 1; k < 3; ++k)
        if(std::abs(T.col(k).normalized().dot(n)) > std::abs(T.col(normal).normalized().dot(n))) normal = k;
      const int first = normal == 0 ? 1 : 0, second = normal == 2 ? 1 : 2;
      Tangent_frame t;
      t.direction = T.col(first);
      t.length_1 = T.col(first).norm();
      t.length_2 = T.col(second).norm();
      return t;
    }, features_angle);
  }

  /*!
   * the unit normal at each corner of each face: the area-weighted mean of the normals of the
   * faces around the corner's vertex that turn by at most `features_angle` degrees from the face
   * \throws std::invalid_argument on no face, a non-finite coordinate, an index out of range or a
   *   degenerate face
   */
  static std::vector<std::array<Eigen::Vector3d, 3>> corner_normals(const std::vector<Point_3>& points,
                                                                    const std::vector<Face>& faces, double features_angle)
  {
    std::vector<Eigen::Vector3d> xyz;
    for(const Point_3& p : points) xyz.push_back(to_eigen(p));
    return internal::Triangle_mesh_features(xyz, faces, features_angle, "Surface_frame_field_3").corner_normals(faces);
  }

  Matrix T(const Point_3& p) const
  {
    const Eigen::Vector3d x = to_eigen(p);
    Eigen::Vector3d nearest;
    const std::size_t f = nearest_face(x, nearest);
    const Corner_frames& c = corners_[f];
    // barycentric weights of the nearest point
    const auto& t = data_->corners[f];
    const Eigen::Vector3d e1 = t[1] - t[0], e2 = t[2] - t[0], q = nearest - t[0];
    const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2), q1 = q.dot(e1), q2 = q.dot(e2);
    const double det = d11 * d22 - d12 * d12;
    double w1 = (d22 * q1 - d12 * q2) / det, w2 = (d11 * q2 - d12 * q1) / det;
    w1 = (std::min)((std::max)(w1, 0.), 1.);
    w2 = (std::min)((std::max)(w2, 0.), 1. - w1);
    const double w[3] = {1 - w1 - w2, w1, w2};
    const int heaviest = w[0] >= w[1] && w[0] >= w[2] ? 0 : (w[1] >= w[2] ? 1 : 2);
    Eigen::Vector3d n = Eigen::Vector3d::Zero(), d = Eigen::Vector3d::Zero();
    Tangent_frame frame;
    frame.length_1 = frame.length_2 = 0;
    const Eigen::Vector3d reference = c.frames[std::size_t(heaviest)].direction.normalized();
    bool isotropic = true;
    for(const Tangent_frame& t : c.frames) isotropic = isotropic && std::abs(t.length_1 - t.length_2) <= 1e-9 * t.length_1;
    for(std::size_t k = 0; k < 3; ++k) {
      n += w[k] * c.normals[k];
      d += w[k] * internal::matched_direction(c.frames[k].direction.normalized(), c.normals[k], reference, isotropic);
      frame.length_1 += w[k] * c.frames[k].length_1;
      frame.length_2 += w[k] * c.frames[k].length_2;
    }
    frame.direction = d.norm() > 0 ? d : reference;
    return tangent_frame_matrix(n.norm() > 0 ? n : c.normals[std::size_t(heaviest)], frame);
  }
  Matrix B(const Point_3& p) const { return T(p).inverse(); }

  /// the index of the face nearest to `p`
  std::size_t face_of(const Point_3& p) const
  {
    Eigen::Vector3d nearest;
    return nearest_face(to_eigen(p), nearest);
  }

  /// the frames and normals at the faces' corners
  const std::vector<Corner_frames>& corner_frames() const { return corners_; }

private:
  /// the point of triangle `t` nearest to `x` (Ericson, Real-Time Collision Detection, 5.1.5)
  static Eigen::Vector3d nearest_on_triangle(const std::array<Eigen::Vector3d, 3>& t, const Eigen::Vector3d& x)
  {
    const Eigen::Vector3d &a = t[0], &b = t[1], &c = t[2];
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = x - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if(d1 <= 0 && d2 <= 0) return a;
    const Eigen::Vector3d bp = x - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if(d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if(vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const Eigen::Vector3d cp = x - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if(d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if(vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if(va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double denominator = 1. / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
  }

  /// the face nearest to `x`, and its nearest point: among the faces listed in `x`'s grid cell if
  /// the ball to the nearest of them lies in that cell (then no other face can be nearer), else
  /// through the AABB tree (about ten times slower)
  std::size_t nearest_face(const Eigen::Vector3d& x, Eigen::Vector3d& nearest) const
  {
    std::size_t best = data_->corners.size();
    double best_d2 = std::numeric_limits<double>::infinity();
    data_->grid.for_each_in_cell(x, [&](std::size_t f) {
      const Eigen::Vector3d q = nearest_on_triangle(data_->corners[f], x);
      const double d2 = (q - x).squaredNorm();
      if(d2 < best_d2 || (d2 == best_d2 && f < best)) {
        best = f;
        best_d2 = d2;
        nearest = q;
      }
    });
    if(best < data_->corners.size()) {
      const Eigen::Vector3d r = Eigen::Vector3d::Constant(std::sqrt(best_d2));
      if(data_->grid.index_of(x - r) == data_->grid.index_of(x + r)) return best;
    }
    const auto hit = data_->tree.closest_point_and_primitive(Point_3(x[0], x[1], x[2]));
    nearest = to_eigen(hit.first);
    return std::size_t(hit.second - data_->triangles.begin());
  }

  template <class P>
  static Eigen::Vector3d to_eigen(const P& p)
  {
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  struct Data // shared by copies: the tree points into the triangles
  {
    std::vector<Triangle_3> triangles;
    Tree tree;
    std::vector<std::array<Eigen::Vector3d, 3>> corners; // the triangles' corners, for the grid's queries
    internal::Uniform_grid_3 grid;                       // the faces by their bounding boxes
  };
  std::vector<Corner_frames> corners_;
  std::shared_ptr<Data> data_;
};

} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_SURFACE_FRAME_FIELD_3_H
