// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::lattice_particles_3(): particles in a domain forming a BCC, FCC or
// cubic lattice aligned with a frame field (dissertation ch. 4.2).

#ifndef CGAL_LATTICE_PARTICLES_3_H
#define CGAL_LATTICE_PARTICLES_3_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Domain_boundary.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Domain_cross_field.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Lattice_optimizer.h>
#include <CGAL/Tetrahedral_lattice_meshing/Lattice.h>
#include <CGAL/Tetrahedral_lattice_meshing/lattice_particle_types.h>
#include <CGAL/Tetrahedral_lattice_meshing/parameters.h>
#include <CGAL/VVM/internal/Parallel_for.h>
#include <CGAL/VVM/internal/Stopping.h>
#include <CGAL/VVM/internal/Thread_limit.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <Eigen/Eigenvalues>

#include <unistd.h>

#include <any>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the largest number of particles `lattice_particles_3()` accepts to make; fewer if the
/// machine's memory cannot hold them (`bytes_per_particle`)
constexpr double maximum_number_of_particles = 2e7;

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the memory a particle takes at the peak of `make_hex_dominant_mesh_3()`, the largest of
/// the three entry points (particles, tets, candidates), rounded up from the measured slope
/// (`benchmark/Hex_dominant_meshing/memory.md`): requests that would need more than the
/// machine's physical memory are refused before any work
constexpr double bytes_per_particle = 10e3;

namespace internal {

/// the machine's physical memory in bytes (0 if unknown)
inline double physical_memory()
{
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGE_SIZE)
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0.;
#else
  return 0.;
#endif
}

/// `x` as people read it: 1234567 -> "1.23 million", 12345 -> "12345", 0.000125 -> "0.000125"
inline std::string readable(double x)
{
  std::ostringstream os;
  os << std::setprecision(3);
  const double a = std::abs(x);
  if(a >= 1 && a < 1e6) os << std::llround(x);
  else if(a >= 1e6 && a < 1e9) os << x / 1e6 << " million";
  else if(a >= 1e9 && a < 1e12) os << x / 1e9 << " billion";
  else os << x;
  return os.str();
}

/// refuses, before any work, `n` particles of `lattice_particles_3()` (for `what`, e.g.
/// "the edge length 0.001") over `maximum_number_of_particles` or the machine's memory
inline void check_particle_count(double n, const std::string& what)
{
  const double memory = physical_memory(), need = n * bytes_per_particle;
  const std::string estimate = what + " would need about " + readable(n) + " particles, about " +
                               readable(need / 1e9) + " GB of memory";
  if(n > maximum_number_of_particles)
    throw std::invalid_argument("lattice_particles_3: " + estimate + " (at most " +
                                readable(maximum_number_of_particles) + " particles)");
  if(memory > 0 && need > memory)
    throw std::invalid_argument("lattice_particles_3: " + estimate + ", more than this machine's " +
                                readable(memory / 1e9) + " GB");
}

/// the domain's boundary and the particles, as `make_lattice_mesh_3()` needs both
template <class MeshDomain>
struct Particles_in_domain
{
  typedef typename MeshDomain::R K;
  std::shared_ptr<Domain_boundary<MeshDomain, K>> boundary;
  Lattice_particles_3<typename K::Point_3> particles;
};

/// the named parameters of `lattice_particles_3()`, read and checked
struct Lattice_request
{
  Lattice lattice;
  bool has_length = false;
  double edge_length = 0;     // given, or 0
  double number_of_particles = 0;
  int threads = 0;
  Lattice_options options;
  /// of the time limit, kept per particle for the stages after the particles that always run
  /// (their connection into tets): the particle rounds stop that much earlier
  double seconds_kept_per_particle = 0;
  /// the generated cross field's scale correction (`Frame_fields::scale_corrected_frame_field()`):
  /// the largest ratio of two scales; 1 for none
  double maximum_scale_ratio = 1;
  /// the domain's boundary, sampled before the particles (beside the generated cross field:
  /// `with_frame_field()`), as a `std::shared_ptr<Domain_boundary<MeshDomain, K>>`; empty: the
  /// particles sample it
  std::any sampled_boundary;
};

