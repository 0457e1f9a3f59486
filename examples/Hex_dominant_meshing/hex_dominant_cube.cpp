// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hex-dominant meshes of the cubes of the dissertation's Fig. 4.15, each with its
// frame field: (a) T = I, (b) the stretch diag(4, 1, 1), (c) the linear scale
// diag(8|x|, 1, 1), all three on [-1,1]^3; (d) the anisotropy along x of Fig. 4.8
// on [0.1, 1.1]^3; (e) the shear on y and (f) the shear on y and z, on the "warped
// cubes" of the figure: [-1,1]^3 mapped by T, whose faces the sheared lattice fits.
// Each mesh is written as cube_<field>.vtu with the scaled Jacobian of each cell in
// the field's space.
//
// usage: hex_dominant_cube [OUTPUT_DIR [SIZE [FIELDS]]]
//        SIZE: a number of particles (an integer >= 1, default 800 per field) or,
//        if it is under 1 or has a fractional part, the edge length l*
//        FIELDS: the letters of the fields to mesh (default abcdef; about a second each at 800)

#include <CGAL/make_mesh_3.h> // first: it brings the TBB headers CGAL's other Mesh_3 headers need

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/Hex_dominant_meshing/IO/write_VTU.h>
#include <CGAL/Hex_dominant_meshing/cell_quality.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_hex_dominant_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Domain;
typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3T3;
typedef CGAL::Hex_dominant_mesh_3<K::Point_3> Mesh;
namespace FF = CGAL::Frame_fields;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;

