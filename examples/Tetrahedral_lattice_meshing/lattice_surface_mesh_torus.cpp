// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An anisotropic triangle mesh of a torus whose vertices form a hexagonal lattice
// aligned with the principal curvature directions (dissertation section 4.3.4):
// short edges around the tube, where the surface bends most, long ones along the
// ring, so that every edge leaves the surface by about as much.
//
// usage: lattice_surface_mesh_torus [INPUT.off [VERTICES [OUTPUT.off]]]
//        (default: data/surfaces/torus.off, 3000 vertices, torus_lattice.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/principal_curvature_frame_field.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/make_lattice_surface_mesh.h>

#include <cstdio>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace FF = CGAL::Frame_fields;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : vvm_example::data_file("surfaces/torus.off");
  const std::size_t vertices = argc > 2 ? std::stoul(argv[2]) : 3000;
  const std::string output = argc > 3 ? argv[3] : "torus_lattice.off";
  Surface_mesh surface;
  if(!CGAL::IO::read_polygon_mesh(input, surface) || !CGAL::is_triangle_mesh(surface)) {
    std::cerr << "cannot read a triangle mesh from " << vvm_example::absolute(input) << "\n";
    return 2;
  }
  try {
    // lengths 1/sqrt|k|: along the ring up to 3 times those around the tube
    const auto field = FF::principal_curvature_frame_field(surface, FF::parameters::maximum_anisotropy(3.));
    TLM::Lattice_surface_mesh_report report;
    const Surface_mesh mesh =
        CGAL::make_lattice_surface_mesh(surface, field, TLM::parameters::report(&report, TLM::parameters::number_of_particles(vertices)));
    const TLM::Surface_mesh_quality q = TLM::surface_mesh_quality(mesh, field);
    std::printf("%zu vertices, %zu triangles: degree 6 at %.1f%% of the vertices; in the field's metric, "
                "quality xi mean %.3f (min %.3f), smallest angle %.1f deg (mean %.1f), edges %.1f deg off the "
                "lattice's directions; closed 2-manifold: %s; %.1f s\n",
                q.number_of_vertices, q.number_of_faces, 100 * q.r6, q.xi_mean, q.xi_min, q.min_angle,
                q.mean_min_angle, q.alignment_error_mean, q.is_closed_manifold ? "yes" : "no",
                report.particle_time + report.triangle_time);
    if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17))) {
      std::cerr << "cannot write " << output << "\n";
      return 1;
    }
    std::cout << "wrote " << vvm_example::absolute(output) << "\n";
    return q.is_closed_manifold ? 0 : 1;
  } catch(const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