/// (`surface`: for `make_lattice_surface_mesh()`, whose lattice is the hexagonal one, which the
/// volume entry points refuse)
template <class NamedParameters>
Lattice_request read_lattice_request(const NamedParameters& np, bool surface = false)
{
  namespace TLM = Tetrahedral_lattice_meshing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto fail = [](const std::string& m) { throw std::invalid_argument("lattice_particles_3: " + m); };

  Lattice_request r;
  r.lattice = Lattice::make(choose_parameter(get_parameter(np, TLM::internal_np::lattice),
                                             surface ? Lattice_type::HEXAGONAL : Lattice_type::BCC));
  if(r.lattice.is_surface_lattice() != surface)
    fail(surface ? "a surface's lattice is hexagonal (BCC, FCC and cubic lattices fill volumes)"
                 : "the hexagonal lattice is a surface's: make_lattice_surface_mesh() makes it");
  constexpr bool has_length =
      !std::is_same<decltype(get_parameter(np, TLM::internal_np::edge_length)), CGAL::internal_np::Param_not_found>::value;
  constexpr bool has_count = !std::is_same<decltype(get_parameter(np, TLM::internal_np::number_of_particles)),
                                           CGAL::internal_np::Param_not_found>::value;
  static_assert(!(has_length && has_count), "lattice_particles_3: give edge_length or number_of_particles, not both");
  r.has_length = has_length;
  r.edge_length = choose_parameter(get_parameter(np, TLM::internal_np::edge_length), 0.);
  r.number_of_particles =
      double(choose_parameter(get_parameter(np, TLM::internal_np::number_of_particles), std::size_t(10000)));
  // a parameter that is given is checked; one that is not takes the lattice's default (-1 here)
  auto given = [](const auto& p) {
    return !std::is_same<std::decay_t<decltype(p)>, CGAL::internal_np::Param_not_found>::value;
  };
  const bool has_sigma = given(get_parameter(np, TLM::internal_np::kernel_width));
  const bool has_radius = given(get_parameter(np, TLM::internal_np::neighbor_radius));
  const bool has_levels = given(get_parameter(np, TLM::internal_np::multiresolution_levels));
  const bool has_rounds = given(get_parameter(np, CGAL::internal_np::number_of_iterations));
  Lattice_options& o = r.options;
  o.kernel_width = choose_parameter(get_parameter(np, TLM::internal_np::kernel_width), -1.);
  o.neighbor_radius = choose_parameter(get_parameter(np, TLM::internal_np::neighbor_radius), -1.);
  o.multiresolution_levels = choose_parameter(get_parameter(np, TLM::internal_np::multiresolution_levels), -1);
  o.number_of_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), -1);
  o.maximum_running_time = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  o.random_seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  o.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  r.threads = choose_parameter(get_parameter(np, VVM::internal_np::number_of_threads), 0);
  // the rounds' visitor, if it takes their reports (the entry points check that it takes some of theirs)
  auto visitor = get_parameter(np, CGAL::internal_np::visitor);
  if constexpr(std::is_invocable<const decltype(visitor)&, const Lattice_round_report&>::value)
    o.visitor = [visitor](const Lattice_round_report& report) { return VVM::internal::visit(visitor, report); };

  if(has_length && !(r.edge_length > 0 && std::isfinite(r.edge_length)))
    fail("the edge length must be positive and finite");
  if(!has_length && !(r.number_of_particles >= 1)) fail("the number of particles must be at least 1");
  if(!has_length) check_particle_count(r.number_of_particles, "number_of_particles");
  if(has_sigma && !(o.kernel_width > 0 && std::isfinite(o.kernel_width))) fail("the kernel width must be positive and finite");
  if(has_radius && !(o.neighbor_radius > 0 && std::isfinite(o.neighbor_radius))) fail("the neighbour radius must be positive and finite");
  if(has_levels && (o.multiresolution_levels < 0 || o.multiresolution_levels > 6)) fail("the number of multiresolution levels must be in [0, 6]");
  if(has_rounds && o.number_of_iterations < 0) fail("the number of rounds must be non-negative");
  if(!(o.maximum_running_time >= 0)) fail("the time limit must be non-negative");
  if(r.threads < 0) fail("the number of threads must be non-negative");
  return r;
}

