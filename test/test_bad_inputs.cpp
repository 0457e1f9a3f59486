// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every public entry point of the three packages driven through bad input, one table: empty
// input, NaN and infinite coordinates, inverted and flat cells, open, non-manifold and
// self-intersecting surfaces, zero, negative, NaN and absurd sizes, counts and bounds, singular
// and non-finite frame fields, negative time limits. Each must throw std::invalid_argument
// whose message names the argument (checked words), and leave the caller's mesh as it was
// (a hash of it before and after). Each named test prints its rows of the table
// (entry point | bad input | outcome). The test `stopping` drives each entry point with a time
// limit that is up at once and with a visitor that asks to stop: a valid result that says so.

// first: Mesh_3 includes TBB headers the others rely on
#include <CGAL/make_mesh_3.h>

#include "output_hash.h"
#include "vvm_test.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Frame_fields/Closed_form_frame_field_3.h>
#include <CGAL/Frame_fields/Constant_frame_field_3.h>
#include <CGAL/Frame_fields/Discrete_frame_field_3.h>
#include <CGAL/Frame_fields/IO/frame_field_text_format.h>
#include <CGAL/Frame_fields/generate_cross_field_3.h>
#include <CGAL/GSM_mesh_optimization/Complex_from_tetrahedra_3.h>
#include <CGAL/GSM_mesh_optimization/IO/read_closed_surface.h>
#include <CGAL/GSM_mesh_optimization/mesh_quality_statistics.h>
#include <CGAL/Hex_dominant_meshing/IO/read_volume_mesh.h>
#include <CGAL/Hex_dominant_meshing/hex_dominant_statistics.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/gsm_optimize_mesh_3.h>
#include <CGAL/lattice_particles_3.h>
#include <CGAL/make_hex_dominant_mesh_3.h>
#include <CGAL/make_lattice_mesh_3.h>
#include <CGAL/tets_to_hex_dominant.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Labeled_mesh_domain_3<K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3T3;
typedef CGAL::Frame_fields::Constant_frame_field_3<K> Constant_field;
typedef CGAL::Frame_fields::Closed_form_frame_field_3<K> Formula_field;
typedef CGAL::Frame_fields::Discrete_frame_field_3<K> Discrete_field;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef std::array<std::size_t, 4> Tet;
namespace GSM = CGAL::GSM_mesh_optimization;
namespace TLM = CGAL::Tetrahedral_lattice_meshing;
namespace HDM = CGAL::Hex_dominant_meshing;
namespace params = CGAL::parameters;

const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// The table

// runs `f`, which must throw std::invalid_argument whose message holds every one of `words`
// (the argument's name), leaving `unchanged()` (a hash of the caller's input) as it was; adds
// the row and checks
template <class F>
void refused(const std::string& entry, const std::string& input, std::initializer_list<const char*> words, F f,
             const std::function<std::uint64_t()>& unchanged = {})
{
  const std::uint64_t before = unchanged ? unchanged() : 0;
  std::string outcome, message;
  bool ok = false;
  try {
    f();
    outcome = "ACCEPTED";
  } catch(const std::invalid_argument& e) {
    message = e.what();
    ok = true;
    for(const char* w : words) ok = ok && message.find(w) != std::string::npos;
    outcome = ok ? "invalid_argument" : "invalid_argument, message lacks the argument's name";
  } catch(const std::exception& e) {
    message = e.what();
    outcome = "OTHER EXCEPTION";
  }
  if(ok && unchanged && unchanged() != before) {
    ok = false;
    outcome = "INPUT CHANGED";
  }
  std::cout << "| " << entry << " | " << input << " | " << outcome << (message.empty() ? "" : ": " + message) << " |"
            << std::endl;
  if(!vvm_test::check(ok, (entry + " on " + input).c_str(), __FILE__, __LINE__))
    std::cerr << "    outcome: " << outcome << (message.empty() ? "" : " (" + message + ")") << "\n";
}

// runs `f`, whose bad input has a documented result instead of an exception: `result_ok`
// (f's result) must hold; adds the row and checks
template <class F, class Check>
void documented(const std::string& entry, const std::string& input, const std::string& result, F f, Check result_ok)
{
  std::string outcome = result;
  bool ok = false;
  try {
    ok = result_ok(f());
    if(!ok) outcome = "UNEXPECTED RESULT";
  } catch(const std::exception& e) {
    outcome = std::string("EXCEPTION: ") + e.what();
  }
  std::cout << "| " << entry << " | " << input << " | " << outcome << " |" << std::endl;
  vvm_test::check(ok, (entry + " on " + input).c_str(), __FILE__, __LINE__);
}

// ---------------------------------------------------------------------------------------------
// Inputs

