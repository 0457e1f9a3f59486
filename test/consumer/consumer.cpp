// Uses an installed VVM: the quality of a Delaunay tetrahedralization of a
// cube's corners and centre: 12 congruent tets (half a face and the centre),
// with dihedral angles 45, 45, 60, 60, 90, 120 deg. Then GSM on it (the hull
// is fixed and the centre is already optimal for the 12 tets) and a frame field.
#include <CGAL/Frame_fields/Constant_frame_field_3.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

int main()
{
  CGAL::Delaunay_triangulation_3<K> dt;
  dt.insert(K::Point_3(0, 0, 0));
  for(int i = 0; i < 8; ++i)
    dt.insert(K::Point_3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  const auto s = CGAL::GSM_mesh_optimization::triangulation_quality_statistics(dt);
  std::cout << "cells " << s.number_of_cells << ", min dihedral " << s.min_dihedral_angle << "\n";
  const bool ok = s.number_of_cells == 12 && s.number_of_inverted_cells == 0 &&
                  std::abs(s.min_dihedral_angle - 45.) < 1e-9 &&
                  std::abs(s.max_dihedral_angle - 120.) < 1e-9;
  CGAL::gsm_optimize_triangulation_3(dt, CGAL::parameters::number_of_iterations(2));
  const auto t = CGAL::GSM_mesh_optimization::triangulation_quality_statistics(dt);
  const CGAL::Frame_fields::Constant_frame_field_3<K> field(Eigen::Matrix3d(Eigen::Vector3d(4, 1, 1).asDiagonal()));
  const bool field_ok = std::abs(field.B(K::Point_3(0, 0, 0))(0, 0) - 0.25) < 1e-15;
  return ok && field_ok && t.number_of_inverted_cells == 0 && t.number_of_cells == 12 ? 0 : 1;
}
