// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::make_lattice_surface_mesh(): a triangle mesh of a surface whose
// vertices form a hexagonal lattice aligned with a tangent frame field
// (dissertation section 4.3.4): the particle engine of lattice_particles_3()
// with six holes in the tangent plane, the particles kept on the surface, then
// their restricted Delaunay triangles and flips to the field's metric.

#ifndef CGAL_MAKE_LATTICE_SURFACE_MESH_H
#define CGAL_MAKE_LATTICE_SURFACE_MESH_H

#include <CGAL/Frame_fields/internal/Triangle_soup.h>
#include <CGAL/Frame_fields/parameters.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Lattice_optimizer.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Restricted_Delaunay_surface.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Surface_boundary.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Surface_metric_flips.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Surface_vertex_smoothing.h>
#include <CGAL/Tetrahedral_lattice_meshing/surface_mesh_quality.h>
#include <CGAL/VVM/internal/Stopping.h>
#include <CGAL/lattice_particles_3.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// what `make_lattice_surface_mesh()` did, filled through the named parameter `report`
struct Lattice_surface_mesh_report
{
  std::size_t number_of_particles = 0;
  std::size_t number_of_sharp_edge_particles = 0; ///< on the feature curves, corners included
  double edge_length = 0;                          ///< \f$ l^* \f$, the lattice's edge in the imagined space
  int number_of_rounds = 0;                        ///< the particles' rounds, all levels
  std::size_t number_of_flips = 0;                 ///< to make the triangles Delaunay in the field's metric, and to undo flat ones
  /// holes of the restricted Delaunay triangles filled (`Polygon_mesh_processing::triangulate_hole()`):
  /// a lattice defect near a sharp edge can leave a particle so near it that no triangle of its
  /// patch reaches the edge there
  std::size_t number_of_filled_holes = 0;
  /// the restricted Delaunay triangles formed a closed 2-manifold (or, on a surface with borders, a
  /// 2-manifold with borders); if not, the triangles on non-manifold edges and vertices were
  /// removed, and their holes filled
  bool is_manifold = false;
  std::size_t number_of_non_manifold_triangles = 0; ///< removed from the restricted Delaunay triangles
  /// vertices moved to raise the smallest angle, in the field's metric, of the triangles around
  /// them (each move counted; a vertex may move in several rounds)
  std::size_t number_of_smoothing_moves = 0;
  double particle_time = 0;                        ///< seconds
  double triangle_time = 0;                        ///< seconds: restricted Delaunay triangles, flips and smoothing
  bool time_limit_reached = false;
  bool stopped_by_visitor = false;
};

} // namespace Tetrahedral_lattice_meshing

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 *
 * makes a triangle mesh of the surface `surface` whose vertices form a hexagonal lattice aligned
 * with the tangent frame field `field` (dissertation section 4.3.4): particles with the Gaussian
 * Hole Kernel of six holes in the plane of the field's first two axes, kept on the surface (each
 * round's L-BFGS moves them in its tangent plane, the projection puts them back on it, AABB tree),
 * with insertion, deletion and the multiresolution start of `lattice_particles_3()`. Sharp edges
 * (the normals of their two faces more than `features_angle` apart), the surface's borders and its
 * non-manifold edges are feature curves: particles near them go onto them and slide along them,
 * their ends and turns over the angle are fixed corners. The triangles are the particles'
 * restricted Delaunay triangles, patch by patch (the patches are the faces between sharp edges;
 * a patch's triangles are the Delaunay facets of its particles whose dual Voronoi edge crosses it
 * at a point no particle is nearer to), so that no triangle cuts a sharp edge; the holes a lattice
 * defect next to a sharp edge leaves are filled (`Polygon_mesh_processing::triangulate_hole()`),
 * and the triangles flipped until they are Delaunay in the field's metric. Last, the vertices of
 * the triangles whose smallest angle in the metric is under 50 degrees move towards the point that
 * makes the triangles around them equilateral in the metric, staying on their patch or sliding
 * along their curve, where that raises the smallest angle around them, and the triangles are
 * flipped again.
 *
 * The field's frames \f$ T(x) \f$ must have their first two axes in the tangent plane at the
 * surface point \f$ x \f$ (`Frame_fields::Surface_frame_field_3`): the lattice's neighbours of a
 * particle at \f$ p \f$ sit at \f$ p + l^* T(p) h_k \f$, \f$ h_k = (\cos k\pi/3, \sin k\pi/3, 0) \f$.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam FrameField a model of `FrameField_3` with the mesh's `Point_3`; it is called from
 *   several threads at once
 * \tparam NamedParameters a sequence of named parameters
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::number_of_particles}
 *     \cgalParamDescription{the number of vertices sought: \f$ l^* \f$ is set so that the lattice
 *       covers the surface's area in the imagined space with that many; if the particles come out
 *       more than 5% off that count (a graded field's lattice has defects), they are made once more
 *       with \f$ l^* \f$ corrected by the ratio (not with `edge_length`)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{10000}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::edge_length}
 *     \cgalParamDescription{\f$ l^* \f$, the lattice's edge in the imagined space}
 *     \cgalParamType{`double`, positive} \cgalParamDefault{from `number_of_particles`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Frame_fields::parameters::features_angle}
 *     \cgalParamDescription{an edge whose faces' normals make a larger angle, in degrees, is a sharp edge}
 *     \cgalParamType{`double`} \cgalParamDefault{60}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{the other named parameters of `lattice_particles_3()`}
 *     \cgalParamDescription{`kernel_width`, `neighbor_radius`, `multiresolution_levels` (default:
 *       \f$ \lceil \log_4 (n / 200) \rceil \f$, at least 0: a coarsest lattice of at most 200 particles), `number_of_iterations`, `random_seed`,
 *       `number_of_threads`, `maximum_running_time` (the rounds stop, the triangles are made),
 *       `visitor` (the particles' rounds and the end of `VVM::Stage::PARTICLES`), `verbose`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::report}
 *     \cgalParamDescription{filled with what the call did}
 *     \cgalParamType{`Tetrahedral_lattice_meshing::Lattice_surface_mesh_report*`} \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the points of `surface`'s vertices}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, surface)`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the triangle mesh; its vertices lie on `surface`
 * \throw std::invalid_argument before any work on a bad parameter, a surface with no face, a face
 *   that is no triangle or is degenerate, a non-finite coordinate, a lattice that is not hexagonal,
 *   or no fewer particles than the sharp edges have corners (each corner is a particle: a small
 *   `features_angle` on a smooth surface makes most vertices corners)
 */
template <class TriangleMesh, class FrameField, class NamedParameters = parameters::Default_named_parameters>
CGAL::Surface_mesh<typename boost::property_traits<
    typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type>
make_lattice_surface_mesh(const TriangleMesh& surface, const FrameField& field,
                          const NamedParameters& np = parameters::default_values())
{
  namespace TLM = Tetrahedral_lattice_meshing;
  namespace PMP = Polygon_mesh_processing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef typename Kernel_traits<Point_3>::Kernel K;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  auto fail = [](const std::string& m) { throw std::invalid_argument("make_lattice_surface_mesh: " + m); };

  auto visitor = get_parameter(np, CGAL::internal_np::visitor);
  VVM::internal::check_visitor<decltype(visitor), TLM::Lattice_round_report>();
  TLM::internal::Lattice_request r = TLM::internal::read_lattice_request(np, true);
  const double features_angle = choose_parameter(get_parameter(np, Frame_fields::internal_np::features_angle), 60.);
  if(!(features_angle >= 0 && features_angle <= 180)) fail("the features angle must be in [0, 180] degrees");
  TLM::Lattice_surface_mesh_report* report =
      choose_parameter(get_parameter(np, VVM::internal_np::report), static_cast<TLM::Lattice_surface_mesh_report*>(nullptr));
  TLM::Lattice_surface_mesh_report local;
  TLM::Lattice_surface_mesh_report& rep = report ? *report : local;
  rep = TLM::Lattice_surface_mesh_report();

  std::vector<Point_3> input_points;
  std::vector<std::array<std::size_t, 3>> faces;
  Frame_fields::internal::triangle_soup(surface, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                                  get_const_property_map(CGAL::vertex_point, surface)),
                                        input_points, faces, "make_lattice_surface_mesh");
  std::vector<Eigen::Vector3d> points;
  for(const Point_3& p : input_points)
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  CGAL::Real_timer timer;
  timer.start();
  const auto thread_limit = VVM::internal::thread_limit(r.threads);
  typedef TLM::internal::Surface_boundary<K> Boundary;
  const Boundary boundary(points, faces, features_angle);

  // l* from the count: the area's particles, and the curves' and corners' rows
  TLM::internal::Domain_measures measures;
  measures.area = TLM::internal::imagined_area<Boundary, FrameField, Point_3>(boundary, field);
  measures.sharp_edge_length = TLM::internal::imagined_sharp_edge_length<Boundary, FrameField, Point_3>(boundary, field);
  measures.number_of_corners = boundary.corners().size();
  if(!(measures.area > 0) || !std::isfinite(measures.area)) fail("the surface has no area");
  double l = r.has_length ? r.edge_length : TLM::internal::lattice_edge_length(r.lattice, measures, r.number_of_particles);
  if(!(l < std::numeric_limits<double>::infinity())) fail("too few particles for the surface's corners");
  const double n = TLM::internal::lattice_particle_count(r.lattice, measures, l);
  TLM::internal::check_particle_count(n, "the edge length " + TLM::internal::readable(l));
  // every corner is a particle: a features angle that makes most edges sharp leaves nothing to place
  if(!(double(measures.number_of_corners) < n))
    fail("the sharp edges have " + std::to_string(measures.number_of_corners) + " corners, not fewer than the " +
         TLM::internal::readable(n) + " particles of the lattice: raise features_angle (0 makes every bent edge sharp) or " +
         "ask for more particles");
  // from a coarsest lattice of at most 200 particles: from a random start at the finest level,
  // grains of different orientations meet in lines of defects
  if(r.options.multiresolution_levels < 0)
    r.options.multiresolution_levels = n > 200 ? (std::min)(6, int(std::ceil(std::log(n / 200) / std::log(4.)))) : 0;

  // the particles; on a graded field the lattice's count is not the estimate's (its defects): if
  // it is more than 5% off the count sought, once more with l* corrected by that ratio
  const VVM::internal::Time_limit time_limit(r.options.maximum_running_time);
  auto particles_at = [&](double length) {
    if(time_limit.is_set()) r.options.maximum_running_time = (std::max)(time_limit.remaining(), 1e-9);
    TLM::internal::Lattice_optimizer<FrameField, Boundary, Point_3> optimizer(r.lattice, field, boundary, length, r.options);
    return optimizer.run();
  };
  TLM::Lattice_particles_3<Point_3> particles = particles_at(l);
  const double count_ratio = double(particles.size()) / r.number_of_particles;
  if(!r.has_length && !particles.time_limit_reached && !particles.stopped_by_visitor && std::abs(count_ratio - 1) > 0.05) {
    l *= std::sqrt(count_ratio);
    const int rounds = particles.number_of_rounds;
    particles = particles_at(l);
    particles.number_of_rounds += rounds;
  }
  rep.number_of_particles = particles.size();
  rep.number_of_sharp_edge_particles =
      particles.number_of(TLM::Particle_kind::SHARP_EDGE) + particles.number_of(TLM::Particle_kind::CORNER);
  rep.edge_length = l;
  rep.number_of_rounds = particles.number_of_rounds;
  rep.time_limit_reached = particles.time_limit_reached;
  rep.stopped_by_visitor = particles.stopped_by_visitor;
  rep.particle_time = timer.time();
  if(!rep.stopped_by_visitor &&
     !VVM::internal::visit_stage_end(visitor, VVM::Stage::PARTICLES, particles.number_of_rounds, rep.particle_time))
    rep.stopped_by_visitor = true;

  // the patches each particle touches, for the restricted Delaunay triangles
  std::vector<Eigen::Vector3d> xyz;
  std::vector<std::set<int>> patches;
  for(std::size_t i = 0; i < particles.size(); ++i) {
    const Point_3& p = particles.points[i];
    xyz.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    const int f = particles.features[i];
    switch(particles.kinds[i]) {
      case TLM::Particle_kind::CORNER: patches.push_back(boundary.corner_patches()[std::size_t(f)]); break;
      case TLM::Particle_kind::SHARP_EDGE: patches.push_back(boundary.curve_patches()[std::size_t(f)]); break;
      default: patches.push_back({f});
    }
  }
  const double timer_before_triangles = timer.time();
  std::vector<std::array<std::size_t, 3>> triangles =
      TLM::internal::restricted_Delaunay_triangles<K>(xyz, patches, boundary, 1e-6 * l);
  std::vector<Point_3> soup_points(particles.points);
  rep.is_manifold = PMP::is_polygon_soup_a_polygon_mesh(triangles);
  if(!rep.is_manifold) {
    rep.number_of_non_manifold_triangles = TLM::internal::remove_non_manifold_triangles(triangles);
    if(!PMP::is_polygon_soup_a_polygon_mesh(triangles)) PMP::orient_polygon_soup(soup_points, triangles);
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup_points, triangles, mesh);
  // the particles not in any triangle
  std::vector<typename Mesh::Vertex_index> isolated;
  for(auto v : mesh.vertices())
    if(mesh.is_isolated(v)) isolated.push_back(v);
  for(auto v : isolated) mesh.remove_vertex(v);
  mesh.collect_garbage();

  // the curve an edge lies on (its midpoint within a tenth of its length, as a chord of a curved
  // curve leaves it by its sagitta), or -1
  auto curve_of = [&](typename Mesh::Edge_index e) {
    if(!boundary.has_sharp_edges()) return -1;
    const Point_3 &a = mesh.point(mesh.vertex(e, 0)), &b = mesh.point(mesh.vertex(e, 1));
    const Eigen::Vector3d m(0.5 * (CGAL::to_double(a.x()) + CGAL::to_double(b.x())),
                            0.5 * (CGAL::to_double(a.y()) + CGAL::to_double(b.y())),
                            0.5 * (CGAL::to_double(a.z()) + CGAL::to_double(b.z())));
    const auto c = boundary.closest_on_sharp_edge(m);
    return c.distance <= 0.1 * std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))) ? c.feature : -1;
  };
  auto is_feature = [&](typename Mesh::Edge_index e) { return curve_of(e) >= 0; };
  // holes: where a lattice defect near a sharp edge left a particle so near it that its
  // triangles' duals leave the patch; a border cycle that is not along the surface's own borders
  {
    std::vector<typename Mesh::Halfedge_index> holes;
    std::set<typename Mesh::Halfedge_index> walked;
    for(auto h : mesh.halfedges()) {
      if(!mesh.is_border(h) || walked.count(h)) continue;
      bool along_borders = true;
      for(auto g : CGAL::halfedges_around_face(h, mesh)) {
        walked.insert(g);
        const int c = curve_of(mesh.edge(g));
        if(c < 0 || !boundary.is_border_curve(c)) along_borders = false;
      }
      if(!along_borders) holes.push_back(h);
    }
    for(auto h : holes) {
      std::vector<typename Mesh::Face_index> filled;
      PMP::triangulate_hole(mesh, h, std::back_inserter(filled));
      rep.number_of_filled_holes += filled.empty() ? 0 : 1;
    }
  }
  rep.number_of_flips = TLM::internal::flip_flat_triangles(mesh, is_feature);
  rep.number_of_flips += TLM::internal::flip_to_metric_Delaunay(mesh, field, is_feature);
  // the vertices of triangles under 50 degrees in the metric, towards equilateral one-rings
  rep.number_of_smoothing_moves = TLM::internal::smooth_worst_triangles(mesh, field, boundary, is_feature, 50., 5);
  if(rep.number_of_smoothing_moves > 0) rep.number_of_flips += TLM::internal::flip_to_metric_Delaunay(mesh, field, is_feature);
  rep.triangle_time = timer.time() - timer_before_triangles;
  return mesh;
}

} // namespace CGAL

#endif // CGAL_MAKE_LATTICE_SURFACE_MESH_H
