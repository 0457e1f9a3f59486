// Tests of the tet merging of Hex_dominant_meshing (tets_to_hex_dominant) and of
// make_hex_dominant_mesh_3:
// - every triangulation of a (perturbed) cube, 5, 6 and 7 tets, all classes up to the
//   cube's symmetries, merges into one hexahedron with the cube's corner order;
// - hand-made prisms and pyramids are found;
// - the Delaunay tets of a perfect cubic grid merge into hexahedra only; per-cell scaled
//   Jacobians of hand-computed cells;
// - on random Delaunay tets the cells partition the tets, are positively oriented, conform,
//   and conflicting candidates are never both kept;
// - tets Delaunay in the field's space: the metric flips turn the Euclidean Delaunay tets of
//   a stretched grid, which cross its boxes, into tets that merge; make_hex_dominant_mesh_3 on
//   a warped cube with a shear field, and on a cube with Fig. 4.8's field (cells 80 times
//   thinner along x than across), gives hexahedra only;
// - a flat tet on a hexahedron's boundary quad is taken in by it;
// - the boundary refinement brings the tets' boundary closer to a sphere;
// - bad inputs throw.

#include <CGAL/make_hex_dominant_mesh_3.h>
#include <CGAL/tets_to_hex_dominant.h>
#include <CGAL/Frame_fields/Constant_frame_field_3.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/Hex_dominant_meshing/cell_quality.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Metric_Delaunay_flips.h>
#include <CGAL/GSM_mesh_optimization/internal/Triangulation_complex.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Regular_triangulation_3.h>

#include <cassert>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Weighted_point_3 Weighted_point_3;
typedef CGAL::Delaunay_triangulation_3<K> Delaunay;
typedef CGAL::Regular_triangulation_3<K> Regular;
typedef CGAL::Triangulation_vertex_base_with_info_3<int, K> Vb_info;
typedef CGAL::Regular_triangulation_vertex_base_3<K, Vb_info> Rvb;
typedef CGAL::Triangulation_data_structure_3<Rvb, CGAL::Regular_triangulation_cell_base_3<K>> Rtds;
typedef CGAL::Regular_triangulation_3<K, Rtds> Regular_with_info;
typedef CGAL::Hex_dominant_mesh_3<Point_3> Mesh;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Cube_domain;
typedef CGAL::Mesh_triangulation_3<Cube_domain, CGAL::Default, CGAL::Sequential_tag>::type Cube_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Cube_tr, Cube_domain::Corner_index, Cube_domain::Curve_index> Cube_c3t3;
typedef CGAL::Frame_fields::Constant_frame_field_3<K> Constant_field;

