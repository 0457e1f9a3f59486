// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every energy-guided change of connectivity (dissertation section 3.3.2)
// shares: cells of one subdomain are replaced by new cells filling the same
// region, when that lowers the mean energy of the cells in the complex
// (sum_new - sum_old < (n_new - n_old) * mean), so that the mesh energy of
// eq. 3.9 never increases and no sequence of changes can cycle; and the
// bookkeeping of the complex: subdomain indices, surface-patch data of the
// facets on the region's boundary, the counters and the running energy sum.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_CELL_REPLACEMENT_H
#define CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_CELL_REPLACEMENT_H

#include <CGAL/GSM_mesh_optimization/internal/Mesh_energy.h>
#include <CGAL/GSM_mesh_optimization/internal/Triangulation_complex.h>
#include <CGAL/VVM/internal/Complex_cell_replacement.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace internal {

using VVM::internal::Complex_cell_replacement;

/// a change of connectivity taken when it lowers the mean energy
template <class C3T3>
class Cell_replacement : public Complex_cell_replacement<C3T3>
{
  typedef Complex_cell_replacement<C3T3> Base;

public:
  typedef typename Base::Tr Tr;
  typedef typename Base::Vertex_handle Vertex_handle;
  typedef typename Base::Cell_handle Cell_handle;
  typedef typename Base::Facet Facet;
  typedef typename Base::Edge Edge;
  typedef typename Base::Subdomain_index Subdomain_index;
  typedef typename Base::Surface_patch_index Surface_patch_index;
  typedef Mesh_energy<C3T3> Energy;

  /// `sum` and `count`: the running total of the energies of the cells in the complex
  Cell_replacement(C3T3& c3t3, const Energy& energy, double& sum, std::size_t& count)
    : Base(c3t3), energy_(energy), sum_(sum), count_(count)
  {}

  double mean() const { return count_ > 0 ? sum_ / double(count_) : 0.; }

protected:
  /// the acceptance criterion: replacing cells of total energy `old_sum` by
  /// `cell_difference` more cells of total energy `new_sum` lowers the mean
  bool lowers_mean(double old_sum, double new_sum, int cell_difference) const
  {
    return new_sum - old_sum < double(cell_difference) * mean();
  }

  double tet_energy(const Vertex_handle& a, const Vertex_handle& b, const Vertex_handle& c,
                    const Vertex_handle& d) const
  {
    return energy_.tetrahedron(a, b, c, d);
  }

  void account(double old_sum, double new_sum, int cell_difference)
  {
    const double before = sum_;
    sum_ += new_sum - old_sum;
    count_ = std::size_t(std::ptrdiff_t(count_) + cell_difference);
    // cells of nearly zero volume have energies so large that removing them leaves only the
    // rounding error of the running sum (even a negative one): sum again
    if(!(sum_ > 1e-6 * before)) {
      const std::pair<double, std::size_t> total = energy_.total();
      sum_ = total.first;
      count_ = total.second;
    }
  }

  const Energy& energy_;
  double& sum_;
  std::size_t& count_;
};

} // namespace internal
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_INTERNAL_CELL_REPLACEMENT_H