/// a first \f$ l^* \f$ from the bounding box of `domain` (where the frames' inverses have
/// determinant `det_B`), refusing empty boxes and absurd sizes before any work
template <class MeshDomain>
double edge_length_from_box(const MeshDomain& domain, double det_B, const Lattice_request& r)
{
  auto fail = [](const std::string& m) { throw std::invalid_argument("lattice_particles_3: " + m); };
  const auto bb = domain.bbox();
  const Eigen::Vector3d lo(bb.xmin(), bb.ymin(), bb.zmin()), hi(bb.xmax(), bb.ymax(), bb.zmax());
  if(!lo.allFinite() || !hi.allFinite() || !((hi - lo).prod() > 0)) fail("the domain's bounding box is empty or not finite");
  const double box_volume = (hi - lo).prod() * std::abs(det_B);
  const double l = r.edge_length;
  // the box holds the domain: a domain filling an eighth of it or more would need the
  // particles of the box's eighth (refused here before the boundary's sampling)
  if(r.has_length) check_particle_count(box_volume * r.lattice.particles_per_cube / (l * l * l) / 8,
                                        "the edge length " + readable(l));
  return r.has_length ? l : std::cbrt(box_volume * r.lattice.particles_per_cube / r.number_of_particles);
}

template <class MeshDomain, class FrameField>
Particles_in_domain<MeshDomain> lattice_particles(const MeshDomain& domain, const FrameField& field,
                                                  Lattice_request r)
{
  typedef typename MeshDomain::R K;
  typedef typename K::Point_3 Point_3;
  auto fail = [](const std::string& m) { throw std::invalid_argument("lattice_particles_3: " + m); };
  const VVM::internal::Time_limit time_limit(r.options.maximum_running_time);

  const auto bb = domain.bbox();
  // the frame at the box's centre, or, where it is degenerate (a hole of the domain on the
  // axis of a cylindrical field), at one of eight points around it; if all are, the error
  Eigen::Matrix3d Tc, Bc;
  for(int k = -1; k < 8; ++k) {
    auto at = [&](double lo, double hi, int bit) { return 0.5 * (lo + hi) + (k < 0 ? 0. : ((k >> bit) & 1 ? 0.25 : -0.25) * (hi - lo)); };
    const Point_3 c(at(bb.xmin(), bb.xmax(), 0), at(bb.ymin(), bb.ymax(), 1), at(bb.zmin(), bb.zmax(), 2));
    try {
      Tc = field.T(c);
      Bc = field.B(c);
      break;
    } catch(const std::invalid_argument&) {
      if(k == 7) throw;
    }
  }
  const double l0 = edge_length_from_box(domain, Bc.determinant(), r);

  Particles_in_domain<MeshDomain> out;
  CGAL::Real_timer timer;
  timer.start();
  const auto thread_limit = VVM::internal::thread_limit(r.threads);
  typedef std::shared_ptr<Domain_boundary<MeshDomain, K>> Sampled_boundary;
  if(const Sampled_boundary* sampled = std::any_cast<Sampled_boundary>(&r.sampled_boundary); sampled && *sampled)
    out.boundary = *sampled;
  else {
    // the boundary sampled at the mean spacing, as accurate as the shortest axis needs
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(Tc);
    const double spacing = l0 * std::cbrt(std::abs(Tc.determinant())), finest = l0 * svd.singularValues().minCoeff();
    out.boundary = std::make_shared<Domain_boundary<MeshDomain, K>>(domain, spacing, finest);
  }
  const Domain_measures measures = domain_measures<Domain_boundary<MeshDomain, K>, FrameField, Point_3>(*out.boundary, field);
  if(!(measures.volume > 0)) fail("the domain is empty (no volume)");
  if(r.options.verbose)
    std::cerr << "  lattice: " << (r.sampled_boundary.has_value() ? "the domain measured (its boundary sampled beside the field), "
                                                                    : "the boundary sampled and the domain measured, ")
              << timer.time() << " s\n";
  const double l = r.has_length ? r.edge_length : lattice_edge_length(r.lattice, measures, r.number_of_particles);
  if(!(l < std::numeric_limits<double>::infinity())) fail("too few particles for the domain's corners");
  const double n = lattice_particle_count(r.lattice, measures, l);
  check_particle_count(n, "the edge length " + readable(l));
  if(measures.volume * r.lattice.particles_per_cube / (l * l * l) < 1)
    fail("the edge length " + readable(l) + " is larger than the domain (under one lattice cell in it)");
  // every corner is a particle: features detected at a small angle leave nothing to place
  if(!(double(measures.number_of_corners) < n))
    fail("the domain has " + std::to_string(measures.number_of_corners) + " corners, not fewer than the " + readable(n) +
         " particles of the lattice: detect its features at a larger angle or ask for more particles");
  // n: the lattice's estimated count
  typedef Lattice_optimizer<FrameField, Domain_boundary<MeshDomain, K>, Point_3> Optimizer;
  // each optimizer gets the time left, less what the stages after it keep
  const double reserve = r.seconds_kept_per_particle * n;
  auto optimizer = [&](Lattice_options o) {
    if(time_limit.is_set()) o.maximum_running_time = (std::max)(time_limit.remaining() - reserve, 1e-9);
    return std::make_unique<Optimizer>(r.lattice, field, *out.boundary, l, o);
  };
  if(r.options.multiresolution_levels < 0 && r.lattice.type == Lattice_type::CUBIC)
    // one run: refined once from 2 l*, a box that wants one layer more or less than twice the
    // coarse lattice's often got a partial layer (a dislocation line); from 4 l* the lattice was
    // strained instead
    r.options.multiresolution_levels = n >= 3200 ? 2 : n >= 400 ? 1 : 0;
  if(r.options.multiresolution_levels >= 0) {
    out.particles = optimizer(r.options)->run();
  } else {
    // BCC and FCC: where the domain is a box (in the field's space), the lattice settles whole
    // or with a partial layer (a dislocation) depending on how its coarsest lattice fits the
    // box, and no level count fits both lattices at all counts. So two starts, from k0 + 1 and
    // k0 levels (the coarsest lattices of at most 250 and 2,000 particles), and the one of the
    // lower energy per particle before the last round (the L-BFGS to convergence) finished: the
    // whole lattice has the lower energy. Settling (nothing left to delete or insert) does not
    // tell: a lattice with a dislocation can settle too.
    const int k0 = n > 2000 ? int(std::ceil(std::log(n / 2000) / std::log(8.))) : 0;
    Lattice_options o = r.options;
    o.multiresolution_levels = n / std::pow(8., k0 + 1) >= 20 ? k0 + 1 : k0;
    std::unique_ptr<Optimizer> kept = optimizer(o);
    const double energy = kept->optimize();
    if(kept->multiresolution_levels() > k0 && !kept->stopped()) {
      o.multiresolution_levels = k0;
      std::unique_ptr<Optimizer> other = optimizer(o);
      const double other_energy = other->optimize();
      if(other->stopped_by_visitor()) kept->request_stop();
      if(r.options.verbose)
        std::cerr << "  lattice: " << k0 + 1 << " levels: energy/particle " << energy << ", " << k0
                  << " levels: " << other_energy << "; kept " << (other_energy < energy ? k0 : k0 + 1) << "\n";
      const int rounds = kept->number_of_rounds() + other->number_of_rounds();
      if(other_energy < energy) {
        kept = std::move(other);
      }
      const int kept_rounds = kept->number_of_rounds();
      out.particles = kept->finish();
      out.particles.number_of_rounds += rounds - kept_rounds; // and the other's
    } else
      out.particles = kept->finish();
  }
  out.particles.time = timer.time();
  return out;
}

