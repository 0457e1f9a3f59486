// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hashes of the entry points' outputs for the determinism tests: equal hashes mean
// bit-identical coordinates, the same cells and the same labels.
// - A complex is hashed in a canonical order (its vertices sorted by their coordinates'
//   bits, its cells and facets by their sorted vertex numbers), so that two complexes that
//   hold the same mesh in a different order of their containers hash the same.
// - Outputs that are arrays (particles, hex-dominant meshes, frame fields) are hashed in
//   their order, which is part of what the caller gets.
// check_deterministic() compares the hashes of runs with 1, 2 and 4 threads and after another run.

#ifndef VVM_OUTPUT_HASH_H
#define VVM_OUTPUT_HASH_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "vvm_test.h"

namespace vvm_test {

/// FNV-1a, 64 bits
class Output_hash
{
public:
  void bytes(const void* data, std::size_t n)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for(std::size_t i = 0; i < n; ++i) value_ = (value_ ^ p[i]) * 1099511628211ull;
  }
  void add(double x) { bytes(&x, sizeof x); }
  void add(std::uint64_t x) { bytes(&x, sizeof x); }
  template <class Point_3>
  void add_point(const Point_3& p)
  {
    add(double(p.x()));
    add(double(p.y()));
    add(double(p.z()));
  }
  std::uint64_t value() const { return value_; }

private:
  std::uint64_t value_ = 14695981039346656037ull;
};

/// a surface patch index as two numbers: a pair of subdomain indices, or a number and 0
template <class A, class B>
std::tuple<std::uint64_t, std::uint64_t> patch_numbers(const std::pair<A, B>& index)
{
  return {std::uint64_t(index.first), std::uint64_t(index.second)};
}
template <class Index>
std::tuple<std::uint64_t, std::uint64_t> patch_numbers(const Index& index)
{
  return {std::uint64_t(index), 0};
}

/// the complex's finite vertices (points, dimensions), cells in the complex (vertices,
/// subdomain index) and facets in the complex (vertices, surface patch index)
template <class C3T3>
std::uint64_t complex_hash(const C3T3& c3t3)
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const Tr& tr = c3t3.triangulation();
  typedef std::array<double, 3> Coordinates;
  std::vector<std::pair<Coordinates, Vertex_handle>> vertices;
  for(Vertex_handle v : tr.finite_vertex_handles()) {
    const auto p = tr.point(v);
    vertices.push_back({{double(p.x()), double(p.y()), double(p.z())}, v});
  }
  // by the coordinates' bits: two points that compare equal as doubles (0 and -0) stay apart
  auto bits = [](const Coordinates& c) {
    std::array<std::uint64_t, 3> b;
    std::memcpy(b.data(), c.data(), sizeof b);
    return b;
  };
  std::sort(vertices.begin(), vertices.end(),
            [&](const auto& a, const auto& b) { return bits(a.first) < bits(b.first); });
  std::map<Vertex_handle, std::uint64_t> number;
  Output_hash h;
  for(const auto& pv : vertices) {
    number.emplace(pv.second, std::uint64_t(number.size()));
    for(double x : pv.first) h.add(x);
    h.add(std::uint64_t(pv.second->in_dimension()));
  }
  std::vector<std::array<std::uint64_t, 5>> cells;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<std::uint64_t, 5> cell;
    for(int i = 0; i < 4; ++i) cell[i] = number.at(c->vertex(i));
    std::sort(cell.begin(), cell.begin() + 4);
    cell[4] = std::uint64_t(c3t3.subdomain_index(c));
    cells.push_back(cell);
  }
  std::sort(cells.begin(), cells.end());
  for(const auto& cell : cells) h.bytes(cell.data(), sizeof cell);
  std::vector<std::array<std::uint64_t, 5>> facets;
  for(auto it = c3t3.facets_in_complex_begin(); it != c3t3.facets_in_complex_end(); ++it) {
    const auto f = *it;
    std::array<std::uint64_t, 5> facet;
    for(int i = 0, k = 0; i < 4; ++i)
      if(i != f.second) facet[k++] = number.at(f.first->vertex(i));
    std::sort(facet.begin(), facet.begin() + 3);
    std::tie(facet[3], facet[4]) = patch_numbers(c3t3.surface_patch_index(f));
    facets.push_back(facet);
  }
  std::sort(facets.begin(), facets.end());
  for(const auto& facet : facets) h.bytes(facet.data(), sizeof facet);
  return h.value();
}

/// the particles' points, kinds and features, in their order
template <class Particles>
std::uint64_t particles_hash(const Particles& particles)
{
  Output_hash h;
  for(const auto& p : particles.points) h.add_point(p);
  for(auto k : particles.kinds) h.add(std::uint64_t(k));
  for(int f : particles.features) h.add(std::uint64_t(f));
  return h.value();
}

/// a hex-dominant mesh's points and cells (type, vertices, subdomain), in their order
template <class Mesh>
std::uint64_t hex_dominant_hash(const Mesh& mesh)
{
  Output_hash h;
  for(const auto& p : mesh.points) h.add_point(p);
  for(const auto& c : mesh.cells) {
    h.add(std::uint64_t(c.type));
    for(std::size_t v : c) h.add(std::uint64_t(v));
    h.add(std::uint64_t(c.subdomain_index));
  }
  return h.value();
}

/// a discrete frame field's points, cells and frames, in their order
template <class Field>
std::uint64_t frame_field_hash(const Field& field)
{
  Output_hash h;
  for(const auto& p : field.points()) h.add_point(p);
  for(const auto& c : field.cells())
    for(auto v : c) h.add(std::uint64_t(v));
  for(const auto& T : field.frames()) h.bytes(T.data(), sizeof(double) * std::size_t(T.size()));
  return h.value();
}

/// fragments the heap (blocks of many sizes, every other one freed), so that what is
/// allocated next lies elsewhere and in another order of addresses than before
struct Fragmented_heap
{
  std::vector<std::vector<char>> blocks;
  Fragmented_heap()
  {
    for(int i = 0; i < 4000; ++i) blocks.emplace_back(std::size_t(64 + (i * 7919) % 20000));
    for(std::size_t i = 0; i < blocks.size(); i += 2) std::vector<char>().swap(blocks[i]);
  }
};

/// checks that `run(threads)`, the hash of an entry point's output, is the same for 1, 2 and
/// 4 threads and for 2 threads after `other()` ran in a fragmented heap; prints the hashes
template <class Run, class Other>
void check_deterministic(const char* name, const Run& run, const Other& other)
{
  const std::uint64_t one = run(1), two = run(2), four = run(4);
  std::uint64_t after_other = 0;
  {
    Fragmented_heap heap;
    other();
    after_other = run(2);
  }
  std::cout << name << ": output hash " << std::hex << one << " (1 thread), " << two << " (2), " << four
            << " (4), " << after_other << " (2, after another run)" << std::dec << "\n";
  VVM_CHECK(one == two);
  VVM_CHECK(one == four);
  VVM_CHECK(one == after_other);
}

} // namespace vvm_test

#endif // VVM_OUTPUT_HASH_H
