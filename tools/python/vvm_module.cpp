// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// vvm._vvm: the front-end layer (tools/front_end) for Python. Meshes cross as
// numpy arrays; vvm/__init__.py makes meshio meshes of them. Each call
// converts its arguments, releases the GIL while the front end works, and
// takes it back only to report progress.
//
// Errors: vvm::Input_error derives from std::invalid_argument, which pybind11
// raises as ValueError with the C++ message.

#include "vvm_front_end.h"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

vvm::Volume_mesh::Cell_type cell_type_of_vtk_code(std::int64_t code)
{
  switch(code) {
    case 10: return vvm::Volume_mesh::Cell_type::TETRAHEDRON;
    case 12: return vvm::Volume_mesh::Cell_type::HEXAHEDRON;
    case 13: return vvm::Volume_mesh::Cell_type::PRISM;
    case 14: return vvm::Volume_mesh::Cell_type::PYRAMID;
    default:
      throw vvm::Input_error("unknown cell type " + std::to_string(code) +
                             " (10 tetrahedron, 12 hexahedron, 13 wedge, 14 pyramid)");
  }
}

/// `mesh` as numpy arrays: points (n, 3), cell_types (m,) VTK codes, connectivity (m, 8)
/// padded with -1, labels (m,), and the per-cell quality arrays. The vertex orders are
/// Volume_mesh's, which are meshio's (VTK's, but Gmsh's for prisms: meshio's VTU reader and
/// writer turn wedges round themselves).
py::dict mesh_to_arrays(const vvm::Volume_mesh& mesh)
{
  const std::size_t n = mesh.points.size(), m = mesh.cells.size();
  py::array_t<double> points({n, std::size_t(3)});
  auto p = points.mutable_unchecked<2>();
  for(std::size_t i = 0; i < n; ++i) {
    p(i, 0) = mesh.points[i].x();
    p(i, 1) = mesh.points[i].y();
    p(i, 2) = mesh.points[i].z();
  }
  py::array_t<std::int8_t> types(m);
  py::array_t<std::int64_t> connectivity({m, std::size_t(8)});
  py::array_t<std::int32_t> labels(m);
  auto t = types.mutable_unchecked<1>();
  auto c = connectivity.mutable_unchecked<2>();
  auto l = labels.mutable_unchecked<1>();
  for(std::size_t i = 0; i < m; ++i) {
    const auto& cell = mesh.cells[i];
    t(i) = std::int8_t(cell.type);
    for(std::size_t j = 0; j < 8; ++j)
      c(i, j) = j < cell.size() ? std::int64_t(cell.vertices[j]) : -1;
    l(i) = cell.subdomain_index;
  }
  py::dict quality;
  for(const auto& array : vvm::cell_quality_arrays(mesh))
    quality[py::str(array.first)] = py::array_t<double>(py::ssize_t(array.second.size()), array.second.data());
  py::dict d;
  d["points"] = points;
  d["cell_types"] = types;
  d["connectivity"] = connectivity;
  d["labels"] = labels;
  d["quality"] = quality;
  return d;
}