namespace {

int failures = 0;
#define CHECK(c)                                                                  \
  do {                                                                            \
    if(!(c)) {                                                                    \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #c "\n";     \
      ++failures;                                                                 \
    }                                                                             \
  } while(0)

// true if `f` throws std::invalid_argument (its message printed)
template <class F>
bool throws(F f)
{
  try {
    f();
  } catch(const std::invalid_argument& e) {
    std::cout << "  refused: " << e.what() << "\n";
    return true;
  }
  return false;
}

// the 48 symmetries of the cube, as permutations of the corner numbers x + 2y + 4z
std::vector<std::array<int, 8>> cube_symmetries()
{
  std::vector<std::array<int, 8>> out;
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for(const auto& a : axes)
    for(int flip = 0; flip < 8; ++flip) {
      std::array<int, 8> s;
      for(int c = 0; c < 8; ++c) {
        int bits[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1}, image = 0;
        for(int k = 0; k < 3; ++k) image |= (bits[a[k]] ^ ((flip >> k) & 1)) << k;
        s[std::size_t(c)] = image;
      }
      out.push_back(s);
    }
  return out;
}

typedef std::vector<std::array<int, 4>> Tet_set;

Tet_set canonical(const Tet_set& tets, const std::vector<std::array<int, 8>>& symmetries)
{
  Tet_set best;
  for(const auto& s : symmetries) {
    Tet_set image;
    for(const auto& t : tets) {
      std::array<int, 4> u = {{s[std::size_t(t[0])], s[std::size_t(t[1])], s[std::size_t(t[2])], s[std::size_t(t[3])]}};
      std::sort(u.begin(), u.end());
      image.push_back(u);
    }
    std::sort(image.begin(), image.end());
    if(best.empty() || image < best) best = image;
  }
  return best;
}

// the hexahedron's edges (VTK order) join cube corners that differ in one coordinate
bool has_cube_corner_order(const Mesh::Cell& c, const std::vector<int>& corner_of_point)
{
  static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for(const auto& e : edges) {
    const int x = corner_of_point[c.vertices[std::size_t(e[0])]] ^ corner_of_point[c.vertices[std::size_t(e[1])]];
    if(x != 1 && x != 2 && x != 4) return false;
  }
  return true;
}

void test_cube_triangulations()
{
  const auto symmetries = cube_symmetries();
  std::map<Tet_set, int> classes; // canonical triangulation -> number of tets
  CGAL::Random random(17);
  int merged = 0, trials = 0, patterns = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    std::vector<std::pair<Weighted_point_3, int>> points;
    // the exact cube with random weights gives the 5 and 6 tet patterns; the Delaunay tets of
    // a perturbed cube also the 7 tet ones (two prisms and a flat tet between them)
    const double perturbation = trial % 3 == 0 ? 0. : trial % 3 == 1 ? 0.05 : 0.12;
    const double max_weight = trial % 3 == 0 ? 0.3 : trial % 3 == 1 ? 0.02 : 0.;
    for(int c = 0; c < 8; ++c) {
      auto shift = [&] { return perturbation > 0 ? random.get_double(-perturbation, perturbation) : 0.; };
      const double x = (c & 1) + shift(), y = ((c >> 1) & 1) + shift(), z = ((c >> 2) & 1) + shift();
      const Point_3 p(x, y, z);
      points.emplace_back(Weighted_point_3(p, max_weight > 0 ? random.get_double(0, max_weight) : 0.), c);
    }
    Regular_with_info tr(points.begin(), points.end());
    if(tr.number_of_vertices() != 8 || tr.dimension() != 3) continue;
    ++trials;
    Tet_set tets;
    for(auto c : tr.finite_cell_handles()) {
      std::array<int, 4> t = {{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()}};
      std::sort(t.begin(), t.end());
      tets.push_back(t);
    }
    std::sort(tets.begin(), tets.end());
    // a hexahedron's pattern uses at most one diagonal of each face; both diagonals of a
    // face make a flat tet on it, not inside (and more than 7 tets)
    std::set<std::pair<int, int>> face_diagonals;
    for(const auto& t : tets)
      for(int a = 0; a < 4; ++a)
        for(int b = a + 1; b < 4; ++b) {
          const int x = t[std::size_t(a)] ^ t[std::size_t(b)];
          if(x == 3 || x == 5 || x == 6) face_diagonals.emplace(t[std::size_t(a)], t[std::size_t(b)]);
        }
    if(face_diagonals.size() > 6) continue;
    ++patterns;
    classes.emplace(canonical(tets, symmetries), int(tets.size()));

    HDM::Hex_dominant_merge_report report;
    const Mesh mesh = CGAL::tets_to_hex_dominant(tr, HDM::parameters::quality_bound(0., HDM::parameters::merge_report(&report)));
    // the points are numbered as met: find each one's cube corner
    std::vector<int> corner_of_point(mesh.points.size(), -1);
    for(auto v : tr.finite_vertex_handles())
      for(std::size_t i = 0; i < mesh.points.size(); ++i)
        if(mesh.points[i] == tr.point(v).point()) corner_of_point[i] = v->info();
    const bool one_hex = mesh.cells.size() == 1 && mesh.cells[0].type == CGAL::Hex_dominant_cell_type::HEXAHEDRON &&
                         has_cube_corner_order(mesh.cells[0], corner_of_point) &&
                         HDM::minimum_corner_jacobian(mesh, mesh.cells[0]) > 0 &&
                         report.cell_tets.size() == 1 && report.cell_tets[0].size() == tets.size();
    if(!one_hex) {
      std::cerr << "cube triangulation with " << tets.size() << " tets: " << mesh.cells.size() << " cells, first of type "
                << int(mesh.cells[0].type) << "\n";
      for(const auto& t : tets) std::cerr << "  " << t[0] << t[1] << t[2] << t[3] << "\n";
    }
    CHECK(one_hex);
    merged += one_hex;
  }
  std::map<int, int> per_count;
  for(const auto& c : classes) ++per_count[c.second];
  std::cout << "cube triangulations: " << trials << " trials, " << patterns << " hexahedron patterns, merged " << merged
            << "; classes up to symmetry: "
            << classes.size() << " (";
  for(const auto& p : per_count) std::cout << p.second << " of " << p.first << " tets, ";
  std::cout << ")\n";
  // Sokolov et al. 2016: 6 ways with 5 or 6 tets
  CHECK(per_count[5] + per_count[6] == 6);
  CHECK(merged == patterns);
}

