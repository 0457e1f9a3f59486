// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a MeshDomain_3's inside test may run on several threads at once.
// The concept does not ask it (sequential Mesh_3 calls it from one thread), so
// the particle engine asks a domain from one thread unless it is known safe.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_THREAD_SAFE_INSIDE_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_THREAD_SAFE_INSIDE_H

#include <CGAL/Polyhedral_mesh_domain_3.h>

#include <type_traits>

namespace CGAL {
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

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_THREAD_SAFE_INSIDE_H
