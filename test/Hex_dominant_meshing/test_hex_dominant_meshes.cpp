// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_hex_dominant_mesh_3 on domains: the cube with the identity field (all hexahedra,
// also at an odd layer count), a tube in the scale-corrected cylinder field (all hexahedra),
// a warped cube with a shear field and a cube with Fig. 4.8's
// field (cells 80 times thinner along x than across) give hexahedra only; a flat tet on a
// hexahedron's boundary quad is taken in by it; the boundary refinement brings the tets'
// boundary closer to a sphere; bad parameters of make_hex_dominant_mesh_3 throw.

#include "hex_dominant_test_support.h"
#include "output_hash.h"

#include "../../benchmark/common/box_surface.h" // the benchmark's tube

namespace {

// make_hex_dominant_mesh_3 on the cube [-1, 1]^3 with the identity field: the cubic lattice
// merges into hexahedra, the cells are valid and partition the tets
void test_make_hex_dominant_mesh_on_cube()
{
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(vvm_test::data_file("cube.off"), surface));
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  std::vector<CGAL::VVM::Stage> stages; // the ends the visitor was told of
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, Constant_field(),
      TLM::parameters::edge_length(0.25, HDM::parameters::report(&report,
          TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(3u).visitor(
              [&](const CGAL::VVM::Stage_report& r) { if(r.stage_done) stages.push_back(r.stage); })))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, cube, l* 0.25: " << report.number_of_particles << " particles, "
            << report.merge.number_of_tets << " tets -> " << s.number_of_hexahedra << " hex, " << s.number_of_prisms
            << " prisms, " << s.number_of_pyramids << " pyramids, " << s.number_of_tetrahedra << " tets; H_vol "
            << s.hexahedron_volume_percent << "%, SJ min/mean " << s.scaled_jacobian_min << "/" << s.scaled_jacobian_mean
            << ", volume " << s.total_volume << ", times " << report.particle_time << " + " << report.tetrahedra_time << " + "
            << report.merge_time << " s\n";
  VVM_CHECK(stages == std::vector<CGAL::VVM::Stage>({CGAL::VVM::Stage::PARTICLES, CGAL::VVM::Stage::TETRAHEDRA,
                                                     CGAL::VVM::Stage::MERGING}));
  VVM_CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
  VVM_CHECK(s.hexahedron_volume_percent > 90);
  VVM_CHECK(s.scaled_jacobian_min > 0.5);
  VVM_CHECK(std::abs(s.total_volume - 8.) < 0.08); // the particles' hull on the cube's surface
  for(const auto& c : mesh.cells) VVM_CHECK(c.subdomain_index == 1);
  // the field given as a named parameter (to the overload without a positional field) is the same field
  const Mesh named = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, HDM::parameters::frame_field(Constant_field(), TLM::parameters::edge_length(0.25,
          TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(3u)))));
  VVM_CHECK_EQUAL(vvm_test::hex_dominant_hash(named), vvm_test::hex_dominant_hash(mesh));

  VVM_CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), TLM::parameters::lattice(TLM::Lattice_type::BCC)); }));
  VVM_CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), TLM::parameters::edge_length(-1.)); }));
  VVM_CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), TLM::parameters::edge_length(1e-5)); }));
  VVM_CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), HDM::parameters::quality_bound(2.)); }));
}

// make_hex_dominant_mesh_3 on the cube at 5,832 = 18^3 particles, with the default levels: the
// cube wants 17 cells across, which a lattice refined once from 2 l* cannot have (it left a
// dislocation line of prisms and tets); the lattice must come out whole, all-hex, filling the cube
void test_all_hex_cube_at_odd_layer_count()
{
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(vvm_test::data_file("cube.off"), surface));
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, Constant_field(),
      TLM::parameters::number_of_particles(std::size_t(5832), HDM::parameters::report(&report,
          TLM::parameters::number_of_threads(2))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, cube, 5832 particles asked: " << report.number_of_particles << " particles, "
            << s.number_of_hexahedra << " hex, " << s.number_of_prisms << " prisms, " << s.number_of_pyramids
            << " pyramids, " << s.number_of_tetrahedra << " tets; H_vol " << s.hexahedron_volume_percent << "%, SJ min "
            << s.scaled_jacobian_min << "\n";
  VVM_CHECK(s.number_of_hexahedra > 0 && s.number_of_prisms + s.number_of_pyramids + s.number_of_tetrahedra == 0);
  VVM_CHECK(s.hexahedron_volume_percent > 99.999);
  VVM_CHECK(std::abs(s.total_volume - 8.) < 0.08);
  VVM_CHECK(s.scaled_jacobian_min > 0.9);
  VVM_CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
}

