// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// gsm_optimize_mesh_3 beyond the single implicit domain: a polyhedral cube with protected
// features (corners fixed, feature vertices on their edges); parallel sweeps that do not
// depend on the threads, sizing fields and the boundary's distance to the input surface
// (on the implicit sphere and a polyhedral one); two subdomains from a labelled implicit
// function, a Parallel_tag triangulation, a 3D image and a polyhedral complex.

#include "gsm_test_support.h"
#include "output_hash.h"

namespace {

// the cube [-1, 1]^3, two triangles a face
Surface_mesh cube_surface()
{
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> v;
  for(int i = 0; i < 8; ++i) v.push_back(sm.add_vertex(K::Point_3(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1)));
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for(const auto& q : quads) sm.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  return sm;
}

void test_cube_with_features()
{
  Cube_domain domain(cube_surface());
  domain.detect_features(60);
  CGAL::Mesh_criteria_3<Cube_tr> criteria(params::edge_size = 0.3, params::facet_angle = 25,
                                          params::facet_size = 0.3, params::facet_distance = 0.03,
                                          params::cell_radius_edge_ratio = 3, params::cell_size = 0.3);
  CGAL::get_default_random() = CGAL::Random(1);
  Cube_c3t3 c3t3 = CGAL::make_mesh_3<Cube_c3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  const auto start = positions(c3t3);
  const double before = GSM::mesh_quality_statistics(c3t3).min_dihedral_angle;
  CGAL::gsm_optimize_mesh_3(c3t3, domain);
  VVM_CHECK(complex_is_valid(c3t3));
  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  VVM_CHECK_EQUAL(after.number_of_inverted_cells, std::size_t(0));
  VVM_CHECK(after.min_dihedral_angle > before + 5);
  bool corners_fixed = true, on_edges = true, on_faces = true, curve_moved = false, surface_moved = false;
  for(auto vh : c3t3.triangulation().finite_vertex_handles()) {
    const Eigen::Vector3d p(vh->point().x(), vh->point().y(), vh->point().z());
    int on_planes = 0;
    for(int k = 0; k < 3; ++k) on_planes += std::abs(std::abs(p[k]) - 1) < 1e-9 ? 1 : 0;
    switch(vh->in_dimension()) {
    case 0: corners_fixed = corners_fixed && p == start.at(vh); break;
    case 1: on_edges = on_edges && on_planes >= 2; curve_moved = curve_moved || p != start.at(vh); break;
    case 2: on_faces = on_faces && on_planes >= 1; surface_moved = surface_moved || p != start.at(vh); break;
    default: break;
    }
  }
  VVM_CHECK(corners_fixed);
  VVM_CHECK(on_edges && curve_moved);
  VVM_CHECK(on_faces && surface_moved);
}

// Parallel sweeps are deterministic: the batches do not depend on the threads.
// A sizing field matters only up to a constant factor (fitted to the vertex
// count). The adaptive run follows the field. The boundary does not get
// farther from the input surface (Hausdorff distance, both ways, within 10%).
void test_threads_fields_and_boundary()
{
  const Implicit_domain domain = sphere_domain();
  const Implicit_c3t3 initial = make_sphere_mesh(0.2);
  Implicit_c3t3 one = initial, two = initial;
  CGAL::gsm_optimize_mesh_3(one, domain, GSM::parameters::number_of_threads(1, params::number_of_iterations(4)));
  CGAL::gsm_optimize_mesh_3(two, domain, GSM::parameters::number_of_threads(2, params::number_of_iterations(4)));
  VVM_CHECK(complex_is_valid(two));
  VVM_CHECK(GSM::mesh_quality_statistics(one).number_of_cells == GSM::mesh_quality_statistics(two).number_of_cells);
  std::vector<Eigen::Vector3d> p1, p2;
  for(const auto& vp : positions(one)) p1.push_back(vp.second);
  for(const auto& vp : positions(two)) p2.push_back(vp.second);
  VVM_CHECK(p1 == p2);
  // the same again after other work: the copy's vertices and cells now lie elsewhere in
  // memory, in another order of addresses (a heap with holes of every size)
  {
    std::vector<std::vector<char>> blocks;
    for(int i = 0; i < 4000; ++i) blocks.emplace_back(std::size_t(64 + (i * 7919) % 20000));
    for(std::size_t i = 0; i < blocks.size(); i += 2) std::vector<char>().swap(blocks[i]);
    Implicit_c3t3 other = initial;
    CGAL::gsm_optimize_mesh_3(other, domain, params::number_of_iterations(2));
    Implicit_c3t3 again = initial;
    CGAL::gsm_optimize_mesh_3(again, domain, GSM::parameters::number_of_threads(1, params::number_of_iterations(4)));
    std::vector<Eigen::Vector3d> p3;
    for(const auto& vp : positions(again)) p3.push_back(vp.second);
    std::sort(p1.begin(), p1.end(), [](const auto& a, const auto& b) { return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3); });
    std::sort(p3.begin(), p3.end(), [](const auto& a, const auto& b) { return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3); });
    VVM_CHECK(p1 == p3);
  }

  // polishing without splits keeps the vertex set and, with a bound above what the
  // rounds reach (31 degrees), lifts the worst cell; sliver_bound(0) skips it
  Implicit_c3t3 no_split = initial, no_polish = initial;
  CGAL::gsm_optimize_mesh_3(no_split, domain, GSM::parameters::split_edges(false, GSM::parameters::sliver_bound(40)));
  VVM_CHECK_EQUAL(no_split.triangulation().number_of_vertices(), initial.triangulation().number_of_vertices());
  VVM_CHECK(complex_is_valid(no_split));
  std::size_t polishing_rounds = 0;
  CGAL::gsm_optimize_mesh_3(no_polish, domain, GSM::parameters::sliver_bound(0, params::visitor(
      [&](const GSM::Round_report& r) { polishing_rounds += r.is_polishing ? 1 : 0; })));
  VVM_CHECK_EQUAL(polishing_rounds, std::size_t(0));
  VVM_CHECK(GSM::mesh_quality_statistics(no_split).min_dihedral_angle >
            GSM::mesh_quality_statistics(no_polish).min_dihedral_angle);

  // shortest_polishing_moves: with flips only in the rounds and no splits, only the polishing
  // moves vertices (each vertex's distance to the nearest initial one: the moves are shorter
  // than half an edge), otherwise than without it, the worst cell still lifted. (The option
  // changes the critical cells' moves only; the penalty moves of the others, the same in both,
  // make most of the sum: since penalty moves near the bound trade no more cells under it + 10
  // than they lift over it, the two sums are close, 10.69 without the option and 10.98 with it,
  // where they were 11.10 and 10.86 without that rule.)
  auto displacement = [&initial](const Implicit_c3t3& c3t3) {
    std::vector<Eigen::Vector3d> before;
    for(const auto& vp : positions(initial)) before.push_back(vp.second);
    double sum = 0;
    for(const auto& vp : positions(c3t3)) {
      double d = std::numeric_limits<double>::infinity();
      for(const Eigen::Vector3d& b : before) d = (std::min)(d, (vp.second - b).norm());
      sum += d;
    }
    return sum;
  };
  Implicit_c3t3 flips_only = initial, farthest = initial, shortest = initial;
  CGAL::gsm_optimize_mesh_3(flips_only, domain, GSM::parameters::smooth_vertices(false, GSM::parameters::sliver_bound(0)));
  auto polish_only = GSM::parameters::smooth_vertices(false, GSM::parameters::split_edges(false,
      GSM::parameters::sliver_bound(40)));
  CGAL::gsm_optimize_mesh_3(farthest, domain, polish_only);
  CGAL::gsm_optimize_mesh_3(shortest, domain, GSM::parameters::shortest_polishing_moves(true, polish_only));
  VVM_CHECK(complex_is_valid(shortest));
  const auto q_flips = GSM::mesh_quality_statistics(flips_only), q_far = GSM::mesh_quality_statistics(farthest),
             q_short = GSM::mesh_quality_statistics(shortest);
  std::printf("  polishing moves (bound 40, flips only, no splits): displacement %.4f (max-min) against %.4f "
              "(shortest), min %.2f / %.2f, tets under 40 %zu / %zu (before the polishing: min %.2f, %zu)\n",
              displacement(farthest), displacement(shortest), q_far.min_dihedral_angle, q_short.min_dihedral_angle,
              q_far.n_min_dihedral_below[3], q_short.n_min_dihedral_below[3], q_flips.min_dihedral_angle,
              q_flips.n_min_dihedral_below[3]);
  VVM_CHECK_EQUAL(displacement(flips_only), 0.);
  VVM_CHECK(displacement(shortest) > 0);
  VVM_CHECK(displacement(shortest) != displacement(farthest));
  VVM_CHECK(q_short.min_dihedral_angle > q_flips.min_dihedral_angle);
  VVM_CHECK(q_short.n_min_dihedral_below[3] < q_flips.n_min_dihedral_below[3]);

  // mean-angle moves after the same polishing: a higher mean smallest angle, no cell under 40
  // that was not (each move keeps its star's count under the bound + 10 and its worst cell
  // over the bound or where it was); a cost that no move can pay leaves the polished mesh as
  // it is; a negative threshold is refused
  Implicit_c3t3 raised = initial, unpaid = initial;
  CGAL::gsm_optimize_mesh_3(raised, domain, GSM::parameters::mean_angle_threshold(60, polish_only));
  typedef Implicit_c3t3::Triangulation::Vertex_handle Implicit_vertex;
  CGAL::gsm_optimize_mesh_3(unpaid, domain, GSM::parameters::vertex_move_cost(
      [&unpaid](const Implicit_vertex& v, const Eigen::Vector3d& x) {
        return 1e12 * (x - GSM::internal::to_eigen(unpaid.triangulation().point(v))).norm();
      }, GSM::parameters::mean_angle_threshold(60, polish_only)));
  VVM_CHECK(complex_is_valid(raised));
  const auto q_raised = GSM::mesh_quality_statistics(raised);
  std::printf("  mean-angle moves (under 60) after the polishing: mean smallest angle %.3f against %.3f, "
              "min %.2f / %.2f, tets under 40 %zu / %zu\n", q_raised.mean_min_dihedral_angle,
              q_far.mean_min_dihedral_angle, q_raised.min_dihedral_angle, q_far.min_dihedral_angle,
              q_raised.n_min_dihedral_below[3], q_far.n_min_dihedral_below[3]);
  VVM_CHECK(q_raised.mean_min_dihedral_angle > q_far.mean_min_dihedral_angle + 0.1);
  VVM_CHECK(q_raised.min_dihedral_angle >= (std::min)(q_far.min_dihedral_angle, 40.) - 1e-9);
  VVM_CHECK(q_raised.n_min_dihedral_below[3] <= q_far.n_min_dihedral_below[3]);
  auto sorted_points = [](const Implicit_c3t3& c3t3) {
    std::vector<std::array<double, 3>> points;
    for(const auto& vp : positions(c3t3)) points.push_back({vp.second[0], vp.second[1], vp.second[2]});
    std::sort(points.begin(), points.end());
    return points;
  };
  VVM_CHECK(sorted_points(unpaid) == sorted_points(farthest));
  VVM_CHECK(sorted_points(raised) != sorted_points(farthest));
  bool refused = false;
  try {
    Implicit_c3t3 copy = initial;
    CGAL::gsm_optimize_mesh_3(copy, domain, GSM::parameters::mean_angle_threshold(-1));
  } catch(const std::invalid_argument& e) { refused = std::string(e.what()).find("mean_angle_threshold") != std::string::npos; }
  VVM_CHECK(refused);

  // h and 4h (a power of two: the fitted scale is then exactly the same)
  auto h = [](const Eigen::Vector3d& x) { return GSM::dissertation::adaptive_sphere_sizing(x); };
  Implicit_c3t3 small = initial, large = initial;
  CGAL::gsm_optimize_mesh_3(small, domain, GSM::parameters::sizing_field(h, params::number_of_iterations(4)));
  CGAL::gsm_optimize_mesh_3(large, domain, GSM::parameters::sizing_field([&h](const Eigen::Vector3d& x) {
    return 4 * h(x);
  }, params::number_of_iterations(4)));
  std::vector<Eigen::Vector3d> ps, pl;
  for(const auto& vp : positions(small)) ps.push_back(vp.second);
  for(const auto& vp : positions(large)) pl.push_back(vp.second);
  VVM_CHECK(ps == pl);
  VVM_CHECK(ps != p2); // and the field did change the result

  // edges near |x| = 0.5 (h = 0.025) against those near the boundary (h >= 0.105)
  auto length_ratio = [](const Implicit_c3t3& c3t3) {
    return mean_edge_length_ratio(c3t3, [](const Eigen::Vector3d& m) {
      return m.norm() > 0.35 && m.norm() < 0.65 ? 0 : m.norm() > 0.9 ? 1 : -1;
    });
  };
  Implicit_c3t3 adaptive = initial;
  CGAL::gsm_optimize_mesh_3(adaptive, domain, GSM::parameters::sizing_field(h));
  VVM_CHECK(complex_is_valid(adaptive));
  std::printf("  adaptive sphere: boundary/middle edge length ratio %.3f before, %.3f after\n",
              length_ratio(initial), length_ratio(adaptive));
  VVM_CHECK(length_ratio(adaptive) > 1.05 * length_ratio(initial));

  // the polyhedral sphere of data/sphere966.off, no features: surface vertices slide on it
  Surface_mesh surface;
  VVM_CHECK(CGAL::IO::read_polygon_mesh(vvm_test::data_file("sphere966.off"), surface));
  Cube_domain polyhedral(surface);
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(surface);
  const double size = 0.08 * (box.xmax() - box.xmin()); // about 2,500 vertices
  CGAL::Mesh_criteria_3<Cube_tr> criteria(params::facet_angle = 25, params::facet_size = size,
                                          params::facet_distance = size / 10, params::cell_radius_edge_ratio = 3,
                                          params::cell_size = size);
  CGAL::get_default_random() = CGAL::Random(1);
  Cube_c3t3 c3t3 = CGAL::make_mesh_3<Cube_c3t3>(polyhedral, criteria, params::no_perturb(), params::no_exude());
  const double density = 30000 / CGAL::Polygon_mesh_processing::area(surface); // sample points per area unit
  auto hausdorff = [&surface, density](const Cube_c3t3& m) {
    namespace PMP = CGAL::Polygon_mesh_processing;
    Surface_mesh boundary;
    CGAL::facets_in_complex_3_to_triangle_mesh(m, boundary);
    CGAL::get_default_random() = CGAL::Random(2);
    const double to_input = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
        boundary, surface, PMP::parameters::number_of_points_per_area_unit(density));
    const double to_boundary = PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
        surface, boundary, PMP::parameters::number_of_points_per_area_unit(density));
    return (std::max)(to_input, to_boundary);
  };
  const double before = hausdorff(c3t3);
  const double min_before = GSM::mesh_quality_statistics(c3t3).min_dihedral_angle;
  CGAL::gsm_optimize_mesh_3(c3t3, polyhedral);
  const double after = hausdorff(c3t3);
  std::printf("  polyhedral sphere: Hausdorff distance to the input %.5f before, %.5f after; "
              "min dihedral %.2f -> %.2f\n", before, after, min_before,
              GSM::mesh_quality_statistics(c3t3).min_dihedral_angle);
  VVM_CHECK(complex_is_valid(c3t3));
  VVM_CHECK(before > 0 && after <= 1.1 * before);
  VVM_CHECK(GSM::mesh_quality_statistics(c3t3).min_dihedral_angle > min_before + 5);
}

