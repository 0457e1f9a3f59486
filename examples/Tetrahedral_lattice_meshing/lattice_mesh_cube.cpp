// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lattice meshes of the cube [-1,1]^3 (dissertation Table 4.2) with
// T = I as a BCC and an FCC lattice whose edge length fits the cube (16 and 13
// cells across: the lattice can close on the faces with every particle on a site).
//
// usage: lattice_mesh_cube [OUTPUT_DIR]   (writes cube_bcc.mesh and cube_fcc.mesh)

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Tetrahedral_lattice_meshing/alignment_error.h>
#include <CGAL/make_lattice_mesh_3.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace FF = CGAL::Frame_fields;

Surface_mesh cube(double lo, double hi)
{
  Surface_mesh sm;
  Surface_mesh::Vertex_index v[8];
  for(int i = 0; i < 8; ++i) v[i] = sm.add_vertex(K::Point_3(i & 4 ? hi : lo, i & 2 ? hi : lo, i & 1 ? hi : lo));
  const int triangles[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  for(const auto& t : triangles) sm.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return sm;
}

template <class FrameField, class MetricB>
void report(const std::string& name, const C3T3& c3t3, const FrameField& field, TLM::Lattice_type lattice,
            const TLM::Lattice_mesh_report& r, const MetricB& B, const std::string& dir)
{
  const auto q = CGAL::GSM_mesh_optimization::mesh_quality_statistics(c3t3, B);
  const auto a = TLM::alignment_statistics(c3t3, field, TLM::Lattice::make(lattice));
  std::printf("%-10s %6zu particles, %6zu tets: min dihedral %5.2f (mean %5.2f), max %6.2f, %zu under 40 deg, "
              "alignment error %.2f deg; particles %.2f s, mesh %.2f s, GSM %.2f s\n",
              name.c_str(), r.number_of_particles, q.number_of_cells, q.min_dihedral_angle,
              q.mean_min_dihedral_angle, q.max_dihedral_angle, q.n_min_dihedral_below[3], a.mean, r.particle_time,
              r.connection_time, r.gsm_time);
  const std::string file = dir + "/" + name + ".mesh";
  std::ofstream os(file);
  CGAL::IO::output_to_medit(os, c3t3, false, true);
  std::cout << "wrote " << vvm_example::absolute(file) << "\n";
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  const auto identity = FF::identity_frame_field<K>();
  const auto isotropic = [](const auto&) { return Eigen::Matrix3d(Eigen::Matrix3d::Identity()); };

  Surface_mesh sm = cube(-1, 1);
  Domain domain(sm);
  domain.detect_features(60); // the 12 edges and 8 corners of the cube
  TLM::Lattice_mesh_report r;

  // BCC: l* = 2/16, 17^3 + 16^3 = 9009 particles on the lattice sites
  C3T3 bcc = CGAL::make_lattice_mesh_3<C3T3>(
      domain, identity,
      TLM::parameters::lattice(TLM::Lattice_type::BCC, TLM::parameters::edge_length(2. / 16, TLM::parameters::report(&r))));
  report("cube_bcc", bcc, identity, TLM::Lattice_type::BCC, r, isotropic, dir);

  // FCC: l* = 2/13, 14^3 + 3 * 13^2 * 14 = 9842 sites
  C3T3 fcc = CGAL::make_lattice_mesh_3<C3T3>(
      domain, identity,
      TLM::parameters::lattice(TLM::Lattice_type::FCC, TLM::parameters::edge_length(2. / 13, TLM::parameters::report(&r))));
  report("cube_fcc", fcc, identity, TLM::Lattice_type::FCC, r, isotropic, dir);

  return 0;
}