// make_hex_dominant_mesh_3 on the tube in the scale-corrected cylinder field (Fig. 4.16a) at
// 30,000 particles asked, the default levels: every ring around the axis holds the same number
// of cells, so the lattice must come out whole (11 x 21 layers of equal rings) and all-hex. The
// exact gradient of the particle energy at the coarsest level left dislocation lines of prisms
// and tets here
void test_all_hex_scale_corrected_cylinder()
{
  const Surface_mesh surface = vvm_benchmark::tube_surface<Surface_mesh>(256);
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, CGAL::Frame_fields::cylinder_frame_field<K>(1., true),
      TLM::parameters::number_of_particles(std::size_t(30000), HDM::parameters::report(&report,
          TLM::parameters::number_of_threads(2))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, scale-corrected cylinder, 30000 particles asked: "
            << report.number_of_particles << " particles, " << s.number_of_hexahedra << " hex, "
            << s.number_of_prisms << " prisms, " << s.number_of_pyramids << " pyramids, " << s.number_of_tetrahedra
            << " tets; H_vol " << s.hexahedron_volume_percent << "%, SJ min " << s.scaled_jacobian_min << "\n";
  VVM_CHECK(report.number_of_particles % (11 * 21) == 0);
  VVM_CHECK(s.number_of_hexahedra == report.number_of_particles / (11 * 21) * 10 * 20);
  VVM_CHECK(s.number_of_prisms + s.number_of_pyramids + s.number_of_tetrahedra == 0);
  VVM_CHECK(s.scaled_jacobian_min > 0.9);
  VVM_CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
}

// make_hex_dominant_mesh_3 on the warped cube T [-1, 1]^3 of the shear T of Fig. 4.15e: its
// faces are lattice planes, and the tets (Delaunay of the particles mapped into the field's
// space) merge into hexahedra only
void test_make_hex_dominant_mesh_on_warped_cube()
{
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(vvm_test::data_file("cube.off"), surface));
  Eigen::Matrix3d T;
  T << 1, 1, 0,
       0, 2, 0,
       0, 0, 1;
  T /= std::cbrt(T.determinant());
  for(auto v : surface.vertices()) {
    const Point_3& p = surface.point(v);
    const Eigen::Vector3d x = T * Eigen::Vector3d(p.x(), p.y(), p.z());
    surface.point(v) = Point_3(x[0], x[1], x[2]);
  }
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  const Constant_field field(T);
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, field, TLM::parameters::edge_length(0.25, HDM::parameters::report(&report,
          TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(1u)))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(
      mesh, [&](const Eigen::Vector3d&) { return field.B(Point_3(0, 0, 0)); }, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, warped cube (shear), l* 0.25: " << report.number_of_particles << " particles, "
            << report.number_of_metric_flips << " metric flips -> " << s.number_of_hexahedra << " hex, "
            << mesh.cells.size() - s.number_of_hexahedra << " other cells; H_vol " << s.hexahedron_volume_percent
            << "%, SJ min " << s.scaled_jacobian_min << "\n";
  VVM_CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
  VVM_CHECK(s.hexahedron_volume_percent > 99.);
  VVM_CHECK(s.scaled_jacobian_min > 0.9);
}

// a face of the cube bent outward along its diagonal 1-2, split by the hexahedron's tets
// along 0-3: Delaunay puts the flat tet 0123 on it, outside the six tets. The hexahedron
// takes it in; a tet on the face that is not flat stays a tet.
void test_flat_tet_on_boundary_quad()
{
  for(double bend : {0.02, 0.4}) {
    std::vector<Point_3> corners;
    for(int c = 0; c < 8; ++c) corners.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    corners[1] = Point_3(1, 0, -bend);
    corners[2] = Point_3(0, 1, -bend);
    const std::vector<std::array<std::size_t, 4>> tets = {
        {{0, 1, 3, 7}}, {{0, 1, 5, 7}}, {{0, 2, 3, 7}}, {{0, 2, 6, 7}}, {{0, 4, 5, 7}}, {{0, 4, 6, 7}}, {{0, 1, 2, 3}}};
    HDM::Hex_dominant_merge_report report;
    const Mesh mesh = CGAL::tets_to_hex_dominant(corners, tets, {}, HDM::parameters::quality_bound(0., HDM::parameters::report(&report)));
    std::vector<int> corner_of_point(8);
    for(int c = 0; c < 8; ++c) corner_of_point[std::size_t(c)] = c;
    const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, nullptr, &report);
    std::vector<int> uses(tets.size(), 0);
    for(const auto& c : report.cell_tets)
      for(std::size_t t : c) ++uses[t];
    std::cout << "flat tet on a boundary quad (bend " << bend << "): " << mesh.cells.size() << " cells, "
              << report.number_of_flat_tets_taken_in << " flat tet taken in\n";
    VVM_CHECK(mesh.cells[0].type == CGAL::Hex_dominant_cell_type::HEXAHEDRON &&
          has_cube_corner_order(mesh.cells[0], corner_of_point));
    VVM_CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
    VVM_CHECK(std::count(uses.begin(), uses.end(), 1) == std::ptrdiff_t(tets.size())); // a partition of the tets
    if(bend < 0.1)
      VVM_CHECK(mesh.cells.size() == 1 && report.cell_tets[0].size() == 7 && report.number_of_flat_tets_taken_in == 1);
    else
      VVM_CHECK(mesh.cells.size() == 2 && report.cell_tets[0].size() == 6 && report.number_of_flat_tets_taken_in == 0);
  }
}

