// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The lattice particle system on its own (unit tests, no domain): the Gaussian Hole
// Kernel's gradient against finite differences (the hexagonal lattice's too), the system's gradient in a varying field,
// a perfect lattice as a stable stationary point, deletion and insertion on hand-made
// configurations.

#include "lattice_test_support.h"

#include <set>


// ---------------------------------------------------------------------------------------------
// 1. The Gaussian Hole Kernel: gradient against central differences, symmetry of the pair.

void test_kernel_gradient()
{
  Eigen::Matrix3d B;
  B << 1.2, 0.3, -0.1, 0.1, 0.8, 0.2, -0.2, 0.15, 1.1;
  const Eigen::Matrix3d T = B.inverse();
  const double l = 0.7;
  CGAL::Random r(11);
  double worst_rel = 0, worst_rel_j = 0, worst_sym = 0, worst_sym_grad = 0, smallest_gradient = 1e300;
  int n = 0;
  // the volume lattices and the surfaces' hexagonal one (six holes in the plane of the first two axes)
  for(TLM::Lattice_type type : {TLM::Lattice_type::BCC, TLM::Lattice_type::FCC, TLM::Lattice_type::CUBIC, TLM::Lattice_type::HEXAGONAL}) {
    const TLM::Lattice lattice = TLM::Lattice::make(type);
    const double sigma = lattice.sigma;
    std::vector<Eigen::Vector3d> offsets; // u = B v / l
    // near the closest neighbours (the holes at l_closest), a little off them
    for(const Eigen::Vector3d& h : lattice.one_ring)
      if(std::abs(h.norm() - lattice.closest) < 1e-12) offsets.push_back(h + r.get_double(0.02, 0.15) * random_unit_vector(r));
    // anywhere within the neighbour radius, and near the origin
    for(int k = 0; k < 12; ++k) offsets.push_back(r.get_double(0.05, lattice.neighbor_radius) * random_unit_vector(r));
    offsets.push_back(0.05 * random_unit_vector(r));
    for(const Eigen::Vector3d& u : offsets) {
      const Eigen::Vector3d v = l * (T * u); // p_i - p_j
      Eigen::Vector3d g_i, g_j_swapped;
      const double e = TLM::gaussian_hole_pair_energy(lattice, B, v, l, sigma, &g_i);
      const double e_swapped = TLM::gaussian_hole_pair_energy(lattice, B, Eigen::Vector3d(-v), l, sigma, &g_j_swapped);
      // the energy without the gradient is the same
      VVM_CHECK_EQUAL(TLM::gaussian_hole_pair_energy(lattice, B, v, l, sigma), e);
      // central differences in p_i (v + h) and in p_j (v - h)
      const double h = 1e-5 * l;
      Eigen::Vector3d fd_i, fd_j;
      for(int a = 0; a < 3; ++a) {
        const Eigen::Vector3d d = h * Eigen::Vector3d::Unit(a);
        fd_i[a] = (TLM::gaussian_hole_pair_energy(lattice, B, Eigen::Vector3d(v + d), l, sigma) -
                   TLM::gaussian_hole_pair_energy(lattice, B, Eigen::Vector3d(v - d), l, sigma)) / (2 * h);
        fd_j[a] = (TLM::gaussian_hole_pair_energy(lattice, B, Eigen::Vector3d(v - d), l, sigma) -
                   TLM::gaussian_hole_pair_energy(lattice, B, Eigen::Vector3d(v + d), l, sigma)) / (2 * h);
      }
      smallest_gradient = std::min(smallest_gradient, g_i.norm());
      worst_rel = std::max(worst_rel, (g_i - fd_i).norm() / g_i.norm());
      worst_rel_j = std::max(worst_rel_j, (-g_i - fd_j).norm() / g_i.norm());
      // E_ij = E_ji and the gradient of E_ji with respect to p_j is minus that of E_ij wrt p_i
      worst_sym = std::max(worst_sym, std::abs(e - e_swapped) / std::max(std::abs(e), 1e-3));
      worst_sym_grad = std::max(worst_sym_grad, (g_j_swapped + g_i).norm() / g_i.norm());
      ++n;
    }
    // the kernel at 0: w minus the holes' Gaussians (eq. 4.2), with a zero gradient
    Eigen::Vector3d g0;
    const double e0 = TLM::gaussian_hole_kernel(lattice, Eigen::Vector3d::Zero(), sigma, &g0);
    double expected = lattice.positive_weight;
    for(const Eigen::Vector3d& hk : lattice.one_ring)
      if(hk.squaredNorm() < 36 * sigma * sigma)
        expected -= std::exp(-0.5 * hk.squaredNorm() / (sigma * sigma)) / double(lattice.number_of_holes());
    VVM_CHECK_CLOSE(e0, expected, 1e-14);
    VVM_CHECK(g0.norm() < 1e-14);
  }
  std::cout << "GHK gradient (bcc, fcc, cubic, hexagonal; non-orthogonal B; " << n << " offsets): max relative error wrt p_i "
            << worst_rel << ", wrt p_j " << worst_rel_j << " (smallest |grad| " << smallest_gradient
            << "); |E_ij - E_ji| rel " << worst_sym << ", |grad_j E_ji + grad_i E_ij| rel " << worst_sym_grad << "\n";
  VVM_CHECK(smallest_gradient > 1e-3); // the relative errors measure something
  VVM_CHECK_LESS(worst_rel, 1e-5);
  VVM_CHECK_LESS(worst_rel_j, 1e-5);
  VVM_CHECK_LESS(worst_sym, 1e-12);
  VVM_CHECK_LESS(worst_sym_grad, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// 1b. The particle system's gradient in a field that varies: at the positions the pairs were
// built at, it is the gradient of the energy with each pair's frame taken at its true midpoint
// (eq. 4.2 as written), central differences of which evaluate the field anew; the frame's
// derivative is in it (without, the relative error here is 0.1 and more).

typedef CGAL::Frame_fields::Closed_form_frame_field_3<K> Varying_field;

void test_system_gradient_in_varying_field()
{
  // a stretch along x that grades steeply (as Fig. 4.8's, smooth), with a rotation about z
  const Varying_field field([](const Point& p) {
    const double s = 0.3 + 0.5 * std::exp(-4 * (p.x() - 0.5) * (p.x() - 0.5));
    return Eigen::Matrix3d(rotation(0.8 * p.y(), Eigen::Vector3d(0, 0, 1)) * Eigen::Vector3d(s, 1, 1).asDiagonal());
  });
  const double l = 0.12;
  double worst = 0, smallest = 1e300, worst_without = 0;
  for(TLM::Lattice_type type : all_lattices) {
    const TLM::Lattice lattice = TLM::Lattice::make(type);
    TLMI::Particle_system<Varying_field, TLMI::No_boundary, Point> s(lattice, field, nullptr, l, lattice.sigma,
                                                                    lattice.neighbor_radius);
    CGAL::Random r(17);
    for(int k = 0; k < 150; ++k)
      s.add(Eigen::Vector3d(r.get_double(0, 1), r.get_double(0, 0.6), r.get_double(0, 0.6)), TLM::Particle_kind::FREE);
    s.build_pairs();
    VVM_CHECK(s.frames_vary());
    VVM_CHECK(s.pairs().size() > 150);
    const Eigen::VectorXd x = s.positions();
    Eigen::VectorXd g;
    s.energy_and_gradient(x, g);
    // the energy of the same pairs, each with the frame at its midpoint
    auto true_energy = [&](const Eigen::VectorXd& y) {
      double e = 0;
      for(const auto& pr : s.pairs()) {
        const Eigen::Vector3d pi = l * y.segment<3>(3 * pr.i), pj = l * y.segment<3>(3 * pr.j);
        e += 2 * TLM::gaussian_hole_pair_energy(lattice, s.B(0.5 * (pi + pj)), Eigen::Vector3d(pi - pj), l, lattice.sigma);
      }
      return e;
    };
    for(std::size_t i = 0; i < s.size(); i += 7) {
      Eigen::Vector3d fd, frozen;
      for(int a = 0; a < 3; ++a) {
        const double h = 1e-6;
        Eigen::VectorXd xp = x, xm = x;
        xp[3 * i + a] += h;
        xm[3 * i + a] -= h;
        fd[a] = (true_energy(xp) - true_energy(xm)) / (2 * h);
        frozen[a] = 0;
      }
      // the same gradient with the pairs' frames frozen (the term of the frame's derivative left out)
      for(const auto& pr : s.pairs()) {
        if(pr.i != i && pr.j != i) continue;
        const Eigen::Vector3d v = x.segment<3>(3 * pr.i) - x.segment<3>(3 * pr.j);
        Eigen::Vector3d de;
        TLM::gaussian_hole_kernel(lattice, Eigen::Vector3d(pr.B * v), lattice.sigma, &de);
        frozen += (pr.i == i ? 2. : -2.) * (pr.B.transpose() * de);
      }
      if(fd.norm() < 1e-2) continue;
      smallest = std::min(smallest, fd.norm());
      worst = std::max(worst, (g.segment<3>(3 * i) - fd).norm() / fd.norm());
      worst_without = std::max(worst_without, (frozen - fd).norm() / fd.norm());
    }
  }
  std::cout << "system gradient in a varying field (bcc, fcc, cubic): max relative error " << worst
            << " (frames frozen: " << worst_without << "), smallest |grad| " << smallest << "\n";
  VVM_CHECK(smallest < 1e300);
  // the pair's derivative is the mean of those at its two particles, not the one at its
  // midpoint: a second-order difference (3.5e-4 here)
  VVM_CHECK_LESS(worst, 2e-3);
  VVM_CHECK(worst_without > 2e-2); // the field varies enough for the derivative to matter
}

// The pairs in a graded field: the particles' own stretches spare the lookups of far pairs, and
// no pair within R is lost (brute force over all pairs, the frame at each pair's midpoint).

void test_pairs_in_graded_field()
{
  // the size triples across the box (gradation 2, steeper than the thickness sizing's 0.3)
  const Varying_field field([](const Point& p) {
    return Eigen::Matrix3d((1 + 2 * p.x()) * rotation(0.5 * p.z(), Eigen::Vector3d(1, 1, 0).normalized()));
  });
  const double l = 0.04;
  for(TLM::Lattice_type type : all_lattices) {
    const TLM::Lattice lattice = TLM::Lattice::make(type);
    TLMI::Particle_system<Varying_field, TLMI::No_boundary, Point> s(lattice, field, nullptr, l, lattice.sigma,
                                                                    lattice.neighbor_radius);
    CGAL::Random r(23);
    for(int k = 0; k < 1500; ++k)
      s.add(Eigen::Vector3d(r.get_double(0, 1), r.get_double(0, 0.3), r.get_double(0, 0.3)), TLM::Particle_kind::FREE);
    s.build_pairs();
    std::set<std::pair<std::size_t, std::size_t>> built, expected;
    for(const auto& pr : s.pairs()) built.emplace(pr.i, pr.j);
    std::size_t far = 0; // pairs within the largest Euclidean radius but beyond R
    const double radius = s.euclidean_radius();
    for(std::size_t i = 0; i < s.size(); ++i)
      for(std::size_t j = i + 1; j < s.size(); ++j) {
        const Eigen::Vector3d v = s.points[i] - s.points[j];
        if(v.norm() > radius) continue;
        if((s.B(0.5 * (s.points[i] + s.points[j])) * v).norm() <= lattice.neighbor_radius * l) expected.emplace(i, j);
        else ++far;
      }
    VVM_CHECK(expected.size() > 3 * s.size());
    VVM_CHECK(far > expected.size()); // most candidates are far: the filter has work to do
    VVM_CHECK(built == expected);
  }
}

// ---------------------------------------------------------------------------------------------
// Perfect blocks of lattice: sites l T q, q in [0, n]^3 of the lattice's basis.

struct Block
{
  std::vector<Eigen::Vector3d> sites;  // Euclidean
  std::vector<Eigen::Vector3d> coords; // lattice coordinates q
  std::vector<char> interior;          // q further than the neighbour radius from the block's faces
  int n = 0;
};

std::vector<Eigen::Vector3d> basis(TLM::Lattice_type t)
{
  if(t == TLM::Lattice_type::BCC) return {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0.5, 0.5)};
  if(t == TLM::Lattice_type::FCC)
    return {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d(0.5, 0, 0.5),
            Eigen::Vector3d(0, 0.5, 0.5)};
  return {Eigen::Vector3d(0, 0, 0)};
}

Block lattice_block(const TLM::Lattice& lattice, const Eigen::Matrix3d& T, double l, int n)
{
  Block b;
  b.n = n;
  const double margin = lattice.neighbor_radius + 0.01;
  for(int x = 0; x <= n; ++x)
    for(int y = 0; y <= n; ++y)
      for(int z = 0; z <= n; ++z)
        for(const Eigen::Vector3d& o : basis(lattice.type)) {
          const Eigen::Vector3d q = Eigen::Vector3d(x, y, z) + o;
          if(q.maxCoeff() > n) continue;
          b.coords.push_back(q);
          b.sites.push_back(l * (T * q));
          b.interior.push_back(q.minCoeff() > margin && q.maxCoeff() < n - margin);
        }
  return b;
}

// distance, in units of l* in the imagined space, from p to the nearest lattice point
double distance_to_lattice(const TLM::Lattice& lattice, const Eigen::Matrix3d& B, double l, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d q = B * p / l;
  double best = 1e300;
  for(const Eigen::Vector3d& o : basis(lattice.type)) {
    const Eigen::Vector3d d = q - o;
    best = std::min(best, (d - d.array().round().matrix()).norm());
  }
  return best;
}

Eigen::Matrix3d block_frame(TLM::Lattice_type t)
{
  // a rotation for BCC, a rotation with unequal axes for FCC, the identity for the cubic lattice
  if(t == TLM::Lattice_type::BCC) return rotation(0.7, Eigen::Vector3d(1, 2, 3));
  if(t == TLM::Lattice_type::FCC)
    return rotation(-0.4, Eigen::Vector3d(3, -1, 2)) * Eigen::Vector3d(1.2, 0.9, 1.0).asDiagonal();
  return Eigen::Matrix3d::Identity();
}

// ---------------------------------------------------------------------------------------------
// 2. A perfect lattice is a stationary point, and a stable one.

void test_perfect_lattice()
{
  const double l = 0.3;
  for(TLM::Lattice_type type : all_lattices) {
    const TLM::Lattice lattice = TLM::Lattice::make(type);
    const Eigen::Matrix3d T = block_frame(type), B = T.inverse();
    const Constant_field field(T);
    const Block block = lattice_block(lattice, T, l, 6);
    Free_system s(lattice, field, nullptr, l, lattice.sigma, lattice.neighbor_radius);
    for(const Eigen::Vector3d& p : block.sites) s.add(p, TLM::Particle_kind::FREE);
    s.build_pairs();
    Eigen::VectorXd g;
    s.energy_and_gradient(s.positions(), g);
    double worst_interior = 0, largest_border = 0;
    std::size_t n_interior = 0, first_interior = block.sites.size();
    for(std::size_t i = 0; i < s.size(); ++i) {
      const double gi = g.segment<3>(3 * i).norm();
      if(block.interior[i]) {
        worst_interior = std::max(worst_interior, gi);
        ++n_interior;
        first_interior = std::min(first_interior, i);
      } else
        largest_border = std::max(largest_border, gi);
    }
    // reference force: an interior particle displaced by 0.1 l* (imagined space)
    CGAL::Random r(5);
    Eigen::VectorXd x = s.positions(), g_ref;
    x.segment<3>(3 * first_interior) += 0.1 * (T * random_unit_vector(r));
    s.energy_and_gradient(x, g_ref);
    const double reference = g_ref.segment<3>(3 * first_interior).norm();

    // perturb the interior by 0.1 l*, fix the rest (CORNER is never moved), relax
    for(std::size_t i = 0; i < s.size(); ++i)
      if(block.interior[i]) s.points[i] += 0.1 * l * (T * random_unit_vector(r));
      else s.kinds[i] = TLM::Particle_kind::CORNER;
    auto worst_offset = [&]() {
      double w = 0;
      for(std::size_t i = 0; i < s.size(); ++i) w = std::max(w, (B * (s.points[i] - block.sites[i])).norm() / l);
      return w;
    };
    const double before = worst_offset();
    int rounds = 0, iterations = 0;
    while(rounds < 8 && worst_offset() > 1e-3) {
      iterations += s.lbfgs_round(1e-5, 200).iterations;
      ++rounds;
    }
    const double after = worst_offset();
    std::cout << "perfect " << TLM::lattice_name(type) << " block (" << s.size() << " particles, " << n_interior
              << " interior): max interior |grad| " << worst_interior << ", reference (0.1 l* off) " << reference
              << ", max border |grad| " << largest_border << "; interior perturbed by 0.1 l*: max offset " << before
              << " -> " << after << " l* after " << rounds << " L-BFGS rounds (" << iterations << " its)\n";
    VVM_CHECK(n_interior >= 27);
    VVM_CHECK(reference > 0.1);
    VVM_CHECK_LESS(worst_interior, 1e-8 * reference);
    VVM_CHECK(largest_border > 1e-3 * reference); // the border is not balanced: the measure discriminates
    VVM_CHECK(before > 0.09);
    VVM_CHECK_LESS(after, 0.01);
  }
}

// ---------------------------------------------------------------------------------------------
// 3. Deletion and insertion on hand-made configurations.

// the index of the interior site nearest the block's centre
std::size_t central_site(const Block& b)
{
  std::size_t best = 0;
  double d = 1e300;
  const Eigen::Vector3d c = Eigen::Vector3d::Constant(0.5 * b.n);
  for(std::size_t i = 0; i < b.coords.size(); ++i)
    if(b.interior[i] && (b.coords[i] - c).norm() < d) d = (b.coords[i] - c).norm(), best = i;
  return best;
}

void test_deletion_and_insertion()
{
  const double l = 0.3;
  for(TLM::Lattice_type type : all_lattices) {
    const TLM::Lattice lattice = TLM::Lattice::make(type);
    const Eigen::Matrix3d T = block_frame(type), B = T.inverse();
    const Constant_field field(T);
    const Block block = lattice_block(lattice, T, l, 5);
    const std::size_t N = block.sites.size(), m = central_site(block);
    auto make_system = [&](bool skip_m) {
      Free_system s(lattice, field, nullptr, l, lattice.sigma, lattice.neighbor_radius);
      for(std::size_t i = 0; i < N; ++i)
        if(!(skip_m && i == m)) s.add(block.sites[i], TLM::Particle_kind::FREE);
      return s;
    };
    auto in_block = [&](const Eigen::Vector3d& p) {
      const Eigen::Vector3d q = B * p / l;
      return q.minCoeff() > -1e-9 && q.maxCoeff() < block.n + 1e-9;
    };

    // deletion: nothing in the perfect block; one of two particles 0.05 l* apart
    Free_system perfect = make_system(false);
    const std::size_t deleted_perfect = TLMI::delete_particles(perfect);
    Free_system crowded = make_system(false);
    CGAL::Random r(17);
    crowded.add(block.sites[m] + 0.05 * l * (T * random_unit_vector(r)), TLM::Particle_kind::FREE);
    const std::size_t deleted = TLMI::delete_particles(crowded);
    // every site holds exactly one particle within 0.1 l*
    std::size_t sites_not_single = 0;
    for(std::size_t k = 0; k < N; ++k) {
      std::size_t c = 0;
      for(const Eigen::Vector3d& p : crowded.points) c += ((B * (p - block.sites[k])).norm() < 0.1 * l);
      sites_not_single += (c != 1);
    }
    VVM_CHECK_EQUAL(deleted_perfect, std::size_t(0));
    VVM_CHECK_EQUAL(deleted, std::size_t(1));
    VVM_CHECK_EQUAL(crowded.size(), N);
    VVM_CHECK_EQUAL(sites_not_single, std::size_t(0));

    // insertion: the perfect block gains particles only outside, at lattice sites one ring
    // away; with one interior site empty it gains the same ones and one at that site
    Free_system grown = make_system(false);
    const std::size_t inserted_perfect = TLMI::insert_particles(grown);
    Free_system holed = make_system(true);
    const std::size_t inserted = TLMI::insert_particles(holed);
    std::size_t perfect_inside = 0, off_lattice = 0, far_out = 0;
    for(std::size_t i = N; i < grown.size(); ++i) {
      perfect_inside += in_block(grown.points[i]);
      off_lattice += distance_to_lattice(lattice, B, l, grown.points[i]) > 1e-9;
      const Eigen::Vector3d q = B * grown.points[i] / l;
      far_out += (q.minCoeff() < -1 - 1e-9 || q.maxCoeff() > block.n + 1 + 1e-9);
    }
    std::vector<Eigen::Vector3d> new_inside, new_outside;
    for(std::size_t i = N - 1; i < holed.size(); ++i)
      (in_block(holed.points[i]) ? new_inside : new_outside).push_back(holed.points[i]);
    const double hole_distance = new_inside.size() == 1 ? (B * (new_inside[0] - block.sites[m])).norm() / l : 1e300;
    // the outside insertions are those of the perfect block
    std::size_t unmatched = 0;
    for(const Eigen::Vector3d& p : new_outside) {
      bool found = false;
      for(std::size_t i = N; i < grown.size() && !found; ++i) found = (p - grown.points[i]).norm() < 1e-12 * l;
      unmatched += !found;
    }
    // then an L-BFGS round with the block's border (and the outside insertions) fixed
    std::size_t new_index = holed.size();
    for(std::size_t i = 0; i < holed.size(); ++i) {
      if(i >= N - 1 && in_block(holed.points[i])) new_index = i;
      const bool interior = i < N - 1 ? block.interior[i < m ? i : i + 1] : in_block(holed.points[i]);
      if(!interior) holed.kinds[i] = TLM::Particle_kind::CORNER;
    }
    double after_lbfgs = 1e300;
    if(new_index < holed.size()) {
      holed.lbfgs_round(1e-5, 200);
      after_lbfgs = (B * (holed.points[new_index] - block.sites[m])).norm() / l;
    }
    std::cout << TLM::lattice_name(type) << " block of " << N << ": deleted " << deleted_perfect
              << " of the perfect block, " << deleted << " of two particles 0.05 l* apart; inserted "
              << inserted_perfect << " around the perfect block (" << perfect_inside << " inside, " << off_lattice
              << " off-lattice), " << inserted << " with a site empty (" << new_inside.size()
              << " inside, at " << hole_distance << " l* of the site, " << after_lbfgs << " l* after L-BFGS)\n";
    VVM_CHECK_EQUAL(perfect_inside, std::size_t(0));
    VVM_CHECK_EQUAL(off_lattice, std::size_t(0));
    VVM_CHECK_EQUAL(far_out, std::size_t(0));
    VVM_CHECK_EQUAL(inserted, inserted_perfect + 1);
    VVM_CHECK_EQUAL(new_inside.size(), std::size_t(1));
    VVM_CHECK_EQUAL(unmatched, std::size_t(0));
    VVM_CHECK_LESS(hole_distance, 0.2);
    VVM_CHECK_LESS(after_lbfgs, 0.01);
  }
}

int main(int argc, char** argv)
{
  return vvm_test::run(argc, argv, "test_particle_system", {
      {"kernel_gradient", test_kernel_gradient},
      {"system_gradient_in_varying_field", test_system_gradient_in_varying_field},
      {"pairs_in_graded_field", test_pairs_in_graded_field},
      {"perfect_lattice", test_perfect_lattice},
      {"deletion_and_insertion", test_deletion_and_insertion}});
}