/// the field of the overloads without one: the domain's cross field, on a mesh about as fine as the lattice
/// (by the domain's volume, not its box's: a domain that fills little of its box would get a coarse
/// field, and the lattice loses layers where that field's turns are coarse), its scales corrected
/// within `r.maximum_scale_ratio`
template <class MeshDomain>
Frame_fields::Discrete_frame_field_3<typename Kernel_traits<typename MeshDomain::R::Point_3>::Kernel>
default_frame_field(const MeshDomain& domain, const Lattice_request& r)
{
  double size = edge_length_from_box(domain, 1., r);
  if(!r.has_length) size *= std::cbrt(domain_volume_fraction(domain));
  return domain_cross_field(domain, size, r.options.maximum_running_time, r.maximum_scale_ratio);
}

/// the boundary of `domain` sampled for the particles of `r` in the default field: its frames
/// are rotations, scaled by the scale correction only (within `r.maximum_scale_ratio`), so the
/// boundary is sampled at the mean spacing, with a chordal error of 2% of it, without the field
template <class MeshDomain>
std::shared_ptr<Domain_boundary<MeshDomain, typename MeshDomain::R>>
boundary_for_default_field(const MeshDomain& domain, const Lattice_request& r)
{
  const double spacing = edge_length_from_box(domain, 1., r);
  return std::make_shared<Domain_boundary<MeshDomain, typename MeshDomain::R>>(domain, spacing, spacing);
}