double sphere_function(const Point& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

Domain sphere_domain()
{
  return Domain::create_implicit_mesh_domain(std::function<double(const Point&)>(sphere_function),
                                             K::Sphere_3(CGAL::ORIGIN, 1.21), params::relative_error_bound = 1e-6);
}

// a domain with no inside: the function is positive everywhere
Domain empty_domain()
{
  return Domain::create_implicit_mesh_domain(std::function<double(const Point&)>([](const Point&) { return 1.; }),
                                             K::Sphere_3(CGAL::ORIGIN, 1.21));
}

const C3T3& sphere_mesh()
{
  static const C3T3 c3t3 = [] {
    const Domain domain = sphere_domain();
    CGAL::Mesh_criteria_3<Tr> criteria(params::facet_angle = 25, params::facet_size = 0.3,
                                       params::facet_distance = 0.03, params::cell_radius_edge_ratio = 3,
                                       params::cell_size = 0.3);
    CGAL::get_default_random() = CGAL::Random(1);
    return CGAL::make_mesh_3<C3T3>(domain, criteria, params::no_perturb(), params::no_exude());
  }();
  return c3t3;
}

// the sphere mesh with one interior vertex moved as `move` says
template <class Move>
C3T3 sphere_mesh_with(const Move& move)
{
  C3T3 c3t3 = sphere_mesh();
  Tr& tr = c3t3.triangulation();
  for(auto c : tr.finite_cell_handles()) {
    if(!c3t3.is_in_complex(c) || c->vertex(0)->in_dimension() != 3) continue;
    const Tr::Bare_point p = c->vertex(0)->point().point();
    const Tr::Bare_point q = CGAL::centroid(tr.point(c, 1).point(), tr.point(c, 2).point(), tr.point(c, 3).point());
    c->vertex(0)->set_point(Tr::Point(move(p, q)));
    break;
  }
  return c3t3;
}
// through its opposite facet (an inverted cell), onto it (a flat cell), to NaN
C3T3 inverted_mesh()
{
  return sphere_mesh_with([](const Tr::Bare_point& p, const Tr::Bare_point& q) {
    return Tr::Bare_point(2 * q.x() - p.x(), 2 * q.y() - p.y(), 2 * q.z() - p.z());
  });
}
C3T3 flat_mesh()
{
  return sphere_mesh_with([](const Tr::Bare_point&, const Tr::Bare_point& q) { return q; });
}
C3T3 nan_mesh()
{
  return sphere_mesh_with([](const Tr::Bare_point& p, const Tr::Bare_point&) { return Tr::Bare_point(nan, p.y(), p.z()); });
}

Formula_field matrix_field(const Eigen::Matrix3d& T)
{
  return Formula_field([T](const Point&) { return T; });
}
const Eigen::Matrix3d singular = Eigen::Vector3d(1, 1, 0).asDiagonal();
const Eigen::Matrix3d not_finite = Eigen::Matrix3d::Constant(nan);

// a regular tetrahedron's corners, and one tet
const std::vector<Point> tet_points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
const std::vector<Tet> one_tet = {Tet{{0, 1, 2, 3}}};

std::string write_file(const std::string& name, const std::string& text)
{
  std::ofstream(name) << text;
  return name;
}

// an octahedron's faces over six points
const std::vector<Point> octahedron_points = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),
                                             Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
const std::vector<std::vector<std::size_t>> octahedron_faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

// ---------------------------------------------------------------------------------------------
// GSM

void test_gsm()
{
  const Domain domain = sphere_domain();
  const std::string gsm = "gsm_optimize_mesh_3";
  // each call on a copy of `c3t3`, the copy hashed before and after
  // (the complex moved in: copying one with a NaN point runs CGAL's assertions on it)
  auto on = [&](const std::string& input, std::initializer_list<const char*> words, C3T3 c3t3, const auto& call) {
    refused(gsm, input, words, [&] { call(c3t3); }, [&] { return vvm_test::complex_hash(c3t3); });
  };
  auto with = [&](const auto& np) { return [&domain, np](C3T3& c) { CGAL::gsm_optimize_mesh_3(c, domain, np); }; };
  const C3T3& good = sphere_mesh();
  on("empty complex", {"no cell"}, C3T3(), with(params::default_values()));
  on("NaN coordinate", {"non-finite"}, nan_mesh(), with(params::default_values()));
  on("inverted cell", {"inverted"}, inverted_mesh(), with(params::default_values()));
  on("flat cell", {"flat"}, flat_mesh(), with(params::default_values()));
  on("number_of_iterations -1", {"number_of_iterations"}, good, with(params::number_of_iterations(-1)));
  on("maximum_running_time -1", {"maximum_running_time"}, good, with(params::maximum_running_time(-1.)));
  on("maximum_running_time NaN", {"maximum_running_time"}, good, with(params::maximum_running_time(nan)));
  on("number_of_threads -1", {"number_of_threads"}, good, with(GSM::parameters::number_of_threads(-1)));
  on("sliver_bound NaN", {"sliver bound"}, good, with(GSM::parameters::sliver_bound(nan)));
  on("sliver_bound -1", {"sliver bound"}, good, with(GSM::parameters::sliver_bound(-1.)));
  on("sliver_bound 75", {"sliver bound"}, good, with(GSM::parameters::sliver_bound(75.)));
  on("convergence_threshold NaN", {"convergence_threshold"}, good, with(GSM::parameters::convergence_threshold(nan)));
  on("boundary_distance -1", {"boundary_distance"}, good, with(GSM::parameters::boundary_distance(-1.)));
  on("boundary_distance inf", {"boundary_distance"}, good, with(GSM::parameters::boundary_distance(inf)));
  on("sizing_field 0", {"sizing field"}, good,
     with(GSM::parameters::sizing_field([](const Eigen::Vector3d&) { return 0.; })));
  on("sizing_field negative", {"sizing field"}, good,
     with(GSM::parameters::sizing_field([](const Eigen::Vector3d&) { return -1.; })));
  on("sizing_field NaN", {"sizing field"}, good,
     with(GSM::parameters::sizing_field([](const Eigen::Vector3d&) { return nan; })));
  on("metric_field not positive definite", {"metric"}, good,
     with(GSM::parameters::metric_field([](const Eigen::Vector3d&) { return Eigen::Matrix3d(Eigen::Vector3d(1, -1, 1).asDiagonal()); })));
  on("metric_field singular", {"metric"}, good,
     with(GSM::parameters::metric_field([](const Eigen::Vector3d&) { return singular; })));
  on("metric_field NaN", {"metric"}, good,
     with(GSM::parameters::metric_field([](const Eigen::Vector3d&) { return not_finite; })));

  // the same on a bare triangulation
  const std::string bare = "gsm_optimize_triangulation_3";
  auto bare_on = [&](const std::string& input, std::initializer_list<const char*> words,
                     const CGAL::Delaunay_triangulation_3<K>& tr, const auto& np) {
    CGAL::Delaunay_triangulation_3<K> copy = tr;
    refused(bare, input, words, [&] { CGAL::gsm_optimize_triangulation_3(copy, np); }, [&] {
      vvm_test::Output_hash h;
      for(auto v : copy.finite_vertex_handles()) h.add_point(v->point());
      return h.value();
    });
  };
  CGAL::Delaunay_triangulation_3<K> cube;
  for(int i = 0; i < 27; ++i) cube.insert(Point(i % 3, (i / 3) % 3, i / 9));
  bare_on("empty triangulation", {"no cell"}, CGAL::Delaunay_triangulation_3<K>(), params::default_values());
  bare_on("number_of_iterations -1", {"number_of_iterations"}, cube, params::number_of_iterations(-1));
  bare_on("sizing_field NaN", {"sizing field"}, cube,
          GSM::parameters::sizing_field([](const Eigen::Vector3d&) { return nan; }));
}

