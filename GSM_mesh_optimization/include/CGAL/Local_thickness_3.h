// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The local thickness of the volume a closed triangle surface bounds, and the
// local gap between two parts of it that face each other across empty space.
// Both are measured by rays cast from points sampled on the surface, along the
// inward (thickness) or outward (gap) normal, counting only the surface parts
// that face back: a sharp edge's other side is not a wall. Where the surface has
// feature curves, also the width of the faces between two of them.

#ifndef CGAL_LOCAL_THICKNESS_3_H
#define CGAL_LOCAL_THICKNESS_3_H

#include <CGAL/VVM/internal/Parallel_for.h>
#include <CGAL/VVM/parameters.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Orthogonal_incremental_neighbor_search.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {

/*!
 * \ingroup PkgVVMSizing
 * The local thickness of the volume bounded by a closed triangle surface, and the local gap
 * between parts of the surface that face each other across the outside.
 *
 * The surface is sampled with points about `sample_spacing` apart (each face gets a number of
 * samples proportional to its area). From each sample, nine rays are cast in a cone around the
 * inward normal (thickness) and nine around the outward normal (gap): along the normal, four at a
 * quarter of the cone angle from it and four at half of it. The first surface point
 * each ray meets is kept if the surface there faces back, its normal within 60 degrees of the
 * opposite of the sample's normal. A ray that leaves through the other side of a sharp edge, or
 * meets nothing, is not kept. The sample's thickness (gap) is the median, over the kept rays, of
 * the distance travelled along the normal, when at least three rays were kept, and infinity
 * otherwise. A slab of thickness \f$ t \f$ thus has the thickness \f$ t \f$ exactly, and a tube
 * or a spherical shell the difference of their radii, up to the rays' spread.
 *
 * At any point, `thickness()` and `gap()` are those of the nearest sample.
 *
 * Feature curves (the edges of `edge_is_constrained_map`, e.g. the sharp edges found by
 * `Polygon_mesh_processing::detect_sharp_edges()` with the angle the mesh domain's features
 * are detected with) are sampled as well. The width at a feature sample is its straight
 * distance to the nearest feature curve that is far from it along the curves (the path along
 * the feature edges is more than ten times as long), across a face, the inside or the outside.
 * Two curves that meet at a corner are near each other unless their angle there is under 11.5
 * degrees: a face that tapers to a corner is left to the mesher's protection of the corner. A
 * narrow face between two feature curves,
 * e.g. a step or the end of a blade, holds a mesh no coarser than its width, since the curves'
 * vertices are kept: this width is to such faces what the thickness is to walls. It is not
 * measured beyond twice the thickness and the gap of the nearest surface sample (a wider face
 * does not set the size over a thinner wall) nor beyond a quarter of the bounding box's
 * diagonal.
 *
 * \tparam GeomTraits a model of `Kernel` with `double` coordinates (default:
 *   `Exact_predicates_inexact_constructions_kernel`)
 */
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel>
class Local_thickness_3
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename Geom_traits::Point_3 Point_3;
  typedef typename Geom_traits::Vector_3 Vector_3;

  /// a point of the surface and what the rays cast from it met
  struct Sample
  {
    Point_3 point;    ///< on the surface
    Vector_3 normal;  ///< the unit outward normal of its face
    double thickness; ///< across the inside; infinity if no wall faces back
    double gap;       ///< across the outside; infinity if nothing faces back
  };

  /// a point of a feature curve and the nearest point of another feature curve
  struct Feature_sample
  {
    Point_3 point;  ///< on a feature edge
    Point_3 facing; ///< the nearest point of a feature curve far from `point` along the curves,
                    ///< or `point` if there is none within reach
    double width;   ///< the distance from `point` to `facing`; infinity if none is within reach
    double length;  ///< the length of the feature edge's piece the sample stands for
  };

  /*!
   * samples `tm` and casts the rays.
   *
   * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles (and of
   *   `EdgeListGraph` and `VertexListGraph` with `edge_is_constrained_map`)
   * \tparam NamedParameters a sequence of named parameters
   *
   * \param tm a closed triangle surface, consistently oriented (either way), bounding a volume
   * \param np an optional sequence of named parameters among the ones listed below
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{vertex_point_map}
   *     \cgalParamDescription{the positions of the vertices of `tm`}
   *     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{sample_spacing}
   *     \cgalParamDescription{the distance between two samples (`CGAL::VVM::parameters`)}
   *     \cgalParamType{`double`}
   *     \cgalParamDefault{the spacing that gives about 20,000 samples}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{edge_is_constrained_map}
   *     \cgalParamDescription{the feature edges of `tm`, whose faces' widths are measured}
   *     \cgalParamType{a class model of `ReadablePropertyMap` with
   *       `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool` as value type}
   *     \cgalParamDefault{no edge is a feature edge}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{vertex_index_map}
   *     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index
   *       between `0` and `num_vertices(tm) - 1`, used with `edge_is_constrained_map`}
   *     \cgalParamDefault{an automatically indexed internal map}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{cone_angle}
   *     \cgalParamDescription{the opening angle of the cone of rays, in degrees, in (0, 120]
   *       (`CGAL::VVM::parameters`)}
   *     \cgalParamType{`double`}
   *     \cgalParamDefault{40}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * \throws std::invalid_argument if `tm` has no face, a face that is not a triangle, a border
   *   edge, a coordinate that is not finite, or no volume; or if the spacing is not positive or
   *   gives more than 20 million samples; or if the cone angle is out of range
   */
  template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Local_thickness_3(const TriangleMesh& tm,
                             const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, tm));
    const double cone_degrees = choose_parameter(get_parameter(np, VVM::internal_np::cone_angle), 40.);
    if(!(cone_degrees > 0 && cone_degrees <= 120))
      throw std::invalid_argument("Local_thickness_3: the cone angle must be in (0, 120] degrees");

    read_triangles(tm, vpm);
    const double area = std::accumulate(areas_.begin(), areas_.end(), 0.);
    spacing_ = choose_parameter(get_parameter(np, VVM::internal_np::sample_spacing), std::sqrt(area / 20000.));
    if(!(spacing_ > 0) || !std::isfinite(spacing_))
      throw std::invalid_argument("Local_thickness_3: the sample spacing must be positive and finite");
    if(area / (spacing_ * spacing_) > 2e7)
      throw std::invalid_argument("Local_thickness_3: the sample spacing " + std::to_string(spacing_) +
                                  " would give more than 20 million samples");
    sample_faces();
    cast_rays(cone_degrees * CGAL_PI / 180.);
    build_search_tree();
    if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value) {
      read_feature_edges(tm, vpm, get_parameter(np, CGAL::internal_np::edge_is_constrained),
                         CGAL::get_initialized_vertex_index_map(tm, np));
      measure_feature_widths();
    }
  }

  /// the samples, with their thickness and gap
  const std::vector<Sample>& samples() const { return samples_; }
  /// the samples of the feature curves, with their widths (none without `edge_is_constrained_map`)
  const std::vector<Feature_sample>& feature_samples() const { return feature_samples_; }
  /// the distance between two samples
  double sample_spacing() const { return spacing_; }
  /// the bounding box of the surface
  const Bbox_3& bbox() const { return bbox_; }

  /// the thickness of the nearest sample: the width of the inside there, or infinity
  double thickness(const Point_3& p) const { return samples_[nearest_sample(p)].thickness; }
  /// the gap of the nearest sample: the width of the outside there, or infinity
  double gap(const Point_3& p) const { return samples_[nearest_sample(p)].gap; }
  /// the index in `samples()` of the sample nearest to `p`
  std::size_t nearest_sample(const Point_3& p) const
  {
    Neighbor_search search(*search_tree_, p, 1, 0, true, Distance(point_map()));
    return search.begin()->first;
  }

