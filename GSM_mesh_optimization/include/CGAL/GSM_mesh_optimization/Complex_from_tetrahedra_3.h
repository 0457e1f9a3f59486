// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A tetrahedral mesh made by any mesher (TetGen, Gmsh, fTetWild, a file) as a
// Mesh_complex_3_in_triangulation_3 with the domain of its own boundary, so that
// gsm_optimize_mesh_3() can improve it without re-meshing.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_COMPLEX_FROM_TETRAHEDRA_3_H
#define CGAL_GSM_MESH_OPTIMIZATION_COMPLEX_FROM_TETRAHEDRA_3_H

#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedral_complex_mesh_domain_3.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {

/*!
 * \ingroup PkgGSMMeshOptimizationRef
 *
 * A tetrahedral mesh given as points, tetrahedra and subdomain labels, turned into what
 * `gsm_optimize_mesh_3()` works on: a `Mesh_complex_3_in_triangulation_3` (`c3t3()`) and
 * the domain of its own boundary (`domain()`), a `Polyhedral_complex_mesh_domain_3` whose
 * surfaces are the mesh's boundary facets and the facets between cells of different labels.
 * The surfaces are split into patches at the edges where the angle between the normals of
 * two adjacent facets exceeds `features_angle` degrees, at the edges where three or more
 * surfaces meet, and at the borders of the label interfaces; those edges are the domain's
 * feature curves (polylines), the complex's edges, and their ends (where not two of them
 * meet) its corners. Vertices are classified as a mesh of `make_mesh_3()` would have them:
 * on a corner, a curve, a patch, or inside a subdomain; so surface vertices slide on the
 * input's own boundary, and vertices on features along them, under GSM's boundary-fidelity
 * guard.
 *
 * The triangulation holds exactly the given cells (no cell outside the domain: its
 * infinite cells rest on the boundary facets, as in `CGAL::IO::read_MEDIT()`), so its
 * boundary need not be convex. Where parts of the mesh touch at vertices or along edges
 * without sharing a facet (as where a surface of `make_mesh_3()` pinches two close parts
 * together), each part has its own copy of the vertices there, in the triangulation only:
 * they are corners of the domain, never moved, and `get_tetrahedra()` gives them back as one
 * vertex. A mesh of several parts, or with cavities, is taken (its
 * boundary is then not connected: the triangulation is fine for the local changes of
 * `gsm_optimize_mesh_3()`, not for a traversal of the infinite vertex's cells).
 *
 * \code
 * CGAL::GSM_mesh_optimization::Complex_from_tetrahedra_3<K> mesh(points, tets, labels, 60);
 * CGAL::gsm_optimize_mesh_3(mesh.c3t3(), mesh.domain());
 * mesh.get_tetrahedra(points, tets, labels);
 * \endcode
 *
 * \tparam K a kernel with exact predicates, e.g. `Exact_predicates_inexact_constructions_kernel`
 */
template <class K>
class Complex_from_tetrahedra_3
{
public:
  typedef typename K::Point_3 Point_3;
  /// the domain: the boundary and interface surfaces of the input, with its features
  typedef CGAL::Polyhedral_complex_mesh_domain_3<K> Mesh_domain;
  typedef typename CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type Triangulation;
  /// the complex
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Triangulation, typename Mesh_domain::Corner_index,
                                                  typename Mesh_domain::Curve_index>
      C3T3;
  typedef std::array<std::size_t, 4> Tetrahedron;