/// the mesh of the arrays `mesh_to_arrays` makes (connectivity: one row per cell, its
/// first columns used, in meshio's order)
vvm::Volume_mesh mesh_from_arrays(const Double_array& points, const Index_array& cell_types,
                                  const Index_array& connectivity, const Index_array& labels)
{
  if(points.ndim() != 2 || points.shape(1) != 3) throw vvm::Input_error("points must be an array of shape (n, 3)");
  if(cell_types.ndim() != 1) throw vvm::Input_error("cell_types must be a one-dimensional array");
  const std::size_t m = std::size_t(cell_types.shape(0));
  if(connectivity.ndim() != 2 || std::size_t(connectivity.shape(0)) != m)
    throw vvm::Input_error("connectivity must be an array of shape (cells, vertices per cell)");
  if(labels.ndim() != 1 || std::size_t(labels.shape(0)) != m)
    throw vvm::Input_error("labels must hold one label per cell");
  vvm::Volume_mesh mesh;
  const auto p = points.unchecked<2>();
  const std::size_t n = std::size_t(points.shape(0));
  for(std::size_t i = 0; i < n; ++i) mesh.points.emplace_back(p(i, 0), p(i, 1), p(i, 2));
  const auto t = cell_types.unchecked<1>();
  const auto c = connectivity.unchecked<2>();
  const auto l = labels.unchecked<1>();
  for(std::size_t i = 0; i < m; ++i) {
    vvm::Volume_mesh::Cell cell;
    cell.type = cell_type_of_vtk_code(t(i));
    if(std::size_t(connectivity.shape(1)) < cell.size())
      throw vvm::Input_error("cell " + std::to_string(i) + " needs " + std::to_string(cell.size()) +
                             " vertices; connectivity has " + std::to_string(connectivity.shape(1)) + " columns");
    for(std::size_t j = 0; j < cell.size(); ++j) {
      const std::int64_t v = c(py::ssize_t(i), py::ssize_t(j));
      if(v < 0 || std::size_t(v) >= n)
        throw vvm::Input_error("cell " + std::to_string(i) + " has the vertex index " + std::to_string(v) +
                               ", out of range (" + std::to_string(n) + " points)");
      cell.vertices[j] = std::size_t(v);
    }
    if(l(i) < INT32_MIN || l(i) > INT32_MAX) throw vvm::Input_error("the label of cell " + std::to_string(i) + " is out of range");
    cell.subdomain_index = int(l(i));
    mesh.cells.push_back(cell);
  }
  return mesh;
}

