// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTU output of a C3T3 with per-cell quality fields, for ParaView.
// The MEDIT output with subdomain references is CGAL's own
// `CGAL::IO::output_to_medit(os, c3t3, false, true)`.

#ifndef CGAL_GSM_MESH_OPTIMIZATION_IO_WRITE_VTU_WITH_QUALITY_H
#define CGAL_GSM_MESH_OPTIMIZATION_IO_WRITE_VTU_WITH_QUALITY_H

#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/IO/output_to_vtu.h>

#include <ostream>
#include <stdexcept>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace GSM_mesh_optimization {
namespace IO {

/*!
 * \ingroup PkgGSMMeshOptimizationIO
 * writes the cells in the complex of `c3t3` to `os` as a VTK XML unstructured
 * grid (`.vtu`), with these cell data arrays:
 * `MeshDomain` (subdomain index), `min_dihedral_angle`, `max_dihedral_angle` (degrees),
 * `radius_ratio`, `edge_radius_ratio`, `condition` and `volume` (signed).
 *
 * \tparam C3T3 a model of `MeshComplex_3InTriangulation_3`
 * \tparam MetricB a callable `Eigen::Matrix3d(const Point_3&)` giving the matrix
 *   by which each cell is mapped (at its centroid) before it is measured; the
 *   identity by default.
 * \param c3t3 the mesh; only its cells in the complex are written
 * \param B the metric (see `MetricB`)
 * \param extra_cell_data more cell data arrays, named, one value per cell in the complex in
 *   the order of `cells_in_complex_begin()` (e.g. the alignment error of
 *   `Tetrahedral_lattice_meshing::cell_alignment_errors()`)
 * \param os an output stream, opened in binary mode for `CGAL::IO::BINARY`
 * \param mode `CGAL::IO::BINARY` (raw appended data, default) or `CGAL::IO::ASCII`
 *   (17 significant digits)
 */
template <class C3T3, class MetricB = internal::Identity_metric>
void write_VTU_with_quality(std::ostream& os, const C3T3& c3t3,
                            CGAL::IO::Mode mode = CGAL::IO::BINARY,
                            const MetricB& B = MetricB(),
                            const std::vector<std::pair<std::string, std::vector<double>>>& extra_cell_data = {})
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Geom_traits::Point_3 Bare_point;
  const Tr& tr = c3t3.triangulation();
  typename Tr::Geom_traits::Construct_point_3 cp = tr.geom_traits().construct_point_3_object();

  std::vector<double> domain, min_dihedral, max_dihedral, radius_ratio, edge_radius_ratio,
      condition, volume;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    const Bare_point p0 = cp(tr.point(c, 0)), p1 = cp(tr.point(c, 1)),
                     p2 = cp(tr.point(c, 2)), p3 = cp(tr.point(c, 3));
    const Tetrahedron_quality q =
        tetrahedron_quality(p0, p1, p2, p3, B(CGAL::centroid(p0, p1, p2, p3)));
    domain.push_back(double(c->subdomain_index()));
    min_dihedral.push_back(q.min_dihedral_angle());
    max_dihedral.push_back(q.max_dihedral_angle());
    radius_ratio.push_back(q.radius_ratio);
    edge_radius_ratio.push_back(q.edge_radius_ratio);
    condition.push_back(q.condition);
    volume.push_back(q.volume);
  }

  typedef CGAL::IO::internal::Vtu_attributes Attributes;
  std::vector<std::pair<const char*, Attributes>> attributes{
      {"MeshDomain", Attributes(&domain)},
      {"min_dihedral_angle", Attributes(&min_dihedral)},
      {"max_dihedral_angle", Attributes(&max_dihedral)},
      {"radius_ratio", Attributes(&radius_ratio)},
      {"edge_radius_ratio", Attributes(&edge_radius_ratio)},
      {"condition", Attributes(&condition)},
      {"volume", Attributes(&volume)}};
  for(const auto& data : extra_cell_data) {
    if(data.second.size() != volume.size())
      throw std::invalid_argument("write_VTU_with_quality: the cell data '" + data.first + "' has " +
                                  std::to_string(data.second.size()) + " values for " +
                                  std::to_string(volume.size()) + " cells");
    attributes.emplace_back(data.first.c_str(), Attributes(&data.second));
  }
  // CGAL 5.5.1 writes BINARY files without the closing </AppendedData> tag, which
  // strict XML readers (meshio, Python's ElementTree) reject: write to a buffer
  // and close the element.
  std::ostringstream buffer(std::ios::out | std::ios::binary);
  buffer.precision(17);
  CGAL::IO::internal::output_to_vtu_with_attributes(buffer, c3t3, attributes, mode);
  std::string vtu = buffer.str();
  const std::size_t end_tag = vtu.rfind("</VTKFile>");
  if(mode == CGAL::IO::BINARY && end_tag != std::string::npos &&
     vtu.find("</AppendedData>") == std::string::npos)
    vtu.insert(end_tag, "\n</AppendedData>\n");
  os << vtu;
}

} // namespace IO
} // namespace GSM_mesh_optimization
} // namespace CGAL

#endif // CGAL_GSM_MESH_OPTIMIZATION_IO_WRITE_VTU_WITH_QUALITY_H
