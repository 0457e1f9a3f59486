// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The front-end layer: what the vvm-mesh program (and the Python module) run,
// over the packages' public API. One option vocabulary, one mesh type for
// files, one error type for bad input, one progress callback.

#ifndef VVM_FRONT_END_H
#define VVM_FRONT_END_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Hex_dominant_mesh_3.h>
#include <CGAL/Tetrahedral_lattice_meshing/surface_mesh_quality.h>

#include <array>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vvm {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
/// a volume mesh as files hold it: points, and tetrahedra, hexahedra, prisms and pyramids with
/// their subdomain labels
typedef CGAL::Hex_dominant_mesh_3<Point> Volume_mesh;

/// a bad argument or a bad input (missing or unreadable file, open surface, unknown
/// extension, inverted cells, NaN, ...): the program's exit code 2, Python's ValueError
struct Input_error : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

/// what a long run reports as it goes
struct Progress_event
{
  std::string stage;    ///< e.g. "make_mesh_3", "gsm", "particles", "merging"
  double fraction = -1; ///< done, in [0, 1]; < 0: unknown
  std::string detail;   ///< e.g. "round 3: min angle 21.4"
  double elapsed = 0;   ///< seconds since the stage started
};
typedef std::function<void(const Progress_event&)> Progress;

/// a closed surface to mesh (for `surface_mesh()` also an open one): a file (OFF, OBJ, PLY, STL,
/// ...; for `tet_mesh()` also a labelled 3D image, .inr or .inr.gz), or points and polygons in memory
struct Surface_source
{
  std::string path; ///< the file; empty: `points` and `polygons`
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons; ///< indices into `points`, three or more each

  Surface_source(std::string file) : path(std::move(file)) {}
  Surface_source(const char* file) : path(file) {}
  Surface_source(std::vector<std::array<double, 3>> p, std::vector<std::vector<std::size_t>> f)
      : points(std::move(p)), polygons(std::move(f))
  {}
  bool is_file() const { return !path.empty(); }
  /// the name of the input in reports
  std::string name() const { return is_file() ? path : "(arrays)"; }
};

/// the size of a mesh: an edge length, or a number of vertices (or particles) sought
struct Mesh_size
{
  double size = 0;                ///< > 0: the edge length
  std::size_t vertices = 10000;   ///< used when `size` is 0
};

/// `vvm-mesh tet`
struct Tet_options
{
  std::string method = "gsm";  ///< gsm, odt+gsm, perturb+exude, bcc, fcc
  Mesh_size size;
  double features_angle = 60;  ///< degrees; 0: no feature protected (surfaces only)
  std::string field = "cross"; ///< cross, identity, or a frame-field file (lattices; a file is GSM's metric too)
  /// uniform, or thickness: the size follows the surface's walls, gaps and the faces between its
  /// protected feature curves, 3 cells across
  /// (CGAL::Thickness_sizing_field_3; surfaces only), its median over the surface being the
  /// size (or the one that gives the vertex count)
  std::string sizing = "uniform";
  int threads = 0;             ///< 0: all cores
  unsigned int seed = 0;
  double time_limit = 0;       ///< seconds of the optimizer or the lattice (`maximum_running_time`); 0: none
};

/// `vvm-mesh hexdom`
struct Hex_dominant_options
{
  Mesh_size size{0, 30000};    ///< particles, or the lattice's edge length
  double quality_bound = 0.5;  ///< Q_bound of the merging, in [0, 1]
  double boundary_distance = 0; ///< the boundary refinement's distance; 0: none
  double features_angle = 60;
  std::string field = "cross";
  std::string sizing = "uniform"; ///< uniform, or thickness: the field's frames scaled as `Tet_options::sizing`
  /// the cross field's scale correction: scales within this ratio (1: none), as
  /// `Frame_fields::parameters::maximum_size_ratio` of make_hex_dominant_mesh_3
  double maximum_size_ratio = 2;
  int threads = 0;
  unsigned int seed = 0;
  double time_limit = 0;       ///< seconds of make_hex_dominant_mesh_3 (field included); 0: none
};