  /*!
   * builds the complex and the domain.
   *
   * \param points the vertices; those in no tetrahedron are dropped
   * \param tetrahedra four indices into `points` each, positively oriented (the fourth point
   *   on the side of the first three's normal by the right-hand rule, as in Gmsh and
   *   `CGAL::Triangulation_3`); a mesh whose cells are all negatively oriented (the other
   *   convention) is taken with each cell's first two vertices swapped
   * \param labels the subdomain of each tetrahedron (any `int`s; empty: all cells in one
   *   subdomain); they are given back unchanged by `get_tetrahedra()`
   * \param features_angle in degrees, in `[0, 180]`; 180 keeps only the edges where surfaces
   *   meet as features
   *
   * \throws std::invalid_argument naming the problem if there is no tetrahedron, an index
   *   is out of range, a coordinate is not finite, two vertices are at the same point, the
   *   cells are not all of one orientation
   *   or one is flat, a facet is shared by more than two cells, an edge of the boundary has
   *   more than two boundary facets where the parts meeting there also share a facet, a
   *   vertex of the boundary is not manifold (its boundary facets do not form one fan where
   *   its cells form one part), or the sizes do not match.
   */
  Complex_from_tetrahedra_3(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tetrahedra,
                            const std::vector<int>& labels = {}, double features_angle = 60)
  {
    if(tetrahedra.empty()) throw std::invalid_argument("the mesh has no tetrahedron");
    if(!labels.empty() && labels.size() != tetrahedra.size())
      throw std::invalid_argument("there are " + std::to_string(labels.size()) + " labels for " +
                                  std::to_string(tetrahedra.size()) + " tetrahedra");
    if(!(features_angle >= 0 && features_angle <= 180))
      throw std::invalid_argument("the features angle must be in [0, 180] degrees");
    compact_vertices(points, tetrahedra);
    orient_cells();
    split_pinched_vertices();
    label_cells(labels);
    collect_surfaces(features_angle);
    build_domain();
    build_complex();
  }

  C3T3& c3t3() { return c3t3_; }
  const C3T3& c3t3() const { return c3t3_; }
  const Mesh_domain& domain() const { return *domain_; }

  /// the number of surface patches of the domain (pieces of the boundary and of the interfaces
  /// between feature curves)
  std::size_t number_of_surface_patches() const { return number_of_patches_; }
  /// the number of feature curves (polylines) of the domain
  std::size_t number_of_curves() const { return polylines_.size(); }

  /*!
   * the cells of the complex, with the labels of the input (its cells keep their subdomain):
   * `points` are the vertices of these cells only, `tetrahedra` positively oriented.
   */
  void get_tetrahedra(std::vector<Point_3>& points, std::vector<Tetrahedron>& tetrahedra,
                      std::vector<int>& labels) const
  {
    points.clear();
    tetrahedra.clear();
    labels.clear();
    std::map<typename Triangulation::Vertex_handle, std::size_t> index;
    const Triangulation& tr = c3t3_.triangulation();
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c) {
      Tetrahedron t;
      for(int i = 0; i < 4; ++i) {
        const auto copy = copied_.find(c->vertex(i));
        const auto inserted = index.emplace(copy == copied_.end() ? c->vertex(i) : copy->second, points.size());
        if(inserted.second) points.push_back(tr.geom_traits().construct_point_3_object()(tr.point(c, i)));
        t[i] = inserted.first->second;
      }
      tetrahedra.push_back(t);
      labels.push_back(label_of_subdomain_.at(std::size_t(c3t3_.subdomain_index(c))));
    }
  }