// Complex_from_tetrahedra_3: a tet mesh from another mesher
void test_complex_from_tetrahedra()
{
  typedef GSM::Complex_from_tetrahedra_3<K> From;
  const std::string entry = "Complex_from_tetrahedra_3";
  auto make = [](std::vector<Point> points, std::vector<Tet> tets, std::vector<int> labels = {}, double angle = 60) {
    return [=] { From from(points, tets, labels, angle); };
  };
  std::vector<Point> nan_points = tet_points, inf_points = tet_points, flat_points = tet_points;
  nan_points[3] = Point(nan, 0, 1);
  inf_points[3] = Point(0, inf, 1);
  flat_points[3] = Point(1, 1, 0);
  refused(entry, "no tetrahedron", {"no tetrahedron"}, make(tet_points, {}));
  refused(entry, "NaN coordinate", {"finite"}, make(nan_points, one_tet));
  refused(entry, "infinite coordinate", {"finite"}, make(inf_points, one_tet));
  refused(entry, "flat tetrahedron", {"flat"}, make(flat_points, one_tet));
  refused(entry, "index out of range", {"vertex 7", "does not exist"}, make(tet_points, {Tet{{0, 1, 2, 7}}}));
  refused(entry, "labels of another size", {"labels"}, make(tet_points, one_tet, {1, 2}));
  refused(entry, "features angle NaN", {"features angle"}, make(tet_points, one_tet, {}, nan));
  refused(entry, "features angle 200", {"features angle"}, make(tet_points, one_tet, {}, 200));
  // two tets of opposite orientations
  std::vector<Point> two_points = tet_points;
  two_points.push_back(Point(1, 1, 1));
  refused(entry, "inverted and positive cells", {"orientation"}, make(two_points, {Tet{{0, 1, 2, 3}}, Tet{{2, 1, 3, 4}}}));
  // three tets on one facet
  std::vector<Point> fan = tet_points;
  fan.push_back(Point(0.3, 0.3, 2));
  fan.push_back(Point(0.3, 0.3, -1));
  refused(entry, "a facet of three cells", {"facet"},
          make(fan, {Tet{{0, 1, 2, 3}}, Tet{{0, 1, 2, 4}}, Tet{{0, 2, 1, 5}}}));
  // two tets that share one vertex only are taken (each has its own copy of it in the
  // triangulation, given back as one vertex)
  std::vector<Point> bowtie = tet_points;
  for(const Point& p : {Point(0, 0, 0), Point(-1, 0, 0), Point(0, -1, 0), Point(0, 0, -1)}) bowtie.push_back(p);
  {
    From from(bowtie, {Tet{{0, 1, 2, 3}}, Tet{{0, 6, 5, 7}}});
    std::vector<Point> points;
    std::vector<Tet> tets;
    std::vector<int> labels;
    from.get_tetrahedra(points, tets, labels);
    vvm_test::check(from.c3t3().triangulation().number_of_vertices() == 8 && points.size() == 7 && tets.size() == 2,
                    "Complex_from_tetrahedra_3 on two tets that share a vertex", __FILE__, __LINE__);
  }
  refused(entry, "two vertices at one point", {"same point"}, make(bowtie, {Tet{{0, 1, 2, 3}}, Tet{{4, 6, 5, 7}}}));
  // a ring of cells around a vertex, which they all touch through their facets: the boundary
  // facets there form two fans (above and below), the vertex is not manifold
  std::vector<Point> ring{Point(0, 0, 0)};
  for(double z : {0.5, -0.5})
    for(int i = 0; i < 6; ++i) ring.push_back(Point(std::cos(i * CGAL_PI / 3), std::sin(i * CGAL_PI / 3), z));
  std::vector<Tet> ring_cells;
  for(std::size_t i = 0; i < 6; ++i) {
    const std::size_t p = 1 + i, pn = 1 + (i + 1) % 6, r = 7 + i, rn = 7 + (i + 1) % 6;
    ring_cells.push_back(Tet{{p, 0, pn, r}});
    ring_cells.push_back(Tet{{pn, 0, rn, r}});
  }
  refused(entry, "non-manifold vertex", {"manifold"}, make(ring, ring_cells));
}

// ---------------------------------------------------------------------------------------------
// Lattices and hex-dominant meshes: the shared request checks through each entry point

template <class Call>
void lattice_requests(const std::string& entry, const Call& call)
{
  const Domain domain = sphere_domain();
  const Constant_field identity;
  refused(entry, "empty domain", {"empty"}, [&] { call(empty_domain(), identity, TLM::parameters::number_of_particles(std::size_t(500))); });
  refused(entry, "number_of_particles 0", {"number of particles"}, [&] { call(domain, identity, TLM::parameters::number_of_particles(std::size_t(0))); });
  refused(entry, "number_of_particles 10^15 (memory)", {"particles"}, [&] { call(domain, identity, TLM::parameters::number_of_particles(std::size_t(1e15))); });
  // a count allowed in general that this machine's memory cannot hold: refused before any work
  const double over_memory = 1.5 * TLM::internal::physical_memory() / TLM::bytes_per_particle;
  if(over_memory > 0 && over_memory <= TLM::maximum_number_of_particles)
    refused(entry, "number_of_particles over the machine's memory", {"number_of_particles", "more than this machine's", "GB"},
            [&] { call(domain, identity, TLM::parameters::number_of_particles(std::size_t(over_memory))); });
  else
    std::cout << entry << ": this machine holds the largest particle count; no memory refusal to test\n";
  refused(entry, "edge_length 0", {"edge length"}, [&] { call(domain, identity, TLM::parameters::edge_length(0.)); });
  refused(entry, "edge_length -1", {"edge length"}, [&] { call(domain, identity, TLM::parameters::edge_length(-1.)); });
  refused(entry, "edge_length NaN", {"edge length"}, [&] { call(domain, identity, TLM::parameters::edge_length(nan)); });
  refused(entry, "edge_length inf", {"edge length"}, [&] { call(domain, identity, TLM::parameters::edge_length(inf)); });
  refused(entry, "edge_length 1e-6 (memory)", {"edge length", "particles"}, [&] { call(domain, identity, TLM::parameters::edge_length(1e-6)); });
  refused(entry, "edge_length 100 (larger than the domain)", {"edge length"}, [&] { call(domain, identity, TLM::parameters::edge_length(100.)); });
  refused(entry, "kernel_width NaN", {"kernel width"}, [&] { call(domain, identity, TLM::parameters::kernel_width(nan)); });
  refused(entry, "neighbor_radius -1", {"neighbour radius"}, [&] { call(domain, identity, TLM::parameters::neighbor_radius(-1.)); });
  refused(entry, "multiresolution_levels -1", {"multiresolution levels"}, [&] { call(domain, identity, TLM::parameters::multiresolution_levels(-1)); });
  refused(entry, "number_of_iterations -1", {"rounds"}, [&] { call(domain, identity, params::number_of_iterations(-1)); });
  refused(entry, "maximum_running_time -1", {"time limit"}, [&] { call(domain, identity, params::maximum_running_time(-1.)); });
  refused(entry, "maximum_running_time NaN", {"time limit"}, [&] { call(domain, identity, params::maximum_running_time(nan)); });
  refused(entry, "number_of_threads -1", {"threads"}, [&] { call(domain, identity, TLM::parameters::number_of_threads(-1)); });
  refused(entry, "singular frame field", {"frame"}, [&] { call(domain, matrix_field(singular), TLM::parameters::number_of_particles(std::size_t(500))); });
  refused(entry, "NaN frame field", {"frame"}, [&] { call(domain, matrix_field(not_finite), TLM::parameters::number_of_particles(std::size_t(500))); });
}

