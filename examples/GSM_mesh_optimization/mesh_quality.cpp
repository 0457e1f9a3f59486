// Measures the element quality of a make_mesh_3 mesh before and after CGAL's
// sliver exudation, and writes the result for ParaView (.vtu with per-cell
// quality fields) and medit (.mesh).
//
// usage: mesh_quality [surface.off] [output_basename]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/exude_mesh_3.h>

#include <CGAL/GSM_mesh_optimization/IO/write_VTU_with_quality.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Mesh_domain;
typedef CGAL::Mesh_triangulation_3<Mesh_domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Mesh_domain::Corner_index,
                                                Mesh_domain::Curve_index> C3T3;
typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;

namespace GSM = CGAL::GSM_mesh_optimization;
namespace params = CGAL::parameters;

void print(const char* title, const GSM::Mesh_quality_statistics& q)
{
  std::printf("%-16s %6zu vertices %7zu tets  min/max dihedral %6.2f %6.2f  "
              "tets under 10/20/30/40 deg: %zu %zu %zu %zu  radius ratio min %.3f mean %.3f\n",
              title, q.number_of_vertices, q.number_of_cells, q.min_dihedral_angle,
              q.max_dihedral_angle, q.n_min_dihedral_below[0], q.n_min_dihedral_below[1],
              q.n_min_dihedral_below[2], q.n_min_dihedral_below[3], q.min_radius_ratio,
              q.mean_radius_ratio);
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : vvm_example::data_file("elephant.off");
  const std::string output = argc > 2 ? argv[2] : "elephant";
  Surface_mesh surface;
  if(!CGAL::IO::read_polygon_mesh(input, surface) || surface.is_empty() || !CGAL::is_closed(surface)) {
    std::cerr << "mesh_quality: '" << input << "' is not a readable closed surface\n";
    return 1;
  }
  Mesh_domain domain(surface);

  Mesh_criteria criteria(params::facet_angle = 25, params::facet_size = 0.05,
                         params::facet_distance = 0.005, params::cell_radius_edge_ratio = 3,
                         params::cell_size = 0.05);
  C3T3 c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
  print("make_mesh_3", GSM::mesh_quality_statistics(c3t3));

  CGAL::exude_mesh_3(c3t3, params::sliver_bound = 0);
  const GSM::Mesh_quality_statistics q = GSM::mesh_quality_statistics(c3t3);
  print("+ exude_mesh_3", q);

  std::ofstream vtu(output + ".vtu", std::ios::binary);
  GSM::IO::write_VTU_with_quality(vtu, c3t3);
  std::ofstream medit(output + ".mesh");
  CGAL::IO::output_to_medit(medit, c3t3, false, true);
  std::cout << "wrote " << vvm_example::absolute(output + ".vtu") << " and " << vvm_example::absolute(output + ".mesh") << "\n";
  return (vtu && medit && q.number_of_inverted_cells == 0) ? 0 : 1;
}