private:
  typedef typename Mesh_domain::Polyhedron Polyhedron;
  typedef std::array<std::size_t, 3> Triangle;
  typedef std::pair<std::size_t, std::size_t> Edge;

  static Edge edge(std::size_t a, std::size_t b) { return a < b ? Edge(a, b) : Edge(b, a); }

  void compact_vertices(const std::vector<Point_3>& points, const std::vector<Tetrahedron>& tetrahedra)
  {
    if(points.size() >= std::size_t((std::numeric_limits<int>::max)()) ||
       tetrahedra.size() >= std::size_t((std::numeric_limits<int>::max)()))
      throw std::invalid_argument("the mesh has more than 2^31 vertices or tetrahedra");
    std::vector<std::size_t> new_index(points.size(), std::size_t(-1));
    tets_.reserve(tetrahedra.size());
    for(std::size_t k = 0; k < tetrahedra.size(); ++k) {
      Tetrahedron t = tetrahedra[k];
      for(std::size_t& i : t) {
        if(i >= points.size())
          throw std::invalid_argument("tetrahedron " + std::to_string(k) + " refers to vertex " + std::to_string(i) +
                                      ", which does not exist");
        if(new_index[i] == std::size_t(-1)) {
          const Point_3& p = points[i];
          if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
             !std::isfinite(CGAL::to_double(p.z())))
            throw std::invalid_argument("vertex " + std::to_string(i) + " has a non-finite coordinate");
          new_index[i] = points_.size();
          points_.push_back(p);
        }
        i = new_index[i];
      }
      if(t[0] == t[1] || t[0] == t[2] || t[0] == t[3] || t[1] == t[2] || t[1] == t[3] || t[2] == t[3])
        throw std::invalid_argument("tetrahedron " + std::to_string(k) + " repeats a vertex");
      tets_.push_back(t);
    }
    // two vertices at one point (unmerged nodes, a crack) would make one corner of two
    std::vector<std::size_t> order(points_.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [this](std::size_t a, std::size_t b) { return points_[a] < points_[b]; });
    for(std::size_t k = 1; k < order.size(); ++k)
      if(points_[order[k - 1]] == points_[order[k]])
        throw std::invalid_argument("two vertices are at the same point (" + to_string(points_[order[k]]) + ")");
  }

  CGAL::Orientation orientation(const Tetrahedron& t) const
  {
    return CGAL::orientation(points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]]);
  }

  void orient_cells()
  {
    std::size_t positive = 0, negative = 0, flat = 0;
    for(const Tetrahedron& t : tets_) {
      const CGAL::Orientation o = orientation(t);
      (o == CGAL::POSITIVE ? positive : o == CGAL::NEGATIVE ? negative : flat)++;
    }
    if(flat > 0) throw std::invalid_argument("the mesh has " + std::to_string(flat) + " flat tetrahedra");
    if(positive > 0 && negative > 0)
      throw std::invalid_argument("the mesh has " + std::to_string((std::min)(positive, negative)) +
                                  " inverted tetrahedra (" + std::to_string(positive) + " of one orientation, " +
                                  std::to_string(negative) + " of the other)");
    if(negative > 0)
      for(Tetrahedron& t : tets_) std::swap(t[0], t[1]);
  }

  // Where parts of the mesh touch at a vertex only, or along edges, the cells around such a
  // vertex form several parts (connected through the facets at the vertex) and the
  // triangulation's infinite cells, which rest on the boundary, cannot be joined there: each
  // part but the first gets its own copy of the vertex (a corner, never moved).
  void split_pinched_vertices()
  {
    std::vector<std::vector<std::size_t>> cells_at(points_.size());
    for(std::size_t k = 0; k < tets_.size(); ++k)
      for(std::size_t v : tets_[k]) cells_at[v].push_back(k);
    n_ = points_.size();
    for(std::size_t v = 0; v < n_; ++v) {
      const std::vector<std::size_t>& cells = cells_at[v];
      std::vector<std::size_t> parent(cells.size());
      std::iota(parent.begin(), parent.end(), 0);
      auto find = [&parent](std::size_t x) {
        while(parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
      };
      std::map<Edge, std::size_t> first_cell_on; // the edge opposite v in a facet at v
      for(std::size_t a = 0; a < cells.size(); ++a) {
        std::vector<std::size_t> others;
        for(std::size_t u : tets_[cells[a]])
          if(u != v) others.push_back(u);
        for(int i = 0; i < 3; ++i) {
          const auto inserted = first_cell_on.emplace(edge(others[i], others[(i + 1) % 3]), a);
          if(!inserted.second) parent[find(a)] = find(inserted.first->second);
        }
      }
      std::map<std::size_t, std::size_t> copy_of_part; // root -> vertex
      for(std::size_t a = 0; a < cells.size(); ++a) {
        const auto inserted = copy_of_part.emplace(find(a), copy_of_part.empty() ? v : points_.size());
        if(inserted.second && inserted.first->second != v) {
          points_.push_back(points_[v]);
          copy_of_.push_back(v);
        }
        for(std::size_t& u : tets_[cells[a]])
          if(u == v) u = inserted.first->second;
      }
      if(copy_of_part.size() > 1) pinched_.push_back(v);
    }
  }

  // subdomain indices 1, 2, ... in the order of the sorted labels (0 is "outside" in a C3T3)
  void label_cells(const std::vector<int>& labels)
  {
    std::vector<int> sorted = labels.empty() ? std::vector<int>{1} : labels;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    label_of_subdomain_.assign(1, 0);
    label_of_subdomain_.insert(label_of_subdomain_.end(), sorted.begin(), sorted.end());
    subdomain_.resize(tets_.size());
    for(std::size_t k = 0; k < tets_.size(); ++k)
      subdomain_[k] = labels.empty() ? 1
                                     : int(std::lower_bound(sorted.begin(), sorted.end(), labels[k]) - sorted.begin()) + 1;
  }

  // the boundary and interface facets, each oriented out of the cell of higher subdomain (out
  // of the mesh on its boundary), their patches and the feature edges
  void collect_surfaces(double features_angle)
  {
    std::map<Triangle, std::vector<std::pair<std::size_t, int>>> facet_cells; // sorted facet -> (cell, side)
    for(std::size_t k = 0; k < tets_.size(); ++k)
      for(int i = 0; i < 4; ++i) {
        Triangle f{tets_[k][(i + 1) & 3], tets_[k][(i + 2) & 3], tets_[k][(i + 3) & 3]};
        std::sort(f.begin(), f.end());
        auto& cells = facet_cells[f];
        cells.emplace_back(k, i);
        if(cells.size() > 2)
          throw std::invalid_argument("a facet is shared by more than two tetrahedra (the mesh is not a manifold)");
      }
    for(const auto& fc : facet_cells) {
      const auto& cells = fc.second;
      const int s0 = subdomain_[cells[0].first], s1 = cells.size() == 2 ? subdomain_[cells[1].first] : 0;
      if(cells.size() == 2 && s0 == s1) continue;
      // out of the cell of higher subdomain: the facet opposite vertex i of a positive cell,
      // its normal pointing away from vertex i, is (i+1, i+2, i+3) for even i and
      // (i+1, i+3, i+2) for odd i
      const auto& own = (cells.size() == 1 || s0 > s1) ? cells[0] : cells[1];
      const Tetrahedron& t = tets_[own.first];
      const int i = own.second;
      const Triangle f = i % 2 == 0 ? Triangle{t[(i + 1) & 3], t[(i + 2) & 3], t[(i + 3) & 3]}
                                    : Triangle{t[(i + 1) & 3], t[(i + 3) & 3], t[(i + 2) & 3]};
      facets_.push_back(f);
      facet_subdomains_.emplace_back((std::min)(s0, s1), (std::max)(s0, s1));
    }
    // the edges of the surfaces and their facets
    std::map<Edge, std::vector<std::size_t>> edge_facets;
    for(std::size_t f = 0; f < facets_.size(); ++f)
      for(int j = 0; j < 3; ++j) edge_facets[edge(facets_[f][j], facets_[f][(j + 1) % 3])].push_back(f);
    const double cos_bound = std::cos(features_angle * CGAL_PI / 180.);
    std::vector<std::size_t> parent(facets_.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&parent](std::size_t x) {
      while(parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for(const auto& ef : edge_facets) {
      const auto& fs = ef.second;
      std::size_t on_boundary = 0;
      for(std::size_t f : fs) on_boundary += facet_subdomains_[f].first == 0;
      if(on_boundary != 0 && on_boundary != 2)
        throw std::invalid_argument("the boundary is not a manifold at the edge (" + to_string(points_[ef.first.first]) +
                                    ") - (" + to_string(points_[ef.first.second]) + "): " +
                                    std::to_string(on_boundary) + " boundary facets meet there");
      bool feature = fs.size() != 2 || facet_subdomains_[fs[0]] != facet_subdomains_[fs[1]];
      if(!feature && features_angle < 180) {
        const auto n0 = normal(facets_[fs[0]]), n1 = normal(facets_[fs[1]]);
        const double l = std::sqrt(CGAL::to_double(n0.squared_length() * n1.squared_length()));
        feature = l > 0 && CGAL::to_double(n0 * n1) < cos_bound * l;
      }
      if(feature)
        feature_edges_.push_back(ef.first);
      else
        parent[find(fs[0])] = find(fs[1]);
    }
    // patches: the facets connected across non-feature edges, numbered from 1
    std::map<std::size_t, int> patch_of_root;
    facet_patch_.resize(facets_.size());
    for(std::size_t f = 0; f < facets_.size(); ++f) {
      const auto inserted = patch_of_root.emplace(find(f), int(patch_of_root.size()) + 1);
      facet_patch_[f] = inserted.first->second;
    }
    number_of_patches_ = patch_of_root.size();
    if(number_of_patches_ == 0) throw std::invalid_argument("the mesh has no boundary facet");
    check_manifold_vertices();
  }

  typename K::Vector_3 normal(const Triangle& f) const
  {
    return CGAL::cross_product(points_[f[1]] - points_[f[0]], points_[f[2]] - points_[f[0]]);
  }

  // the boundary facets around a vertex form one fan, cycle or chain (else, its cells being
  // one part since split_pinched_vertices(), they ring it: its boundary is not a surface there)
  void check_manifold_vertices() const
  {
    std::map<std::size_t, std::vector<std::size_t>> vertex_facets;
    for(std::size_t f = 0; f < facets_.size(); ++f)
      if(facet_subdomains_[f].first == 0)
        for(std::size_t v : facets_[f]) vertex_facets[v].push_back(f);
    for(const auto& vf : vertex_facets) {
      const auto& fs = vf.second;
      std::vector<std::size_t> parent(fs.size());
      std::iota(parent.begin(), parent.end(), 0);
      auto find = [&parent](std::size_t x) {
        while(parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
      };
      std::map<std::size_t, std::size_t> first_facet_of_neighbour;
      for(std::size_t a = 0; a < fs.size(); ++a)
        for(std::size_t u : facets_[fs[a]]) {
          if(u == vf.first) continue;
          const auto inserted = first_facet_of_neighbour.emplace(u, a);
          if(!inserted.second) parent[find(a)] = find(inserted.first->second);
        }
      for(std::size_t a = 1; a < fs.size(); ++a)
        if(find(a) != find(0))
          throw std::invalid_argument("the boundary is not a manifold at vertex (" + to_string(points_[vf.first]) +
                                      "): its boundary facets form more than one fan");
    }
  }

  static std::string to_string(const Point_3& p)
  {
    return std::to_string(CGAL::to_double(p.x())) + ", " + std::to_string(CGAL::to_double(p.y())) + ", " +
           std::to_string(CGAL::to_double(p.z()));
  }

  // one polyhedral surface per patch, then the feature polylines
  void build_domain()
  {
    std::vector<Polyhedron> surfaces(number_of_patches_);
    std::vector<std::pair<int, int>> incident_subdomains(number_of_patches_);
    std::vector<std::vector<std::size_t>> patch_facets(number_of_patches_);
    for(std::size_t f = 0; f < facets_.size(); ++f) {
      patch_facets[std::size_t(facet_patch_[f] - 1)].push_back(f);
      // the facet's normal points into the lower subdomain (or out of the mesh): CGAL takes
      // the first of the pair behind the normal, the second in front of it
      incident_subdomains[std::size_t(facet_patch_[f] - 1)] = {facet_subdomains_[f].second, facet_subdomains_[f].first};
    }
    namespace PMP = CGAL::Polygon_mesh_processing;
    for(std::size_t p = 0; p < number_of_patches_; ++p) {
      std::map<std::size_t, std::size_t> local;
      std::vector<Point_3> points;
      std::vector<std::vector<std::size_t>> polygons;
      for(std::size_t f : patch_facets[p]) {
        std::vector<std::size_t> polygon;
        for(std::size_t v : facets_[f]) {
          const auto inserted = local.emplace(v, points.size());
          if(inserted.second) points.push_back(points_[v]);
          polygon.push_back(inserted.first->second);
        }
        polygons.push_back(polygon);
      }
      // a patch pinched at a vertex is not a polygon mesh: its vertex is duplicated
      if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) PMP::orient_polygon_soup(points, polygons);
      PMP::polygon_soup_to_polygon_mesh(points, polygons, surfaces[p]);
    }
    domain_ = std::make_unique<Mesh_domain>(surfaces.begin(), surfaces.end(), incident_subdomains.begin(),
                                            incident_subdomains.end());
    make_polylines();
    std::vector<std::vector<Point_3>> polylines;
    for(const auto& line : polylines_) {
      polylines.emplace_back();
      for(std::size_t v : line) polylines.back().push_back(points_[v]);
    }
    curve_index_.clear();
    domain_->add_features(polylines.begin(), polylines.end(), std::back_inserter(curve_index_));
    std::vector<std::pair<typename Mesh_domain::Corner_index, Point_3>> corners;
    domain_->get_corners(std::back_inserter(corners));
    std::set<Point_3> at_corner;
    for(const auto& c : corners) at_corner.insert(c.second);
    for(std::size_t v : pinched_)
      if(at_corner.insert(points_[v]).second) domain_->add_corner(points_[v]);
  }

  bool is_pinched(std::size_t v) const
  {
    return v >= n_ || std::binary_search(pinched_.begin(), pinched_.end(), v);
  }

  // the feature edges as polylines between corners (vertices where not two of them meet, and
  // the vertices where parts touch),
  // and closed ones (first point repeated at the end)
  void make_polylines()
  {
    std::map<std::size_t, std::vector<std::size_t>> adjacent;
    for(const Edge& e : feature_edges_) {
      adjacent[e.first].push_back(e.second);
      adjacent[e.second].push_back(e.first);
    }
    std::map<Edge, bool> used;
    for(const Edge& e : feature_edges_) used[e] = false;
    auto walk = [&](std::size_t start, std::size_t next) {
      std::vector<std::size_t> line{start};
      std::size_t previous = start, current = next;
      used[edge(start, next)] = true;
      line.push_back(current);
      while(adjacent[current].size() == 2 && current != start && !is_pinched(current)) {
        const std::size_t n = adjacent[current][0] == previous ? adjacent[current][1] : adjacent[current][0];
        if(used[edge(current, n)]) break;
        used[edge(current, n)] = true;
        previous = current;
        current = n;
        line.push_back(current);
      }
      polylines_.push_back(line);
    };
    for(const auto& a : adjacent)
      if(a.second.size() != 2 || is_pinched(a.first))
        for(std::size_t n : a.second)
          if(!used[edge(a.first, n)]) walk(a.first, n);
    for(const Edge& e : feature_edges_) // what is left are cycles
      if(!used[e]) walk(e.first, e.second);
  }

  void build_complex()
  {
    typedef typename Triangulation::Vertex_handle Vertex_handle;
    typedef typename Triangulation::Cell::Surface_patch_index Surface_patch_index;
    std::vector<std::array<int, 5>> cells;
    cells.reserve(tets_.size());
    for(std::size_t k = 0; k < tets_.size(); ++k)
      cells.push_back({int(tets_[k][0]), int(tets_[k][1]), int(tets_[k][2]), int(tets_[k][3]), subdomain_[k]});
    std::map<std::array<int, 3>, Surface_patch_index> border_facets;
    for(std::size_t f = 0; f < facets_.size(); ++f) {
      // CGAL's key: the facet's vertices turned so that the smallest comes first
      std::array<int, 3> key{int(facets_[f][0]), int(facets_[f][1]), int(facets_[f][2])};
      std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
      border_facets[key] = Surface_patch_index(facet_patch_[f]);
      std::swap(key[1], key[2]);
      border_facets[key] = Surface_patch_index(facet_patch_[f]);
    }
    std::vector<Vertex_handle> vertices;
    Triangulation& tr = c3t3_.triangulation();
    std::vector<typename Triangulation::Point> weighted(points_.begin(), points_.end());
    // (not checked as a triangulation of the 3-sphere: with the infinite vertex on its boundary,
    // a mesh with handles or cavities is not one, and is fine for local changes, as in read_MEDIT())
    if(!CGAL::build_triangulation<Triangulation, true>(tr, weighted, cells, border_facets, vertices))
      throw std::invalid_argument("the tetrahedra do not form a valid triangulation");
    c3t3_.rescan_after_load_of_triangulation(); // counts the cells and surface facets
    // vertices: interior, then on a patch, on a curve, at a corner (vertices[0] is the infinite one)
    for(std::size_t k = 0; k < tets_.size(); ++k)
      for(std::size_t v : tets_[k]) {
        c3t3_.set_dimension(vertices[v + 1], 3);
        c3t3_.set_index(vertices[v + 1], domain_->index_from_subdomain_index(subdomain_[k]));
      }
    for(std::size_t f = 0; f < facets_.size(); ++f)
      for(std::size_t v : facets_[f]) {
        c3t3_.set_dimension(vertices[v + 1], 2);
        c3t3_.set_index(vertices[v + 1], domain_->index_from_surface_patch_index(facet_patch_[f]));
      }
    for(std::size_t l = 0; l < polylines_.size(); ++l) {
      const auto& line = polylines_[l];
      for(std::size_t i = 0; i + 1 < line.size(); ++i)
        c3t3_.add_to_complex(vertices[line[i] + 1], vertices[line[i + 1] + 1], curve_index_[l]);
      for(std::size_t v : line) {
        c3t3_.set_dimension(vertices[v + 1], 1);
        c3t3_.set_index(vertices[v + 1], domain_->index_from_curve_index(curve_index_[l]));
      }
    }
    for(std::size_t c = 0; c < copy_of_.size(); ++c) copied_[vertices[n_ + c + 1]] = vertices[copy_of_[c] + 1];
    std::vector<std::pair<typename Mesh_domain::Corner_index, Point_3>> corners;
    domain_->get_corners(std::back_inserter(corners));
    std::map<Point_3, typename Mesh_domain::Corner_index> corner_at;
    for(const auto& c : corners) corner_at.emplace(c.second, c.first);
    for(std::size_t v = 0; v < points_.size(); ++v) {
      const Vertex_handle vh = vertices[v + 1];
      const auto corner = corner_at.find(points_[v]);
      if(corner != corner_at.end() && c3t3_.in_dimension(vh) != 3) {
        c3t3_.add_to_complex(vh, corner->second);
        c3t3_.set_index(vh, domain_->index_from_corner_index(corner->second));
      }
    }
  }

  std::vector<Point_3> points_;
  std::vector<Tetrahedron> tets_;
  std::vector<std::size_t> pinched_;       // vertices where parts touch (split_pinched_vertices())
  std::vector<std::size_t> copy_of_;       // the vertex each copy, points_[n_ + c], copies
  std::size_t n_ = 0;                      // the number of vertices before the copies
  std::map<typename Triangulation::Vertex_handle, typename Triangulation::Vertex_handle> copied_; // copy -> vertex
  std::vector<int> subdomain_;
  std::vector<int> label_of_subdomain_;
  std::vector<Triangle> facets_;
  std::vector<std::pair<int, int>> facet_subdomains_;
  std::vector<int> facet_patch_;
  std::size_t number_of_patches_ = 0;
  std::vector<Edge> feature_edges_;
  std::vector<std::vector<std::size_t>> polylines_;
  std::vector<typename Mesh_domain::Curve_index> curve_index_;
  std::unique_ptr<Mesh_domain> domain_;
  C3T3 c3t3_;
};

} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_COMPLEX_FROM_TETRAHEDRA_3_H
