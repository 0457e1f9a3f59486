// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the particle engine needs of a domain, for any MeshDomain_3: the inside
// test (the domain's own), and its boundary as CGAL's Mesh_3 samples it (surface
// facets with their patches, feature edges with their curves, corners), with
// AABB trees for the closest point on the surface and on the sharp edges
// (Boundary_samples).

#ifndef CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_BOUNDARY_H
#define CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_BOUNDARY_H

#include <CGAL/Tetrahedral_lattice_meshing/internal/Boundary_samples.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Reproducible_sampling.h>
#include <CGAL/Tetrahedral_lattice_meshing/internal/Thread_safe_inside.h>
#include <CGAL/VVM/internal/Edges_in_complex.h>
#include <CGAL/make_mesh_3.h>

#include <CGAL/Mesh_3/Has_features.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <Eigen/Core>

#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Tetrahedral_lattice_meshing {
namespace internal {

template <class MeshDomain, bool = CGAL::Mesh_3::internal::Has_features<MeshDomain>::value>
struct Complex_indices
{
  typedef int Corner_index;
  typedef int Curve_index;
};

template <class MeshDomain>
struct Complex_indices<MeshDomain, true>
{
  typedef typename MeshDomain::Corner_index Corner_index;
  typedef typename MeshDomain::Curve_index Curve_index;
};

/// the complex type Mesh_3 makes for `MeshDomain`
template <class MeshDomain>
struct Sampling_complex
{
  typedef typename CGAL::Mesh_triangulation_3<MeshDomain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, typename Complex_indices<MeshDomain>::Corner_index,
                                                  typename Complex_indices<MeshDomain>::Curve_index>
      type;
};

/*
 * The sampled boundary of a domain. Patches, curves and corners are numbered
 * 0, 1, ... in the order of the domain's own indices (kept in `patch_indices` ...).
 */
template <class MeshDomain, class GeomTraits>
class Domain_boundary : public Boundary_samples<GeomTraits>
{
  typedef Boundary_samples<GeomTraits> Base;
  using Base::eig;

public:
  typedef GeomTraits K;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Triangle_3 Triangle_3;
  typedef typename K::Segment_3 Segment_3;
  typedef typename Sampling_complex<MeshDomain>::type C3T3;
  typedef typename MeshDomain::Surface_patch_index Surface_patch_index;
  typedef typename MeshDomain::Subdomain_index Subdomain_index;
  typedef typename C3T3::Curve_index Curve_index;
  typedef typename C3T3::Corner_index Corner_index;

  /// samples the boundary of `domain` with Mesh_3 at a resolution fit for particles
  /// `spacing` apart (facets about that size), with a chordal error of 2% of the smallest
  /// spacing, `finest_spacing` (an anisotropic field's shortest axis): the surface is as
  /// accurate as the densest particles need, without facets that small on flat parts
  Domain_boundary(const MeshDomain& domain, double spacing, double finest_spacing = 0) : domain_(domain)
  {
    if(!(finest_spacing > 0) || finest_spacing > spacing) finest_spacing = spacing;
    namespace P = CGAL::parameters;
    typedef CGAL::Mesh_criteria_3<typename C3T3::Triangulation> Criteria;
    Criteria criteria(P::edge_size = spacing, P::facet_angle = 25, P::facet_size = spacing,
                      P::facet_distance = 0.02 * finest_spacing, P::cell_radius_edge_ratio = 3,
                      P::cell_size = 2 * spacing);
    refuse_empty(domain);
    C3T3 c3t3;
    {
      const Reproducible_sampling reproducible(domain); // the boundary must not depend on the process's history
      c3t3 = CGAL::make_mesh_3<C3T3>(domain, criteria, P::no_perturb(), P::no_exude());
    }
    read(c3t3);
  }

  const MeshDomain& domain() const { return domain_; }

  /// whether `inside()` may be called from several threads at once
  static constexpr bool has_thread_safe_inside = internal::has_thread_safe_inside<MeshDomain>;

  /// whether `domain` may be sampled while another thread meshes it with Mesh_3: CGAL's
  /// polyhedral domains but complexes (`may_be_meshed_concurrently`), whose trees are built under
  /// a lock, whose cache of the last intersection query is per thread when CGAL is linked with
  /// TBB (shared otherwise), and whose initial points come from a generator of each call's own
  /// (unless one was given with `set_random_generator()`, which Polyhedral_mesh_domain_3 does not
  /// let us see: both runs then draw from it); no domain with a generator we can see (a labelled
  /// domain's is shared by every call)
  static bool may_sample_beside_other_meshing(const MeshDomain& domain)
  {
#ifdef CGAL_LINKED_WITH_TBB
    return may_be_meshed_concurrently<MeshDomain> && Domain_random_generator<MeshDomain>::of(domain) == nullptr;
#else
    return (void)domain, false;
#endif
  }

  /// throws unless a point of a grid over the bounding box of `domain` lies inside it: CGAL's
  /// search for the initial points of make_mesh_3 does not end on a domain with no inside (an
  /// implicit function positive everywhere, an image of background only)
  static void refuse_empty(const MeshDomain& domain)
  {
    const CGAL::Bbox_3 bb = domain.bbox();
    const auto is_in_domain = domain.is_in_domain_object();
    constexpr int n = 24;
    auto at = [](double lo, double hi, int i) { return lo + (i + 0.5) / n * (hi - lo); };
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j)
        for(int k = 0; k < n; ++k)
          if(is_in_domain(Point_3(at(bb.xmin(), bb.xmax(), i), at(bb.ymin(), bb.ymax(), j),
                                  at(bb.zmin(), bb.zmax(), k))))
            return;
    throw std::invalid_argument("lattice_particles_3: the domain is empty (no point of a 24^3 grid over its "
                                "bounding box lies inside it)");
  }

