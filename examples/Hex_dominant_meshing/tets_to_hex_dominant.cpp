// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Merging one's own tets: the Delaunay triangulation of a jittered grid (whose
// cubes split into 5, 6 or 7 tets) merged into hexahedra, prisms and pyramids
// for several quality bounds Q_bound, the same tets given as points and index
// tets, and a make_mesh_3 mesh (few of its tets make hexahedra). The result is
// converted to a Linear_cell_complex_for_combinatorial_map<3>.
//
// usage: tets_to_hex_dominant [CELLS_PER_SIDE]   (default 10)

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_mesh_to_linear_cell_complex.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/tets_to_hex_dominant.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_3<K> Delaunay;
typedef CGAL::Labeled_mesh_domain_3<K> Implicit_domain;
typedef CGAL::Mesh_triangulation_3<Implicit_domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
typedef CGAL::Mesh_criteria_3<Tr> Criteria;
typedef CGAL::Hex_dominant_mesh_3<K::Point_3> Mesh;
typedef CGAL::Linear_cell_complex_for_combinatorial_map<3> LCC;
namespace HDM = CGAL::Hex_dominant_meshing;

// prints the measures of `mesh`; false if it is empty, has inverted cells, does not
// conform, or its cells do not use each tet exactly once
bool report(const char* name, const Mesh& mesh, const HDM::Hex_dominant_merge_report& r, double seconds)
{
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, {}, &r);
  std::printf("%-22s %6zu tets -> %5zu hex %5zu prisms %5zu pyramids %5zu tets; H_vol %6.2f%%, SJ min %.3f mean %.3f, "
              "%zu inverted, %zu non-conforming; %.2f s\n",
              name, r.number_of_tets, s.number_of_hexahedra, s.number_of_prisms, s.number_of_pyramids,
              s.number_of_tetrahedra, s.hexahedron_volume_percent, s.scaled_jacobian_min, s.scaled_jacobian_mean,
              s.number_of_inverted_cells, s.number_of_nonconforming_faces, seconds);
  std::vector<int> used(r.number_of_tets, 0);
  for(const auto& tets : r.cell_tets)
    for(std::size_t t : tets) ++used[t];
  bool partition = true;
  for(int u : used) partition &= u == 1;
  return mesh.number_of_cells() > 0 && s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0 &&
         partition;
}

int main(int argc, char** argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 10;
  if(n < 1 || n > 60) {
    std::fprintf(stderr, "tets_to_hex_dominant: CELLS_PER_SIDE must be in [1, 60]\n");
    return EXIT_FAILURE;
  }
  bool ok = true;
  try {
    // the grid of the unit cube, n cells per side, its points moved by up to 5% of a cell
    // but kept on the cube's faces (a bumpy convex hull would be lined with flat tets)
    CGAL::Random random(1);
    auto jitter = [&random, n](int i) { return i == 0 || i == n ? 0. : random.get_double(-0.05, 0.05); };
    std::vector<K::Point_3> points;
    const double h = 1. / n;
    for(int i = 0; i <= n; ++i)
      for(int j = 0; j <= n; ++j)
        for(int k = 0; k <= n; ++k) points.emplace_back(h * (i + jitter(i)), h * (j + jitter(j)), h * (k + jitter(k)));
    const Delaunay dt(points.begin(), points.end());

    // higher Q_bound: better hexahedra, fewer of them
    Mesh mesh;
    HDM::Hex_dominant_merge_report r;
    for(double q_bound : {0., 0.5, 0.8}) {
      CGAL::Real_timer timer;
      timer.start();
      mesh = CGAL::tets_to_hex_dominant(dt, HDM::parameters::quality_bound(q_bound, HDM::parameters::report(&r)));
      char name[64];
      std::snprintf(name, sizeof(name), "Delaunay, Q_bound %.1f:", q_bound);
      ok &= report(name, mesh, r, timer.time());
    }
    std::printf("  candidates: %zu hexahedra, %zu prisms, %zu pyramids\n", r.number_of_hexahedron_candidates,
                r.number_of_prism_candidates, r.number_of_pyramid_candidates);
    // the hexahedra by their number of tets: 5, 6, 7 (a flat tet between two prisms), plus the
    // flat tets they took in from between two quads of the same corners
    std::size_t of_tets[9] = {};
    for(std::size_t c = 0; c < mesh.number_of_cells(); ++c)
      if(mesh.cells[c].type == CGAL::Hex_dominant_cell_type::HEXAHEDRON)
        ++of_tets[(std::min)(r.cell_tets[c].size(), std::size_t(8))];
    std::printf("  hexahedra of 5 tets: %zu, of 6: %zu, of 7: %zu, of 8: %zu (flat tets taken in included)\n",
                of_tets[5], of_tets[6], of_tets[7], of_tets[8]);

    // the same tets as index tets (the report lists them as indices of the mesh's points)
    const std::vector<std::array<std::size_t, 4>> tets = r.tets;
    HDM::Hex_dominant_merge_report r2;
    const Mesh same = CGAL::tets_to_hex_dominant(
        mesh.points, tets, {}, HDM::parameters::quality_bound(0.8, HDM::parameters::report(&r2)));
    ok &= report("index tets, Q_bound 0.8:", same, r2, r2.candidate_time + r2.selection_time);
    ok &= same.number_of_cells() == mesh.number_of_cells();

    // a 3D linear cell complex: one volume per cell, 3-sewn along the shared faces
    LCC lcc;
    HDM::hex_dominant_mesh_to_linear_cell_complex(mesh, lcc);
    std::printf("Linear_cell_complex: %zu volumes, %zu vertex attributes, is_valid() = %s\n",
                lcc.one_dart_per_cell<3>().size(), lcc.number_of_vertex_attributes(),
                lcc.is_valid() ? "true" : "false");
    ok &= lcc.is_valid() && lcc.one_dart_per_cell<3>().size() == mesh.number_of_cells();

    // a make_mesh_3 mesh of the unit ball: isotropic tets, with few lattice-like groups
    namespace P = CGAL::parameters;
    auto ball = [](const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; };
    const Implicit_domain domain = Implicit_domain::create_implicit_mesh_domain(
        ball, K::Sphere_3(CGAL::ORIGIN, 4.), P::relative_error_bound = 1e-6);
    CGAL::get_default_random() = CGAL::Random(0); // the same mesh at every run
    const C3T3 c3t3 = CGAL::make_mesh_3<C3T3>(
        domain, Criteria(P::facet_angle = 25, P::facet_size = 0.2, P::facet_distance = 0.01,
                         P::cell_radius_edge_ratio = 2, P::cell_size = 0.2));
    CGAL::Real_timer timer;
    timer.start();
    HDM::Hex_dominant_merge_report r3;
    const Mesh mesh_of_ball =
        CGAL::tets_to_hex_dominant(c3t3, HDM::parameters::quality_bound(0.5, HDM::parameters::report(&r3)));
    ok &= report("make_mesh_3, Q_bound 0.5:", mesh_of_ball, r3, timer.time());
  } catch(const std::exception& e) {
    std::fprintf(stderr, "tets_to_hex_dominant: %s\n", e.what());
    return EXIT_FAILURE;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