// make_hex_dominant_mesh_3 on [0.1, 1.1]^3 with Fig. 4.8's field T = diag(1.0125 -
// exp(-|x - 0.6|), 1, 1) (Fig. 4.15d): near x = 0.6 the lattice's cells are 80 times thinner
// along x than across, flat in Euclidean space. Only in the field's space are the boundary
// cells not flat; measured in Euclidean space, those along the cube's edges were peeled off
// as flat surface cells (95.8% of hexahedron volume at 800 particles)
void test_make_hex_dominant_mesh_on_graded_cube()
{
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(vvm_test::data_file("cube.off"), surface));
  for(auto v : surface.vertices()) {
    const Point_3& p = surface.point(v); // [-1, 1]^3 -> [0.1, 1.1]^3
    surface.point(v) = Point_3(0.6 + 0.5 * p.x(), 0.6 + 0.5 * p.y(), 0.6 + 0.5 * p.z());
  }
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  const auto field = CGAL::Frame_fields::single_direction_anisotropy_frame_field<K>();
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, field, TLM::parameters::number_of_particles(800, HDM::parameters::report(&report,
          TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(1u)))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(
      mesh, [&](const Eigen::Vector3d& x) { return Eigen::Matrix3d(field.B(Point_3(x[0], x[1], x[2]))); }, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, cube with Fig. 4.8's field, 800 particles asked: " << report.number_of_particles
            << " particles -> " << s.number_of_hexahedra << " hex, " << mesh.cells.size() - s.number_of_hexahedra
            << " other cells; H_vol " << s.hexahedron_volume_percent << "%, SJ min " << s.scaled_jacobian_min
            << ", volume " << s.total_volume << "\n";
  VVM_CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
  VVM_CHECK(std::abs(s.total_volume - 1) < 1e-9);
  VVM_CHECK(s.hexahedron_volume_percent > 99.99);
  VVM_CHECK(s.scaled_jacobian_min > 0.9);
}

// the largest distance from the tets' boundary facets (corners, edge midpoints, centroids) to
// the surface
double boundary_facet_distance(const Cube_c3t3& c3t3, const Surface_mesh& surface)
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Surface_mesh> Primitive;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree(faces(surface).first, faces(surface).second, surface);
  double d2 = 0;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    std::array<Point_3, 3> p;
    for(int k = 0; k < 3; ++k) p[std::size_t(k)] = f->first->vertex((f->second + k + 1) & 3)->point().point();
    for(const Point_3& x : {CGAL::centroid(p[0], p[1], p[2]), CGAL::midpoint(p[0], p[1]), CGAL::midpoint(p[1], p[2]),
                            CGAL::midpoint(p[2], p[0])})
      d2 = (std::max)(d2, tree.squared_distance(x));
  }
  return std::sqrt(d2);
}

