// Anisotropic meshing with a metric field M(x) (dissertation section 3.4.4):
// make_mesh_3 meshes the domain isotropically with the metric's density, then
// gsm_optimize_mesh_3 reshapes the cells so that each is close to regular in
// the metric (mapped by M^1/2). Quality is reported in the metric.
//
// usage: gsm_anisotropic_metric [sphere|cube] [scale] [output.mesh]
//   sphere: the unit ball with M = Q diag(100, 10, 10) Q^T (Fig. 3.8)
//   cube:   [-1, 1]^3 with M = diag(1 / (0.025 + 0.2 (1 - e^-u)), 5, 5)^2 (Fig. 3.9)
//   scale multiplies the isotropic size given to make_mesh_3 (default 0.6 for the sphere, 1.2 for
//   the cube: about 2,000 vertices; the figures' 10,000 vertices take 0.32 and 0.59)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/IO/File_medit.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <CGAL/GSM_mesh_optimization/dissertation_metric_fields.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> Metric;

namespace GSM = CGAL::GSM_mesh_optimization;
namespace params = CGAL::parameters;

Eigen::Vector3d to_eigen(const K::Point_3& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

double unit_ball(const K::Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

// [-1, 1]^3 as a triangle surface, for a domain with its sharp edges protected
CGAL::Surface_mesh<K::Point_3> cube_surface()
{
  CGAL::Surface_mesh<K::Point_3> sm;
  std::vector<CGAL::Surface_mesh<K::Point_3>::Vertex_index> v;
  for(int i = 0; i < 8; ++i)
    v.push_back(sm.add_vertex(K::Point_3(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1)));
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for(const auto& q : quads) sm.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  CGAL::Polygon_mesh_processing::triangulate_faces(sm);
  return sm;
}

// make_mesh_3's sizing field: the isotropic edge of the metric's density, det(M)^(-1/6), times `scale`
struct Density_sizing
{
  double scale;
  const Metric* metric;
  template <class Index>
  double operator()(const K::Point_3& p, int, const Index&) const
  {
    return scale * std::pow((*metric)(to_eigen(p)).determinant(), -1. / 6.);
  }
};

// meshes `domain` with the metric's density, optimizes in the metric, reports and writes the mesh
template <class C3T3, class MeshDomain>
int mesh_and_optimize(const MeshDomain& domain, const Metric& metric, double scale, const std::string& output)
{
  typedef CGAL::Mesh_criteria_3<typename C3T3::Triangulation> Mesh_criteria;
  const Density_sizing size{scale, &metric};
  Mesh_criteria criteria(params::edge_size = size, params::facet_angle = 25, params::facet_size = size,
                         params::facet_distance = 0.01 * scale, params::cell_radius_edge_ratio = 3,
                         params::cell_size = size);
  C3T3 c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());

  // quality in the metric: each cell mapped by B = M^1/2 at its centroid
  auto B = [&metric](const K::Point_3& p) {
    return Eigen::Matrix3d(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(metric(to_eigen(p))).operatorSqrt());
  };
  auto report = [&](const char* stage) {
    const GSM::Mesh_quality_statistics q = GSM::mesh_quality_statistics(c3t3, B);
    std::printf("%s: %zu vertices, %zu tets; in the metric: min dihedral %.2f deg, max %.2f deg, "
                "mean min %.2f deg, %zu tets under 30 deg, %zu inverted\n",
                stage, q.number_of_vertices, q.number_of_cells, q.min_dihedral_angle,
                q.max_dihedral_angle, q.mean_min_dihedral_angle, q.n_min_dihedral_below[2],
                q.number_of_inverted_cells);
    return q;
  };
  report("make_mesh_3");
  // only the variation of M matters: GSM fits its scale to the vertex count
  CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::metric_field(metric));
  const GSM::Mesh_quality_statistics after = report("gsm_optimize_mesh_3");

  std::ofstream medit(output);
  CGAL::IO::output_to_medit(medit, c3t3);
  std::cout << "wrote " << vvm_example::absolute(output) << "\n";
  return (medit && after.number_of_inverted_cells == 0) ? 0 : 1;
}

int main(int argc, char** argv)
{
  const std::string shape = argc > 1 ? argv[1] : "sphere";
  const bool is_sphere = shape == "sphere";
  const double scale = argc > 2 ? std::atof(argv[2]) : (is_sphere ? 0.6 : 1.2);
  const std::string output = argc > 3 ? argv[3] : "anisotropic_" + shape + "_gsm.mesh";
  if((shape != "sphere" && shape != "cube") || !(scale > 0)) {
    std::fprintf(stderr, "usage: gsm_anisotropic_metric [sphere|cube] [scale > 0] [output.mesh]\n");
    return 1;
  }
  if(is_sphere) {
    typedef CGAL::Labeled_mesh_domain_3<K> Domain;
    typedef CGAL::Mesh_complex_3_in_triangulation_3<CGAL::Mesh_triangulation_3<Domain>::type> C3T3;
    Domain domain = Domain::create_implicit_mesh_domain(unit_ball, K::Sphere_3(CGAL::ORIGIN, 4.),
                                                        params::relative_error_bound = 1e-6);
    return mesh_and_optimize<C3T3>(domain, Metric(GSM::dissertation::anisotropic_sphere_metric), scale, output);
  }
  typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, CGAL::Surface_mesh<K::Point_3>> Domain;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<CGAL::Mesh_triangulation_3<Domain>::type,
                                                  Domain::Corner_index, Domain::Curve_index> C3T3;
  Domain domain(cube_surface());
  domain.detect_features(60);
  return mesh_and_optimize<C3T3>(
      domain, [](const Eigen::Vector3d& x) { return GSM::dissertation::anisotropic_cube_metric(x); }, scale,
      output);
}
