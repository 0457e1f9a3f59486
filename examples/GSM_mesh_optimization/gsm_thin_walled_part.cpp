// Meshes a thin-walled part with a size that follows its walls: the local
// thickness of the surface (CGAL::Local_thickness_3) gives a sizing field with
// three cells across every wall, gap and face between two protected feature
// curves (CGAL::Thickness_sizing_field_3), which
// make_mesh_3 takes as its edge, facet and cell sizes and gsm_optimize_mesh_3 as
// its target size.
//
// usage: gsm_thin_walled_part [surface.off] [scale] [output.mesh]
//   scale multiplies every size (default 1: three cells across the walls)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/Local_thickness_3.h>
#include <CGAL/Thickness_sizing_field_3.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Mesh_domain;
typedef CGAL::Mesh_triangulation_3<Mesh_domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Mesh_domain::Corner_index, Mesh_domain::Curve_index> C3T3;
typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;

namespace GSM = CGAL::GSM_mesh_optimization;
namespace VVM = CGAL::VVM;
namespace params = CGAL::parameters;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : vvm_example::data_file("thin_walled/open_box.off");
  const double scale = argc > 2 ? std::atof(argv[2]) : 1.;
  const std::string output = argc > 3 ? argv[3] : "thin_walled_gsm.mesh";
  Surface_mesh surface;
  if(!CGAL::IO::read_polygon_mesh(input, surface) || surface.is_empty() || !CGAL::is_closed(surface)) {
    std::cerr << "gsm_thin_walled_part: '" << input << "' is not a readable closed surface\n";
    return 1;
  }
  try {
    // the walls' and gaps' widths, and those of the faces between the sharp edges that the
    // domain will protect; then the size: 3 cells across, growing by at most 0.3 times the
    // distance away from the thinnest parts
    const double features_angle = 60;
    auto is_feature = surface.add_property_map<Surface_mesh::Edge_index, bool>("e:sharp", false).first;
    CGAL::Polygon_mesh_processing::detect_sharp_edges(surface, features_angle, is_feature);
    const CGAL::Local_thickness_3<K> thickness(surface, params::edge_is_constrained_map(is_feature));
    const CGAL::Thickness_sizing_field_3<K> size =
        CGAL::Thickness_sizing_field_3<K>(thickness, VVM::parameters::cells_across(3, VVM::parameters::gradation(0.3)))
            .scaled(scale);
    std::printf("sizes from %.4g to %.4g over %zu surface samples and %zu samples of feature curves\n",
                size.minimum_size(), size.maximum_size(), thickness.samples().size(),
                thickness.feature_samples().size());

    Mesh_domain domain(surface);
    domain.detect_features(features_angle);
    // a facet may stray from the surface by a tenth of its size
    auto distance = [&size](const K::Point_3& p, int, const Mesh_domain::Index&) { return 0.1 * size(p); };
    Mesh_criteria criteria(params::edge_size = size, params::facet_angle = 25, params::facet_size = size,
                           params::facet_distance = distance, params::cell_radius_edge_ratio = 3,
                           params::cell_size = size);
    C3T3 c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
    const GSM::Mesh_quality_statistics before = GSM::mesh_quality_statistics(c3t3);
    std::printf("make_mesh_3: %zu vertices, %zu tets, min dihedral %.2f deg, %zu tets under 30 deg\n",
                before.number_of_vertices, before.number_of_cells, before.min_dihedral_angle,
                before.n_min_dihedral_below[2]);

    CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::sizing_field(size));
    const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
    std::printf("gsm_optimize_mesh_3: %zu tets, min dihedral %.2f deg, %zu tets under 30 deg, %zu inverted\n",
                after.number_of_cells, after.min_dihedral_angle, after.n_min_dihedral_below[2],
                after.number_of_inverted_cells);
    std::ofstream medit(output);
    CGAL::IO::output_to_medit(medit, c3t3, false, true);
    std::cout << "wrote " << vvm_example::absolute(output) << "\n";
    return (medit && after.number_of_inverted_cells == 0) ? 0 : 1;
  } catch(const std::invalid_argument& e) {
    std::cerr << "gsm_thin_walled_part: " << e.what() << "\n";
    return 1;
  }
}
