// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Speed of matching (symmetry_descriptor.h): the cost of comparing two descriptors, bull.off
// against armadillo.off (CGAL's sample data, libcgal-demo), at 32^3 (the target: <= 20 us per
// comparison; the thesis quotes 0.1 ms) and 64^3, for the PRST part
// (reflective_symmetry_descriptor_distance), the GEDT part (gedt_distance) and their product
// (descriptor_distance). Single-threaded.
//
// Two settings: "Pair" compares the same two descriptors again and again (both in cache);
// "Collection" compares a query with 256 distinct copies in turn, 64 MiB at 32^3, more than
// the caches hold, as ranking a large indexed collection does (the time is per comparison).
// The Time column is the time of one comparison. Computing the descriptors happens outside
// the timed loops.
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Symmetry_transform/symmetry_descriptor.h>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Symmetry_descriptor<K> Descriptor;

// Descriptors are computed once per mesh and resolution (2e5 Monte Carlo samples: the values,
// not their accuracy, matter here).
const Descriptor& descriptor(const std::string& name, int n)
{
  static std::map<std::pair<std::string, int>, std::unique_ptr<Descriptor>> cache;
  std::unique_ptr<Descriptor>& d = cache[{name, n}];
  if(!d) {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(mesh_path(name), m) || faces(m).empty())
      throw std::runtime_error("cannot read " + mesh_path(name) + " (run scripts/setup.sh)");
    d = std::make_unique<Descriptor>(
      ST::symmetry_descriptor(m, CGAL::parameters::grid_resolution(n).number_of_samples(200000)));
  }
  return *d;
}

template <typename Distance>
void Pair(benchmark::State& state, Distance distance)
{
  const int n = int(state.range(0));
  const Descriptor* a = nullptr;
  const Descriptor* b = nullptr;
  try {
    a = &descriptor("bull.off", n);
    b = &descriptor("armadillo.off", n);
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  for(auto _ : state) benchmark::DoNotOptimize(distance(*a, *b));
  state.SetItemsProcessed(std::int64_t(state.iterations())); // comparisons per second
}

void Collection(benchmark::State& state)
{
  const int n = int(state.range(0));
  std::vector<Descriptor> collection;
  const Descriptor* query = nullptr;
  try {
    query = &descriptor("bull.off", n);
    for(int i = 0; i < 256; ++i) collection.push_back(descriptor(i % 2 ? "bull.off" : "armadillo.off", n));
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  std::size_t next = 0;
  for(auto _ : state) {
    benchmark::DoNotOptimize(ST::descriptor_distance(*query, collection[next]));
    next = (next + 1) % collection.size();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations())); // comparisons per second
}

double prst_part(const Descriptor& a, const Descriptor& b) { return ST::reflective_symmetry_descriptor_distance(a, b); }
double gedt_part(const Descriptor& a, const Descriptor& b) { return ST::gedt_distance(a, b); }
double combined(const Descriptor& a, const Descriptor& b) { return ST::descriptor_distance(a, b); }

} // namespace

BENCHMARK_CAPTURE(Pair, reflective_symmetry_descriptor_distance, &prst_part)->Arg(32)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Pair, gedt_distance, &gedt_part)->Arg(32)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Pair, descriptor_distance, &combined)->Arg(32)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(Collection)->Arg(32)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