void test_lattice()
{
  lattice_requests("lattice_particles_3", [](const Domain& d, const auto& field, const auto& np) {
    CGAL::lattice_particles_3(d, field, np);
  });
  lattice_requests("make_lattice_mesh_3", [](const Domain& d, const auto& field, const auto& np) {
    CGAL::make_lattice_mesh_3<C3T3>(d, field, np);
  });
  refused("make_lattice_mesh_3", "sliver_bound NaN", {"sliver bound"}, [] {
    CGAL::make_lattice_mesh_3<C3T3>(sphere_domain(), Constant_field(), GSM::parameters::sliver_bound(nan));
  });
}

void test_hex_dominant()
{
  lattice_requests("make_hex_dominant_mesh_3", [](const Domain& d, const auto& field, const auto& np) {
    CGAL::make_hex_dominant_mesh_3<C3T3>(d, field, np);
  });
  const std::string entry = "make_hex_dominant_mesh_3";
  const Domain domain = sphere_domain();
  refused(entry, "quality_bound NaN", {"quality bound"}, [&] { CGAL::make_hex_dominant_mesh_3<C3T3>(domain, Constant_field(), HDM::parameters::quality_bound(nan)); });
  refused(entry, "quality_bound 2", {"quality bound"}, [&] { CGAL::make_hex_dominant_mesh_3<C3T3>(domain, Constant_field(), HDM::parameters::quality_bound(2.)); });
  refused(entry, "boundary_distance -1", {"boundary distance"}, [&] { CGAL::make_hex_dominant_mesh_3<C3T3>(domain, Constant_field(), HDM::parameters::boundary_distance(-1.)); });
  refused(entry, "BCC lattice", {"cubic lattice"}, [&] { CGAL::make_hex_dominant_mesh_3<C3T3>(domain, Constant_field(), TLM::parameters::lattice(TLM::Lattice_type::BCC)); });
  refused(entry, "maximum_size_ratio 0.5", {"maximum_size_ratio"}, [&] { CGAL::make_hex_dominant_mesh_3<C3T3>(domain, Constant_field(), CGAL::Frame_fields::parameters::maximum_size_ratio(0.5)); });
  refused(entry, "maximum_size_ratio NaN", {"maximum_size_ratio"}, [&] { CGAL::make_hex_dominant_mesh_3<C3T3>(domain, Constant_field(), CGAL::Frame_fields::parameters::maximum_size_ratio(nan)); });

  const std::string tets = "tets_to_hex_dominant (indices)";
  std::vector<Point> nan_points = tet_points, flat_points = tet_points;
  nan_points[0] = Point(nan, 0, 0);
  flat_points[3] = Point(1, 1, 0);
  refused(tets, "NaN coordinate", {"non-finite"}, [&] { CGAL::tets_to_hex_dominant(nan_points, one_tet); });
  refused(tets, "flat tet", {"flat"}, [&] { CGAL::tets_to_hex_dominant(flat_points, one_tet); });
  refused(tets, "index out of range", {"no point"}, [&] { CGAL::tets_to_hex_dominant(tet_points, {Tet{{0, 1, 2, 9}}}); });
  refused(tets, "subdomains of another size", {"subdomain"}, [&] { CGAL::tets_to_hex_dominant(tet_points, one_tet, {1, 2}); });
  refused(tets, "quality_bound NaN", {"quality bound"}, [&] { CGAL::tets_to_hex_dominant(tet_points, one_tet, {}, HDM::parameters::quality_bound(nan)); });
  refused(tets, "number_of_threads -1", {"threads"}, [&] { CGAL::tets_to_hex_dominant(tet_points, one_tet, {}, TLM::parameters::number_of_threads(-1)); });
  auto empty_mesh = [](const CGAL::Hex_dominant_mesh_3<Point>& m) { return m.cells.empty(); };
  documented(tets, "no tet", "an empty mesh", [&] { return CGAL::tets_to_hex_dominant(tet_points, std::vector<Tet>()); },
             empty_mesh);
  documented("tets_to_hex_dominant (triangulation)", "empty triangulation", "an empty mesh",
             [&] { return CGAL::tets_to_hex_dominant(CGAL::Delaunay_triangulation_3<K>()); }, empty_mesh);
}

// ---------------------------------------------------------------------------------------------
// Frame fields

