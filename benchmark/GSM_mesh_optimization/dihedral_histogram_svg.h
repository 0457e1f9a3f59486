// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A dihedral-angle histogram as a self-contained SVG picture: all dihedral
// angles in one-degree bins (grey) and, in front, the smallest angle of each
// tet (red), on a square-root scale so that the few slivers stay visible.

#ifndef VVM_BENCHMARK_DIHEDRAL_HISTOGRAM_SVG_H
#define VVM_BENCHMARK_DIHEDRAL_HISTOGRAM_SVG_H

#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

namespace vvm_benchmark {

inline void write_dihedral_histogram_svg(std::ostream& os, const std::string& title,
                                         const CGAL::GSM_mesh_optimization::Mesh_quality_statistics& q)
{
  const double width = 720, height = 370, left = 60, right = 20, top = 50, bottom = 50;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  std::size_t max_count = 1;
  for(std::size_t c : q.dihedral_angle_histogram) max_count = (std::max)(max_count, c);
  auto bar_height = [&](std::size_t c) { return plot_h * std::sqrt(double(c) / double(max_count)); };
  const double bin_w = plot_w / 180.;

  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
     << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
     << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
     << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\">" << title << "</text>\n";
  os.precision(4);
  os << "<text x=\"" << left << "\" y=\"38\">tets " << q.number_of_cells << ", min dihedral "
     << q.min_dihedral_angle << ", max " << q.max_dihedral_angle << ", tets with min &lt; 30: "
     << q.n_min_dihedral_below[2] << "</text>\n"
     << "<text x=\"" << left + plot_w << "\" y=\"" << top + 12
     << "\" text-anchor=\"end\">grey: all dihedral angles; red: smallest angle of each tet</text>\n"
     << "<text x=\"" << left + plot_w << "\" y=\"" << top + 28
     << "\" text-anchor=\"end\">count on a square-root scale</text>\n";
  for(int pass = 0; pass < 2; ++pass) {
    const auto& h = pass == 0 ? q.dihedral_angle_histogram : q.min_dihedral_angle_histogram;
    const char* colour = pass == 0 ? "#9a9a9a" : "#d62728";
    for(std::size_t b = 0; b < h.size(); ++b) {
      if(h[b] == 0) continue;
      const double bh = bar_height(h[b]);
      os << "<rect x=\"" << left + b * bin_w << "\" y=\"" << top + plot_h - bh << "\" width=\""
         << bin_w << "\" height=\"" << bh << "\" fill=\"" << colour << "\"><title>" << b << "-"
         << b + 1 << " deg: " << h[b] << "</title></rect>\n";
    }
  }
  os << "<line x1=\"" << left << "\" y1=\"" << top + plot_h << "\" x2=\"" << left + plot_w
     << "\" y2=\"" << top + plot_h << "\" stroke=\"black\"/>\n";
  for(int deg = 0; deg <= 180; deg += 30)
    os << "<text x=\"" << left + deg * bin_w << "\" y=\"" << top + plot_h + 16
       << "\" text-anchor=\"middle\">" << deg << "</text>\n";
  os << "<text x=\"" << left + plot_w / 2 << "\" y=\"" << height - 6
     << "\" text-anchor=\"middle\">dihedral angle (degrees)</text>\n";
  os << "<text x=\"" << left - 8 << "\" y=\"" << top + 4 << "\" text-anchor=\"end\">" << max_count
     << "</text>\n<text x=\"" << left - 8 << "\" y=\"" << top + plot_h
     << "\" text-anchor=\"end\">0</text>\n</svg>\n";
}

} // namespace vvm_benchmark

#endif // VVM_BENCHMARK_DIHEDRAL_HISTOGRAM_SVG_H
