// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hex-dominant mesh of a CAD part: no frame field is given, so
// make_hex_dominant_mesh_3() generates the boundary-aligned cross field
// (generate_cross_field_3) on a make_mesh_3 mesh of the domain. Sharp edges
// (normals off by more than 60 degrees) carry particles that slide on them.
// The mesh is written for ParaView (.vtu), Gmsh (.msh) and MEDIT (.mesh); its tets
// are merged again with no quality bound.
//
// usage: hex_dominant_polyhedral_domain [SURFACE [PARTICLES [OUTPUT_PREFIX]]]
//        (default: data/fandisk.off, 3000 particles, fandisk_hex.{vtu,msh,mesh})

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MEDIT.h>
#include <CGAL/Hex_dominant_meshing/IO/write_MSH.h>
#include <CGAL/Hex_dominant_meshing/IO/write_VTU.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_hex_dominant_mesh_3.h>
#include <CGAL/tets_to_hex_dominant.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : vvm_example::data_file("fandisk.off");
  const std::size_t particles = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 3000;
  const std::string prefix = argc > 3 ? argv[3] : "fandisk_hex";

  Surface_mesh sm;
  if(!CGAL::IO::read_polygon_mesh(input, sm) || sm.is_empty() || !CGAL::is_closed(sm) ||
     !CGAL::is_triangle_mesh(sm)) {
    std::fprintf(stderr, "hex_dominant_polyhedral_domain: '%s' is not a closed triangle mesh\n", input.c_str());
    return EXIT_FAILURE;
  }
  Domain domain(sm);
  domain.detect_features(60);

  HDM::Hex_dominant_report r;
  HDM::Hex_dominant_statistics s;
  try {
    // no field: the (domain, np) overload generates the cross field; Q_bound 0.5 (the default)
    CGAL::Real_timer timer;
    timer.start();
    C3T3 tets; // the tets that were merged, kept to merge them again below
    const CGAL::Hex_dominant_mesh_3<K::Point_3> mesh = CGAL::make_hex_dominant_mesh_3<C3T3>(
        domain, TLM::parameters::number_of_particles(
                    particles, HDM::parameters::quality_bound(
                                   0.5, HDM::parameters::report(
                                            &r, HDM::parameters::tetrahedral_mesh(&tets)))));
    const double total = timer.time();

    // The generated field is a cross field: its B is a rotation, which leaves the scaled
    // Jacobian unchanged, so the isotropic measure (no B) is eq. 4.5 in the field's space.
    s = HDM::hex_dominant_statistics(mesh, {}, &r.merge);
    std::printf("%zu particles (l* = %.4g, %zu put onto the boundary), %zu tets -> %zu cells: %zu hexahedra, "
                "%zu prisms, %zu pyramids, %zu tetrahedra\n",
                r.number_of_particles, r.edge_length, r.number_of_projected_particles, r.merge.number_of_tets,
                mesh.number_of_cells(), s.number_of_hexahedra, s.number_of_prisms, s.number_of_pyramids,
                s.number_of_tetrahedra);
    std::printf("candidates: %zu hexahedra, %zu prisms, %zu pyramids\n", r.merge.number_of_hexahedron_candidates,
                r.merge.number_of_prism_candidates, r.merge.number_of_pyramid_candidates);
    std::printf("H_vol %.2f%%, #Hex %.2f%%, #Prism %.2f%%, #Pyr %.2f%%, #Tet %.2f%%; SJ min %.3f mean %.3f, "
                "Verdict SJ min %.3f mean %.3f; %zu inverted cells, %zu non-conforming faces; volume %.4g\n",
                s.hexahedron_volume_percent, s.hexahedron_count_percent, s.prism_count_percent, s.pyramid_count_percent,
                s.tetrahedron_count_percent, s.scaled_jacobian_min, s.scaled_jacobian_mean,
                s.verdict_scaled_jacobian_min, s.verdict_scaled_jacobian_mean, s.number_of_inverted_cells,
                s.number_of_nonconforming_faces, s.total_volume);
    // the report times the three stages; the cross field is made before them
    std::printf("time: %.2f s = cross field %.2f s + particles %.2f s + tets %.2f s + merging %.2f s\n", total,
                total - r.particle_time - r.tetrahedra_time - r.merge_time, r.particle_time, r.tetrahedra_time,
                r.merge_time);

    // the same tets with no quality bound: more hexahedra, worse ones (H*_vol, Q*_SJ of Table 4.7)
    HDM::Hex_dominant_merge_report r0;
    const auto unbounded =
        CGAL::tets_to_hex_dominant(tets, HDM::parameters::quality_bound(0., HDM::parameters::report(&r0)));
    const HDM::Hex_dominant_statistics s0 = HDM::hex_dominant_statistics(unbounded, {}, &r0);
    std::printf("Q_bound 0: %zu hexahedra, H_vol %.2f%%, SJ min %.3f mean %.3f; %zu inverted cells, "
                "%zu non-conforming faces\n",
                s0.number_of_hexahedra, s0.hexahedron_volume_percent, s0.scaled_jacobian_min, s0.scaled_jacobian_mean,
                s0.number_of_inverted_cells, s0.number_of_nonconforming_faces);
    if(s0.number_of_inverted_cells != 0 || s0.number_of_nonconforming_faces != 0) return EXIT_FAILURE;

    HDM::IO::write_VTU(prefix + ".vtu", mesh);
    HDM::IO::write_MSH(prefix + ".msh", mesh);
    HDM::IO::write_MEDIT(prefix + ".mesh", mesh);
    std::cout << "wrote " << vvm_example::absolute(prefix) << ".vtu, .msh and .mesh\n";
  } catch(const std::exception& e) {
    std::fprintf(stderr, "hex_dominant_polyhedral_domain: %s\n", e.what());
    return EXIT_FAILURE;
  }
  return s.number_of_hexahedra > 0 && s.number_of_inverted_cells == 0 && s.number_of_nonconforming_faces == 0
             ? EXIT_SUCCESS
             : EXIT_FAILURE;
}