/// `vvm-mesh optimize`
struct Optimize_options
{
  double features_angle = 60; ///< edges of the boundary and interfaces sharper than this are kept (0: none)
  bool fixed_boundary = false; ///< only interior vertices move
  /// how far the boundary facets may stray from the input's boundary; < 0: 1% of its mean edge
  /// length; 0: boundary vertices slide on flat parts only
  double boundary_distance = -1;
  int threads = 0;
  unsigned int seed = 0;
  double time_limit = 0;       ///< seconds of GSM; 0: none
};

/// `vvm-mesh field`
struct Field_options
{
  Mesh_size size;              ///< of the tetrahedral mesh that carries the field
  double features_angle = 60;
  unsigned int seed = 0;
  double time_limit = 0;       ///< seconds of generate_cross_field_3; 0: none
};

/// `vvm-mesh surface`
struct Surface_options
{
  Mesh_size size;                  ///< the vertices sought, or the lattice's edge length in the field's metric
  std::string field = "curvature"; ///< curvature, isotropic (its directions, one length each) or identity
  double maximum_anisotropy = 3;   ///< curvature: the largest ratio of a frame's two lengths, >= 1
  double maximum_size_ratio = 4;   ///< curvature, isotropic: the largest ratio of two frames' lengths, >= 1
  double features_angle = 60;      ///< degrees; edges sharper than this are kept (0: none)
  int threads = 0;
  unsigned int seed = 0;
  double time_limit = 0;           ///< seconds of the particles' rounds; 0: none
};

/// what a run made, for the summary and the JSON line
struct Run_report
{
  std::string input;
  std::string method;
  double mesh_time = 0;     ///< seconds to make the initial mesh (or to read it)
  double optimize_time = 0; ///< seconds of the optimizer / lattice / merging
  double run_time = 0;      ///< seconds of the whole call (input checks, measures and conversions included)
  std::size_t input_vertices = 0; ///< optimize: the input's
  double boundary_distance_bound = -1; ///< optimize: the bound the boundary was held to
  double boundary_hausdorff = -1;      ///< optimize: two-sided distance between the input's and the output's boundaries
  bool time_limit_reached = false;     ///< the time limit stopped the optimizer, lattice, merging or field
  std::string field;                   ///< surface: the frame field (its time is `mesh_time`)
};

/// the quality table of a volume mesh
struct Mesh_quality
{
  std::size_t vertices = 0, cells = 0;
  std::size_t tetrahedra = 0, hexahedra = 0, prisms = 0, pyramids = 0;
  std::size_t inverted = 0;        ///< cells with a non-positive corner Jacobian
  std::vector<int> labels;         ///< the subdomain labels, sorted
  // tetrahedra
  double min_dihedral = 0, max_dihedral = 0, mean_min_dihedral = 0;
  std::array<std::size_t, 4> tets_under{{0, 0, 0, 0}}; ///< smallest dihedral angle under 10, 20, 30, 40 degrees
  double min_radius_ratio = 0, mean_radius_ratio = 0;
  std::array<std::size_t, 18> min_dihedral_histogram{}; ///< the tets' smallest angles in bins of 10 degrees
  // all cells
  double hex_volume_percent = 0;   ///< H_vol%
  double min_scaled_jacobian = 0;  ///< over all cells (corner Jacobians of unit edges)
  double mean_hex_scaled_jacobian = 0;
};

/// the quality of a triangle mesh of a surface in its frame field's metric
typedef CGAL::Tetrahedral_lattice_meshing::Surface_mesh_quality Surface_quality;

/// a triangle mesh of a surface as files hold it, and its quality
struct Surface_mesh_result
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles; ///< indices into `points`, outward as the input's
  Surface_quality quality;
};

/// `vvm-mesh tet INPUT`: a closed surface (OFF, OBJ, PLY, STL, ...) or a labelled 3D image
/// (.inr, .inr.gz): make_mesh_3 and an optimizer, or a lattice mesh
Volume_mesh tet_mesh(const Surface_source& input, const Tet_options& options, const Progress& progress = {},
                     Run_report* report = nullptr);

