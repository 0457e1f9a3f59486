// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh as a 3D linear cell complex: one volume per cell, the
// vertices shared, the volumes 3-sewn along the faces they share.

#ifndef CGAL_HEX_DOMINANT_MESHING_HEX_DOMINANT_MESH_TO_LINEAR_CELL_COMPLEX_H
#define CGAL_HEX_DOMINANT_MESHING_HEX_DOMINANT_MESH_TO_LINEAR_CELL_COMPLEX_H

#include <CGAL/Hex_dominant_mesh_3.h>

#include <CGAL/Linear_cell_complex_incremental_builder.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Hex_dominant_meshing {
namespace internal {

// the mesh's point as a point of the complex, through doubles if it does not convert
template <class Target, class Source>
Target lcc_point(const Source& p)
{
  if constexpr(std::is_convertible<const Source&, Target>::value)
    return p;
  else
    return Target(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

} // namespace internal

/*!
 * \ingroup PkgHexDominantMeshingRef
 * replaces the content of `lcc` by `mesh`: one volume per cell, the volumes that share a
 * whole face 3-sewn along it, and one vertex attribute per point of `mesh` used by a cell,
 * shared by the volumes around it.
 *
 * Tetrahedra are made by `make_tetrahedron()` and hexahedra by `make_hexahedron()`
 * (whose vertices `4 5 6 7` lie above `3 0 1 2`, where the mesh's `4 5 6 7` lie above
 * `0 1 2 3`); prisms and pyramids, for which CGAL has no such function, face by face
 * with `Linear_cell_complex_incremental_builder_3`. All volumes come out alike
 * oriented, their faces turning around normals that point into the volume, as
 * `make_tetrahedron()` makes a positively oriented tetrahedron (this is how
 * `import_from_triangulation_3()` builds them); two volumes sharing a face thus run
 * through it in opposite directions, as 3-sewing requires.
 *
 * A triangle of a tetrahedron, prism or pyramid lying on one half of the quadrilateral
 * of a hexahedron or prism (a quadrilateral against two triangles) is no face of the
 * other volume: these faces stay 3-free, as do the faces on the boundary of the mesh.
 * The volumes around a point of such a face may then no longer be joined through sewn
 * faces, and a combinatorial map wants an attribute to belong to one vertex (one orbit
 * of darts): such a point gets one vertex attribute per group of joined volumes (by
 * `correct_invalid_attributes()`), so that `lcc` has more vertex attributes than
 * `mesh` has points.
 *
 * \tparam LCC a `Linear_cell_complex_for_combinatorial_map<3>` (dimension 3 in the
 * 3D space) whose `Point` converts from `Point_3` or is made from three doubles
 * \pre `mesh` is a conforming mesh whose cells are positively oriented and whose points
 * are pairwise distinct (shared faces are found by their points, with `sew3_same_facets()`)
 * \post `lcc.is_valid()`; `lcc.number_of_vertex_attributes() == mesh.number_of_points()`
 * if every point is used by a cell and the cells around every point are joined through
 * the faces they share
 */
template <class LCC, class Point_3>
void hex_dominant_mesh_to_linear_cell_complex(const Hex_dominant_mesh_3<Point_3>& mesh, LCC& lcc)
{
  static_assert(LCC::dimension == 3 && LCC::ambient_dimension == 3,
                "hex_dominant_mesh_to_linear_cell_complex: a 3D linear cell complex of dimension 3 is needed");
  typedef typename LCC::Point LCC_point;
  typedef typename LCC::Vertex_attribute_handle Vertex_handle;
  typedef Hex_dominant_cell_type Cell_type;

  lcc.clear();
  // The builder creates the vertex attributes, so that its indices are the mesh's.
  Linear_cell_complex_incremental_builder_3<LCC> builder(lcc);
  std::vector<Vertex_handle> vh;
  vh.reserve(mesh.number_of_points());
  for(const auto& p : mesh.points) vh.push_back(builder.add_vertex(internal::lcc_point<LCC_point>(p)));

  for(const auto& c : mesh.cells) {
    const auto& v = c.vertices;
    for(std::size_t i = 0; i < c.size(); ++i) CGAL_precondition(v[i] < mesh.number_of_points());
    auto id = [&v](int i) { return static_cast<typename LCC::size_type>(v[i]); }; // the builder's index
    switch(c.type) {
      case Cell_type::TETRAHEDRON:
        lcc.make_tetrahedron(vh[v[0]], vh[v[1]], vh[v[2]], vh[v[3]]);
        break;
      case Cell_type::HEXAHEDRON:
        lcc.make_hexahedron(vh[v[0]], vh[v[1]], vh[v[2]], vh[v[3]], vh[v[7]], vh[v[4]], vh[v[5]], vh[v[6]]);
        break;
      case Cell_type::PRISM: // the faces turn around inner normals, as the triangle 0 1 2 does
        builder.begin_surface();
        builder.add_facet({id(0), id(1), id(2)});
        builder.add_facet({id(3), id(5), id(4)});
        builder.add_facet({id(1), id(0), id(3), id(4)});
        builder.add_facet({id(2), id(1), id(4), id(5)});
        builder.add_facet({id(0), id(2), id(5), id(3)});
        builder.end_surface();
        break;
      case Cell_type::PYRAMID: // as the base 0 1 2 3, whose normal points to the apex
        builder.begin_surface();
        builder.add_facet({id(0), id(1), id(2), id(3)});
        builder.add_facet({id(1), id(0), id(4)});
        builder.add_facet({id(2), id(1), id(4)});
        builder.add_facet({id(3), id(2), id(4)});
        builder.add_facet({id(0), id(3), id(4)});
        builder.end_surface();
        break;
    }
  }
  // The builder has sewn the prisms and pyramids among themselves; this sews the rest.
  lcc.sew3_same_facets();
  // Splits the attributes of the points whose volumes stay apart (quadrilateral against
  // two triangles), and removes those of the unused points.
  lcc.correct_invalid_attributes();
  CGAL_postcondition(lcc.is_valid());
}

} // namespace Hex_dominant_meshing
} // namespace CGAL

#endif // CGAL_HEX_DOMINANT_MESHING_HEX_DOMINANT_MESH_TO_LINEAR_CELL_COMPLEX_H
