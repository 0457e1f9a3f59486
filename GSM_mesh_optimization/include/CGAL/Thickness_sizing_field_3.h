// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mesh size that puts a given number of cells across every wall and gap of a
// domain and grows away from them at a bounded rate: the min of the cones
// h_s + g |x - s| over the surface samples s, kept on a regular grid.

#ifndef CGAL_THICKNESS_SIZING_FIELD_3_H
#define CGAL_THICKNESS_SIZING_FIELD_3_H

#include <CGAL/Local_thickness_3.h>
#include <CGAL/VVM/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {

/*!
 * \ingroup PkgVVMSizing
 * A sizing field from the local thickness of a domain: at a sample \f$ s \f$ of the surface
 * whose thickness or gap (the smaller) is \f$ w_s \f$, the size is
 * \f$ h_s = \min(h_{max}, \max(h_{min}, w_s / k)) \f$, \f$ k \f$ cells across, on the whole
 * segment \f$ \sigma_s \f$ across the wall (the sample alone if the gap is the smaller),
 * thickened by the samples' spacing \f$ r \f$ (a sample stands for the surface around it);
 * everywhere the size is \f$ h(x) = \min(h_{max}, \min_s (h_s + g \max(0, d(x, \sigma_s) - r))) \f$,
 * so that it grows by at most the gradation \f$ g \f$ times the distance. The samples of the
 * feature curves (`Local_thickness_3::feature_samples()`) are cones too: \f$ w_s \f$ is the
 * width of the face between two feature curves, on the segment joining them. \f$ h \f$ is computed on a regular grid (the cones
 * propagated from node to node, as a chamfer distance) and interpolated trilinearly in between;
 * the bound on its growth holds between points a few grid cells apart.
 *
 * It is a model of Mesh_3's sizing field (`operator()(p, dimension, index)`), to be passed as
 * `edge_size`, `facet_size` and `cell_size` of `Mesh_criteria_3`, and a callable `double(p)`,
 * to be passed as GSM's `sizing_field` (and, scaled, as the lattice meshers' frame field's
 * scale: `Frame_fields::Scaled_frame_field_3`). Copies share the grid.
 *
 * \tparam GeomTraits the traits of the `Local_thickness_3` it is made from
 */