// Determinism: the same complex optimized with 1, 2 and 4 threads, and again after another
// complex was optimized in a fragmented heap (its vertices and cells then lie elsewhere and
// in another order of addresses), gives the same mesh bit for bit: on an implicit sphere and
// torus and on a polyhedral cube with features (curves and corners).
template <class C3T3, class Domain>
void check_deterministic(const char* name, const C3T3& initial, const Domain& domain, const C3T3& other)
{
  auto optimized = [&](int threads) {
    C3T3 c3t3 = initial;
    CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::number_of_threads(threads));
    return vvm_test::complex_hash(c3t3);
  };
  const std::uint64_t one = optimized(1);
  const std::uint64_t two = optimized(2), four = optimized(4);
  std::uint64_t after_other = 0;
  {
    vvm_test::Fragmented_heap heap;
    C3T3 c = other;
    CGAL::gsm_optimize_mesh_3(c, domain, GSM::parameters::number_of_threads(2));
    after_other = optimized(2);
  }
  std::cout << name << ": output hash " << std::hex << one << " (1 thread), " << two << " (2), " << four
            << " (4), " << after_other << " (2, after another mesh)" << std::dec << "\n";
  VVM_CHECK(vvm_test::complex_hash(C3T3(initial)) == vvm_test::complex_hash(initial));
  VVM_CHECK(vvm_test::complex_hash(initial) != one);
  VVM_CHECK(one == two);
  VVM_CHECK(one == four);
  VVM_CHECK(one == after_other);
}

