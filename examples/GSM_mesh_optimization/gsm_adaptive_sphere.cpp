// Adaptive meshing of the unit ball (dissertation Fig. 3.7): make_mesh_3 with
// the sizing field h(x) = 0.025 + 0.2 | |x| - 0.5 |, then gsm_optimize_mesh_3
// with the same field, so that every tetrahedron comes close to the regular
// one of the local size.
//
// usage: gsm_adaptive_sphere [scale] [output.mesh]
//   scale multiplies h for make_mesh_3 (default 1.2: about 10,000 vertices)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <CGAL/GSM_mesh_optimization/dissertation_metric_fields.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Labeled_mesh_domain_3<K> Mesh_domain;
typedef CGAL::Mesh_triangulation_3<Mesh_domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;

namespace GSM = CGAL::GSM_mesh_optimization;
namespace params = CGAL::parameters;

double unit_ball(const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

Eigen::Vector3d to_eigen(const K::Point_3& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

// make_mesh_3's sizing field: the target edge length, times `scale`
struct Scaled_sizing
{
  double scale;
  double operator()(const K::Point_3& p, int, const Mesh_domain::Index&) const
  {
    return scale * GSM::dissertation::adaptive_sphere_sizing(to_eigen(p));
  }
};

int main(int argc, char** argv)
{
  const double scale = argc > 1 ? std::atof(argv[1]) : 1.2;
  const std::string output = argc > 2 ? argv[2] : "adaptive_sphere_gsm.mesh";
  if(!(scale > 0)) {
    std::fprintf(stderr, "gsm_adaptive_sphere: the scale must be positive\n");
    return 1;
  }
  Mesh_domain domain = Mesh_domain::create_implicit_mesh_domain(
      unit_ball, K::Sphere_3(CGAL::ORIGIN, 4.), params::relative_error_bound = 1e-6);
  const Scaled_sizing size{scale};
  Mesh_criteria criteria(params::facet_angle = 25, params::facet_size = size,
                         params::facet_distance = 0.01 * scale, params::cell_radius_edge_ratio = 3,
                         params::cell_size = size);
  C3T3 c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
  const GSM::Mesh_quality_statistics before = GSM::mesh_quality_statistics(c3t3);
  std::printf("make_mesh_3: %zu vertices, %zu tets, min dihedral %.2f deg, %zu tets under 30 deg\n",
              before.number_of_vertices, before.number_of_cells, before.min_dihedral_angle,
              before.n_min_dihedral_below[2]);

  // Only the variation of the field matters: GSM fits its scale to the vertex count.
  CGAL::gsm_optimize_mesh_3(c3t3, domain,
                            GSM::parameters::sizing_field(&GSM::dissertation::adaptive_sphere_sizing));

  const GSM::Mesh_quality_statistics after = GSM::mesh_quality_statistics(c3t3);
  std::printf("gsm_optimize_mesh_3: %zu tets, min dihedral %.2f deg, max %.2f deg, %zu tets under 30 deg, "
              "%zu inverted\n",
              after.number_of_cells, after.min_dihedral_angle, after.max_dihedral_angle,
              after.n_min_dihedral_below[2], after.number_of_inverted_cells);

  // the mesh follows the field: edges near the sphere of radius 0.5 against those near the boundary
  // (an edge counted once per cell around it)
  double length[2] = {0, 0};
  int count[2] = {0, 0};
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const Eigen::Vector3d a = to_eigen(c->vertex(i)->point().point());
        const Eigen::Vector3d b = to_eigen(c->vertex(j)->point().point());
        const double r = (0.5 * (a + b)).norm();
        const int k = r > 0.4 && r < 0.6 ? 0 : r > 0.9 ? 1 : -1;
        if(k >= 0) {
          length[k] += (a - b).norm();
          ++count[k];
        }
      }
  std::printf("mean edge length: %.4f for 0.4 < |x| < 0.6, %.4f for |x| > 0.9 (field ratio %.2f)\n",
              length[0] / count[0], length[1] / count[1],
              GSM::dissertation::adaptive_sphere_sizing(Eigen::Vector3d(0.95, 0, 0)) /
                  GSM::dissertation::adaptive_sphere_sizing(Eigen::Vector3d(0.5, 0, 0)));
  std::ofstream medit(output);
  CGAL::IO::output_to_medit(medit, c3t3);
  std::cout << "wrote " << vvm_example::absolute(output) << "\n";
  return (medit && after.number_of_inverted_cells == 0) ? 0 : 1;
}
