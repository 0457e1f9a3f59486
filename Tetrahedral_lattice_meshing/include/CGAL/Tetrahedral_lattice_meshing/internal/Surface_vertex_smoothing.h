// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Moves the vertices of a surface mesh's worst triangles, measured in a frame
// field's metric, towards the point that makes their one-ring's triangles
// equilateral in that metric, and back onto the surface: where a lattice defect
// or a curve leaves a thin triangle, its vertices move only if the smallest angle
// of their one-ring grows. CGAL's angle smoothing
// (Polygon_mesh_processing::angle_and_area_smoothing()) measures Euclidean angles
// and projects onto the mesh it smooths; here the angles are the field's and the
// vertices stay on the input surface, sliding along its sharp edges.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_VERTEX_SMOOTHING_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_VERTEX_SMOOTHING_H

#include <CGAL/Tetrahedral_lattice_meshing/surface_mesh_quality.h>
#include <CGAL/VVM/internal/Parallel_for.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

using VVM::internal::parallel_for_each_index;

/*
 * Rounds (at most `max_rounds`) over the vertices of the triangles of `mesh` whose smallest angle
 * in the metric of `field` (its frame at the centroid) is under `bound` degrees. A vertex goes
 * towards the mean of the apexes that make each triangle of its one-ring equilateral in the
 * metric of its own frame, then onto `boundary`: onto its curve if two feature edges
 * (`is_feature(edge)`) meet at it, else onto its patch; a corner of `boundary` and a vertex of
 * a border or of another number of feature edges stay. The move, or a half or quarter of it, is
 * kept if no triangle of the one-ring turns by more than 60 degrees and the one-ring's smallest
 * angle grows.
 * A round after the first looks only at the triangles around the vertices the last one moved.
 * Returns the number of moves.
 */
template <class Mesh, class FrameField, class Boundary, class IsFeature>
std::size_t smooth_worst_triangles(Mesh& mesh, const FrameField& field, const Boundary& boundary, const IsFeature& is_feature,
                                   double bound, int max_rounds)
{
  typedef typename Mesh::Point Point;
  typedef typename Mesh::Vertex_index Vertex;
  typedef typename Mesh::Face_index Face;
  auto eig = [&](Vertex v) {
    const Point& p = mesh.point(v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  auto point = [](const Eigen::Vector3d& p) { return Point(p[0], p[1], p[2]); };
  // a face's corners, with `v` at `at` if v is one of them
  auto corners = [&](Face f, Vertex v, const Eigen::Vector3d& at) {
    std::array<Eigen::Vector3d, 3> c;
    int k = 0;
    for(Vertex u : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) c[std::size_t(k++)] = u == v ? at : eig(u);
    return c;
  };
  auto smallest_angle = [&](const std::array<Eigen::Vector3d, 3>& c) {
    return smallest_angle_in_metric(field.B(point((c[0] + c[1] + c[2]) / 3.)), c[0], c[1], c[2]);
  };
  const double cos_turn = 0.5;
  std::size_t moves = 0;
  std::vector<Vertex> last_moved;
  for(int round = 0; round < max_rounds; ++round) {
    // the faces to look at: all of them, then those around the vertices that moved
    std::vector<Face> faces;
    if(round == 0) faces.assign(mesh.faces().begin(), mesh.faces().end());
    else
      for(Vertex v : last_moved)
        for(Face f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
          if(f != Mesh::null_face()) faces.push_back(f);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    last_moved.clear();
    std::vector<char> bad(faces.size(), 0);
    parallel_for_each_index(faces.size(), [&](std::size_t k) {
      bad[k] = smallest_angle(corners(faces[k], Vertex(), Eigen::Vector3d())) < bound;
    });
    std::vector<Vertex> candidates;
    for(std::size_t k = 0; k < faces.size(); ++k)
      if(bad[k])
        for(Vertex v : CGAL::vertices_around_face(mesh.halfedge(faces[k]), mesh)) candidates.push_back(v);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::size_t moved = 0;
    for(Vertex v : candidates) {
      if(mesh.is_border(v)) continue;
      int feature_edges = 0;
      for(auto h : CGAL::halfedges_around_target(v, mesh))
        if(is_feature(mesh.edge(h))) ++feature_edges;
      if(feature_edges != 0 && feature_edges != 2) continue;
      const Eigen::Vector3d p = eig(v);
      const bool on_curve = feature_edges == 2;
      if(on_curve && !boundary.has_sharp_edges()) continue;
      // a corner where two curves meet has two feature edges too; its particle never moved
      if(on_curve && std::find(boundary.corners().begin(), boundary.corners().end(), p) != boundary.corners().end()) continue;
      const int feature = on_curve ? boundary.closest_on_sharp_edge(p).feature : boundary.closest_on_surface(p).feature;
      // the apexes, in the imagined space of v's frame, each in its triangle's plane
      const Eigen::Matrix3d B = field.B(point(p));
      std::vector<Face> ring;
      std::vector<Eigen::Vector3d> normals;
      Eigen::Vector3d target = Eigen::Vector3d::Zero();
      double before = 180;
      for(auto h : CGAL::halfedges_around_target(v, mesh)) {
        const Face f = mesh.face(h);
        ring.push_back(f);
        const auto c = corners(f, Vertex(), Eigen::Vector3d());
        normals.push_back((c[1] - c[0]).cross(c[2] - c[0]));
        before = (std::min)(before, smallest_angle(c));
        // the face (v, a, b), counterclockwise
        const Eigen::Vector3d a = B * eig(mesh.target(mesh.next(h))), b = B * eig(mesh.source(h)), w = B * p;
        const Eigen::Vector3d n = (a - w).cross(b - w);
        target += 0.5 * (a + b) + std::sqrt(3.) / 2 * n.normalized().cross(b - a);
      }
      target = B.inverse() * (target / double(ring.size())) - p;
      if(!target.allFinite()) continue;
      for(double t : {1., 0.5, 0.25}) {
        Eigen::Vector3d q = p + t * target;
        if(on_curve) {
          const auto c = boundary.closest_on_sharp_edge(q);
          if(c.feature != feature) continue;
          q = c.point;
        } else {
          const auto c = boundary.closest_on_surface(q);
          if(c.feature != feature) continue;
          q = c.point;
        }
        double after = 180;
        bool folds = false;
        for(std::size_t k = 0; k < ring.size() && !folds; ++k) {
          const auto c = corners(ring[k], v, q);
          const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]);
          folds = !(n.dot(normals[k]) > cos_turn * n.norm() * normals[k].norm());
          after = (std::min)(after, smallest_angle(c));
        }
        if(folds || !(after > before)) continue;
        mesh.point(v) = point(q);
        last_moved.push_back(v);
        ++moved;
        break;
      }
    }
    moves += moved;
    if(moved == 0) break;
  }
  return moves;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_SURFACE_VERTEX_SMOOTHING_H