// the hexahedra of 7 tets: the cube cut by the plane x = y into two prisms, a flat tet
// between them whose opposite edges 000-111 and 110-001 are both in the mesh (the plane's
// corners moved apart a little), each prism split into 3 tets in any of its ways that uses
// its own diagonal of the plane
void test_seven_tet_hexahedra()
{
  const auto symmetries = cube_symmetries();
  std::vector<Point_3> corners;
  const double d = 0.05;
  for(int c = 0; c < 8; ++c) {
    double x = c & 1, y = (c >> 1) & 1, z = (c >> 2) & 1;
    if(c == 3 || c == 4) { // 110 and 001 towards x < y
      x -= d;
      y += d;
    }
    corners.emplace_back(x, y, z);
  }
  // a prism's 6 triangulations: lift its bottom corners to the top in each order
  auto prism_triangulations = [](std::array<int, 3> bottom, std::array<int, 3> top) {
    std::vector<Tet_set> out;
    int order[3] = {0, 1, 2};
    do {
      const int a = order[0], b = order[1], c = order[2];
      out.push_back({{{bottom[std::size_t(a)], bottom[std::size_t(b)], bottom[std::size_t(c)], top[std::size_t(a)]}},
                     {{bottom[std::size_t(b)], bottom[std::size_t(c)], top[std::size_t(a)], top[std::size_t(b)]}},
                     {{bottom[std::size_t(c)], top[std::size_t(a)], top[std::size_t(b)], top[std::size_t(c)]}}});
    } while(std::next_permutation(order, order + 3));
    return out;
  };
  auto has_edge = [](const Tet_set& tets, int a, int b) {
    for(const auto& t : tets)
      if(std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b)) return true;
    return false;
  };
  std::set<Tet_set> classes;
  int merged = 0, built = 0;
  for(const Tet_set& left : prism_triangulations({{0, 2, 3}}, {{4, 6, 7}})) {
    if(!has_edge(left, 0, 7)) continue;
    for(const Tet_set& right : prism_triangulations({{0, 1, 3}}, {{4, 5, 7}})) {
      if(!has_edge(right, 3, 4)) continue;
      Tet_set tets = left;
      tets.insert(tets.end(), right.begin(), right.end());
      tets.push_back({{0, 7, 3, 4}});
      ++built;
      std::vector<std::array<std::size_t, 4>> indices;
      for(const auto& t : tets) indices.push_back({{std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2]), std::size_t(t[3])}});
      Tet_set sorted = tets;
      for(auto& t : sorted) std::sort(t.begin(), t.end());
      classes.insert(canonical(sorted, symmetries));
      HDM::Hex_dominant_merge_report report;
      const Mesh mesh = CGAL::tets_to_hex_dominant(corners, indices, {}, HDM::parameters::quality_bound(0., HDM::parameters::merge_report(&report)));
      std::vector<int> corner_of_point(8);
      for(int c = 0; c < 8; ++c) corner_of_point[std::size_t(c)] = c;
      const bool one_hex = mesh.cells.size() == 1 && mesh.cells[0].type == CGAL::Hex_dominant_cell_type::HEXAHEDRON &&
                           has_cube_corner_order(mesh.cells[0], corner_of_point) && report.cell_tets[0].size() == 7;
      CHECK(one_hex);
      merged += one_hex;
    }
  }
  std::cout << "7-tet hexahedra: " << built << " built, " << merged << " merged, " << classes.size()
            << " classes up to symmetry\n";
  CHECK(built == 9 && merged == 9);
  CHECK(classes.size() == 4); // Sokolov et al. 2016: 4 ways
}

// a prism and a pyramid of their tets, with the corner order checked
void test_prism_and_pyramid()
{
  // prism: triangle (0,0,0) (1,0,0) (0,1,0), lifted by z = 1; split into 3 tets by Delaunay
  // (regular with weights chosen so that it is not degenerate)
  {
    std::vector<Weighted_point_3> p = {Weighted_point_3(Point_3(0, 0, 0), 0.), Weighted_point_3(Point_3(1, 0, 0), 0.1),
                                       Weighted_point_3(Point_3(0, 1, 0), 0.2), Weighted_point_3(Point_3(0, 0, 1), 0.05),
                                       Weighted_point_3(Point_3(1, 0, 1), 0.15), Weighted_point_3(Point_3(0, 1, 1), 0.25)};
    Regular tr(p.begin(), p.end());
    CHECK(tr.number_of_finite_cells() == 3);
    const Mesh m = CGAL::tets_to_hex_dominant(tr, HDM::parameters::quality_bound(0.));
    CHECK(m.cells.size() == 1 && m.cells[0].type == CGAL::Hex_dominant_cell_type::PRISM);
    if(m.cells.size() == 1) {
      // 0 1 2 a triangle at one z, 3 4 5 above it in the same order
      const auto& c = m.cells[0];
      for(int k = 0; k < 3; ++k) {
        const Point_3& a = m.points[c.vertices[std::size_t(k)]];
        const Point_3& b = m.points[c.vertices[std::size_t(k + 3)]];
        CHECK(a.x() == b.x() && a.y() == b.y() && a.z() != b.z());
      }
      CHECK(HDM::minimum_corner_jacobian(m, c) > 0);
      CHECK(std::abs(HDM::cell_volume(m, c) - 0.5) < 1e-12);
    }
    // prisms not allowed: tets stay
    const Mesh h = CGAL::tets_to_hex_dominant(tr, HDM::parameters::cell_types(HDM::Cell_types::HEXAHEDRA));
    CHECK(h.cells.size() == 3 && h.number_of_cells(CGAL::Hex_dominant_cell_type::TETRAHEDRON) == 3);
  }
  // pyramid: unit square base, apex above its centre
  {
    std::vector<Point_3> p = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0), Point_3(0.5, 0.5, 0.7)};
    Delaunay tr(p.begin(), p.end());
    CHECK(tr.number_of_finite_cells() == 2);
    const Mesh m = CGAL::tets_to_hex_dominant(tr, HDM::parameters::quality_bound(0.));
    CHECK(m.cells.size() == 1 && m.cells[0].type == CGAL::Hex_dominant_cell_type::PYRAMID);
    if(m.cells.size() == 1) {
      CHECK(m.points[m.cells[0].vertices[4]] == p[4]); // the apex last
      CHECK(HDM::minimum_corner_jacobian(m, m.cells[0]) > 0);
      CHECK(std::abs(HDM::cell_volume(m, m.cells[0]) - 0.7 / 3) < 1e-12);
    }
    const Mesh t = CGAL::tets_to_hex_dominant(tr, HDM::parameters::cell_types(HDM::Cell_types::HEXAHEDRA_AND_PRISMS));
    CHECK(t.cells.size() == 2);
  }
}