/// a surface: a path (str), or a (vertices (n, 3), faces (m, k >= 3)) pair
vvm::Surface_source surface_source(const py::object& surface)
{
  if(py::isinstance<py::str>(surface)) return vvm::Surface_source(surface.cast<std::string>());
  if(!py::isinstance<py::tuple>(surface) || py::len(surface) != 2)
    throw vvm::Input_error("the surface must be a file name or a (vertices, faces) pair of arrays");
  const auto vertices = surface[py::int_(0)].cast<Double_array>();
  const auto faces = surface[py::int_(1)].cast<Index_array>();
  if(vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw vvm::Input_error("the surface's vertices must be an array of shape (n, 3)");
  if(faces.ndim() != 2 || faces.shape(1) < 3)
    throw vvm::Input_error("the surface's faces must be an array of shape (m, k), k >= 3");
  std::vector<std::array<double, 3>> points(std::size_t(vertices.shape(0)));
  const auto v = vertices.unchecked<2>();
  for(std::size_t i = 0; i < points.size(); ++i) points[i] = {v(i, 0), v(i, 1), v(i, 2)};
  std::vector<std::vector<std::size_t>> polygons(std::size_t(faces.shape(0)));
  const auto f = faces.unchecked<2>();
  for(std::size_t i = 0; i < polygons.size(); ++i)
    for(py::ssize_t j = 0; j < faces.shape(1); ++j) {
      if(f(py::ssize_t(i), j) < 0)
        throw vvm::Input_error("face " + std::to_string(i) + " of the surface has a negative vertex index");
      polygons[i].push_back(std::size_t(f(py::ssize_t(i), j)));
    }
  return vvm::Surface_source(std::move(points), std::move(polygons));
}

/// the front end's progress callback over a Python callable progress(stage, fraction, detail,
/// elapsed); also where a Ctrl-C stops the run (KeyboardInterrupt). The Python error that ends
/// a run is kept, so that it reaches the caller even if the front end swallows it (a stage's
/// end is reported from a destructor): every later event and `rethrow()`, called when the
/// front end returns, raise it again.
class Progress_relay
{
public:
  explicit Progress_relay(const py::object& callable) : callable_(callable) {}

  /// the callback; it holds a reference to this relay, not a copy of the callable: copies
  /// of the callback are made while the GIL is released
  vvm::Progress callback()
  {
    return [this](const vvm::Progress_event& e) {
      if(error_) std::rethrow_exception(error_);
      py::gil_scoped_acquire gil;
      try {
        if(PyErr_CheckSignals() != 0) throw py::error_already_set();
        if(!callable_.is_none()) callable_(e.stage, e.fraction, e.detail, e.elapsed);
      } catch(const py::error_already_set&) {
        error_ = std::current_exception();
        throw;
      }
    };
  }
  /// raises the error that ended the run, if any (with the GIL held)
  void rethrow() const
  {
    if(error_) std::rethrow_exception(error_);
  }

private:
  const py::object& callable_;
  std::exception_ptr error_;
};

/// runs `run(progress callback)` with the GIL released; the callback's Python error, if
/// any, is raised when the run ends
template <class Run>
auto without_gil(const py::object& progress, const Run& run)
{
  Progress_relay relay(progress);
  std::optional<decltype(run(relay.callback()))> result;
  try {
    py::gil_scoped_release released;
    result.emplace(run(relay.callback()));
  } catch(...) {
    relay.rethrow(); // the Python error first: the front end may have wrapped or replaced it
    throw;
  }
  relay.rethrow();
  return std::move(*result);
}

py::dict report_dict(const vvm::Run_report& r)
{
  py::dict d;
  d["input"] = r.input;
  d["method"] = r.method;
  d["mesh_time"] = r.mesh_time;
  d["optimize_time"] = r.optimize_time;
  d["run_time"] = r.run_time;
  if(r.input_vertices > 0) d["input_vertices"] = r.input_vertices;
  if(r.boundary_distance_bound >= 0) d["boundary_distance_bound"] = r.boundary_distance_bound;
  if(r.boundary_hausdorff >= 0) d["boundary_hausdorff"] = r.boundary_hausdorff;
  d["time_limit_reached"] = r.time_limit_reached;
  if(!r.field.empty()) d["field"] = r.field;
  return d;
}

vvm::Mesh_size mesh_size(double size, std::size_t count)
{
  vvm::Mesh_size s;
  s.size = size;
  s.vertices = count;
  return s;
}

py::dict result(const vvm::Volume_mesh& mesh, const vvm::Run_report& report)
{
  py::dict d = mesh_to_arrays(mesh);
  d["report"] = report_dict(report);
  return d;
}

py::dict tet_mesh(const py::object& surface, const std::string& method, std::size_t vertices, double size,
                  double features_angle, const std::string& field, const std::string& sizing, int threads,
                  unsigned int seed, double time_limit, const py::object& progress)
{
  const vvm::Surface_source source = surface_source(surface);
  vvm::Tet_options o;
  o.sizing = sizing;
  o.time_limit = time_limit;
  o.method = method;
  o.size = mesh_size(size, vertices);
  o.features_angle = features_angle;
  o.field = field;
  o.threads = threads;
  o.seed = seed;
  vvm::Run_report report;
  const vvm::Volume_mesh mesh =
      without_gil(progress, [&](const vvm::Progress& p) { return vvm::tet_mesh(source, o, p, &report); });
  return result(mesh, report);
}

py::dict hex_dominant(const py::object& surface, std::size_t particles, double size, double q_bound,
                      double boundary_distance, double features_angle, const std::string& field,
                      const std::string& sizing, double maximum_size_ratio, int threads, unsigned int seed,
                      double time_limit, const py::object& progress)
{
  const vvm::Surface_source source = surface_source(surface);
  vvm::Hex_dominant_options o;
  o.sizing = sizing;
  o.maximum_size_ratio = maximum_size_ratio;
  o.time_limit = time_limit;
  o.size = mesh_size(size, particles);
  o.quality_bound = q_bound;
  o.boundary_distance = boundary_distance;
  o.features_angle = features_angle;
  o.field = field;
  o.threads = threads;
  o.seed = seed;
  vvm::Run_report report;
  const vvm::Volume_mesh mesh =
      without_gil(progress, [&](const vvm::Progress& p) { return vvm::hex_dominant_mesh(source, o, p, &report); });
  return result(mesh, report);
}

py::dict surface_quality_dict(const vvm::Surface_quality& q)
{
  py::dict d;
  d["vertices"] = q.number_of_vertices;
  d["faces"] = q.number_of_faces;
  d["r6"] = q.r6;
  d["xi_mean"] = q.xi_mean;
  d["xi_min"] = q.xi_min;
  d["min_angle"] = q.min_angle;
  d["mean_min_angle"] = q.mean_min_angle;
  d["alignment_error_mean"] = q.alignment_error_mean;
  d["is_closed_manifold"] = q.is_closed_manifold;
  return d;
}

py::dict surface_mesh(const py::object& surface, std::size_t vertices, double size, const std::string& field,
                      double maximum_anisotropy, double maximum_size_ratio, double features_angle, int threads,
                      unsigned int seed, double time_limit, const py::object& progress)
{
  const vvm::Surface_source source = surface_source(surface);
  vvm::Surface_options o;
  o.size = mesh_size(size, vertices);
  o.field = field;
  o.maximum_anisotropy = maximum_anisotropy;
  o.maximum_size_ratio = maximum_size_ratio;
  o.features_angle = features_angle;
  o.threads = threads;
  o.seed = seed;
  o.time_limit = time_limit;
  vvm::Run_report report;
  const vvm::Surface_mesh_result mesh =
      without_gil(progress, [&](const vvm::Progress& p) { return vvm::surface_mesh(source, o, p, &report); });
  py::array_t<double> points({mesh.points.size(), std::size_t(3)});
  py::array_t<std::int64_t> triangles({mesh.triangles.size(), std::size_t(3)});
  auto p = points.mutable_unchecked<2>();
  auto t = triangles.mutable_unchecked<2>();
  for(std::size_t i = 0; i < mesh.points.size(); ++i) {
    p(i, 0) = mesh.points[i].x();
    p(i, 1) = mesh.points[i].y();
    p(i, 2) = mesh.points[i].z();
  }
  for(std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for(std::size_t j = 0; j < 3; ++j) t(i, j) = std::int64_t(mesh.triangles[i][j]);
  py::dict d;
  d["points"] = points;
  d["triangles"] = triangles;
  d["quality"] = surface_quality_dict(mesh.quality);
  d["report"] = report_dict(report);
  return d;
}

py::dict optimize(const Double_array& points, const Index_array& cell_types, const Index_array& connectivity,
                  const Index_array& labels, double features_angle, bool fixed_boundary, double boundary_distance,
                  int threads, unsigned int seed, double time_limit, const py::object& progress)
{
  const vvm::Volume_mesh input = mesh_from_arrays(points, cell_types, connectivity, labels);
  vvm::Optimize_options o;
  o.time_limit = time_limit;
  o.features_angle = features_angle;
  o.fixed_boundary = fixed_boundary;
  o.boundary_distance = boundary_distance;
  o.threads = threads;
  o.seed = seed;
  vvm::Run_report report;
  report.input = "(arrays)";
  const vvm::Volume_mesh mesh =
      without_gil(progress, [&](const vvm::Progress& p) { return vvm::optimize_tet_mesh(input, o, p, &report); });
  return result(mesh, report);
}

py::dict frame_field_dict(const vvm::Frame_field_arrays& a)
{
  py::array_t<double> points({a.points.size(), std::size_t(3)});
  py::array_t<std::int64_t> tetrahedra({a.tetrahedra.size(), std::size_t(4)});
  py::array_t<double> frames({a.frames.size(), std::size_t(3), std::size_t(3)});
  auto p = points.mutable_unchecked<2>();
  auto t = tetrahedra.mutable_unchecked<2>();
  auto f = frames.mutable_unchecked<3>();
  for(std::size_t i = 0; i < a.points.size(); ++i)
    for(std::size_t j = 0; j < 3; ++j) p(i, j) = a.points[i][j];
  for(std::size_t i = 0; i < a.tetrahedra.size(); ++i)
    for(std::size_t j = 0; j < 4; ++j) t(i, j) = std::int64_t(a.tetrahedra[i][j]);
  for(std::size_t i = 0; i < a.frames.size(); ++i)
    for(std::size_t j = 0; j < 9; ++j) f(i, j / 3, j % 3) = a.frames[i][j];
  py::dict d;
  d["points"] = points;
  d["tetrahedra"] = tetrahedra;
  d["frames"] = frames;
  d["location"] = a.on_cells ? "cells" : "vertices";
  return d;
}

py::dict cross_field(const py::object& surface, std::size_t vertices, double size, double features_angle,
                     unsigned int seed, double time_limit, const py::object& progress)
{
  const vvm::Surface_source source = surface_source(surface);
  vvm::Field_options o;
  o.time_limit = time_limit;
  o.size = mesh_size(size, vertices);
  o.features_angle = features_angle;
  o.seed = seed;
  vvm::Run_report report;
  const vvm::Frame_field_arrays field = without_gil(
      progress, [&](const vvm::Progress& p) { return vvm::frame_field_from_text(vvm::cross_field(source, o, p, &report)); });
  py::dict d = frame_field_dict(field);
  d["report"] = report_dict(report);
  return d;
}

std::string frame_field_text(const Double_array& points, const Index_array& tetrahedra, const Double_array& frames,
                             const std::string& location)
{
  if(points.ndim() != 2 || points.shape(1) != 3) throw vvm::Input_error("the field's points must be of shape (n, 3)");
  if(tetrahedra.ndim() != 2 || tetrahedra.shape(1) != 4)
    throw vvm::Input_error("the field's tetrahedra must be of shape (m, 4)");
  if(frames.ndim() != 3 || frames.shape(1) != 3 || frames.shape(2) != 3)
    throw vvm::Input_error("the field's frames must be of shape (k, 3, 3)");
  if(location != "vertices" && location != "cells") throw vvm::Input_error("location must be 'vertices' or 'cells'");
  vvm::Frame_field_arrays a;
  a.on_cells = location == "cells";
  const auto p = points.unchecked<2>();
  for(py::ssize_t i = 0; i < points.shape(0); ++i) a.points.push_back({p(i, 0), p(i, 1), p(i, 2)});
  const auto t = tetrahedra.unchecked<2>();
  for(py::ssize_t i = 0; i < tetrahedra.shape(0); ++i) {
    std::array<std::size_t, 4> cell;
    for(py::ssize_t j = 0; j < 4; ++j) {
      if(t(i, j) < 0) throw vvm::Input_error("tetrahedron " + std::to_string(i) + " has a negative vertex index");
      cell[std::size_t(j)] = std::size_t(t(i, j));
    }
    a.tetrahedra.push_back(cell);
  }
  const auto f = frames.unchecked<3>();
  for(py::ssize_t i = 0; i < frames.shape(0); ++i) {
    std::array<double, 9> T;
    for(std::size_t j = 0; j < 9; ++j) T[j] = f(i, py::ssize_t(j / 3), py::ssize_t(j % 3));
    a.frames.push_back(T);
  }
  py::gil_scoped_release released;
  return vvm::frame_field_text(a);
}

py::dict quality_dict(const vvm::Mesh_quality& q)
{
  py::dict d;
  d["vertices"] = q.vertices;
  d["cells"] = q.cells;
  d["tetrahedra"] = q.tetrahedra;
  d["hexahedra"] = q.hexahedra;
  d["prisms"] = q.prisms;
  d["pyramids"] = q.pyramids;
  d["inverted"] = q.inverted;
  d["labels"] = q.labels;
  if(q.tetrahedra > 0) {
    d["min_dihedral"] = q.min_dihedral;
    d["max_dihedral"] = q.max_dihedral;
    d["mean_min_dihedral"] = q.mean_min_dihedral;
    const int thresholds[4] = {10, 20, 30, 40};
    py::dict under;
    for(std::size_t i = 0; i < 4; ++i) under[py::int_(thresholds[i])] = q.tets_under[i];
    d["tets_under"] = under;
    d["min_radius_ratio"] = q.min_radius_ratio;
    d["mean_radius_ratio"] = q.mean_radius_ratio;
    d["min_dihedral_histogram"] = std::vector<std::size_t>(q.min_dihedral_histogram.begin(), q.min_dihedral_histogram.end());
  }
  d["hex_volume_percent"] = q.hex_volume_percent;
  d["min_scaled_jacobian"] = q.min_scaled_jacobian;
  d["mean_hex_scaled_jacobian"] = q.mean_hex_scaled_jacobian;
  return d;
}

py::dict quality(const Double_array& points, const Index_array& cell_types, const Index_array& connectivity,
                 const Index_array& labels)
{
  const vvm::Volume_mesh mesh = mesh_from_arrays(points, cell_types, connectivity, labels);
  vvm::Mesh_quality q;
  {
    py::gil_scoped_release released;
    q = vvm::mesh_quality(mesh);
  }
  return quality_dict(q);
}

py::dict read_mesh(const std::string& path)
{
  vvm::Volume_mesh mesh;
  {
    py::gil_scoped_release released;
    mesh = vvm::read_volume_mesh(path);
  }
  return mesh_to_arrays(mesh);
}

void write_mesh(const Double_array& points, const Index_array& cell_types, const Index_array& connectivity,
           const Index_array& labels, const std::string& path)
{
  const vvm::Volume_mesh mesh = mesh_from_arrays(points, cell_types, connectivity, labels);
  py::gil_scoped_release released;
  vvm::write_volume_mesh(mesh, path);
}

} // namespace

PYBIND11_MODULE(_vvm, m)
{
  m.doc() = "VVM's front end over numpy arrays; use the vvm package, which makes meshio meshes of them.";
  m.attr("__version__") = VVM_VERSION;
  using py::arg;
  m.def("tet_mesh", &tet_mesh, arg("surface"), arg("method"), arg("vertices"), arg("size"), arg("features_angle"),
        arg("field"), arg("sizing"), arg("threads"), arg("seed"), arg("time_limit"), arg("progress"));
  m.def("hex_dominant", &hex_dominant, arg("surface"), arg("particles"), arg("size"), arg("q_bound"),
        arg("boundary_distance"), arg("features_angle"), arg("field"), arg("sizing"), arg("maximum_size_ratio"),
        arg("threads"), arg("seed"), arg("time_limit"), arg("progress"));
  m.def("surface_mesh", &surface_mesh, arg("surface"), arg("vertices"), arg("size"), arg("field"),
        arg("maximum_anisotropy"), arg("maximum_size_ratio"), arg("features_angle"), arg("threads"), arg("seed"),
        arg("time_limit"), arg("progress"));
  m.def("optimize", &optimize, arg("points"), arg("cell_types"), arg("connectivity"), arg("labels"),
        arg("features_angle"), arg("fixed_boundary"), arg("boundary_distance"), arg("threads"), arg("seed"),
        arg("time_limit"), arg("progress"));
  m.def("cross_field", &cross_field, arg("surface"), arg("vertices"), arg("size"), arg("features_angle"), arg("seed"),
        arg("time_limit"), arg("progress"));
  m.def("frame_field_text", &frame_field_text, arg("points"), arg("tetrahedra"), arg("frames"), arg("location"));
  m.def(
      "frame_field_from_text",
      [](const std::string& text) {
        vvm::Frame_field_arrays field;
        {
          py::gil_scoped_release released;
          field = vvm::frame_field_from_text(text);
        }
        return frame_field_dict(field);
      },
      arg("text"));
  m.def("quality", &quality, arg("points"), arg("cell_types"), arg("connectivity"), arg("labels"));
  m.def("read", &read_mesh, arg("path"));
  m.def("write", &write_mesh, arg("points"), arg("cell_types"), arg("connectivity"), arg("labels"), arg("path"));
}