// the cube [lo, hi]^3 mapped by T, as 12 triangles, outward oriented if det T > 0
Surface_mesh cube(double lo, double hi, const Eigen::Matrix3d& T = Eigen::Matrix3d::Identity())
{
  Surface_mesh sm;
  Surface_mesh::Vertex_index v[8];
  for(int i = 0; i < 8; ++i) {
    const Eigen::Vector3d p = T * Eigen::Vector3d(i & 4 ? hi : lo, i & 2 ? hi : lo, i & 1 ? hi : lo);
    v[i] = sm.add_vertex(K::Point_3(p[0], p[1], p[2]));
  }
  const int triangles[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  for(const auto& t : triangles) sm.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return sm;
}

struct Size
{
  std::size_t particles = 800;
  double edge_length = 0; // used instead of `particles` if positive
};

// meshes the closed surface `sm` (of volume `volume`) aligned with `field`, prints one line
// of measures and writes DIR/cube_NAME.vtu; returns false if the mesh is empty, inverted,
// non-conforming, or does not fill the domain
template <class FrameField>
bool mesh_cube(const std::string& name, Surface_mesh sm, double volume, const FrameField& field, const Size& size,
               const std::string& dir)
{
  Domain domain(sm);
  domain.detect_features(30); // the 12 edges and 8 corners (the warped cubes' edges turn by 63 degrees or more)

  HDM::Hex_dominant_report r;
  auto run = [&](const auto& size_np) {
    return CGAL::make_hex_dominant_mesh_3<C3T3>(domain, field, HDM::parameters::report(&r, size_np));
  };
  Mesh mesh;
  try {
    mesh = size.edge_length > 0 ? run(TLM::parameters::edge_length(size.edge_length))
                                : run(TLM::parameters::number_of_particles(size.particles));
  } catch(const std::invalid_argument& e) { // e.g. the particles make no cell inside the domain
    std::printf("%-16s failed: %s\n", name.c_str(), e.what());
    return false;
  }

  // eq. 4.5 is measured in the field's space: pass the frame inverse B
  auto B = [&field](const Eigen::Vector3d& x) { return Eigen::Matrix3d(field.B(K::Point_3(x[0], x[1], x[2]))); };
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, B, &r.merge);
  std::printf("%-16s %5zu %5zu %5zu %5zu %5zu  %6.2f  %5.3f/%5.3f  %6.3f  %5.2f  %3zu  %3zu  %6.2f s "
              "(%.2f + %.2f + %.2f)\n",
              name.c_str(), r.number_of_particles, s.number_of_hexahedra, s.number_of_prisms, s.number_of_pyramids,
              s.number_of_tetrahedra, s.hexahedron_volume_percent, s.scaled_jacobian_min, s.scaled_jacobian_mean,
              s.verdict_scaled_jacobian_min, s.alignment_error_mean, s.number_of_inverted_cells,
              s.number_of_nonconforming_faces, r.particle_time + r.tetrahedra_time + r.merge_time, r.particle_time,
              r.tetrahedra_time, r.merge_time);

  const std::string file = dir + "/cube_" + name + ".vtu";
  HDM::IO::write_VTU(file, mesh, {{"scaled_jacobian", HDM::cell_scaled_jacobians(mesh, B)}});
  std::cout << "wrote " << vvm_example::absolute(file) << "\n";

  // the cells fill the domain up to the particles' hull
  return mesh.number_of_cells() > 0 && s.number_of_hexahedra > 0 && s.number_of_inverted_cells == 0 &&
         s.number_of_nonconforming_faces == 0 && std::abs(s.total_volume - volume) < 0.05 * volume;
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  Size size;
  if(argc > 2) {
    const double v = std::strtod(argv[2], nullptr);
    if(!(v > 0)) {
      std::fprintf(stderr, "hex_dominant_cube: the size '%s' is not a positive number\n", argv[2]);
      return EXIT_FAILURE;
    }
    if(v >= 1 && v == std::floor(v)) size.particles = std::size_t(v);
    else size.edge_length = v;
  }

  // Fig. 4.15c: T = diag(8x, 1, 1) is degenerate on the plane x = 0, in the middle of its
  // cube, and left-handed for x < 0. The figure's scale first decreases, then increases:
  // use |x|, kept at least 1/16 (T = diag(0.5, 1, 1) there) so that the frame stays regular.
  const auto linear = FF::linear_scale_frame_field<K>();
  const auto linear_scale = FF::make_closed_form_frame_field_3<K>([linear](const K::Point_3& p) {
    return linear.T(K::Point_3((std::max)(std::abs(p.x()), 1. / 16), p.y(), p.z()));
  });

  const std::string fields = argc > 3 ? argv[3] : "abcdef";
  auto wanted = [&fields](char f) { return fields.find(f) != std::string::npos; };

  std::printf("%-16s %5s %5s %5s %5s %5s  %6s  %11s  %6s  %5s  %3s  %3s  %s\n", "field", "part.", "hex", "prism", "pyr",
              "tet", "H_vol%", "SJ min/mean", "Verd.", "align", "inv", "ncf", "time (particles + tets + merging)");
  bool ok = true;
  if(wanted('a')) ok &= mesh_cube("a_identity", cube(-1, 1), 8, FF::identity_frame_field<K>(), size, dir);
  if(wanted('b')) ok &= mesh_cube("b_stretch", cube(-1, 1), 8, FF::constant_stretch_frame_field<K>(), size, dir);
  if(wanted('c')) ok &= mesh_cube("c_linear_scale", cube(-1, 1), 8, linear_scale, size, dir);
  // Fig. 4.8's T (densest at x = 0.6, its x axis 80 times shorter there); Fig. 4.15d prints its
  // inverse (see the header)
  if(wanted('d'))
    ok &= mesh_cube("d_single_dir", cube(0.1, 1.1), 1, FF::single_direction_anisotropy_frame_field<K>(), size, dir);
  const auto shear_y = FF::shear_y_frame_field<K>(), shear_yz = FF::shear_yz_frame_field<K>();
  const Eigen::Matrix3d T_y = shear_y.T(K::Point_3(0, 0, 0)), T_yz = shear_yz.T(K::Point_3(0, 0, 0));
  if(wanted('e')) ok &= mesh_cube("e_shear_y", cube(-1, 1, T_y), 8 * T_y.determinant(), shear_y, size, dir);
  if(wanted('f')) ok &= mesh_cube("f_shear_yz", cube(-1, 1, T_yz), 8 * T_yz.determinant(), shear_yz, size, dir);
  std::printf("(SJ: eq. 4.5 in the field's space; Verd.: Verdict's isotropic SJ min; align: mean alignment error\n"
              " of the hexahedra's edges, degrees; inv: inverted cells; ncf: non-conforming faces; times in s)\n");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