/// `r` with the time `limit` leaves as its time limit: what the stages after the field get
inline Lattice_request with_time_left(Lattice_request r, const VVM::internal::Time_limit& limit)
{
  r.options.maximum_running_time = limit.remaining();
  return r;
}

/// `run(field, request)` with the frame field of `np` (`frame_field`), or, without one, with
/// the domain's cross field, made within the time limit of `r` (the rest left to `run`); the
/// boundary's sampling for the particles then runs beside it (in `request.sampled_boundary`), on
/// another thread where the domain allows two Mesh_3 runs at once
template <class MeshDomain, class NamedParameters, class Run>
decltype(auto) with_frame_field(const MeshDomain& domain, const Lattice_request& r, const NamedParameters& np,
                                const Run& run)
{
  const auto& given = CGAL::parameters::get_parameter_reference(np, VVM::internal_np::frame_field);
  if constexpr(!std::is_same<std::decay_t<decltype(given)>, CGAL::internal_np::Param_not_found>::value)
    return run(given, r);
  else {
    const VVM::internal::Time_limit time_limit(r.options.maximum_running_time);
    const auto thread_limit = VVM::internal::thread_limit(r.threads);
    std::shared_ptr<Domain_boundary<MeshDomain, typename MeshDomain::R>> boundary;
    std::optional<decltype(default_frame_field(domain, r))> field;
    if(Domain_boundary<MeshDomain, typename MeshDomain::R>::may_sample_beside_other_meshing(domain))
      VVM::internal::run_beside([&] { boundary = boundary_for_default_field(domain, r); },
                                [&] { field.emplace(default_frame_field(domain, r)); });
    else {
      field.emplace(default_frame_field(domain, r));
      boundary = boundary_for_default_field(domain, r);
    }
    Lattice_request fr = with_time_left(r, time_limit);
    fr.sampled_boundary = boundary;
    return run(*field, fr);
  }
}

