// Uses an installed VVM: the quality of a Delaunay tetrahedralization of a
// cube's corners and centre: 12 congruent tets (half a face and the centre),
// with dihedral angles 45, 45, 60, 60, 90, 120 deg.
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

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
  return ok ? 0 : 1;
}