void test_frame_fields()
{
  const std::string generate = "generate_cross_field_3";
  const C3T3& c3t3 = sphere_mesh();
  const std::uint64_t hash = vvm_test::complex_hash(c3t3);
  auto same = [&] { return vvm_test::complex_hash(c3t3) == hash ? std::uint64_t(0) : std::uint64_t(1); };
  refused(generate, "empty complex", {"no cell"}, [] { CGAL::Frame_fields::generate_cross_field_3(C3T3()); });
  refused(generate, "number_of_iterations -1", {"iterations"}, [&] { CGAL::Frame_fields::generate_cross_field_3(c3t3, params::number_of_iterations(-1)); }, same);
  refused(generate, "smoothing_tolerance NaN", {"tolerance"}, [&] { CGAL::Frame_fields::generate_cross_field_3(c3t3, CGAL::Frame_fields::parameters::smoothing_tolerance(nan)); }, same);
  refused(generate, "axis_length 0", {"axis_length"}, [&] { CGAL::Frame_fields::generate_cross_field_3(c3t3, CGAL::Frame_fields::parameters::axis_length(0.)); }, same);
  refused(generate, "axis_length NaN", {"axis_length"}, [&] { CGAL::Frame_fields::generate_cross_field_3(c3t3, CGAL::Frame_fields::parameters::axis_length(nan)); }, same);
  refused(generate, "NaN coordinate", {"finite"}, [&] { CGAL::Frame_fields::generate_cross_field_3(nan_mesh()); });
  const std::string on_tr = "generate_cross_field_3 (triangulation)";
  CGAL::Delaunay_triangulation_3<K> cube;
  for(int i = 0; i < 27; ++i) cube.insert(Point(i % 3, (i / 3) % 3, i / 9));
  refused(on_tr, "empty triangulation", {"no cell"}, [] { CGAL::Frame_fields::generate_cross_field_3(CGAL::Delaunay_triangulation_3<K>()); });
  refused(on_tr, "features_angle -1", {"features_angle"}, [&] { CGAL::Frame_fields::generate_cross_field_3(cube, CGAL::Frame_fields::parameters::features_angle(-1.)); });
  refused(on_tr, "features_angle NaN", {"features_angle"}, [&] { CGAL::Frame_fields::generate_cross_field_3(cube, CGAL::Frame_fields::parameters::features_angle(nan)); });

  const std::string discrete = "Discrete_frame_field_3";
  typedef CGAL::Frame_fields::Frame_location Location;
  const std::vector<Eigen::Matrix3d> identities(4, Eigen::Matrix3d::Identity());
  std::vector<Point> nan_points = tet_points, far_points = tet_points;
  nan_points[1] = Point(nan, 0, 0);
  far_points[1] = Point(1e300, 0, 0);
  std::vector<Eigen::Matrix3d> singular_frames = identities, nan_frames = identities;
  singular_frames[2] = singular;
  nan_frames[2] = not_finite;
  const std::vector<Discrete_field::Cell> cells(1, Discrete_field::Cell{{0, 1, 2, 3}});
  refused(discrete, "no vertex", {"no vertex"}, [&] { Discrete_field({}, {}, {}, Location::VERTICES); });
  refused(discrete, "frames of another count", {"frames for"}, [&] { Discrete_field(tet_points, cells, {Eigen::Matrix3d::Identity()}, Location::VERTICES); });
  refused(discrete, "NaN coordinate", {"non-finite"}, [&] { Discrete_field(nan_points, cells, identities, Location::VERTICES); });
  refused(discrete, "coordinate 1e300", {"1e100"}, [&] { Discrete_field(far_points, cells, identities, Location::VERTICES); });
  refused(discrete, "index out of range", {"vertex 8"}, [&] { Discrete_field(tet_points, {Discrete_field::Cell{{0, 1, 2, 8}}}, identities, Location::VERTICES); });
  refused(discrete, "singular frame", {"frame"}, [&] { Discrete_field(tet_points, cells, singular_frames, Location::VERTICES); });
  refused(discrete, "NaN frame", {"frame"}, [&] { Discrete_field(tet_points, cells, nan_frames, Location::VERTICES); });

  const std::string text = "IO::read_frame_field";
  auto read = [](const std::string& s) {
    return [s] {
      std::istringstream is(s);
      CGAL::Frame_fields::IO::read_frame_field<K>(is);
    };
  };
  refused(text, "empty text", {"read_frame_field", "end of file"}, read(""));
  refused(text, "NaN coordinate", {"non-finite"},
          read("VVMFrameField 1\nLocation Vertices\nVertices\n1\nnan 0 0\nTetrahedra\n0\nFrames\n1\n1 0 0 0 1 0 0 0 1\nEnd\n"));
  refused(text, "singular frame", {"degenerate frame"},
          read("VVMFrameField 1\nLocation Vertices\nVertices\n1\n0 0 0\nTetrahedra\n0\nFrames\n1\n1 0 0 0 1 0 0 0 0\nEnd\n"));
}

// ---------------------------------------------------------------------------------------------
// Files

