// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The importance of scale correction (dissertation Fig. 4.16): a thick tube about
// the z axis (radii 0.5 and 1, height 1), a closed triangle surface made here,
// meshed with the cylinder's cross field (radial, tangential, axial unit axes)
// and with the same field scale-corrected (the tangential axis r / r0 long, so
// that every ring holds the same number of cells). Without the correction the
// rings hold more cells outside than inside, and the non-hex cells fill the gaps
// between them; with it the lattice is a polar grid that can be all hexahedra.
// The corrected field is degenerate on the axis, hence the tube rather than a
// solid cylinder. Writes cylinder_cross.vtu and cylinder_corrected.vtu.
//
// usage: hex_dominant_cylinder [OUTPUT_DIR [EDGE_LENGTH]]   (default l* = 0.125)

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
#include <exception>
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

const double pi = 3.14159265358979323846;

// the tube r_in <= r <= r_out, 0 <= z <= height, n facets around, outward oriented
Surface_mesh tube(double r_in, double r_out, double height, int n)
{
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> ob, ot, ib, it; // outer/inner, bottom/top rings
  for(int i = 0; i < n; ++i) {
    const double c = std::cos(2 * pi * i / n), s = std::sin(2 * pi * i / n);
    ob.push_back(sm.add_vertex(K::Point_3(r_out * c, r_out * s, 0)));
    ot.push_back(sm.add_vertex(K::Point_3(r_out * c, r_out * s, height)));
    ib.push_back(sm.add_vertex(K::Point_3(r_in * c, r_in * s, 0)));
    it.push_back(sm.add_vertex(K::Point_3(r_in * c, r_in * s, height)));
  }
  // each quad counter-clockwise seen from outside the domain, as two triangles
  auto quad = [&sm](auto a, auto b, auto c, auto d) {
    sm.add_face(a, b, c);
    sm.add_face(a, c, d);
  };
  for(int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    quad(ob[i], ob[j], ot[j], ot[i]); // outer wall, normal e_r
    quad(ib[i], it[i], it[j], ib[j]); // inner wall, normal -e_r
    quad(ot[i], ot[j], it[j], it[i]); // top, normal z
    quad(ob[i], ib[i], ib[j], ob[j]); // bottom, normal -z
  }
  return sm;
}

// meshes `domain` aligned with `field`, prints one line of measures, writes DIR/NAME.vtu
// and returns the measures
template <class FrameField>
HDM::Hex_dominant_statistics mesh_tube(const std::string& name, const Domain& domain, const FrameField& field,
                                       double edge_length, const std::string& dir)
{
  HDM::Hex_dominant_report r;
  const Mesh mesh = CGAL::make_hex_dominant_mesh_3<C3T3>(
      domain, field, TLM::parameters::edge_length(edge_length, HDM::parameters::report(&r)));

  // eq. 4.5 is measured in the field's space: pass the frame inverse B
  auto B = [&field](const Eigen::Vector3d& x) { return Eigen::Matrix3d(field.B(K::Point_3(x[0], x[1], x[2]))); };
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh, B, &r.merge);
  std::printf("%-20s %5zu %5zu %5zu %5zu %5zu  %6.2f  %5.3f/%5.3f  %6.3f  %5.2f  %3zu  %3zu  %6.2f s "
              "(%.2f + %.2f + %.2f)\n",
              name.c_str(), r.number_of_particles, s.number_of_hexahedra, s.number_of_prisms, s.number_of_pyramids,
              s.number_of_tetrahedra, s.hexahedron_volume_percent, s.scaled_jacobian_min, s.scaled_jacobian_mean,
              s.verdict_scaled_jacobian_min, s.alignment_error_mean, s.number_of_inverted_cells,
              s.number_of_nonconforming_faces, r.particle_time + r.tetrahedra_time + r.merge_time, r.particle_time,
              r.tetrahedra_time, r.merge_time);

  const std::string file = dir + "/" + name + ".vtu";
  HDM::IO::write_VTU(file, mesh, {{"scaled_jacobian", HDM::cell_scaled_jacobians(mesh, B)}});
  std::cout << "wrote " << vvm_example::absolute(file) << "\n";
  return s;
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  const double l = argc > 2 ? std::strtod(argv[2], nullptr) : 0.125;
  if(!(l > 0 && l < 0.5)) {
    std::fprintf(stderr, "hex_dominant_cylinder: the edge length must be in (0, 0.5)\n");
    return EXIT_FAILURE;
  }
  const double r_in = 0.5, r_out = 1, height = 1;
  Surface_mesh sm = tube(r_in, r_out, height, 96);
  Domain domain(sm);
  domain.detect_features(60); // the four rims; the walls turn by 3.75 degrees between facets

  // r0: the radius where the corrected tangential axis has unit length; taken so that a whole
  // number of cells l* long fits around the middle of the tube's wall
  const double cells_around = std::round(2 * pi * 0.5 * (r_in + r_out) / l);
  const double r0 = cells_around * l / (2 * pi);

  std::printf("%-20s %5s %5s %5s %5s %5s  %6s  %11s  %6s  %5s  %3s  %3s  %s\n", "field", "part.", "hex", "prism", "pyr",
              "tet", "H_vol%", "SJ min/mean", "Verd.", "align", "inv", "ncf", "time (particles + tets + merging)");
  HDM::Hex_dominant_statistics cross, corrected;
  try {
    cross = mesh_tube("cylinder_cross", domain, FF::cylinder_frame_field<K>(r0, false), l, dir);
    // The corrected field is degenerate on the axis, outside the tube, but the particle engine
    // also looks at the field at the centre of the domain's bounding box: there, and anywhere
    // in the hole, take the frame of the nearest point of the inner wall (nothing changes inside).
    const auto field = FF::cylinder_frame_field<K>(r0, true);
    const auto corrected_field = FF::make_closed_form_frame_field_3<K>([field, r_in](const K::Point_3& p) {
      const double r = std::hypot(p.x(), p.y());
      if(r >= r_in) return field.T(p);
      if(r > 0) return field.T(K::Point_3(p.x() * r_in / r, p.y() * r_in / r, p.z()));
      return field.T(K::Point_3(r_in, 0, p.z()));
    });
    corrected = mesh_tube("cylinder_corrected", domain, corrected_field, l, dir);
  } catch(const std::exception& e) {
    std::fprintf(stderr, "hex_dominant_cylinder: %s\n", e.what());
    return EXIT_FAILURE;
  }
  std::printf("(r0 = %.4f: the corrected field fits %.0f cells around; SJ: eq. 4.5 in the field's space;\n"
              " Verd.: Verdict's isotropic SJ min; align: mean alignment error of the hexahedra's edges, degrees;\n"
              " inv: inverted cells; ncf: non-conforming faces; times in seconds)\n",
              r0, cells_around);

  const double volume = pi * (r_out * r_out - r_in * r_in) * height;
  bool ok = true;
  for(const auto* s : {&cross, &corrected})
    ok &= s->number_of_hexahedra > 0 && s->number_of_inverted_cells == 0 && s->number_of_nonconforming_faces == 0 &&
          std::abs(s->total_volume - volume) < 0.05 * volume;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
