// Meshes a polyhedral surface with sharp features by make_mesh_3 (no
// perturbation, no exudation), then removes the slivers with
// gsm_optimize_mesh_3, printing its progress after each round.
//
// usage: gsm_polyhedral_domain_with_features [surface.off] [output.mesh]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/gsm_optimize_mesh_3.h>

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

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : vvm_example::data_file("fandisk.off");
  const std::string output = argc > 2 ? argv[2] : "fandisk_gsm.mesh";
  Surface_mesh surface;
  if(!CGAL::IO::read_polygon_mesh(input, surface) || surface.is_empty() || !CGAL::is_closed(surface)) {
    std::cerr << "gsm_polyhedral_domain_with_features: '" << input << "' is not a readable closed surface\n";
    return 1;
  }
  Mesh_domain domain(surface);
  domain.detect_features(60); // protect the edges sharper than 120 degrees

  Mesh_criteria criteria(params::edge_size = 0.025, params::facet_angle = 25, params::facet_size = 0.05,
                         params::facet_distance = 0.005, params::cell_radius_edge_ratio = 3,
                         params::cell_size = 0.05);
  C3T3 c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
  const GSM::Mesh_quality_statistics before = GSM::mesh_quality_statistics(c3t3);
  std::printf("make_mesh_3: %zu tets, min dihedral %.2f deg, %zu tets under 30 deg\n",
              before.number_of_cells, before.min_dihedral_angle, before.n_min_dihedral_below[2]);

  // GSM is a final stage: the triangulation is no longer regular afterwards,
  // so refine_mesh_3, perturb_mesh_3 or exude_mesh_3 must not run after it.
  const CGAL::Mesh_optimization_return_code code = CGAL::gsm_optimize_mesh_3(
      c3t3, domain,
      params::maximum_running_time(60).visitor([](const GSM::Round_report& r) {
        std::printf("  round %2d: mean energy %.5f, min dihedral %6.2f, %zu moves, %zu flips, %.2f s\n",
                    r.round, r.energy, r.min_dihedral_angle, r.number_of_moves, r.number_of_flips,
                    r.elapsed_time);
      }));

  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  std::printf("gsm_optimize_mesh_3 (return code %d): %zu tets, min dihedral %.2f deg, max %.2f deg, "
              "%zu tets under 30 deg, %zu inverted\n",
              int(code), after.number_of_cells, after.min_dihedral_angle, after.max_dihedral_angle,
              after.n_min_dihedral_below[2], after.number_of_inverted_cells);
  std::ofstream medit(output);
  CGAL::IO::output_to_medit(medit, c3t3, false, true);
  std::cout << "wrote " << vvm_example::absolute(output) << "\n";
  return (medit && after.number_of_inverted_cells == 0) ? 0 : 1;
}