  /// the subdomain index of `p`, 0 outside
  Subdomain_index subdomain(const Eigen::Vector3d& p) const
  {
    const auto s = domain_.is_in_domain_object()(Point_3(p[0], p[1], p[2]));
    return s ? *s : Subdomain_index();
  }
  bool inside(const Eigen::Vector3d& p) const { return subdomain(p) != Subdomain_index(); }

  /// the point of the domain's own feature curve nearest to `p`, a point of the sampled sharp
  /// edges: Mesh_3's curve queries (geodesic distances) expect points on the curve itself
  Eigen::Vector3d point_on_curve(const Eigen::Vector3d& p) const
  {
    CGAL_precondition(this->has_sharp_edges());
    if constexpr(CGAL::Mesh_3::internal::Has_features<MeshDomain>::value) {
      const auto r = edge_tree_.closest_point_and_primitive(Point_3(p[0], p[1], p[2]));
      const std::size_t s = std::size_t(r.second - segments_.begin());
      const Eigen::Vector3d a = eig(segments_[s].source()), b = eig(segments_[s].target()), q = eig(r.first);
      const double t = (q - a).norm() / (b - a).norm();
      if(t <= 0) return a;
      if(t >= 1) return b;
      const auto x = domain_.construct_point_on_curve(segments_[s].source(), curve_indices_[segment_curves_[s]],
                                                      t * segment_arc_lengths_[s]);
      return eig(x);
    } else
      return p;
  }

  /// the cells of the sampling complex, for the volume and random points
  const std::vector<std::array<Eigen::Vector3d, 4>>& cells() const { return cells_; }

  const std::vector<Surface_patch_index>& patch_indices() const { return patch_indices_; }
  const std::vector<Curve_index>& curve_indices() const { return curve_indices_; }
  const std::vector<Corner_index>& corner_indices() const { return corner_indices_; }

private:
  using Base::triangles_;
  using Base::segments_;
  using Base::segment_curves_;
  using Base::edge_tree_;
  using Base::corners_;
  using Base::corner_numbers_;

  void read(const C3T3& c3t3)
  {
    const auto& tr = c3t3.triangulation();
    const auto cp = tr.geom_traits().construct_point_3_object();
    auto point = [&](typename C3T3::Vertex_handle v) { return eig(cp(tr.point(v))); };
    std::map<Surface_patch_index, int> patch_number;
    std::map<Curve_index, int> curve_number;
    for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
      const Surface_patch_index s = c3t3.surface_patch_index(*f);
      auto it = patch_number.emplace(s, int(patch_indices_.size()));
      if(it.second) patch_indices_.push_back(s);
      std::array<Eigen::Vector3d, 3> p;
      for(int k = 0; k < 3; ++k) p[k] = point(f->first->vertex((f->second + 1 + k) & 3));
      this->add_triangle(p[0], p[1], p[2], it.first->second); // a flat sampling facet tells nothing: skipped
    }
    if(triangles_.empty())
      throw std::invalid_argument("lattice particles: the domain is empty (Mesh_3 found no boundary facet)");
    for(const auto& e : VVM::internal::edges_in_complex(c3t3)) {
      const Curve_index ci = c3t3.curve_index(e);
      auto it = curve_number.emplace(ci, int(curve_indices_.size()));
      if(it.second) curve_indices_.push_back(ci);
      const Eigen::Vector3d a = point(e.first->vertex(e.second)), b = point(e.first->vertex(e.third));
      if(!this->add_segment(a, b, it.first->second)) continue;
      // the chord's length, signed with the curve's orientation (CGAL 5.5.1's
      // signed_geodesic_distance() can loop forever on some point pairs)
      if constexpr(CGAL::Mesh_3::internal::Has_features<MeshDomain>::value) {
        Eigen::Vector3d forward = b - a;
        if(domain_.is_loop(ci)) // a step along the loop (distances wrap around)
          forward = eig(domain_.construct_point_on_curve(segments_.back().source(), ci, 0.01 * (b - a).norm())) - a;
        else if(domain_.distance_sign(segments_.back().source(), segments_.back().target(), ci) == CGAL::NEGATIVE)
          forward = a - b;
        segment_arc_lengths_.push_back(forward.dot(b - a) >= 0 ? (b - a).norm() : -(b - a).norm());
      }
    }
    std::map<Corner_index, int> corner_number;
    for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v) {
      const Corner_index ci = c3t3.corner_index(v);
      auto it = corner_number.emplace(ci, int(corner_indices_.size()));
      if(it.second) corner_indices_.push_back(ci);
      corners_.push_back(point(v));
      corner_numbers_.push_back(it.first->second);
    }
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      std::array<Eigen::Vector3d, 4> p;
      for(int k = 0; k < 4; ++k) p[k] = point(c->vertex(k));
      cells_.push_back(p);
    }
    this->build_trees();
  }

  const MeshDomain& domain_;
  std::vector<double> segment_arc_lengths_; // chord lengths, signed with the domain's curve
  std::vector<std::array<Eigen::Vector3d, 4>> cells_;
  std::vector<Surface_patch_index> patch_indices_;
  std::vector<Curve_index> curve_indices_;
  std::vector<Corner_index> corner_indices_;
};

} // namespace internal
} // namespace Tetrahedral_lattice_meshing
} // namespace CGAL

#endif // CGAL_TETRAHEDRAL_LATTICE_MESHING_INTERNAL_DOMAIN_BOUNDARY_H