private:
  typedef std::vector<typename Geom_traits::Triangle_3> Triangles;
  typedef typename Triangles::const_iterator Triangle_iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Geom_traits, CGAL::AABB_triangle_primitive<Geom_traits, Triangle_iterator>>>
      Triangle_tree;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Sample_point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Sample_point_map, CGAL::Search_traits_3<Geom_traits>> Search_traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Search_traits> Neighbor_search;
  typedef typename Neighbor_search::Tree Search_tree;
  typedef typename Neighbor_search::Distance Distance;
  typedef CGAL::Orthogonal_incremental_neighbor_search<Search_traits> Incremental_search;
  static_assert(std::is_same<typename Incremental_search::Tree, Search_tree>::value, "one kd-tree type for both searches");

  template <class TriangleMesh, class VertexPointMap>
  void read_triangles(const TriangleMesh& tm, const VertexPointMap& vpm)
  {
    if(faces(tm).empty()) throw std::invalid_argument("Local_thickness_3: the surface has no face");
    if(!CGAL::is_triangle_mesh(tm))
      throw std::invalid_argument("Local_thickness_3: the surface has a face that is not a triangle");
    if(!CGAL::is_closed(tm))
      throw std::invalid_argument("Local_thickness_3: the surface is not closed (it has border edges), "
                                  "so it bounds no volume");
    double six_volume = 0;
    for(auto f : faces(tm)) {
      Point_3 p[3];
      int i = 0;
      for(auto v : vertices_around_face(halfedge(f, tm), tm)) {
        const auto& q = get(vpm, v);
        p[i] = Point_3(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
        if(!std::isfinite(p[i].x()) || !std::isfinite(p[i].y()) || !std::isfinite(p[i].z()))
          throw std::invalid_argument("Local_thickness_3: the surface has a vertex whose coordinates are not finite");
        ++i;
      }
      triangles_.emplace_back(p[0], p[1], p[2]);
      const Vector_3 n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
      const double length = std::sqrt(n.squared_length());
      areas_.push_back(0.5 * length);
      normals_.push_back(length > 0 ? n / length : Vector_3(0, 0, 0));
      six_volume += CGAL::determinant(p[0] - CGAL::ORIGIN, p[1] - CGAL::ORIGIN, p[2] - CGAL::ORIGIN);
      bbox_ += triangles_.back().bbox();
    }
    const double diagonal = std::sqrt(CGAL::square(bbox_.x_span()) + CGAL::square(bbox_.y_span()) +
                                      CGAL::square(bbox_.z_span()));
    if(!(std::abs(six_volume) > 1e-12 * diagonal * diagonal * diagonal))
      throw std::invalid_argument("Local_thickness_3: the surface bounds no volume");
    if(six_volume < 0) // oriented inward: the normals are made to point outward
      for(Vector_3& n : normals_) n = -n;
  }

  // each face gets floor(its area / spacing^2 + the carry) samples, spread by a low-discrepancy
  // sequence starting at its centroid: the count follows the area whatever the faces' shapes
  void sample_faces()
  {
    const double per_area = 1. / (spacing_ * spacing_);
    double carry = 0.5;
    for(std::size_t f = 0; f < triangles_.size(); ++f) {
      const double expected = areas_[f] * per_area + carry;
      const std::size_t n = std::size_t(expected);
      carry = expected - double(n);
      const Point_3& a = triangles_[f].vertex(0);
      const Vector_3 u = triangles_[f].vertex(1) - a, v = triangles_[f].vertex(2) - a;
      for(std::size_t k = 0; k < n; ++k) {
        // the R2 sequence (the plastic number's powers), folded into the triangle
        double s = std::fmod(1. / 3. + 0.7548776662466927 * double(k), 1.);
        double t = std::fmod(1. / 3. + 0.5698402909980532 * double(k), 1.);
        if(s + t > 1) {
          s = 1 - s;
          t = 1 - t;
        }
        samples_.push_back(Sample{a + s * u + t * v, normals_[f], 0., 0.});
        sample_faces_.push_back(f);
      }
    }
    if(samples_.empty()) throw std::invalid_argument("Local_thickness_3: the surface has no area");
  }

  void cast_rays(double cone_angle)
  {
    Triangle_tree tree(triangles_.begin(), triangles_.end());
    tree.build();
    VVM::internal::parallel_for_ranges(
        samples_.size(), 64, [&](const VVM::internal::Index_range& range) {
          std::vector<double> kept;
          for(std::size_t i = range.begin(); i != range.end(); ++i) {
            Sample& s = samples_[i];
            const Triangle_iterator face = triangles_.begin() + std::ptrdiff_t(sample_faces_[i]);
            for(int side = 0; side < 2; ++side) { // 0: inward (thickness), 1: outward (gap)
              const Vector_3 axis = side == 0 ? -s.normal : s.normal;
              const Vector_3 u = unit_orthogonal(axis), v = CGAL::cross_product(axis, u);
              kept.clear();
              for(int r = 0; r < 9; ++r) {
                const Vector_3 d = r == 0 ? axis : ray_direction(axis, u, v, r, cone_angle);
                const auto hit = tree.first_intersection(typename Geom_traits::Ray_3(s.point, d),
                                                         [face](const Triangle_iterator& t) { return t == face; });
                if(!hit) continue;
                const Point_3* q = boost::get<Point_3>(&hit->first);
                if(q == nullptr) continue; // the ray runs inside a face
                const Vector_3& n = normals_[std::size_t(hit->second - triangles_.begin())];
                if(n * s.normal > -0.5) continue; // not facing back: across a sharp edge, or a side wall
                kept.push_back(std::abs((*q - s.point) * s.normal));
              }
              double width = std::numeric_limits<double>::infinity();
              if(kept.size() >= 3) {
                std::nth_element(kept.begin(), kept.begin() + std::ptrdiff_t(kept.size() / 2), kept.end());
                width = kept[kept.size() / 2];
              }
              (side == 0 ? s.thickness : s.gap) = width;
            }
          }
        });
  }

  // rays 1-4 at a quarter of the cone angle from the axis, 5-8 at half of it, between them:
  // the median of the nine lengths comes from the axis or the inner ring, near the normal
  static Vector_3 ray_direction(const Vector_3& axis, const Vector_3& u, const Vector_3& v, int r, double cone_angle)
  {
    const bool outer = r > 4;
    const double tilt = outer ? cone_angle / 2 : cone_angle / 4;
    const double phi = CGAL_PI / 2 * (r - 1) + (outer ? CGAL_PI / 4 : 0.);
    return std::cos(tilt) * axis + std::sin(tilt) * (std::cos(phi) * u + std::sin(phi) * v);
  }

  template <class TriangleMesh, class VertexPointMap, class EdgeIsFeatureMap, class VertexIndexMap>
  void read_feature_edges(const TriangleMesh& tm, const VertexPointMap& vpm, const EdgeIsFeatureMap& is_feature,
                          const VertexIndexMap& vertex_index)
  {
    const std::size_t none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> node_of(num_vertices(tm), none);
    std::map<std::array<double, 3>, std::size_t> node_at; // vertices at one place are one node
    auto node = [&](typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) {
      std::size_t& n = node_of[std::size_t(get(vertex_index, v))];
      if(n == none) {
        const auto& q = get(vpm, v);
        const std::array<double, 3> x = {CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
        const auto inserted = node_at.emplace(x, feature_nodes_.size());
        n = inserted.first->second;
        if(inserted.second) {
          feature_nodes_.emplace_back(x[0], x[1], x[2]);
          feature_adjacency_.emplace_back();
        }
      }
      return n;
    };
    for(auto e : edges(tm)) {
      if(!get(is_feature, e)) continue;
      const std::size_t a = node(source(e, tm)), b = node(target(e, tm));
      if(a == b) continue;
      const double length = std::sqrt(CGAL::squared_distance(feature_nodes_[a], feature_nodes_[b]));
      feature_adjacency_[a].push_back({b, length});
      feature_adjacency_[b].push_back({a, length});
      feature_edges_.push_back({a, b});
    }
  }

  // a point of another feature curve is far from a sample along the curves when the path
  // between them along the feature edges is more than this times the straight distance (with
  // 4, corners under 29 degrees, the tapering faces of ordinary corners counted as narrow)
  static constexpr double detour_ratio = 10;

  // the feature edges cut into pieces at most half a sample spacing long, one sample in the
  // middle of each; for each sample, the nearest piece (by increasing distance) whose sample is
  // far from it along the curves (a lazy Dijkstra from the sample, run as far as the straight
  // distance asks)
  void measure_feature_widths()
  {
    struct Piece { std::size_t edge; double t, half; }; // edge parameter of the middle, half extent
    std::vector<Piece> pieces;
    for(std::size_t e = 0; e < feature_edges_.size(); ++e) {
      const Point_3 &a = feature_nodes_[feature_edges_[e].first], &b = feature_nodes_[feature_edges_[e].second];
      const double length = std::sqrt(CGAL::squared_distance(a, b));
      const std::size_t n = (std::max)(std::size_t(1), std::size_t(std::ceil(2 * length / spacing_)));
      for(std::size_t k = 0; k < n; ++k) {
        const double t = (double(k) + 0.5) / double(n);
        pieces.push_back({e, t, 0.5 / double(n)});
        feature_samples_.push_back(Feature_sample{a + t * (b - a), a + t * (b - a),
                                                  std::numeric_limits<double>::infinity(), length / double(n)});
      }
    }
    if(pieces.empty()) return;
    std::vector<Point_3> points;
    for(const Feature_sample& s : feature_samples_) points.push_back(s.point);
    std::vector<std::size_t> indices(points.size());
    std::iota(indices.begin(), indices.end(), std::size_t(0));
    const Sample_point_map point_map(points.data());
    Search_tree tree(indices.begin(), indices.end(), typename Search_tree::Splitter(), Search_traits(point_map));
    tree.build();
    const double diagonal = std::sqrt(CGAL::square(bbox_.x_span()) + CGAL::square(bbox_.y_span()) +
                                      CGAL::square(bbox_.z_span()));
    // a face wider than the wall or the gap under it does not set the size
    auto reach_at = [&](const Point_3& p) {
      const Sample& nearest = samples_[nearest_sample(p)];
      return (std::min)(diagonal / 4, 2 * (std::min)(nearest.thickness, nearest.gap));
    };
    const double touching = 1e-12 * diagonal;
    auto edge_length = [&](std::size_t e) {
      return std::sqrt(CGAL::squared_distance(feature_nodes_[feature_edges_[e].first], feature_nodes_[feature_edges_[e].second]));
    };
    VVM::internal::parallel_for_ranges(
        pieces.size(), 16, [&](const VVM::internal::Index_range& range) {
          typedef std::pair<double, std::size_t> Entry;
          for(std::size_t i = range.begin(); i != range.end(); ++i) {
            const Piece& mine = pieces[i];
            const Point_3& p = points[i];
            // the distance along the feature edges from p to the nodes settled so far (all those
            // within the radius of the last settle_up_to call)
            std::unordered_map<std::size_t, double> along;
            std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> front;
            const double my_length = edge_length(mine.edge);
            const auto& my_edge = feature_edges_[mine.edge];
            front.push({mine.t * my_length, my_edge.first});
            front.push({(1 - mine.t) * my_length, my_edge.second});
            auto settle_up_to = [&](double radius) {
              while(!front.empty() && front.top().first <= radius) {
                const Entry top = front.top();
                front.pop();
                auto found = along.find(top.second);
                if(found != along.end() && found->second <= top.first) continue;
                along[top.second] = top.first;
                for(const auto& next : feature_adjacency_[top.second]) {
                  auto known = along.find(next.first);
                  if(known == along.end() || known->second > top.first + next.second)
                    front.push({top.first + next.second, next.first});
                }
              }
            };
            auto distance_along = [&](const Piece& q) {
              const double length = edge_length(q.edge);
              if(q.edge == mine.edge) return std::abs(q.t - mine.t) * length;
              double d = std::numeric_limits<double>::infinity();
              const auto& edge = feature_edges_[q.edge];
              auto a = along.find(edge.first), b = along.find(edge.second);
              if(a != along.end()) d = (std::min)(d, a->second + q.t * length);
              if(b != along.end()) d = (std::min)(d, b->second + (1 - q.t) * length);
              return d;
            };
            Feature_sample& result = feature_samples_[i];
            const double reach = reach_at(p);
            Incremental_search search(tree, p, 0, true, Distance(point_map));
            for(auto it = search.begin(); it != search.end(); ++it) {
              const double straight = std::sqrt(it->second);
              if(straight > reach || straight - spacing_ / 2 > result.width) break;
              const Piece& q = pieces[it->first];
              settle_up_to(detour_ratio * straight);
              if(distance_along(q) <= detour_ratio * straight) continue;
              // the point of q's piece nearest to p
              const Point_3 &a = feature_nodes_[feature_edges_[q.edge].first],
                            &b = feature_nodes_[feature_edges_[q.edge].second];
              const Vector_3 ab = b - a;
              const double t = std::clamp(((p - a) * ab) / (std::max)(ab.squared_length(), 1e-300),
                                          q.t - q.half, q.t + q.half);
              const Point_3 nearest = a + t * ab;
              const double width = std::sqrt(CGAL::squared_distance(p, nearest));
              if(width > touching && width < result.width) { // curves that touch (an input defect) are no face
                result.width = width;
                result.facing = nearest;
              }
            }
          }
        });
  }

  static Vector_3 unit_orthogonal(const Vector_3& n)
  {
    const Vector_3 e = std::abs(n.x()) < 0.6 ? Vector_3(1, 0, 0) : Vector_3(0, 1, 0);
    const Vector_3 u = CGAL::cross_product(n, e);
    return u / std::sqrt(u.squared_length());
  }

  Sample_point_map point_map() const { return Sample_point_map(points_->data()); }

  void build_search_tree()
  {
    points_ = std::make_shared<std::vector<Point_3>>();
    points_->reserve(samples_.size());
    for(const Sample& s : samples_) points_->push_back(s.point);
    std::vector<std::size_t> indices(samples_.size());
    std::iota(indices.begin(), indices.end(), std::size_t(0));
    search_tree_ = std::make_shared<Search_tree>(indices.begin(), indices.end(), typename Search_tree::Splitter(),
                                                 Search_traits(point_map()));
    search_tree_->build();
  }

  Triangles triangles_;
  std::vector<double> areas_;
  std::vector<Vector_3> normals_; // unit, outward; zero on a degenerate face
  Bbox_3 bbox_;
  double spacing_ = 0;
  std::vector<Sample> samples_;
  std::vector<std::size_t> sample_faces_;
  // shared by copies: the search tree refers to the points
  std::shared_ptr<std::vector<Point_3>> points_;
  std::shared_ptr<Search_tree> search_tree_;
  // the feature curves: their vertices, edges (pairs of vertices) and adjacency (vertex, length)
  std::vector<Point_3> feature_nodes_;
  std::vector<std::pair<std::size_t, std::size_t>> feature_edges_;
  std::vector<std::vector<std::pair<std::size_t, double>>> feature_adjacency_;
  std::vector<Feature_sample> feature_samples_;
};

} // namespace CGAL

#endif // CGAL_LOCAL_THICKNESS_3_H