template <class GeomTraits = Exact_predicates_inexact_constructions_kernel>
class Thickness_sizing_field_3
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename Geom_traits::Point_3 Point_3;

  /*!
   * computes the size on a grid over the bounding box of `thickness`'s surface.
   *
   * \param thickness the local thickness of the domain's boundary surface
   * \param np an optional sequence of named parameters among the ones listed below
   *   (`CGAL::VVM::parameters`, except `grid_spacing`: `CGAL::parameters`)
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{cells_across}
   *     \cgalParamDescription{\f$ k \f$, the number of cells across a wall or a gap, positive}
   *     \cgalParamType{`double`}
   *     \cgalParamDefault{3}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{minimum_size}
   *     \cgalParamDescription{\f$ h_{min} \f$, positive}
   *     \cgalParamType{`double`}
   *     \cgalParamDefault{the bounding box's diagonal / 1000}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{maximum_size}
   *     \cgalParamDescription{\f$ h_{max} \f$, at least \f$ h_{min} \f$}
   *     \cgalParamType{`double`}
   *     \cgalParamDefault{the bounding box's diagonal / 10}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{gradation}
   *     \cgalParamDescription{\f$ g \f$, positive}
   *     \cgalParamType{`double`}
   *     \cgalParamDefault{0.3}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{grid_spacing}
   *     \cgalParamDescription{the spacing of the grid}
   *     \cgalParamType{`double`}
   *     \cgalParamDefault{half the smallest sample size, or larger to keep the grid under
   *       \f$ 2^{21} \f$ nodes}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * \throws std::invalid_argument if a parameter is out of range, or the grid would have more
   *   than \f$ 2^{27} \f$ nodes
   */
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Thickness_sizing_field_3(const Local_thickness_3<Geom_traits>& thickness,
                                    const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const Bbox_3& box = thickness.bbox();
    const double diagonal =
        std::sqrt(CGAL::square(box.x_span()) + CGAL::square(box.y_span()) + CGAL::square(box.z_span()));
    cells_across_ = choose_parameter(get_parameter(np, VVM::internal_np::cells_across), 3.);
    min_size_ = choose_parameter(get_parameter(np, VVM::internal_np::minimum_size), diagonal / 1000);
    max_size_ = choose_parameter(get_parameter(np, VVM::internal_np::maximum_size), diagonal / 10);
    gradation_ = choose_parameter(get_parameter(np, VVM::internal_np::gradation), 0.3);
    if(!(cells_across_ > 0) || !std::isfinite(cells_across_))
      throw std::invalid_argument("Thickness_sizing_field_3: cells_across must be positive and finite");
    if(!(min_size_ > 0) || !std::isfinite(min_size_))
      throw std::invalid_argument("Thickness_sizing_field_3: minimum_size must be positive and finite");
    if(!(max_size_ >= min_size_) || !std::isfinite(max_size_))
      throw std::invalid_argument("Thickness_sizing_field_3: maximum_size must be finite and at least minimum_size");
    if(!(gradation_ > 0) || !std::isfinite(gradation_))
      throw std::invalid_argument("Thickness_sizing_field_3: gradation must be positive and finite");

    std::vector<double> sample_sizes, feature_sizes;
    double smallest = max_size_;
    for(const auto& s : thickness.samples()) {
      const double width = (std::min)(s.thickness, s.gap);
      sample_sizes.push_back(std::clamp(width / cells_across_, min_size_, max_size_));
      smallest = (std::min)(smallest, sample_sizes.back());
    }
    for(const auto& s : thickness.feature_samples()) {
      feature_sizes.push_back(std::clamp(s.width / cells_across_, min_size_, max_size_));
      smallest = (std::min)(smallest, feature_sizes.back());
    }
    const double box_volume = (box.x_span() + 1e-9 * diagonal) * (box.y_span() + 1e-9 * diagonal) *
                              (box.z_span() + 1e-9 * diagonal);
    spacing_ = choose_parameter(get_parameter(np, CGAL::internal_np::grid_spacing),
                                (std::max)(0.5 * smallest, std::cbrt(box_volume / double(1 << 21))));
    if(!(spacing_ > 0) || !std::isfinite(spacing_))
      throw std::invalid_argument("Thickness_sizing_field_3: grid_spacing must be positive and finite");
    auto grid = std::make_shared<Grid>();
    const double lower[3] = {box.xmin(), box.ymin(), box.zmin()}, upper[3] = {box.xmax(), box.ymax(), box.zmax()};
    double nodes = 1;
    for(int a = 0; a < 3; ++a) { // two cells of margin on each side
      grid->origin[a] = lower[a] - 2 * spacing_;
      grid->size[a] = std::size_t(std::ceil((upper[a] - lower[a]) / spacing_)) + 5;
      nodes *= double(grid->size[a]);
    }
    if(nodes > double(1 << 27))
      throw std::invalid_argument("Thickness_sizing_field_3: the grid spacing " + std::to_string(spacing_) +
                                  " would give more than 2^27 grid nodes");
    grid->spacing = spacing_;
    grid->values.assign(std::size_t(nodes), float(max_size_));
    seed_cones(*grid, thickness, sample_sizes);
    seed_feature_cones(*grid, thickness, feature_sizes);
    propagate_cones(*grid);
    grid_ = grid;
    std::vector<double> on_surface;
    for(const auto& s : thickness.samples()) on_surface.push_back(grid_->interpolate(s.point.x(), s.point.y(), s.point.z()));
    std::nth_element(on_surface.begin(), on_surface.begin() + std::ptrdiff_t(on_surface.size() / 2), on_surface.end());
    typical_size_ = on_surface[on_surface.size() / 2];
  }

  /// the size at `p`, a `Point_3` or any point whose coordinates are `p[0]`, `p[1]`, `p[2]`
  /// (e.g. `Eigen::Vector3d`, as GSM's `sizing_field` is called)
  template <class Point>
  double operator()(const Point& p) const
  {
    return scale_ * grid_->interpolate(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
  }

  /// the size at `p`, as Mesh_3's sizing fields are called
  template <class Index>
  FT operator()(const Point_3& p, int /*dimension*/, const Index& /*index*/) const
  {
    return FT((*this)(p));
  }

  /// the same field with every size multiplied by `factor` (e.g. to reach a number of vertices)
  Thickness_sizing_field_3 scaled(double factor) const
  {
    if(!(factor > 0) || !std::isfinite(factor))
      throw std::invalid_argument("Thickness_sizing_field_3: the scale factor must be positive and finite");
    Thickness_sizing_field_3 f = *this;
    f.scale_ *= factor;
    return f;
  }

  /// the median size over the surface's samples: what a uniform size of the same density is
  /// compared with, e.g. to scale the field to a uniform size \f$ s \f$ by `scaled(s / typical_size())`
  double typical_size() const { return scale_ * typical_size_; }
  double cells_across() const { return cells_across_; }
  double minimum_size() const { return scale_ * min_size_; }
  double maximum_size() const { return scale_ * max_size_; }
  double gradation() const { return gradation_; }
  double grid_spacing() const { return spacing_; }

private:
  struct Grid
  {
    double origin[3];
    std::size_t size[3];
    double spacing;
    std::vector<float> values; // x fastest

    std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return i + size[0] * (j + size[1] * k); }

    double interpolate(double x, double y, double z) const
    {
      const double p[3] = {x, y, z};
      std::size_t cell[3];
      double t[3];
      for(int a = 0; a < 3; ++a) {
        const double u = std::clamp((p[a] - origin[a]) / spacing, 0., double(size[a] - 1));
        cell[a] = (std::min)(std::size_t(u), size[a] - 2);
        t[a] = u - double(cell[a]);
      }
      double h = 0;
      for(int corner = 0; corner < 8; ++corner) {
        double w = 1;
        std::size_t c[3];
        for(int a = 0; a < 3; ++a) {
          const bool up = (corner >> a) & 1;
          c[a] = cell[a] + (up ? 1 : 0);
          w *= up ? t[a] : 1 - t[a];
        }
        h += w * double(values[index(c[0], c[1], c[2])]);
      }
      return h;
    }
  };

  // each sample's cone, at the nodes around the points of its apex: the segment across the
  // wall when the size comes from the thickness (the wall's middle is as thin as its sides), the
  // sample alone when it comes from the gap. A sample stands for the surface around it, so the
  // apex is thickened by the samples' spacing: the cones of neighbouring samples overlap, and
  // the size does not rise between them
  void seed_cones(Grid& grid, const Local_thickness_3<Geom_traits>& thickness,
                  const std::vector<double>& sample_sizes) const
  {
    const auto& samples = thickness.samples();
    const double radius = thickness.sample_spacing();
    for(std::size_t s = 0; s < samples.size(); ++s) {
      if(!(sample_sizes[s] < max_size_)) continue;
      const auto& sample = samples[s];
      const double across = sample.thickness <= sample.gap ? sample.thickness : 0.;
      const int steps = int(std::ceil((std::min)(32., across / (std::max)(grid.spacing, radius))));
      for(int step = 0; step <= steps; ++step) {
        const double depth = steps == 0 ? 0. : across * step / steps;
        const double p[3] = {sample.point.x() - depth * sample.normal.x(), sample.point.y() - depth * sample.normal.y(),
                             sample.point.z() - depth * sample.normal.z()};
        seed_cone(grid, p, radius, sample_sizes[s]);
      }
    }
  }

  // each feature sample's cone, on the segment across the face to the facing curve; the apex
  // thickened by half the piece of feature edge the sample stands for
  void seed_feature_cones(Grid& grid, const Local_thickness_3<Geom_traits>& thickness,
                          const std::vector<double>& sizes) const
  {
    const auto& samples = thickness.feature_samples();
    for(std::size_t s = 0; s < samples.size(); ++s) {
      if(!(sizes[s] < max_size_)) continue;
      const auto& sample = samples[s];
      const int steps = int(std::ceil((std::min)(32., sample.width / (std::max)(grid.spacing, sample.length))));
      for(int step = 0; step <= steps; ++step) {
        const double t = steps == 0 ? 0. : double(step) / steps;
        const double p[3] = {sample.point.x() + t * (sample.facing.x() - sample.point.x()),
                             sample.point.y() + t * (sample.facing.y() - sample.point.y()),
                             sample.point.z() + t * (sample.facing.z() - sample.point.z())};
        seed_cone(grid, p, sample.length / 2, sizes[s]);
      }
    }
  }

  // size + g max(0, |x - p| - radius) at the nodes x of the block around the ball
  void seed_cone(Grid& grid, const double (&p)[3], double radius, double size) const
  {
    const long reach = long(std::ceil(radius / grid.spacing)) + 1;
    long first[3];
    for(int a = 0; a < 3; ++a) first[a] = long(std::floor((p[a] - grid.origin[a]) / grid.spacing)) - reach + 1;
    for(long k = first[2]; k < first[2] + 2 * reach; ++k)
      for(long j = first[1]; j < first[1] + 2 * reach; ++j)
        for(long i = first[0]; i < first[0] + 2 * reach; ++i) {
          if(i < 0 || j < 0 || k < 0 || i >= long(grid.size[0]) || j >= long(grid.size[1]) || k >= long(grid.size[2]))
            continue;
          const double dx = grid.origin[0] + double(i) * grid.spacing - p[0],
                       dy = grid.origin[1] + double(j) * grid.spacing - p[1],
                       dz = grid.origin[2] + double(k) * grid.spacing - p[2];
          const double beyond = (std::max)(0., std::sqrt(dx * dx + dy * dy + dz * dz) - radius);
          float& value = grid.values[grid.index(std::size_t(i), std::size_t(j), std::size_t(k))];
          value = (std::min)(value, float(size + gradation_ * beyond));
        }
  }

  // value(node) <= value(neighbour) + g |node - neighbour| over the 26 neighbours: forward and
  // backward raster sweeps until nothing changes
  void propagate_cones(Grid& grid) const
  {
    struct Offset { int di, dj, dk; float step; };
    std::vector<Offset> before; // the 13 neighbours a forward sweep has already visited
    for(int dk = -1; dk <= 1; ++dk)
      for(int dj = -1; dj <= 1; ++dj)
        for(int di = -1; di <= 1; ++di)
          if(dk < 0 || (dk == 0 && (dj < 0 || (dj == 0 && di < 0))))
            before.push_back({di, dj, dk, float(gradation_ * grid.spacing * std::sqrt(double(di * di + dj * dj + dk * dk)))});
    const long n[3] = {long(grid.size[0]), long(grid.size[1]), long(grid.size[2])};
    for(int sweep = 0, unchanged = 0; sweep < 16 && unchanged < 2; ++sweep) {
      bool changed = false;
      const int direction = sweep % 2 == 0 ? 1 : -1;
      for(long kk = 0; kk < n[2]; ++kk)
        for(long jj = 0; jj < n[1]; ++jj)
          for(long ii = 0; ii < n[0]; ++ii) {
            const long i = direction > 0 ? ii : n[0] - 1 - ii, j = direction > 0 ? jj : n[1] - 1 - jj,
                       k = direction > 0 ? kk : n[2] - 1 - kk;
            float& value = grid.values[grid.index(std::size_t(i), std::size_t(j), std::size_t(k))];
            for(const Offset& o : before) {
              const long ni = i + direction * o.di, nj = j + direction * o.dj, nk = k + direction * o.dk;
              if(ni < 0 || nj < 0 || nk < 0 || ni >= n[0] || nj >= n[1] || nk >= n[2]) continue;
              const float candidate = grid.values[grid.index(std::size_t(ni), std::size_t(nj), std::size_t(nk))] + o.step;
              if(candidate < value) {
                value = candidate;
                changed = true;
              }
            }
          }
      unchanged = changed ? 0 : unchanged + 1; // a forward and a backward sweep that change nothing
    }
  }

  double cells_across_ = 3, min_size_ = 0, max_size_ = 0, gradation_ = 0.3, spacing_ = 0, scale_ = 1, typical_size_ = 0;
  std::shared_ptr<const Grid> grid_;
};

} // namespace CGAL

#endif // CGAL_THICKNESS_SIZING_FIELD_3_H
