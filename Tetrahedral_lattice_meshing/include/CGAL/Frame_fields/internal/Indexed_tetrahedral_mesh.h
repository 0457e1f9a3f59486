// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the cross-field generator needs from a tetrahedral mesh, as plain
// indices: the cells of the domain, its boundary facets and its sharp edges,
// from a Mesh_complex_3_in_triangulation_3 (cells, facets and edges in the
// complex) or from a Triangulation_3 (finite cells, convex hull, hull edges
// sharper than an angle).

#ifndef CGAL_FRAME_FIELDS_INTERNAL_INDEXED_TETRAHEDRAL_MESH_H
#define CGAL_FRAME_FIELDS_INTERNAL_INDEXED_TETRAHEDRAL_MESH_H

#include <CGAL/VVM/internal/Eigen_conversion.h>
#include <CGAL/VVM/internal/Edges_in_complex.h>
#include <CGAL/VVM/internal/Vertex_numbering.h>

#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/number_type_config.h> // CGAL_PI
#include <CGAL/Triangulation_3.h>

#include <Eigen/Core>
#include <Eigen/Geometry> // cross()

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Frame_fields {
namespace internal {

template <class Point_3>
struct Indexed_tetrahedral_mesh
{
  std::vector<Point_3> points;            // bare points
  std::vector<Eigen::Vector3d> xyz;       // the same, in doubles
  std::vector<std::array<std::size_t, 4>> cells;
  std::vector<std::array<std::size_t, 3>> boundary_facets;
  std::vector<std::array<std::size_t, 2>> feature_edges;

  void check(const char* who) const
  {
    if(cells.empty())
      throw std::invalid_argument(std::string(who) + ": the mesh has no cell (empty mesh)");
    for(const Eigen::Vector3d& p : xyz)
      if(!p.allFinite())
        throw std::invalid_argument(std::string(who) + ": a vertex has a non-finite coordinate");
  }
};

// numbers the vertices of a triangulation as they are met, adding them to the mesh
template <class Tr, class Mesh>
class Mesh_vertex_numbering
{
public:
  Mesh_vertex_numbering(const Tr& tr, Mesh& mesh) : number_(tr), mesh_(mesh) {}

  std::size_t operator()(typename Tr::Vertex_handle v)
  {
    return number_(v, [this](const auto& p) {
      mesh_.points.push_back(p);
      mesh_.xyz.push_back(VVM::internal::to_eigen(p));
    });
  }

private:
  VVM::internal::Vertex_numbering<Tr> number_;
  Mesh& mesh_;
};

template <class Tr, class Mesh>
std::array<std::size_t, 3> facet_indices(const typename Tr::Facet& f, Mesh_vertex_numbering<Tr, Mesh>& number)
{
  std::array<std::size_t, 3> t;
  for(int k = 0, j = 0; k < 4; ++k)
    if(k != f.second) t[std::size_t(j++)] = number(f.first->vertex(k));
  return t;
}

/// the convex hull's edges whose two facets' normals differ by more than `angle_deg`
template <class Mesh>
void detect_sharp_boundary_edges(Mesh& mesh, const std::vector<Eigen::Vector3d>& outward_normals,
                                 double angle_deg)
{
  if(!(angle_deg > 0)) return;
  const double cos_bound = std::cos(angle_deg * CGAL_PI / 180);
  std::map<std::array<std::size_t, 2>, std::vector<std::size_t>> facets_of_edge;
  for(std::size_t f = 0; f < mesh.boundary_facets.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      std::size_t a = mesh.boundary_facets[f][std::size_t(k)], b = mesh.boundary_facets[f][std::size_t((k + 1) % 3)];
      facets_of_edge[{{(std::min)(a, b), (std::max)(a, b)}}].push_back(f);
    }
  for(const auto& ef : facets_of_edge)
    if(ef.second.size() == 2 &&
       outward_normals[ef.second[0]].dot(outward_normals[ef.second[1]]) < cos_bound)
      mesh.feature_edges.push_back(ef.first);
}

/// finite cells; the convex hull as boundary; hull edges sharper than `features_angle_deg`
template <class GT, class TDS, class Lds>
Indexed_tetrahedral_mesh<typename GT::Point_3>
indexed_mesh(const Triangulation_3<GT, TDS, Lds>& tr, double features_angle_deg)
{
  typedef Triangulation_3<GT, TDS, Lds> Tr;
  typedef Indexed_tetrahedral_mesh<typename GT::Point_3> Mesh;
  Mesh mesh;
  if(tr.dimension() < 3) return mesh;
  Mesh_vertex_numbering<Tr, Mesh> number(tr, mesh);
  std::vector<Eigen::Vector3d> normals;
  for(auto c : tr.finite_cell_handles()) {
    mesh.cells.push_back({{number(c->vertex(0)), number(c->vertex(1)), number(c->vertex(2)), number(c->vertex(3))}});
    for(int i = 0; i < 4; ++i) {
      if(!tr.is_infinite(c->neighbor(i))) continue;
      const std::array<std::size_t, 3> t = facet_indices<Tr, Mesh>(typename Tr::Facet(c, i), number);
      mesh.boundary_facets.push_back(t);
      Eigen::Vector3d n = (mesh.xyz[t[1]] - mesh.xyz[t[0]]).cross(mesh.xyz[t[2]] - mesh.xyz[t[0]]);
      if(n.dot(mesh.xyz[number(c->vertex(i))] - mesh.xyz[t[0]]) > 0) n = -n; // away from the cell
      normals.push_back(n.normalized());
    }
  }
  detect_sharp_boundary_edges(mesh, normals, features_angle_deg);
  return mesh;
}

/// cells, facets and edges in the complex
template <class Tr, class CornerIndex, class CurveIndex>
Indexed_tetrahedral_mesh<typename Tr::Geom_traits::Point_3>
indexed_mesh(const Mesh_complex_3_in_triangulation_3<Tr, CornerIndex, CurveIndex>& c3t3, double)
{
  typedef Indexed_tetrahedral_mesh<typename Tr::Geom_traits::Point_3> Mesh;
  Mesh mesh;
  Mesh_vertex_numbering<Tr, Mesh> number(c3t3.triangulation(), mesh);
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    mesh.cells.push_back({{number(c->vertex(0)), number(c->vertex(1)), number(c->vertex(2)), number(c->vertex(3))}});
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    mesh.boundary_facets.push_back(facet_indices<Tr, Mesh>(*f, number));
  for(const auto& e : VVM::internal::edges_in_complex(c3t3)) {
    const std::size_t a = number(e.first->vertex(e.second)), b = number(e.first->vertex(e.third));
    mesh.feature_edges.push_back({{(std::min)(a, b), (std::max)(a, b)}});
  }
  return mesh;
}

} // namespace internal
} // namespace Frame_fields
} // namespace CGAL

#endif // CGAL_FRAME_FIELDS_INTERNAL_INDEXED_TETRAHEDRAL_MESH_H