/// `lattice_particles_3()`: the particles, then the visitor of `np` told that the stage is over
template <class MeshDomain, class FrameField, class NamedParameters>
Lattice_particles_3<typename MeshDomain::R::Point_3>
particles_of_request(const MeshDomain& domain, const FrameField& field, const Lattice_request& r,
                     const NamedParameters& np)
{
  auto visitor = CGAL::parameters::get_parameter(np, CGAL::internal_np::visitor);
  VVM::internal::check_visitor<decltype(visitor), Lattice_round_report>();
  Lattice_particles_3<typename MeshDomain::R::Point_3> p = lattice_particles(domain, field, r).particles;
  if(!p.stopped_by_visitor && !VVM::internal::visit_stage_end(visitor, VVM::Stage::PARTICLES, p.number_of_rounds, p.time))
    p.stopped_by_visitor = true;
  return p;
}

} // namespace internal
} // namespace Tetrahedral_lattice_meshing

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 *
 * places particles in `domain` so that they form a lattice (BCC, FCC or cubic) aligned
 * with the frame field `field` (dissertation ch. 4.2): random particles, rounds of L-BFGS on
 * the Gaussian Hole Kernel energy (eq. 4.2, 4.4; LBFGS++), each followed by the projection of
 * the particles near the boundary onto it and of those near sharp edges onto them, and by
 * particle deletion and insertion (Alg. 2-5), optionally from a coarser lattice
 * (multiresolution). Corners of the domain are fixed particles, particles on sharp edges
 * slide along them, particles on the boundary slide on it.
 *
 * The domain's boundary, feature curves and corners are those `make_mesh_3()` finds for it
 * (sampled at about the mean particle spacing, with a chordal error of 2% of the spacing along
 * the frame's shortest axis; of the mean spacing with the generated cross field, whose frames are
 * rotations scaled by the scale correction only, and the sampling then runs beside the field,
 * on another thread for CGAL's polyhedral domains but complexes), so any `MeshDomain_3`
 * works: polyhedral (with features), implicit, labelled (several subdomains: their
 * interfaces are boundaries too). The lattice's edge length \f$ l^* \f$ is measured in the
 * imagined space, where the field's frames \f$ T \f$ are the identity: particle \f$ p_i \f$'s
 * neighbours sit at \f$ p_i + l^* T h_k \f$, \f$ h_k \f$ the lattice's one-ring.
 *
 * \tparam MeshDomain a model of `MeshDomain_3` with `bbox()` (all of CGAL's domains)
 * \tparam FrameField a model of `FrameField_3` with the domain's `Point_3`; it is called from
 *   several threads at once
 * \tparam NamedParameters a sequence of named parameters
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::lattice}
 *     \cgalParamType{`Tetrahedral_lattice_meshing::Lattice_type`} \cgalParamDefault{`BCC`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::edge_length}
 *     \cgalParamDescription{\f$ l^* \f$, the cube edge of the lattice in the imagined space}
 *     \cgalParamType{`double`, positive} \cgalParamDefault{from `number_of_particles`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::number_of_particles}
 *     \cgalParamDescription{the number of particles sought: \f$ l^* \f$ is set so that the lattice
 *       fills the domain's volume in the imagined space with that many (not with `edge_length`)}
 *     \cgalParamType{`std::size_t`} \cgalParamDefault{10000}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::kernel_width}
 *     \cgalParamDescription{\f$ \sigma \f$ in units of \f$ l^* \f$}
 *     \cgalParamType{`double`} \cgalParamDefault{0.3 \f$ l_{closest} \f$ (BCC \f$ 0.26 \f$, FCC \f$ 0.21 \f$, cubic 0.3)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::neighbor_radius}
 *     \cgalParamDescription{\f$ R \f$ in units of \f$ l^* \f$, in the imagined space (the Euclidean
 *       search radius is widened by the field's largest stretch)}
 *     \cgalParamType{`double`} \cgalParamDefault{1.3 (cubic 1.5)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::multiresolution_levels}
 *     \cgalParamDescription{\f$ k \f$: optimize at \f$ 2^k l^* \f$ first, then refine level by level.
 *       When it is not given, BCC and FCC particles are optimized twice, from \f$ k_0 + 1 \f$ and
 *       \f$ k_0 \f$ levels, \f$ k_0 = \lceil \log_8 (n / 2000) \rceil \f$ (at least 0; the coarsest
 *       lattices then have at most 250 and 2,000 of the \f$ n \f$ particles; the first start only if
 *       its coarsest lattice has 20 particles or more), and the run of the lower energy per particle
 *       is kept and finished (its last round, the L-BFGS to convergence): in a box-shaped domain
 *       the lattice settles whole or with a partial layer depending on how its coarsest lattice
 *       fits the box, and the whole lattice has the lower energy. The visitor sees the rounds of
 *       both runs; `Lattice_particles_3::multiresolution_levels` tells the one kept. Given or not,
 *       a run starts from a finer level where the domain's corners (fixed particles at every level)
 *       outnumber the coarsest lattice's own particles more than sixteen times: each would meet as many
 *       times its share of neighbours there.}
 *     \cgalParamType{`int` in [0, 6]} \cgalParamDefault{see above (cubic lattice: 2 from 3,200 particles, 1 from 400, else 0)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{MaxRoundNum: the largest number of deletion-insertion rounds per level}
 *     \cgalParamType{`int`} \cgalParamDefault{16 at the first level, 8 at the next ones}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{random_seed}
 *     \cgalParamDescription{the seed of the random initial particles: the same domain, field,
 *       parameters and seed give the same particles, whatever ran before in the process (the
 *       random generators `make_mesh_3()` draws from when it samples the boundary, CGAL's default
 *       one and a `Labeled_mesh_domain_3`'s own, are set for the sampling and given back their
 *       state afterwards)}
 *     \cgalParamType{`unsigned int`} \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{Tetrahedral_lattice_meshing::parameters::number_of_threads}
 *     \cgalParamDescription{the largest number of threads; 0 lets TBB choose. The result does not depend on it.}
 *     \cgalParamType{`int`} \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{maximum_running_time}
 *     \cgalParamDescription{a time limit in seconds, from the call: the rounds stop once it is
 *       reached and the particles are those of the last round
 *       (`Lattice_particles_3::time_limit_reached`); the boundary's sampling and the first
 *       particles always run (and, in the overload without a field, the mesh and the
 *       least-squares solve of the cross field); 0 for none}
 *     \cgalParamType{`double`} \cgalParamDefault{0}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{visitor}
 *     \cgalParamDescription{called after each round with its
 *       `Tetrahedral_lattice_meshing::Lattice_round_report`, and once the rounds are over with a
 *       `VVM::Stage_report`; if it returns `false`, the rounds stop there
 *       (`Lattice_particles_3::stopped_by_visitor`)}
 *     \cgalParamType{a callable taking `const VVM::Stage_report&` or
 *       `const Tetrahedral_lattice_meshing::Lattice_round_report&`, returning `void` or `bool`}
 *     \cgalParamDefault{none}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{verbose}
 *     \cgalParamDescription{one line per round on `std::cerr`} \cgalParamType{`bool`} \cgalParamDefault{false}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the particles with their kinds and features, \f$ l^* \f$, the final energy and the time
 * \throw std::invalid_argument before any optimization on a bad parameter, a degenerate frame,
 *   an empty domain, an edge length larger than the domain, no fewer particles than the domain
 *   has corners (each corner is a particle), or a request of more than
 *   `Tetrahedral_lattice_meshing::maximum_number_of_particles` particles or of more memory than
 *   the machine has (`Tetrahedral_lattice_meshing::bytes_per_particle` each; the message gives
 *   the estimate)
 */
template <class MeshDomain, class FrameField, class NamedParameters = parameters::Default_named_parameters>
Tetrahedral_lattice_meshing::Lattice_particles_3<typename MeshDomain::R::Point_3>
lattice_particles_3(const MeshDomain& domain, const FrameField& field,
                    const NamedParameters& np = parameters::default_values())
{
  namespace TLM_internal = Tetrahedral_lattice_meshing::internal;
  return TLM_internal::particles_of_request(domain, field, TLM_internal::read_lattice_request(np), np);
}

/*!
 * \ingroup PkgTetrahedralLatticeMeshingRef
 *
 * the same with the frame field of the named parameter `Tetrahedral_lattice_meshing::parameters::frame_field`
 * or, without it, the boundary-aligned cross field of `Frame_fields::generate_cross_field_3()`
 * (unit frames, one axis on the surface normal and along the feature curves), computed on a
 * `make_mesh_3()` mesh of `domain` whose edges are about \f$ l^* \f$ long.
 */
template <class MeshDomain, class T, class Tag, class Base>
Tetrahedral_lattice_meshing::Lattice_particles_3<typename MeshDomain::R::Point_3>
lattice_particles_3(const MeshDomain& domain, const Named_function_parameters<T, Tag, Base>& np)
{
  namespace TLM_internal = Tetrahedral_lattice_meshing::internal;
  return TLM_internal::with_frame_field(domain, TLM_internal::read_lattice_request(np), np,
                                        [&](const auto& field, const TLM_internal::Lattice_request& r) {
                                          return TLM_internal::particles_of_request(domain, field, r, np);
                                        });
}

/// \ingroup PkgTetrahedralLatticeMeshingRef
/// the same with the default named parameters
template <class MeshDomain>
Tetrahedral_lattice_meshing::Lattice_particles_3<typename MeshDomain::R::Point_3>
lattice_particles_3(const MeshDomain& domain)
{
  return lattice_particles_3(domain, parameters::default_values());
}

} // namespace CGAL

#endif // CGAL_LATTICE_PARTICLES_3_H
