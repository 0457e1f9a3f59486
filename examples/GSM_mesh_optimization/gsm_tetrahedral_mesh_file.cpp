// Removes the slivers of a tetrahedral mesh made by another mesher (TetGen,
// Gmsh, ...), read from a file, without re-meshing: its boundary and label
// interfaces become the surfaces its boundary vertices slide on.
//
// usage: gsm_tetrahedral_mesh_file [mesh.(mesh|msh|vtu)] [output.mesh]
// (default data/ball_in_box.mesh: Gmsh's mesh of a ball inside a box, two labels)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/GSM_mesh_optimization/Complex_from_tetrahedra_3.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/Hex_dominant_meshing/IO/read_volume_mesh.h>
#include <CGAL/gsm_optimize_mesh_3.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <iostream>
#include <string>
#include <vector>

#include "example_data.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::GSM_mesh_optimization::Complex_from_tetrahedra_3<K> Imported_mesh;
namespace GSM = CGAL::GSM_mesh_optimization;

void print(const char* title, const GSM::Mesh_quality_statistics& q)
{
  std::printf("%-8s %6zu vertices %7zu tets  smallest dihedral angle %6.2f  tets under 20/30/40 deg: %zu %zu %zu\n",
              title, q.number_of_vertices, q.number_of_cells, q.min_dihedral_angle, q.n_min_dihedral_below[1],
              q.n_min_dihedral_below[2], q.n_min_dihedral_below[3]);
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : vvm_example::data_file("ball_in_box.mesh");
  const std::string output = argc > 2 ? argv[2] : "ball_in_box_gsm.mesh";
  try {
    // points, cells and labels, in any of the three formats
    CGAL::Hex_dominant_mesh_3<K::Point_3> file;
    CGAL::Hex_dominant_meshing::IO::read_volume_mesh(input, file);
    std::vector<Imported_mesh::Tetrahedron> tets;
    std::vector<int> labels;
    for(const auto& c : file.cells) {
      if(c.type != CGAL::Hex_dominant_cell_type::TETRAHEDRON) throw std::invalid_argument("not a tetrahedral mesh");
      tets.push_back({c.vertices[0], c.vertices[1], c.vertices[2], c.vertices[3]});
      labels.push_back(c.subdomain_index);
    }

    // the complex and the domain of its own boundary; edges sharper than 60 degrees stay put
    Imported_mesh mesh(file.points, tets, labels, 60);
    print("input", GSM::mesh_quality_statistics(mesh.c3t3()));

    // boundary facets may stray from the input's boundary by up to 0.1% of the model's size
    const CGAL::Bbox_3 box = CGAL::bbox_3(file.points.begin(), file.points.end());
    const double size = std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    CGAL::gsm_optimize_mesh_3(mesh.c3t3(), mesh.domain(), GSM::parameters::boundary_distance(0.001 * size));
    print("GSM", GSM::mesh_quality_statistics(mesh.c3t3()));

    // back to points, tetrahedra and the input's labels
    file.clear();
    mesh.get_tetrahedra(file.points, tets, labels);
    for(std::size_t k = 0; k < tets.size(); ++k) {
      CGAL::Hex_dominant_mesh_3<K::Point_3>::Cell c;
      std::copy(tets[k].begin(), tets[k].end(), c.vertices.begin());
      c.subdomain_index = labels[k];
      file.cells.push_back(c);
    }
    CGAL::Hex_dominant_meshing::IO::write_volume_mesh(output, file);
    std::cout << "wrote " << vvm_example::absolute(output) << "\n";
  } catch(const std::exception& e) {
    std::cerr << "gsm_tetrahedral_mesh_file: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