void test_files()
{
  Surface_mesh surface;
  auto read_surface = [&](const std::string& file) {
    return [&surface, file] { GSM::IO::read_closed_surface(file, surface); };
  };
  const std::string surfaces = "IO::read_closed_surface";
  refused(surfaces, "missing file", {"missing.off"}, read_surface("missing.off"));
  refused(surfaces, "empty file", {"empty.off"}, read_surface(write_file("empty.off", "")));
  refused(surfaces, "open surface", {"open"}, read_surface(write_file("open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")));
  refused(surfaces, "NaN coordinate", {"nan.off"},
          read_surface(write_file("nan.off", "OFF\n4 4 0\nnan 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")));
  refused(surfaces, "PLY face of 4294967295 vertices", {"huge.ply", "4294967295"},
          read_surface(write_file("huge.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                              "property float y\nproperty float z\nelement face 4\n"
                                              "property list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
                                              "0 1 0\n0 0 1\n4294967295 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")));
  refused(surfaces, "OFF header of 10^9 vertices", {"huge.off", "more vertices"},
          read_surface(write_file("huge.off", "OFF\n1000000000 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n")));
  {
    // a binary OFF tetrahedron whose first face declares 2^31 - 1 vertices (big-endian int32s)
    std::string binary = "OFF BINARY\n";
    auto put = [&binary](std::uint32_t word) {
      for(int shift = 24; shift >= 0; shift -= 8) binary += char((word >> shift) & 0xff);
    };
    for(std::uint32_t count : {4u, 4u, 0u}) put(count);
    for(float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f}) {
      std::uint32_t word;
      std::memcpy(&word, &c, 4);
      put(word);
    }
    for(std::uint32_t index : {0x7fffffffu, 0u, 2u, 1u}) put(index);
    refused(surfaces, "binary OFF face of 2^31 - 1 vertices", {"binary.off", "2147483647"},
            read_surface(write_file("binary.off", binary)));
  }
  refused(surfaces, "flat closed surface", {"flat.off"},
          read_surface(write_file("flat.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")));

  const std::string soup = "IO::closed_surface_from_polygon_soup";
  auto from_soup = [&](std::vector<Point> points, std::vector<std::vector<std::size_t>> faces) {
    return [&surface, points, faces] { GSM::IO::closed_surface_from_polygon_soup(points, faces, surface); };
  };
  std::vector<Point> nan_points = octahedron_points;
  nan_points[0] = Point(nan, 0, 0);
  std::vector<std::vector<std::size_t>> open_faces = octahedron_faces, out_of_range = octahedron_faces;
  open_faces.pop_back();
  out_of_range[0][0] = 17;
  std::vector<std::vector<std::size_t>> two_octahedra = octahedron_faces; // sharing vertex 0
  std::vector<Point> two_points = octahedron_points;
  for(const Point& p : {Point(3, 0, 0), Point(2, 1, 0), Point(2, -1, 0), Point(2, 0, 1), Point(2, 0, -1)}) two_points.push_back(p);
  const std::size_t m[6] = {6, 0, 7, 8, 9, 10}; // 0 <-> the second one's (-1, 0, 0) corner
  for(const auto& f : octahedron_faces) two_octahedra.push_back({m[f[0]], m[f[1]], m[f[2]]});
  refused(soup, "no face", {"no face"}, from_soup(octahedron_points, {}));
  refused(soup, "index out of range", {"out of range"}, from_soup(octahedron_points, out_of_range));
  refused(soup, "NaN coordinate", {"non-finite"}, from_soup(nan_points, octahedron_faces));
  refused(soup, "open surface", {"open"}, from_soup(octahedron_points, open_faces));
  refused(soup, "non-manifold vertex", {"polygon mesh"}, from_soup(two_points, two_octahedra));
  std::vector<Point> two_tets = tet_points;
  for(const Point& p : tet_points) two_tets.push_back(p + K::Vector_3(0.2, 0.2, 0.2));
  std::vector<std::vector<std::size_t>> two_tet_faces;
  for(std::size_t o : {0, 4})
    for(const auto& f : {std::array<std::size_t, 3>{{0, 2, 1}}, {{0, 1, 3}}, {{0, 3, 2}}, {{1, 2, 3}}})
      two_tet_faces.push_back({o + f[0], o + f[1], o + f[2]});
  refused(soup, "self-intersecting surface", {"self-intersects"}, from_soup(two_tets, two_tet_faces));

  const std::string volume = "IO::read_volume_mesh";
  CGAL::Hex_dominant_mesh_3<Point> mesh;
  auto read_mesh = [&](const std::string& file) {
    return [&mesh, file] { HDM::IO::read_volume_mesh(file, mesh); };
  };
  refused(volume, "missing file", {"missing.mesh"}, read_mesh("missing.mesh"));
  refused(volume, "empty file", {"empty.mesh"}, read_mesh(write_file("empty.mesh", "")));
  refused(volume, "unknown extension", {"extension"}, read_mesh(write_file("mesh.xyz", "")));
  refused(volume, "NaN coordinate", {"finite"},
          read_mesh(write_file("nan.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n4\nnan 0 0 0\n1 0 0 0\n0 1 0 0\n"
                                           "0 0 1 0\nTetrahedra\n1\n1 2 3 4 1\nEnd\n")));
  refused(volume, "index out of range", {"range"},
          read_mesh(write_file("range.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
                                             "0 0 1 0\nTetrahedra\n1\n1 2 3 9 1\nEnd\n")));
}

// ---------------------------------------------------------------------------------------------
// Stopping: every entry point under a time limit that is up at once, and with a visitor that
// asks to stop at its first call, gives a valid result and says why it stopped

bool valid_complex(const C3T3& c3t3)
{
  const auto q = CGAL::GSM_mesh_optimization::mesh_quality_statistics(c3t3);
  // combinatorial validity: GSM's flips leave a triangulation that is not regular on purpose
  return c3t3.triangulation().tds().is_valid() && c3t3.number_of_cells_in_complex() > 0 &&
         q.number_of_inverted_cells == 0;
}

bool all_tetrahedra(const CGAL::Hex_dominant_mesh_3<Point>& mesh, std::size_t number_of_tets)
{
  const HDM::Hex_dominant_statistics s = HDM::hex_dominant_statistics(mesh);
  return s.number_of_tetrahedra == number_of_tets && mesh.cells.size() == number_of_tets && s.number_of_inverted_cells == 0;
}