// every tet in exactly one cell, made of the cell's corners; cells positive and conforming;
// the cells' volumes (faces split around their centres) add up to the tets' volume within
// `volume_tolerance` (exactly for planar faces)
template <class Tr>
void check_partition(const Mesh& mesh, const HDM::Hex_dominant_merge_report& report, const Tr& tr,
                     double volume_tolerance)
{
  std::vector<typename Tr::Cell_handle> cells;
  for(auto c : tr.finite_cell_handles()) cells.push_back(c);
  double tet_volume = 0;
  for(auto c : cells) tet_volume += tr.tetrahedron(c).volume();
  CHECK(report.number_of_tets == cells.size());
  std::vector<int> uses(report.number_of_tets, 0);
  bool corners_match = report.cell_tets.size() == mesh.cells.size();
  for(std::size_t i = 0; corners_match && i < mesh.cells.size(); ++i) {
    std::set<Point_3> corners, used;
    for(std::size_t v : mesh.cells[i]) corners.insert(mesh.points[v]);
    for(std::size_t t : report.cell_tets[i]) {
      ++uses[t];
      for(int k = 0; k < 4; ++k) used.insert(cells[t]->vertex(k)->point());
    }
    corners_match = corners == used;
  }
  CHECK(corners_match);
  CHECK(std::count(uses.begin(), uses.end(), 1) == std::ptrdiff_t(uses.size()));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report);
  std::cout << "  partition: nonconforming " << s.number_of_nonconforming_faces << ", volume " << s.total_volume << " vs tets "
            << tet_volume << "\n";
  CHECK(s.number_of_inverted_cells == 0);
  CHECK(s.number_of_nonconforming_faces == 0);
  CHECK(std::abs(s.total_volume - tet_volume) <= volume_tolerance * tet_volume);
}

void test_cubic_grid()
{
  std::vector<Point_3> points;
  const int n = 6;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      for(int k = 0; k < n; ++k) points.emplace_back(0.5 * i, 0.5 * j, 0.5 * k);
  Delaunay tr(points.begin(), points.end());
  HDM::Hex_dominant_merge_report report;
  const Mesh mesh = CGAL::tets_to_hex_dominant(tr, HDM::parameters::merge_report(&report, HDM::parameters::quality_bound(0.9)));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh);
  std::cout << "cubic grid " << n << "^3: " << report.number_of_tets << " tets, " << report.number_of_hexahedron_candidates
            << " hexahedron candidates -> " << s.number_of_hexahedra << " hexahedra, " << mesh.cells.size() - s.number_of_hexahedra
            << " other cells, H_vol " << s.hexahedron_volume_percent << "%, SJ min " << s.scaled_jacobian_min << "\n";
  CHECK(s.number_of_hexahedra == std::size_t((n - 1) * (n - 1) * (n - 1)));
  CHECK(mesh.cells.size() == s.number_of_hexahedra);
  CHECK(std::abs(s.hexahedron_volume_percent - 100.) < 1e-9);
  CHECK(std::abs(s.scaled_jacobian_min - 1.) < 1e-12 && std::abs(s.verdict_scaled_jacobian_min - 1.) < 1e-12);
  CHECK(s.alignment_error_mean < 1e-9);
  check_partition(mesh, report, tr, 1e-12);
  // a left-handed frame field (an axis reversed) measures the same cells
  const Mesh mirrored = CGAL::tets_to_hex_dominant(tr, HDM::parameters::frame_field(
      Constant_field(Eigen::Vector3d(-1, 1, 1).asDiagonal()), HDM::parameters::quality_bound(0.9)));
  CHECK(mirrored.number_of_cells(CGAL::Hex_dominant_cell_type::HEXAHEDRON) == std::size_t((n - 1) * (n - 1) * (n - 1)));
}