// Determinism: make_hex_dominant_mesh_3 on a polyhedral sphere and tets_to_hex_dominant on
// the Delaunay tets of a jittered cubic grid give bit-identical meshes with 1, 2 and 4
// threads, and again after another run in a fragmented heap (the objects of the run then lie
// elsewhere, in another order of addresses).
void test_determinism()
{
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(vvm_test::data_file("sphere966.off"), surface));
  Cube_domain domain(surface);
  domain.detect_features(60);
  auto mesh = [&](int threads, std::size_t particles) {
    return CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(),
        TLM::parameters::number_of_particles(particles, TLM::parameters::number_of_threads(threads,
            CGAL::parameters::random_seed(3u))));
  };
  vvm_test::check_deterministic("make_hex_dominant_mesh_3, sphere",
      [&](int threads) { return vvm_test::hex_dominant_hash(mesh(threads, 1500)); },
      [&] { mesh(2, 1000); });

  auto grid = [](int n) {
    CGAL::Random random(7);
    std::vector<Point_3> points;
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j)
        for(int k = 0; k < n; ++k)
          points.emplace_back(i + random.get_double(-0.1, 0.1), j + random.get_double(-0.1, 0.1),
                              k + random.get_double(-0.1, 0.1));
    return Delaunay(points.begin(), points.end());
  };
  const Delaunay tets = grid(9), other_tets = grid(7);
  auto merged = [&](int threads, const Delaunay& tr) {
    return CGAL::tets_to_hex_dominant(tr, TLM::parameters::number_of_threads(threads));
  };
  vvm_test::check_deterministic("tets_to_hex_dominant, jittered grid",
      [&](int threads) { return vvm_test::hex_dominant_hash(merged(threads, tets)); },
      [&] { merged(2, other_tets); });
}

// the boundary refinement of section 4.4.2 on a sphere: surface points are added where the
// tets' facets cut the sphere too deep, and the facets come closer to it
void test_boundary_refinement()
{
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(vvm_test::data_file("sphere966.off"), surface));
  Cube_domain domain(surface);
  double distance[2] = {0, 0};
  for(int refine = 0; refine < 2; ++refine) {
    HDM::Hex_dominant_report report;
    Cube_c3t3 tets;
    const double threshold = refine ? 0.5 * distance[0] : 0.;
    const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
        domain, Constant_field(), TLM::parameters::edge_length(2.5, HDM::parameters::boundary_distance(threshold,
            HDM::parameters::report(&report, HDM::parameters::tetrahedral_mesh(&tets,
                TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(2u)))))));
    distance[refine] = boundary_facet_distance(tets, surface);
    const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report.merge);
    std::cout << "sphere of radius 10, l* 2.5, boundary distance " << threshold << ": " << report.number_of_boundary_points
              << " surface points added, facets within " << distance[refine] << " of the sphere; " << s.number_of_hexahedra
              << " hex, H_vol " << s.hexahedron_volume_percent << "%\n";
    VVM_CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
    VVM_CHECK((report.number_of_boundary_points > 0) == (refine == 1));
  }
  VVM_CHECK(distance[1] < 0.75 * distance[0]);
  VVM_CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), HDM::parameters::boundary_distance(-1.)); }));
  VVM_CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), HDM::parameters::boundary_distance(std::nan(""))); }));
}


} // namespace

int main(int argc, char** argv)
{
  return vvm_test::run(argc, argv, "test_hex_dominant_meshes", {
      {"make_hex_dominant_mesh_on_cube", test_make_hex_dominant_mesh_on_cube},
      {"all_hex_cube_at_odd_layer_count", test_all_hex_cube_at_odd_layer_count},
      {"all_hex_scale_corrected_cylinder", test_all_hex_scale_corrected_cylinder},
      {"make_hex_dominant_mesh_on_warped_cube", test_make_hex_dominant_mesh_on_warped_cube},
      {"make_hex_dominant_mesh_on_graded_cube", test_make_hex_dominant_mesh_on_graded_cube},
      {"flat_tet_on_boundary_quad", test_flat_tet_on_boundary_quad},
      {"boundary_refinement", test_boundary_refinement},
      {"determinism", test_determinism}});
}
