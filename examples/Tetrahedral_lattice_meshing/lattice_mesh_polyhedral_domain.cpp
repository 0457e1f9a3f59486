// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A BCC lattice mesh of a CAD part aligned with its boundary: no frame field is
// given, so make_lattice_mesh_3() generates the boundary-aligned cross field
// (generate_cross_field_3) on a make_mesh_3 mesh of the domain. Sharp edges
// (dihedral angle off by more than 60 degrees) carry particles that slide on
// them; their meeting points are fixed corner particles.
//
// usage: lattice_mesh_polyhedral_domain [SURFACE [PARTICLES [OUTPUT.mesh]]]
//        (default: data/fandisk.off, 5000 particles, fandisk_bcc.mesh)

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_lattice_mesh_3.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : vvm_example::data_file("fandisk.off");
  const std::size_t particles = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 5000;
  const std::string output = argc > 3 ? argv[3] : "fandisk_bcc.mesh";

  Surface_mesh sm;
  if(!CGAL::IO::read_polygon_mesh(input, sm) || sm.is_empty() || !CGAL::is_closed(sm) ||
     !CGAL::is_triangle_mesh(sm)) {
    std::cerr << "lattice_mesh_polyhedral_domain: '" << input << "' is not a closed triangle mesh\n";
    return EXIT_FAILURE;
  }
  Domain domain(sm);
  domain.detect_features(60);

  TLM::Lattice_mesh_report r;
  try {
    const C3T3 c3t3 = CGAL::make_lattice_mesh_3<C3T3>(
        domain, TLM::parameters::number_of_particles(particles, TLM::parameters::report(&r)));
    const auto q = CGAL::GSM_mesh_optimization::mesh_quality_statistics(c3t3);
    std::printf("%zu particles (l* = %.4g), %zu tets, %zu feature edges: min dihedral %.2f (mean %.2f), "
                "%zu under 20 deg; particles %.2f s, mesh %.2f s, GSM %.2f s\n",
                r.number_of_particles, r.edge_length, q.number_of_cells, r.number_of_feature_edges,
                q.min_dihedral_angle, q.mean_min_dihedral_angle, q.n_min_dihedral_below[1], r.particle_time,
                r.connection_time, r.gsm_time);
    std::ofstream os(output);
    CGAL::IO::output_to_medit(os, c3t3, false, true);
    std::cout << "wrote " << vvm_example::absolute(output) << "\n";
  } catch(const std::invalid_argument& e) {
    std::cerr << "lattice_mesh_polyhedral_domain: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
