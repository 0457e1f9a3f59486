// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Frame fields: a closed-form field, one of the dissertation's, and a
// boundary-aligned cross field generated on a Delaunay tetrahedralization of
// a box, written for ParaView and in the text format, then read back.
//
// usage: frame_fields [OUTPUT_PREFIX]   (writes PREFIX.vtu and PREFIX.frames)

#include <CGAL/Frame_fields/Closed_form_frame_field_3.h>
#include <CGAL/Frame_fields/IO/frame_field_text_format.h>
#include <CGAL/Frame_fields/IO/write_VTU.h>
#include <CGAL/Frame_fields/boundary_alignment.h>
#include <CGAL/Frame_fields/dissertation_frame_fields.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace FF = CGAL::Frame_fields;

int main(int argc, char** argv)
{
  const std::string prefix = argc > 1 ? argv[1] : "frame_fields";

  // T(x): the axes with their lengths as columns; here cells twice as long along x near x = 1
  auto field = FF::make_closed_form_frame_field_3<K>([](const K::Point_3& p) {
    return Eigen::Matrix3d(Eigen::Vector3d(1 + p.x() * p.x(), 1, 1).asDiagonal());
  });
  const K::Point_3 p(1, 0, 0);
  std::cout << "closed form: T(1,0,0) =\n" << field.T(p) << "\nB(1,0,0) =\n" << field.B(p) << "\n";

  // the torus field of the dissertation (Table 4.3)
  const auto torus = FF::rotation_about_y_frame_field<K>();
  std::cout << "rotation about y at (1,0,0): radial axis " << torus.T(p).col(2).transpose() << "\n";

  // a cross field aligned with the faces and edges of the box [0,2]x[0,1]x[0,1]
  std::vector<K::Point_3> points;
  for(int i = 0; i <= 12; ++i)
    for(int j = 0; j <= 6; ++j)
      for(int k = 0; k <= 6; ++k) {
        // a slight shear off the grid inside: no four cospherical points
        const double t = (i % 12 && j % 6 && k % 6) ? 0.01 * ((i * 7 + j * 3 + k) % 5 - 2) : 0.;
        points.emplace_back(i / 6. + t, j / 6. + 0.7 * t, k / 6. - 0.4 * t);
      }
  CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
  // the visitor shows the smoothing's progress: the energy after each L-BFGS round
  const auto progress = [](const FF::Cross_field_round_report& r) {
    std::cout << "  smoothing round " << r.round << ": energy " << r.energy << "\n";
  };
  const FF::Generated_cross_field_3<K> g = FF::generate_cross_field_3(
      dt, FF::parameters::features_angle(60, FF::parameters::axis_length(1. / 6, CGAL::parameters::visitor(progress))));
  const FF::Boundary_alignment_statistics a = FF::boundary_alignment_statistics(g);
  std::cout << "generated: " << g.field.points().size() << " frames, " << g.singular_edges.size()
            << " singular edges of " << g.number_of_interior_edges << " (" << g.singular_curves.size()
            << " curves), boundary alignment error mean "
            << a.mean << " deg, max " << a.max << " deg\n";
  std::cout << "frame at the centre:\n" << g.field.T(K::Point_3(1, 0.5, 0.5)) << "\n";

  std::ofstream vtu(prefix + ".vtu");
  FF::IO::write_VTU(vtu, g.field);
  {
    std::ofstream text(prefix + ".frames");
    FF::IO::write_frame_field(text, g.field);
  }
  std::ifstream in(prefix + ".frames");
  const FF::Discrete_frame_field_3<K> back = FF::IO::read_frame_field<K>(in);
  std::cout << "wrote " << vvm_example::absolute(prefix + ".vtu") << " and " << vvm_example::absolute(prefix + ".frames")
            << ", read back " << back.frames().size() << " frames\n";
  return back.frames().size() == g.field.frames().size() && a.max < 1 ? 0 : 1;
}