// cell_scaled_jacobians on hand-computed cells: the unit cube with its top shifted by (1, 0, 0)
// has corner edges (1,0,0), (0,1,0), (1,0,1): 1/sqrt(2), and 1 in the space of the field that
// undoes the shear; the corner tetrahedron (0, e1, e2, e3): 1/2 at the corners other than 0
void test_cell_scaled_jacobians()
{
  Mesh mesh;
  for(int i = 0; i < 8; ++i) {
    const int x = (i == 1 || i == 2 || i == 5 || i == 6), y = (i == 2 || i == 3 || i == 6 || i == 7), z = i >= 4;
    mesh.points.emplace_back(x + z, y, z); // VTK order, top shifted
  }
  Mesh::Cell hex;
  hex.type = CGAL::Hex_dominant_cell_type::HEXAHEDRON;
  for(std::size_t k = 0; k < 8; ++k) hex.vertices[k] = k;
  mesh.cells.push_back(hex);
  Mesh::Cell tet;
  tet.type = CGAL::Hex_dominant_cell_type::TETRAHEDRON;
  mesh.points.emplace_back(10, 0, 0);
  mesh.points.emplace_back(11, 0, 0);
  mesh.points.emplace_back(10, 1, 0);
  mesh.points.emplace_back(10, 0, 1);
  for(std::size_t k = 0; k < 4; ++k) tet.vertices[k] = 8 + k;
  mesh.cells.push_back(tet);
  const std::vector<double> euclidean = HDM::cell_scaled_jacobians(mesh);
  Eigen::Matrix3d unshear = Eigen::Matrix3d::Identity();
  unshear(0, 2) = -1;
  const std::vector<double> in_field = HDM::cell_scaled_jacobians(mesh, [&](const Eigen::Vector3d&) { return unshear; });
  std::cout << "cell scaled Jacobians: sheared hexahedron " << euclidean[0] << ", unsheared " << in_field[0]
            << ", corner tetrahedron " << euclidean[1] << "\n";
  CHECK(euclidean.size() == 2 && in_field.size() == 2);
  CHECK(std::abs(euclidean[0] - std::sqrt(0.5)) < 1e-12);
  CHECK(std::abs(in_field[0] - 1) < 1e-12);
  CHECK(std::abs(euclidean[1] - 0.5) < 1e-12);
}

void test_random_tets()
{
  CGAL::Random random(5);
  for(int round = 0; round < 2; ++round) {
    std::vector<Point_3> points;
    if(round == 0) // random points: few cells merge, the rest must still partition
      for(int i = 0; i < 3000; ++i) points.emplace_back(random.get_double(), random.get_double(), random.get_double());
    else // a perturbed grid: many candidates in conflict
      for(int i = 0; i < 12; ++i)
        for(int j = 0; j < 12; ++j)
          for(int k = 0; k < 12; ++k)
            points.emplace_back(i + random.get_double(-0.15, 0.15), j + random.get_double(-0.15, 0.15),
                                k + random.get_double(-0.15, 0.15));
    Delaunay tr(points.begin(), points.end());
    for(double q : {0., 0.5}) {
      HDM::Hex_dominant_merge_report report;
      const Mesh mesh = CGAL::tets_to_hex_dominant(tr, HDM::parameters::quality_bound(q, HDM::parameters::merge_report(&report)));
      const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh);
      std::cout << (round == 0 ? "random points" : "perturbed grid") << ", Q_bound " << q << ": " << report.number_of_tets
                << " tets, candidates " << report.number_of_hexahedron_candidates << " hex / " << report.number_of_prism_candidates
                << " prism / " << report.number_of_pyramid_candidates << " pyramid -> " << s.number_of_hexahedra << " hex, "
                << s.number_of_prisms << " prisms, " << s.number_of_pyramids << " pyramids, " << s.number_of_tetrahedra
                << " tets; H_vol " << s.hexahedron_volume_percent << "%\n";
      // faces may be non-planar: the cell volumes add up to the tets' within the non-planarity
      check_partition(mesh, report, tr, q > 0 ? 0.02 : 0.05);
      if(round == 1) CHECK(s.number_of_hexahedra > 0);
      // identical for one thread
      const Mesh one = CGAL::tets_to_hex_dominant(
          tr, HDM::parameters::quality_bound(q, CGAL::Tetrahedral_lattice_meshing::parameters::number_of_threads(1)));
      bool same = one.cells.size() == mesh.cells.size();
      for(std::size_t i = 0; same && i < one.cells.size(); ++i)
        same = one.cells[i].type == mesh.cells[i].type && one.cells[i].vertices == mesh.cells[i].vertices;
      CHECK(same);
    }
  }
}