/// `vvm-mesh hexdom INPUT`: a hex-dominant mesh of a closed surface
Volume_mesh hex_dominant_mesh(const Surface_source& input, const Hex_dominant_options& options,
                              const Progress& progress = {}, Run_report* report = nullptr);

/// `vvm-mesh surface INPUT`: a triangle mesh of a triangle surface (open or closed) whose vertices
/// form a hexagonal lattice aligned with a tangent frame field (CGAL::make_lattice_surface_mesh):
/// the principal curvature field, its isotropic variant or the identity projected; its quality
/// measured in that field's metric. With `options.size.vertices`, one more run if the count is
/// more than 5% off. Input_error on an unreadable file, no face, a face that is no triangle, a
/// non-finite coordinate, faces that form no surface, a bad option.
Surface_mesh_result surface_mesh(const Surface_source& input, const Surface_options& options,
                                 const Progress& progress = {}, Run_report* report = nullptr);

/// `vvm-mesh optimize MESH`: GSM on the tetrahedra of a mesh made by any mesher (labels kept)
Volume_mesh optimize_tet_mesh(const Volume_mesh& mesh, const Optimize_options& options,
                              const Progress& progress = {}, Run_report* report = nullptr);

/// `vvm-mesh field INPUT`: the boundary-aligned cross field of a closed surface, in the
/// frame-field text format (CGAL/Frame_fields/IO/frame_field_text_format.h)
std::string cross_field(const Surface_source& input, const Field_options& options, const Progress& progress = {},
                        Run_report* report = nullptr);

/// a frame field on a tetrahedral mesh as arrays: what the frame-field text format holds
struct Frame_field_arrays
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tetrahedra;
  std::vector<std::array<double, 9>> frames; ///< T row by row (its columns are the axes), per vertex or per cell
  bool on_cells = false;                     ///< frames per tetrahedron, not per vertex
};
/// the field in `text` (frame-field text format); Input_error if it is not one
Frame_field_arrays frame_field_from_text(const std::string& text);
/// `field` in the frame-field text format; Input_error if it is not a valid field (counts,
/// indices, non-finite or singular frames)
std::string frame_field_text(const Frame_field_arrays& field);

/// the quality table of any tetrahedral or hex-dominant mesh
Mesh_quality mesh_quality(const Volume_mesh& mesh);
/// per-cell arrays for a VTU file: smallest dihedral angle (tets; 0 for others), scaled Jacobian
std::vector<std::pair<std::string, std::vector<double>>> cell_quality_arrays(const Volume_mesh& mesh);

/// reads a .mesh (MEDIT), .msh (Gmsh 2.2 or 4.1) or .vtu file; Input_error if it cannot
Volume_mesh read_volume_mesh(const std::string& path);
/// writes by extension (.mesh, .msh 4.1, .vtu with the quality arrays) through a temporary file
/// in the same folder, renamed at the end: a failed write leaves no file and `path` untouched
void write_volume_mesh(const Volume_mesh& mesh, const std::string& path);
/// writes `text` to `path` the same way
void write_text_file(const std::string& text, const std::string& path);
/// whether `path` has one of the extensions write_volume_mesh() writes
bool is_volume_mesh_file(const std::string& path);
/// writes the triangles by extension (.off, .obj, .ply binary, .stl binary) as write_volume_mesh()
/// writes its files
void write_surface_mesh(const Surface_mesh_result& mesh, const std::string& path);
/// whether `path` has one of the extensions write_surface_mesh() writes
bool is_surface_mesh_file(const std::string& path);

/// the figures of a run as one JSON line (the benchmark drivers' keys where they match)
std::string json_line(const Run_report& report, const Mesh_quality& quality);
/// the figures of a surface mesh's run as one JSON line (compare_surface_meshers' keys)
std::string json_line(const Run_report& report, const Surface_quality& quality);

} // namespace vvm

#endif // VVM_FRONT_END_H
