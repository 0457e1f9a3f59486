// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_mesh_3() draws random numbers from two generators: CGAL's default one
// and, for Labeled_mesh_domain_3 (implicit functions, labelled images), the
// domain's own, which it keeps from one call to the next (its initial points
// on the surface are cast along random rays). A sampling of the domain made
// for the particles must depend on neither's history, or two calls with the
// same domain and seed would give different particles. This guard sets both
// to a fixed seed and gives them back their state afterwards, so that the
// caller's own later meshing is as if nothing had run.

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_REPRODUCIBLE_SAMPLING_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_REPRODUCIBLE_SAMPLING_H

#include <CGAL/Random.h>

#include <memory>
#include <optional>
#include <type_traits>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

/// the random generator a Mesh_3 domain keeps (Labeled_mesh_domain_3's protected `p_rng_`, a
/// shared or plain pointer; Polyhedral_mesh_domain_3's is null unless given), or null
template <class MeshDomain>
class Domain_random_generator : private MeshDomain
{
  template <class T, class = void>
  struct Has_generator : std::false_type {};
  template <class T>
  struct Has_generator<T, std::void_t<decltype(&T::p_rng_)>> : std::true_type {};

  static CGAL::Random* get(CGAL::Random* p) { return p; }
  static CGAL::Random* get(const std::shared_ptr<CGAL::Random>& p) { return p.get(); }

public:
  static CGAL::Random* of(const MeshDomain& domain)
  {
    if constexpr(Has_generator<Domain_random_generator>::value)
      return get(domain.*(&Domain_random_generator::p_rng_));
    else
      return nullptr;
  }
};

class Reproducible_sampling
{
public:
  template <class MeshDomain>
  explicit Reproducible_sampling(const MeshDomain& domain)
    : default_(CGAL::get_default_random()), domain_generator_(Domain_random_generator<MeshDomain>::of(domain))
  {
    CGAL::get_default_random() = CGAL::Random(0);
    if(domain_generator_ != nullptr) {
      domain_state_.emplace(*domain_generator_);
      *domain_generator_ = CGAL::Random(0);
    }
  }

  ~Reproducible_sampling()
  {
    CGAL::get_default_random() = default_;
    if(domain_generator_ != nullptr) *domain_generator_ = *domain_state_;
  }

  Reproducible_sampling(const Reproducible_sampling&) = delete;
  Reproducible_sampling& operator=(const Reproducible_sampling&) = delete;

private:
  const CGAL::Random default_;
  CGAL::Random* const domain_generator_;
  std::optional<CGAL::Random> domain_state_;
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_REPRODUCIBLE_SAMPLING_H