void test_stopping()
{
  const Domain domain = sphere_domain();
  const Constant_field identity;
  const double now = 1e-9; // seconds: up before the first check
  const auto few = TLM::parameters::number_of_particles(std::size_t(600));
  int calls = 0;
  auto stop_at_once = [&calls](const auto&...) {
    ++calls;
    return false;
  };

  { // GSM
    C3T3 timed = sphere_mesh(), visited = sphere_mesh();
    VVM_CHECK(CGAL::gsm_optimize_mesh_3(timed, domain, params::maximum_running_time(now)) == CGAL::TIME_LIMIT_REACHED);
    VVM_CHECK(valid_complex(timed));
    calls = 0;
    VVM_CHECK(CGAL::gsm_optimize_mesh_3(visited, domain, params::visitor(stop_at_once)) ==
              CGAL::MAX_ITERATION_NUMBER_REACHED);
    VVM_CHECK_EQUAL(calls, 1);
    VVM_CHECK(valid_complex(visited));
    // 0 is no limit, as in CGAL's optimizers
    documented("gsm_optimize_mesh_3", "maximum_running_time 0", "no time limit (CGAL's convention)", [&] {
      C3T3 c3t3 = sphere_mesh();
      return CGAL::gsm_optimize_mesh_3(c3t3, domain, params::maximum_running_time(0.));
    }, [](CGAL::Mesh_optimization_return_code code) { return code != CGAL::TIME_LIMIT_REACHED; });
  }
  { // particles
    const auto timed = CGAL::lattice_particles_3(domain, identity, few.maximum_running_time(now));
    VVM_CHECK(timed.time_limit_reached && !timed.stopped_by_visitor && timed.size() > 0);
    calls = 0;
    const auto visited = CGAL::lattice_particles_3(domain, identity, few.visitor(stop_at_once));
    VVM_CHECK(visited.stopped_by_visitor && !visited.time_limit_reached && visited.size() > 0);
    VVM_CHECK_EQUAL(calls, 1);
  }
  { // lattice meshes, with the generated field too (its smoothing is a stage)
    TLM::Lattice_mesh_report r;
    const C3T3 timed = CGAL::make_lattice_mesh_3<C3T3>(domain, identity,
        TLM::parameters::report(&r, few.maximum_running_time(now)));
    VVM_CHECK(r.time_limit_reached && !r.stopped_by_visitor && r.gsm_time == 0);
    VVM_CHECK(valid_complex(timed));
    const C3T3 timed_field = CGAL::make_lattice_mesh_3<C3T3>(domain,
        TLM::parameters::report(&r, few.maximum_running_time(now)));
    VVM_CHECK(r.time_limit_reached && r.gsm_time == 0);
    VVM_CHECK(valid_complex(timed_field));
    calls = 0;
    const C3T3 visited = CGAL::make_lattice_mesh_3<C3T3>(domain, identity,
        TLM::parameters::report(&r, few.visitor(stop_at_once)));
    VVM_CHECK(r.stopped_by_visitor && !r.time_limit_reached && r.gsm_time == 0);
    VVM_CHECK_EQUAL(calls, 1);
    VVM_CHECK(valid_complex(visited));
  }
  { // hex-dominant meshes: the tets stay tetrahedra
    HDM::Hex_dominant_report r;
    const auto timed = CGAL::make_hex_dominant_mesh_3<C3T3>(domain, identity,
        HDM::parameters::report(&r, few.maximum_running_time(now)));
    VVM_CHECK(r.time_limit_reached && !r.stopped_by_visitor && r.merge.stopped);
    VVM_CHECK(all_tetrahedra(timed, r.merge.number_of_tets));
    calls = 0;
    C3T3 tets;
    const auto visited = CGAL::make_hex_dominant_mesh_3<C3T3>(domain, identity,
        HDM::parameters::report(&r, HDM::parameters::tetrahedral_mesh(&tets, few.visitor(stop_at_once))));
    VVM_CHECK(r.stopped_by_visitor && !r.time_limit_reached && r.merge.stopped);
    VVM_CHECK_EQUAL(calls, 1); // not told of anything after its stop
    VVM_CHECK(all_tetrahedra(visited, r.merge.number_of_tets));
    // the deprecated stage visitor: told of each stage, whatever it returned
    calls = 0;
    const auto staged = CGAL::make_hex_dominant_mesh_3<C3T3>(domain, identity,
        HDM::parameters::report(&r, HDM::parameters::stage_visitor(stop_at_once, few)));
    VVM_CHECK(r.stopped_by_visitor && !r.time_limit_reached && r.merge.stopped);
    VVM_CHECK_EQUAL(calls, 3);
    VVM_CHECK(all_tetrahedra(staged, r.merge.number_of_tets));

    // tets_to_hex_dominant on the same tets: hexahedra without a limit, none with one up at once
    HDM::Hex_dominant_merge_report m;
    const auto merged = CGAL::tets_to_hex_dominant(tets, HDM::parameters::report(&m));
    VVM_CHECK(!m.stopped && HDM::hex_dominant_statistics(merged).number_of_hexahedra > 0);
    const auto cut = CGAL::tets_to_hex_dominant(tets, HDM::parameters::report(&m, params::maximum_running_time(now)));
    VVM_CHECK(m.stopped);
    VVM_CHECK(all_tetrahedra(cut, m.number_of_tets));
    refused("tets_to_hex_dominant", "maximum_running_time -1", {"maximum_running_time"},
            [&] { CGAL::tets_to_hex_dominant(tets, params::maximum_running_time(-1.)); });
  }
  { // cross fields: the field of the least-squares solve, or of the rounds run
    const C3T3& c3t3 = sphere_mesh();
    const auto timed = CGAL::Frame_fields::generate_cross_field_3(c3t3, params::maximum_running_time(now));
    VVM_CHECK(timed.time_limit_reached && !timed.stopped_by_visitor);
    VVM_CHECK_EQUAL(timed.round_energies.size(), std::size_t(1));
    VVM_CHECK(timed.field.frames().size() == timed.field.points().size() && !timed.field.points().empty());
    calls = 0;
    const auto visited = CGAL::Frame_fields::generate_cross_field_3(c3t3, params::visitor(stop_at_once));
    VVM_CHECK(visited.stopped_by_visitor && !visited.time_limit_reached);
    VVM_CHECK_EQUAL(visited.round_energies.size(), std::size_t(2));
    VVM_CHECK_EQUAL(calls, 1);
    refused("generate_cross_field_3", "maximum_running_time -1", {"maximum_running_time"},
            [&] { CGAL::Frame_fields::generate_cross_field_3(c3t3, params::maximum_running_time(-1.)); });
  }
}

// The reports one visitor taking `const VVM::Stage_report&` is given by an entry point: each
// stage's rounds, then its end, in blocks; the stages whose end came, in order.
struct Stage_log
{
  std::vector<CGAL::VVM::Stage_report> seen;
  bool (*stop)(const CGAL::VVM::Stage_report&) = nullptr;

  auto visitor()
  {
    return [this](const CGAL::VVM::Stage_report& r) {
      seen.push_back(r);
      return !(stop && stop(r));
    };
  }
  std::vector<CGAL::VVM::Stage> ends() const
  {
    std::vector<CGAL::VVM::Stage> e;
    for(const auto& r : seen)
      if(r.stage_done) e.push_back(r.stage);
    return e;
  }
  int rounds(CGAL::VVM::Stage s) const
  {
    int n = 0;
    for(const auto& r : seen) n += !r.stage_done && r.stage == s;
    return n;
  }
  // every round is followed by a round of its stage or by the stage's end; each end reports the
  // rounds before it (the particles count theirs from 1 at each level)
  bool in_blocks() const
  {
    int block = 0;
    for(std::size_t i = 0; i < seen.size(); ++i) {
      if(seen[i].stage_done) {
        if(seen[i].stage != CGAL::VVM::Stage::PARTICLES && seen[i].round != block) return false;
        block = 0;
        continue;
      }
      ++block;
      if(i + 1 == seen.size() || seen[i + 1].stage != seen[i].stage) return false;
    }
    return true;
  }
};

