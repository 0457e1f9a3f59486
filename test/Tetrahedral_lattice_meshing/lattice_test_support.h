// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tests of the lattice particle engine share: types, checks and small helpers.

#ifndef VVM_LATTICE_TEST_SUPPORT_H
#define VVM_LATTICE_TEST_SUPPORT_H

// first: Mesh_3 includes TBB headers the others rely on
#include <CGAL/make_mesh_3.h>

#include "output_hash.h"
#include "vvm_test.h"

#include <CGAL/Frame_fields/Closed_form_frame_field_3.h>
#include <CGAL/Frame_fields/Constant_frame_field_3.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/Tetrahedral_lattice_meshing/Lattice.h>
#include <CGAL/Tetrahedral_lattice_meshing/alignment_error.h>
#include <CGAL/Tetrahedral_lattice_meshing/gaussian_hole_kernel.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_deletion.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_insertion.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Particle_system.h>
#include <CGAL/Tetrahedral_lattice_meshing/lattice_particle_types.h>
#include <CGAL/Tetrahedral_lattice_meshing/parameters.h>
#include <CGAL/lattice_particles_3.h>
#include <CGAL/make_lattice_mesh_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <tbb/global_control.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface_mesh> Cube_domain;
typedef CGAL::Mesh_triangulation_3<Cube_domain, CGAL::Default, CGAL::Sequential_tag>::type Cube_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Cube_tr, Cube_domain::Corner_index, Cube_domain::Curve_index> Cube_c3t3;
typedef CGAL::Labeled_mesh_domain_3<K> Implicit_domain;
typedef CGAL::Frame_fields::Constant_frame_field_3<K> Constant_field;

namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace TLMI = CGAL::Tetrahedral_lattice_meshing::internal;

namespace {

typedef TLMI::Particle_system<Constant_field, TLMI::No_boundary, Point> Free_system;


using vvm_test::throws_invalid_argument;

const TLM::Lattice_type all_lattices[3] = {TLM::Lattice_type::BCC, TLM::Lattice_type::FCC, TLM::Lattice_type::CUBIC};

Eigen::Vector3d random_unit_vector(CGAL::Random& r)
{
  for(;;) {
    const Eigen::Vector3d v(r.get_double(-1, 1), r.get_double(-1, 1), r.get_double(-1, 1));
    if(v.norm() > 0.1 && v.norm() <= 1) return v.normalized();
  }
}

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

using vvm_test::data_file;

} // namespace

#endif // VVM_LATTICE_TEST_SUPPORT_H