// the counter of non-conforming faces fires: two hexahedra of a 2x1x1 grid, the second
// relabelled so that its face through the shared facets is no longer the shared quad
void test_nonconforming_detected()
{
  std::vector<Point_3> points;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 2; ++j)
      for(int k = 0; k < 2; ++k) points.emplace_back(i, j, k);
  Delaunay tr(points.begin(), points.end());
  HDM::Hex_dominant_merge_report report;
  Mesh mesh = CGAL::tets_to_hex_dominant(tr, HDM::parameters::merge_report(&report));
  CHECK(mesh.cells.size() == 2 && HDM::count_nonconforming_faces(mesh, report) == 0);
  if(mesh.cells.size() != 2) return;
  // a quarter turn of the second hexahedron's corner list about its 0-1 axis keeps it a
  // hexahedron of the same corners but moves its faces
  auto& v = mesh.cells[1].vertices;
  const std::array<std::size_t, 8> w = {{v[3], v[2], v[6], v[7], v[0], v[1], v[5], v[4]}};
  std::copy(w.begin(), w.end(), v.begin());
  CHECK(HDM::count_nonconforming_faces(mesh, report) == 0); // a symmetry of the cell: still conforming
  const std::array<std::size_t, 8> twisted = {{w[0], w[1], w[2], w[3], w[5], w[6], w[7], w[4]}};
  std::copy(twisted.begin(), twisted.end(), v.begin());
  CHECK(HDM::count_nonconforming_faces(mesh, report) > 0);
}

// make_hex_dominant_mesh_3 on the cube [-1, 1]^3 with the identity field: the cubic lattice
// merges into hexahedra, the cells are valid and partition the tets
void test_make_hex_dominant_mesh_on_cube()
{
  Surface_mesh surface;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(VVM_DATA_DIR) + "/cube.off", surface));
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  std::vector<HDM::Hex_dominant_stage> stages;
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, Constant_field(),
      TLM::parameters::edge_length(0.25, HDM::parameters::hex_dominant_report(&report,
          HDM::parameters::stage_visitor([&](HDM::Hex_dominant_stage s, double) { stages.push_back(s); },
              TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(3u))))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, cube, l* 0.25: " << report.number_of_particles << " particles, "
            << report.merge.number_of_tets << " tets -> " << s.number_of_hexahedra << " hex, " << s.number_of_prisms
            << " prisms, " << s.number_of_pyramids << " pyramids, " << s.number_of_tetrahedra << " tets; H_vol "
            << s.hexahedron_volume_percent << "%, SJ min/mean " << s.scaled_jacobian_min << "/" << s.scaled_jacobian_mean
            << ", volume " << s.total_volume << ", times " << report.particle_time << " + " << report.tetrahedra_time << " + "
            << report.merge_time << " s\n";
  CHECK(stages.size() == 3 && stages[0] == HDM::Hex_dominant_stage::PARTICLES && stages[2] == HDM::Hex_dominant_stage::MERGING);
  CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
  CHECK(s.hexahedron_volume_percent > 90);
  CHECK(s.scaled_jacobian_min > 0.5);
  CHECK(std::abs(s.total_volume - 8.) < 0.08); // the particles' hull on the cube's surface
  for(const auto& c : mesh.cells) CHECK(c.subdomain_index == 1);

  CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), TLM::parameters::lattice(TLM::Lattice_type::BCC)); }));
  CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), TLM::parameters::edge_length(-1.)); }));
  CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), TLM::parameters::edge_length(1e-5)); }));
  CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), HDM::parameters::quality_bound(2.)); }));
}

// make_hex_dominant_mesh_3 on the cube at 5,832 = 18^3 particles, with the default levels: the
// cube wants 17 cells across, which a lattice refined once from 2 l* cannot have (it left a
// dislocation line of prisms and tets); the lattice must come out whole, all-hex, filling the cube
void test_all_hex_cube_at_odd_layer_count()
{
  Surface_mesh surface;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(VVM_DATA_DIR) + "/cube.off", surface));
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, Constant_field(),
      TLM::parameters::number_of_particles(std::size_t(5832), HDM::parameters::hex_dominant_report(&report,
          TLM::parameters::number_of_threads(2))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, cube, 5832 particles asked: " << report.number_of_particles << " particles, "
            << s.number_of_hexahedra << " hex, " << s.number_of_prisms << " prisms, " << s.number_of_pyramids
            << " pyramids, " << s.number_of_tetrahedra << " tets; H_vol " << s.hexahedron_volume_percent << "%, SJ min "
            << s.scaled_jacobian_min << "\n";
  CHECK(s.number_of_hexahedra > 0 && s.number_of_prisms + s.number_of_pyramids + s.number_of_tetrahedra == 0);
  CHECK(s.hexahedron_volume_percent > 99.999);
  CHECK(std::abs(s.total_volume - 8.) < 0.08);
  CHECK(s.scaled_jacobian_min > 0.9);
  CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
}

