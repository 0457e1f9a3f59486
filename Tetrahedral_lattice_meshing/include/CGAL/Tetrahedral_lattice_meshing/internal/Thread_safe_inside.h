// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a MeshDomain_3's inside test may run on several threads at once, and whether
// two Mesh_3 runs may mesh it at once.
// The concept does not ask it (sequential Mesh_3 calls it from one thread), so
// the particle engine asks a domain from one thread unless it is known safe.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_THREAD_SAFE_INSIDE_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_THREAD_SAFE_INSIDE_H

#include <CGAL/Polyhedral_mesh_domain_3.h>

#include <type_traits>

namespace CGAL {

template <class IGT, class Polyhedron, class TriangleAccessor>
class Polyhedral_complex_mesh_domain_3;

namespace Tetrahedral_lattice_meshing {
namespace internal {

template <class P, class G, class T, class I, class E>
std::true_type is_polyhedral_domain(const CGAL::Polyhedral_mesh_domain_3<P, G, T, I, E>*);
std::false_type is_polyhedral_domain(const void*);

/// true for CGAL's polyhedral domains, with features or not: their AABB trees are built under a
/// lock, and a ray cast of their inside test draws from a generator of its own
template <class MeshDomain>
constexpr bool has_thread_safe_inside =
    decltype(is_polyhedral_domain(static_cast<const MeshDomain*>(nullptr)))::value;

template <class G, class P, class A>
std::true_type is_polyhedral_complex_domain(const CGAL::Polyhedral_complex_mesh_domain_3<G, P, A>*);
std::false_type is_polyhedral_complex_domain(const void*);

/// true for the polyhedral domains two Mesh_3 runs may share (seeded alike: see
/// `Domain_boundary::may_sample_beside_other_meshing()`), not a polyhedral complex, whose first
/// run detects its borders (a const member function that writes the domain)
template <class MeshDomain>
constexpr bool may_be_meshed_concurrently =
    has_thread_safe_inside<MeshDomain> &&
    !decltype(is_polyhedral_complex_domain(static_cast<const MeshDomain*>(nullptr)))::value;

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_THREAD_SAFE_INSIDE_H