// One visitor for every entry point (a callable taking `const VVM::Stage_report&`) is told of
// each stage's rounds and end, in order, and the reports agree with what it saw; a stop at a
// stage's end keeps the stages after it from running
void test_stage_reports()
{
  typedef CGAL::VVM::Stage Stage;
  const Domain domain = sphere_domain();
  const Constant_field identity;
  const auto few = TLM::parameters::number_of_particles(std::size_t(600));

  { // GSM: its rounds, then its polishing
    C3T3 c3t3 = sphere_mesh();
    Stage_log log;
    GSM::Optimization_report r;
    const auto code = CGAL::gsm_optimize_mesh_3(c3t3, domain, GSM::parameters::report(&r, params::visitor(log.visitor())));
    VVM_CHECK(log.ends() == std::vector<Stage>({Stage::OPTIMIZATION, Stage::POLISHING}));
    VVM_CHECK(log.in_blocks());
    VVM_CHECK_EQUAL(r.number_of_rounds, log.rounds(Stage::OPTIMIZATION));
    VVM_CHECK_EQUAL(r.number_of_polishing_rounds, log.rounds(Stage::POLISHING));
    VVM_CHECK(r.number_of_rounds > 0 && r.number_of_moves > 0 && r.return_code == code && r.time > 0);
    VVM_CHECK(!r.stopped_by_visitor && !r.time_limit_reached);
    const auto q = GSM::mesh_quality_statistics(c3t3);
    VVM_CHECK_EQUAL(r.min_dihedral_angle, q.min_dihedral_angle); // after the last round: the result's
    // a report alone, without a visitor, is the same
    C3T3 again = sphere_mesh();
    GSM::Optimization_report alone;
    CGAL::gsm_optimize_mesh_3(again, domain, GSM::parameters::report(&alone));
    VVM_CHECK(alone.number_of_rounds == r.number_of_rounds && alone.number_of_moves == r.number_of_moves &&
              alone.min_dihedral_angle == r.min_dihedral_angle);
  }
  { // particles
    Stage_log log;
    const auto p = CGAL::lattice_particles_3(domain, identity, few.visitor(log.visitor()));
    VVM_CHECK(log.ends() == std::vector<Stage>({Stage::PARTICLES}));
    VVM_CHECK(log.in_blocks());
    VVM_CHECK(log.rounds(Stage::PARTICLES) == p.number_of_rounds && log.seen.back().round == p.number_of_rounds);
  }
  { // lattice meshes: particles, tets, then GSM's flips and polishing; a stop after the tets
    Stage_log log;
    TLM::Lattice_mesh_report r;
    const C3T3 c3t3 = CGAL::make_lattice_mesh_3<C3T3>(domain, identity, TLM::parameters::report(&r, few.visitor(log.visitor())));
    VVM_CHECK(log.ends() ==
              std::vector<Stage>({Stage::PARTICLES, Stage::TETRAHEDRA, Stage::OPTIMIZATION, Stage::POLISHING}));
    VVM_CHECK(log.in_blocks());
    VVM_CHECK(!r.stopped_by_visitor && r.gsm_time > 0 && valid_complex(c3t3));
    Stage_log stopped;
    stopped.stop = [](const CGAL::VVM::Stage_report& e) { return e.stage_done && e.stage == CGAL::VVM::Stage::TETRAHEDRA; };
    const C3T3 tets = CGAL::make_lattice_mesh_3<C3T3>(domain, identity, TLM::parameters::report(&r, few.visitor(stopped.visitor())));
    VVM_CHECK(stopped.ends() == std::vector<Stage>({Stage::PARTICLES, Stage::TETRAHEDRA}));
    VVM_CHECK(r.stopped_by_visitor && r.gsm_time == 0 && valid_complex(tets));
  }
  { // hex-dominant meshes, and the merging alone
    Stage_log log;
    HDM::Hex_dominant_report r;
    C3T3 tets;
    CGAL::make_hex_dominant_mesh_3<C3T3>(domain, identity,
        HDM::parameters::report(&r, HDM::parameters::tetrahedral_mesh(&tets, few.visitor(log.visitor()))));
    VVM_CHECK(log.ends() == std::vector<Stage>({Stage::PARTICLES, Stage::TETRAHEDRA, Stage::MERGING}));
    VVM_CHECK(log.in_blocks());
    VVM_CHECK(!r.stopped_by_visitor && r.merge.number_of_tets > 0);
    Stage_log merging;
    CGAL::tets_to_hex_dominant(tets, params::visitor(merging.visitor()));
    VVM_CHECK(merging.ends() == std::vector<Stage>({Stage::MERGING}) && merging.seen.size() == 1);
  }
  { // cross fields: the rounds' reports carry the energies of the result
    Stage_log log;
    std::vector<double> energies;
    const auto g = CGAL::Frame_fields::generate_cross_field_3(sphere_mesh(), params::visitor(log.visitor()));
    const auto h = CGAL::Frame_fields::generate_cross_field_3(sphere_mesh(), params::visitor(
        [&energies](const CGAL::Frame_fields::Cross_field_round_report& r) { energies.push_back(r.energy); }));
    VVM_CHECK(log.ends() == std::vector<Stage>({Stage::FRAME_FIELD}));
    VVM_CHECK(log.in_blocks());
    VVM_CHECK_EQUAL(std::size_t(log.rounds(Stage::FRAME_FIELD)) + 1, g.round_energies.size());
    VVM_CHECK(energies == std::vector<double>(h.round_energies.begin() + 1, h.round_energies.end()));
  }
  { // the former names of the report parameters still work
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    TLM::Lattice_mesh_report r;
    CGAL::make_lattice_mesh_3<C3T3>(domain, identity, TLM::parameters::mesh_report(&r, few));
    VVM_CHECK(r.number_of_particles > 0);
#pragma GCC diagnostic pop
  }
}

} // namespace

int main(int argc, char** argv)
{
  std::cout << "| entry point | bad input | outcome |\n|---|---|---|\n";
  return vvm_test::run(argc, argv, "test_bad_inputs", {
      {"gsm", test_gsm},
      {"complex_from_tetrahedra", test_complex_from_tetrahedra},
      {"lattice", test_lattice},
      {"hex_dominant", test_hex_dominant},
      {"frame_fields", test_frame_fields},
      {"files", test_files},
      {"stopping", test_stopping},
      {"stage_reports", test_stage_reports}});
}