// the Euclidean Delaunay tets of a perturbed grid of 4 x 1 x 1 boxes cross the boxes; the
// flips towards the Delaunay tets in the space of T = diag(4, 1, 1) let more of them merge,
// keep a valid partition, and end at a fixed point
void test_metric_flips()
{
  CGAL::Random random(11);
  std::vector<Point_3> points;
  const int n = 8;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      for(int k = 0; k < n; ++k)
        points.emplace_back(4 * (i + random.get_double(-0.04, 0.04)), j + random.get_double(-0.04, 0.04),
                            k + random.get_double(-0.04, 0.04));
  Delaunay tr(points.begin(), points.end());
  const Constant_field field(Eigen::Vector3d(4, 1, 1).asDiagonal());
  auto hexahedra = [&] {
    return CGAL::tets_to_hex_dominant(tr, HDM::parameters::frame_field(field)).number_of_cells(CGAL::Hex_dominant_cell_type::HEXAHEDRON);
  };
  const std::size_t before = hexahedra();
  CGAL::GSM_mesh_optimization::internal::Triangulation_complex<Delaunay> complex(tr);
  TLM::internal::Metric_Delaunay_flips<decltype(complex)> flips(complex, [](const Eigen::Vector3d&) {
    return Eigen::Matrix3d(Eigen::Vector3d(0.25, 1, 1).asDiagonal());
  });
  const std::size_t done = flips.run(100000);
  const std::size_t after = hexahedra();
  std::cout << "metric flips, 4x1x1 boxes " << n << "^3: " << done << " flips, hexahedra " << before << " -> " << after
            << " of " << (n - 1) * (n - 1) * (n - 1) << "\n";
  // Lawson's flips can get stuck in 3D (here at 280 of 343): make_hex_dominant_mesh_3 starts
  // from the Delaunay tets of the points mapped by the field's mean metric, exact for a
  // constant field, and flips only for the variation of the field
  CHECK(done > 0 && after > before);
  CHECK(tr.tds().is_valid());
  std::size_t positive = 0;
  for(auto c : tr.finite_cell_handles()) positive += tr.tetrahedron(c).orientation() == CGAL::POSITIVE;
  CHECK(positive == tr.number_of_finite_cells());
  HDM::Hex_dominant_merge_report report;
  const Mesh mesh = CGAL::tets_to_hex_dominant(tr, HDM::parameters::frame_field(field, HDM::parameters::merge_report(&report)));
  check_partition(mesh, report, tr, 0.02);
  // a second run finds nothing left to flip
  CHECK(flips.run(100000) == 0);
}

// make_hex_dominant_mesh_3 on the warped cube T [-1, 1]^3 of the shear T of Fig. 4.15e: its
// faces are lattice planes, and the tets (Delaunay of the particles mapped into the field's
// space) merge into hexahedra only
void test_make_hex_dominant_mesh_on_warped_cube()
{
  Surface_mesh surface;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(VVM_DATA_DIR) + "/cube.off", surface));
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
      domain, field, TLM::parameters::edge_length(0.25, HDM::parameters::hex_dominant_report(&report,
          TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(1u)))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(
      mesh, [&](const Eigen::Vector3d&) { return field.B(Point_3(0, 0, 0)); }, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, warped cube (shear), l* 0.25: " << report.number_of_particles << " particles, "
            << report.number_of_metric_flips << " metric flips -> " << s.number_of_hexahedra << " hex, "
            << mesh.cells.size() - s.number_of_hexahedra << " other cells; H_vol " << s.hexahedron_volume_percent
            << "%, SJ min " << s.scaled_jacobian_min << "\n";
  CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
  CHECK(s.hexahedron_volume_percent > 99.);
  CHECK(s.scaled_jacobian_min > 0.9);
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
    const Mesh mesh = CGAL::tets_to_hex_dominant(corners, tets, {}, HDM::parameters::quality_bound(0., HDM::parameters::merge_report(&report)));
    std::vector<int> corner_of_point(8);
    for(int c = 0; c < 8; ++c) corner_of_point[std::size_t(c)] = c;
    const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, nullptr, &report);
    std::vector<int> uses(tets.size(), 0);
    for(const auto& c : report.cell_tets)
      for(std::size_t t : c) ++uses[t];
    std::cout << "flat tet on a boundary quad (bend " << bend << "): " << mesh.cells.size() << " cells, "
              << report.number_of_flat_tets_taken_in << " flat tet taken in\n";
    CHECK(mesh.cells[0].type == CGAL::Hex_dominant_cell_type::HEXAHEDRON &&
          has_cube_corner_order(mesh.cells[0], corner_of_point));
    CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
    CHECK(std::count(uses.begin(), uses.end(), 1) == std::ptrdiff_t(tets.size())); // a partition of the tets
    if(bend < 0.1)
      CHECK(mesh.cells.size() == 1 && report.cell_tets[0].size() == 7 && report.number_of_flat_tets_taken_in == 1);
    else
      CHECK(mesh.cells.size() == 2 && report.cell_tets[0].size() == 6 && report.number_of_flat_tets_taken_in == 0);
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
  CHECK(CGAL::IO::read_polygon_mesh(std::string(VVM_DATA_DIR) + "/cube.off", surface));
  for(auto v : surface.vertices()) {
    const Point_3& p = surface.point(v); // [-1, 1]^3 -> [0.1, 1.1]^3
    surface.point(v) = Point_3(0.6 + 0.5 * p.x(), 0.6 + 0.5 * p.y(), 0.6 + 0.5 * p.z());
  }
  Cube_domain domain(surface);
  domain.detect_features(60);
  HDM::Hex_dominant_report report;
  const auto field = CGAL::Frame_fields::single_direction_anisotropy_frame_field<K>();
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
      domain, field, TLM::parameters::number_of_particles(800, HDM::parameters::hex_dominant_report(&report,
          TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(1u)))));
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(
      mesh, [&](const Eigen::Vector3d& x) { return Eigen::Matrix3d(field.B(Point_3(x[0], x[1], x[2]))); }, &report.merge);
  std::cout << "make_hex_dominant_mesh_3, cube with Fig. 4.8's field, 800 particles asked: " << report.number_of_particles
            << " particles -> " << s.number_of_hexahedra << " hex, " << mesh.cells.size() - s.number_of_hexahedra
            << " other cells; H_vol " << s.hexahedron_volume_percent << "%, SJ min " << s.scaled_jacobian_min
            << ", volume " << s.total_volume << "\n";
  CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
  CHECK(std::abs(s.total_volume - 1) < 1e-9);
  CHECK(s.hexahedron_volume_percent > 99.99);
  CHECK(s.scaled_jacobian_min > 0.9);
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

