// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The lattices of the particle engine (dissertation eq. 2.1, 2.2, 4.6, and the
// hexagonal lattice of surfaces, section 4.3.4) and the constants that go with each: one-ring, closest neighbour distance,
// particle density, kernel width, neighbour radius, deletion and insertion
// thresholds (section 4.2.2, Table 4.5). All lengths are in units of the
// target edge length l* in the imagined (isotropic) space.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_LATTICE_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_LATTICE_H

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the lattice the particles form
enum class Lattice_type
{
  BCC,  ///< body-centred cubic: cube corners and centres, 14 one-ring neighbours (eq. 2.1)
  FCC,  ///< face-centred cubic: cube corners and face centres, 18 one-ring neighbours (eq. 2.2)
  CUBIC, ///< cubic: cube corners, 6 one-ring neighbours (eq. 4.6), for hexahedral meshing
  HEXAGONAL ///< hexagonal: the triangles of a surface's tangent plane (the frame's first two axes), 6 one-ring neighbours (section 4.3.4)
};

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the name of a lattice ("bcc", "fcc", "cubic", "hexagonal")
inline const char* lattice_name(Lattice_type t)
{
  switch(t) {
    case Lattice_type::BCC: return "bcc";
    case Lattice_type::FCC: return "fcc";
    case Lattice_type::HEXAGONAL: return "hexagonal";
    default: return "cubic";
  }
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 * A lattice with the constants of the particle engine, in units of the cube edge
 * \f$ l^* \f$ of the lattice in the imagined space (where the frame field is the identity).
 */
struct Lattice
{
  Lattice_type type = Lattice_type::BCC;
  /// the one-ring neighbour offsets: the holes of the Gaussian Hole Kernel
  std::vector<Eigen::Vector3d> one_ring;
  /// \f$ l_{closest} \f$: the distance to the nearest neighbours
  double closest = 0;
  /// particles per cube of edge \f$ l^* \f$ (BCC 2, FCC 4, cubic 1; 0 for the hexagonal lattice, a surface's)
  double particles_per_cube = 1;
  /// the particles a boundary of area \f$ l^{*2} \f$ adds to the volume's count: the lattice
  /// closes with a full layer on the boundary, half a layer more than the volume holds
  /// (half the particles of a (100) plane: BCC 1/2, FCC 1, cubic 1/2); for the hexagonal
  /// lattice, the particles of a surface of area \f$ l^{*2} \f$ (\f$ 2 / \sqrt{3} \f$)
  double particles_per_boundary_square = 0.5;
  /// \f$ w \f$: the weight of the positive kernel (eq. 4.6; 1 for BCC and FCC, eq. 4.2)
  double positive_weight = 1;
  /// \f$ \sigma \f$: the kernel width (0.3 \f$ l_{closest} \f$; 0.3 for the cubic lattice, Table 4.5)
  double sigma = 0.3;
  /// \f$ R \f$: the neighbour radius in the imagined space (1.3; 1.5 for the cubic lattice)
  double neighbor_radius = 1.3;
  /// deletion rules (Alg. 3): a particle is deleted if the mean of the distances to its
  /// `first` nearest neighbours is under `second`
  std::vector<std::pair<int, double>> deletion_rules;
  /// \f$ d_{ins} \f$: a candidate is inserted only this far from every particle (Alg. 4)
  double insertion_distance = 0;
  /// \f$ e_{ins} \f$: a candidate is inserted only if its energy is under this (Alg. 4)
  double insertion_energy = -0.1;
  /// a particle on the boundary this near a sharp edge goes onto it (0.3; 0.5 for the hexagonal
  /// lattice, halfway to the row beside a curve at \f$ \sqrt{3}/2 \f$: nearer, it leaves a
  /// cap triangle over the curve)
  double sharp_edge_snap = 0.3;

  std::size_t number_of_holes() const { return one_ring.size(); }
  /// true for the lattice of surfaces (hexagonal), whose particles all lie on the surface
  bool is_surface_lattice() const { return type == Lattice_type::HEXAGONAL; }

  /// the lattice of type `t`; `w` is the positive kernel's weight of the cubic lattice
  static Lattice make(Lattice_type t, double w = 1.)
  {
    if(!(w > 0) || !std::isfinite(w))
      throw std::invalid_argument("Lattice: the positive kernel weight must be positive and finite");
    Lattice l;
    l.type = t;
    const double axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for(const auto& a : axes) l.one_ring.emplace_back(a[0], a[1], a[2]);
    if(t == Lattice_type::HEXAGONAL) { // six unit offsets at 60 degrees in the plane of the first two axes
      l.one_ring.clear();
      for(int k = 0; k < 6; ++k)
        l.one_ring.emplace_back(std::cos(k * CGAL_PI / 3), std::sin(k * CGAL_PI / 3), 0.);
      l.closest = 1;
      l.particles_per_cube = 0;
      l.particles_per_boundary_square = 2 / std::sqrt(3.);
      l.sharp_edge_snap = 0.5;
    } else if(t == Lattice_type::BCC) {
      for(int x = -1; x <= 1; x += 2)
        for(int y = -1; y <= 1; y += 2)
          for(int z = -1; z <= 1; z += 2) l.one_ring.emplace_back(0.5 * x, 0.5 * y, 0.5 * z);
      l.closest = std::sqrt(3.) / 2;
      l.particles_per_cube = 2;
    } else if(t == Lattice_type::FCC) {
      for(int a = -1; a <= 1; a += 2)
        for(int b = -1; b <= 1; b += 2) {
          l.one_ring.emplace_back(0.5 * a, 0.5 * b, 0);
          l.one_ring.emplace_back(0.5 * a, 0, 0.5 * b);
          l.one_ring.emplace_back(0, 0.5 * a, 0.5 * b);
        }
      l.closest = std::sqrt(2.) / 2;
      l.particles_per_cube = 4;
      l.particles_per_boundary_square = 1;
    } else {
      l.closest = 1;
      l.particles_per_cube = 1;
      l.positive_weight = w;
    }
    if(t == Lattice_type::CUBIC) {
      // Table 4.5: d_particle, d_edge, d_quad, d_hex; sigma, R, d_ins, e_ins
      l.deletion_rules = {{1, 0.5}, {2, 0.75}, {4, 0.9}, {6, 0.9}};
      l.sigma = 0.3;
      l.neighbor_radius = 1.5;
      l.insertion_distance = 0.8;
    } else {
      // section 4.2.2 (Alg. 3, 4) and 4.3.3, relative to l_closest
      // (the hexagonal lattice has six nearest neighbours: its rules stop there)
      for(auto r : std::vector<std::pair<int, double>>{{1, 0.5}, {2, 0.75}, {4, 0.85}, {6, 0.9}, {8, 0.95}})
        if(t != Lattice_type::HEXAGONAL || r.first <= 6) l.deletion_rules.emplace_back(r.first, r.second * l.closest);
      l.sigma = 0.3 * l.closest;
      l.neighbor_radius = 1.3;
      l.insertion_distance = 0.75 * l.closest;
    }
    l.insertion_energy = -0.1;
    return l;
  }
};

} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_LATTICE_H