void test_determinism()
{
  check_deterministic("sphere", make_sphere_mesh(0.2), sphere_domain(), make_sphere_mesh(0.3));
  check_deterministic("torus", make_implicit_mesh(torus_function, 0.1), implicit_domain(torus_function),
                      make_implicit_mesh(torus_function, 0.15));
  Cube_domain domain(cube_surface());
  domain.detect_features(60);
  auto cube_mesh = [&](double size) {
    CGAL::Mesh_criteria_3<Cube_tr> criteria(params::edge_size = size, params::facet_angle = 25,
                                            params::facet_size = size, params::facet_distance = size / 10,
                                            params::cell_radius_edge_ratio = 3, params::cell_size = size);
    CGAL::get_default_random() = CGAL::Random(1);
    return CGAL::make_mesh_3<Cube_c3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  };
  check_deterministic("cube with features", cube_mesh(0.3), domain, cube_mesh(0.4));
}

void test_several_subdomains()
{
  // a labelled implicit domain
  const Implicit_domain implicit(std::function<int(const K::Point_3&)>(torus_in_ball), K::Sphere_3(CGAL::ORIGIN, 2.),
                                 params::relative_error_bound = 1e-6);
  Implicit_c3t3 labelled = mesh_two_subdomains<Implicit_c3t3>(implicit, 0.12);
  check_two_subdomains("labelled implicit domain", labelled, implicit);

  // the same on a triangulation made for the concurrent mesher
#ifdef CGAL_LINKED_WITH_TBB
  typedef CGAL::Mesh_triangulation_3<Implicit_domain, CGAL::Default, CGAL::Parallel_tag>::type Parallel_tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Parallel_tr> Parallel_c3t3;
  Parallel_c3t3 parallel = mesh_two_subdomains<Parallel_c3t3>(implicit, 0.12);
  check_two_subdomains("Parallel_tag triangulation", parallel, implicit);
#endif

  // a labelled 3D image: a ball of label 1 around a smaller ball of label 2, 0.05 voxels
  const std::size_t n = 52;
  const double voxel = 0.05, centre = 0.5 * voxel * double(n - 1);
  CGAL::Image_3 image(_createImage(n, n, n, 1, voxel, voxel, voxel, 1, WK_FIXED, SGN_UNSIGNED));
  unsigned char* label = static_cast<unsigned char*>(image.data());
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        const double r = Eigen::Vector3d(voxel * double(i) - centre, voxel * double(j) - centre,
                                         voxel * double(k) - centre).norm();
        label[(k * n + j) * n + i] = r < 0.45 ? 2 : r < 1.1 ? 1 : 0;
      }
  const Implicit_domain image_domain = Implicit_domain::create_labeled_image_mesh_domain(image);
  Implicit_c3t3 from_image = mesh_two_subdomains<Implicit_c3t3>(image_domain, 0.12);
  check_two_subdomains("labelled 3D image", from_image, image_domain);

  // a polyhedral complex: the box [-1,1]^3 (subdomain 1) around the box [-0.4,0.4]^3
  // (subdomain 2), their edges protected as features
  typedef CGAL::Polyhedral_complex_mesh_domain_3<K> Complex_domain;
  typedef Complex_domain::Polyhedron Polyhedron;
  typedef CGAL::Mesh_triangulation_3<Complex_domain>::type Complex_tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Complex_tr, Complex_domain::Corner_index,
                                                  Complex_domain::Curve_index> Complex_c3t3;
  auto box = [](double a) {
    Polyhedron p;
    CGAL::make_hexahedron(K::Point_3(-a, -a, -a), K::Point_3(a, -a, -a), K::Point_3(a, a, -a), K::Point_3(-a, a, -a),
                          K::Point_3(-a, a, a), K::Point_3(-a, -a, a), K::Point_3(a, -a, a), K::Point_3(a, a, a), p);
    CGAL::Polygon_mesh_processing::triangulate_faces(p);
    if(!CGAL::Polygon_mesh_processing::is_outward_oriented(p)) CGAL::Polygon_mesh_processing::reverse_face_orientations(p);
    return p;
  };
  const std::vector<Polyhedron> patches = {box(1.), box(0.4)};
  const std::vector<std::pair<int, int>> sides = {{1, 0}, {2, 1}}; // (inside, outside) of each
  Complex_domain boxes(patches.begin(), patches.end(), sides.begin(), sides.end());
  boxes.detect_features();
  Complex_c3t3 from_boxes = mesh_two_subdomains<Complex_c3t3>(boxes, 0.15);
  check_two_subdomains("polyhedral complex", from_boxes, boxes);
}


} // namespace

int main(int argc, char** argv)
{
  return vvm_test::run(argc, argv, "test_gsm_domains", {
      {"cube_with_features", test_cube_with_features},
      {"threads_fields_and_boundary", test_threads_fields_and_boundary},
      {"several_subdomains", test_several_subdomains},
      {"determinism", test_determinism}});
}