// the boundary refinement of section 4.4.2 on a sphere: surface points are added where the
// tets' facets cut the sphere too deep, and the facets come closer to it
void test_boundary_refinement()
{
  Surface_mesh surface;
  CHECK(CGAL::IO::read_polygon_mesh(std::string(VVM_DATA_DIR) + "/sphere966.off", surface));
  Cube_domain domain(surface);
  double distance[2] = {0, 0};
  for(int refine = 0; refine < 2; ++refine) {
    HDM::Hex_dominant_report report;
    Cube_c3t3 tets;
    const double threshold = refine ? 0.5 * distance[0] : 0.;
    const Mesh mesh = CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(
        domain, Constant_field(), TLM::parameters::edge_length(2.5, HDM::parameters::boundary_distance(threshold,
            HDM::parameters::hex_dominant_report(&report, HDM::parameters::tetrahedral_mesh(&tets,
                TLM::parameters::number_of_threads(2, CGAL::parameters::random_seed(2u)))))));
    distance[refine] = boundary_facet_distance(tets, surface);
    const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &report.merge);
    std::cout << "sphere of radius 10, l* 2.5, boundary distance " << threshold << ": " << report.number_of_boundary_points
              << " surface points added, facets within " << distance[refine] << " of the sphere; " << s.number_of_hexahedra
              << " hex, H_vol " << s.hexahedron_volume_percent << "%\n";
    CHECK(s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0);
    CHECK((report.number_of_boundary_points > 0) == (refine == 1));
  }
  CHECK(distance[1] < 0.75 * distance[0]);
  CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), HDM::parameters::boundary_distance(-1.)); }));
  CHECK(throws([&] { CGAL::make_hex_dominant_mesh_3<Cube_c3t3>(domain, Constant_field(), HDM::parameters::boundary_distance(std::nan(""))); }));
}

void test_bad_input()
{
  std::vector<Point_3> p = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1)};
  Delaunay tr(p.begin(), p.end());
  CHECK(throws([&] { CGAL::tets_to_hex_dominant(tr, HDM::parameters::quality_bound(1.5)); }));
  CHECK(throws([&] { CGAL::tets_to_hex_dominant(tr, HDM::parameters::quality_bound(std::nan(""))); }));
  CHECK(throws([&] { CGAL::tets_to_hex_dominant(tr, CGAL::Tetrahedral_lattice_meshing::parameters::number_of_threads(-1)); }));
  Delaunay empty;
  CHECK(CGAL::tets_to_hex_dominant(empty).cells.empty());
}

} // namespace

int main()
{
  test_cube_triangulations();
  test_seven_tet_hexahedra();
  test_prism_and_pyramid();
  test_cubic_grid();
  test_cell_scaled_jacobians();
  test_random_tets();
  test_nonconforming_detected();
  test_make_hex_dominant_mesh_on_cube();
  test_all_hex_cube_at_odd_layer_count();
  test_metric_flips();
  test_make_hex_dominant_mesh_on_warped_cube();
  test_make_hex_dominant_mesh_on_graded_cube();
  test_flat_tet_on_boundary_quad();
  test_boundary_refinement();
  test_bad_input();
  if(failures) std::cerr << failures << " checks failed\n";
  else std::cout << "all checks passed\n";
  return failures ? 1 : 0;
}
