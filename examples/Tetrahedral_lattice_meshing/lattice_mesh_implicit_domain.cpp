// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The torus of Table 4.3 (radii 1 and 0.4 about the y axis), an implicit
// domain, with the frame field that turns with it (rotation about y): first the
// particles alone, with a visitor showing the rounds, then the lattice mesh.
//
// usage: lattice_mesh_implicit_domain [OUTPUT.mesh]   (default torus_bcc.mesh)

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/lattice_particles_3.h>
#include <CGAL/make_lattice_mesh_3.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;

double torus(const K::Point_3& p)
{
  const double d = std::hypot(p.x(), p.z()) - 1.;
  return d * d + p.y() * p.y() - 0.16;
}

int main(int argc, char** argv)
{
  const std::string output = argc > 1 ? argv[1] : "torus_bcc.mesh";
  namespace P = CGAL::parameters;
  Domain domain = Domain::create_implicit_mesh_domain(torus, K::Sphere_3(CGAL::ORIGIN, 4.), P::relative_error_bound = 1e-6);
  const auto field = CGAL::Frame_fields::rotation_about_y_frame_field<K>();

  // the particles, round by round
  auto progress = [](const TLM::Lattice_round_report& r) {
    std::printf("  level %d round %2d: %5zu particles (-%zu +%zu), energy per particle %.4f, %.2f s\n", r.level,
                r.round, r.number_of_particles, r.number_deleted, r.number_inserted, r.energy, r.elapsed_time);
  };
  const TLM::Lattice_particles_3<K::Point_3> particles =
      CGAL::lattice_particles_3(domain, field, TLM::parameters::number_of_particles(2400, P::visitor(progress)));
  std::printf("%zu particles: %zu on the surface, %zu inside\n", particles.size(),
              particles.number_of(TLM::Particle_kind::BOUNDARY), particles.number_of(TLM::Particle_kind::FREE));

  // the mesh: the same particles (same seed), connected, then GSM
  TLM::Lattice_mesh_report r;
  const C3T3 c3t3 =
      CGAL::make_lattice_mesh_3<C3T3>(domain, field, TLM::parameters::number_of_particles(2400, TLM::parameters::report(&r)));
  const auto q = CGAL::GSM_mesh_optimization::mesh_quality_statistics(c3t3);
  std::printf("torus: %zu tets, min dihedral %.2f (mean %.2f), %zu under 20 deg, %zu under 40 deg\n", q.number_of_cells,
              q.min_dihedral_angle, q.mean_min_dihedral_angle, q.n_min_dihedral_below[1], q.n_min_dihedral_below[3]);
  std::ofstream os(output);
  CGAL::IO::output_to_medit(os, c3t3, false, true);
  std::cout << "wrote " << vvm_example::absolute(output) << "\n";
  return 0;
}
