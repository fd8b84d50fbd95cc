// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Speed of the transforms of chapter 3 on real meshes (CGAL's sample data, libcgal-demo):
// GEDT, PST, exact PRST, Monte Carlo PRST (default estimator, 2e6 samples) and the end-to-end
// "GEDT + Monte Carlo PRST", for bull.off and armadillo.off at 32^3, 64^3 and 128^3.
//
// Times are wall-clock (the transforms use all cores), in ms; the "CPU" column is the CPU time
// of the whole process (all threads), which other programs on the machine disturb little: a
// wall time far above CPU time / number of cores reveals a disturbed run. Loading the mesh and computing
// the GEDT an operation starts from happen outside the timed loop, once per mesh and
// resolution.
//
// The exact PRST at 128^3 takes minutes per mesh (O(n^5 log n)): it is registered only when
// the environment variable SYMMETRY_TRANSFORM_BENCHMARK_EXACT_128 is set, e.g.
//   SYMMETRY_TRANSFORM_BENCHMARK_EXACT_128=1 ./benchmark_transforms --benchmark_filter=PRST_exact/.*/128
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Symmetry_transform::Voxel_grid<K> Grid;
namespace ST = CGAL::Symmetry_transform;

constexpr std::size_t monte_carlo_samples = 2000000;

// Meshes and GEDTs are computed once and kept: they are inputs, not what is measured.
const Mesh& mesh(const std::string& name)
{
  static std::map<std::string, std::unique_ptr<Mesh>> cache;
  std::unique_ptr<Mesh>& m = cache[name];
  if(!m) {
    m = std::make_unique<Mesh>();
    if(!CGAL::IO::read_polygon_mesh(mesh_path(name), *m) || faces(*m).empty())
      throw std::runtime_error("cannot read " + mesh_path(name) + " (run scripts/setup.sh)");
  }
  return *m;
}

const Grid& gedt(const std::string& name, int n)
{
  static std::map<std::pair<std::string, int>, std::unique_ptr<Grid>> cache;
  std::unique_ptr<Grid>& g = cache[{name, n}];
  if(!g) g = std::make_unique<Grid>(ST::gaussian_distance_transform(mesh(name), CGAL::parameters::grid_resolution(n)));
  return *g;
}

// Counters shared by all benchmarks: what the input is.
void describe(benchmark::State& state, const std::string& name, int n)
{
  const Grid& f = gedt(name, n);
  std::size_t non_zero = 0;
  for(double v : f.values()) non_zero += v != 0.;
  state.counters["faces"] = double(faces(mesh(name)).size());
  state.counters["nonzero_voxels"] = double(non_zero);
  state.counters["threads"] = double(std::max(1u, std::thread::hardware_concurrency()));
}

template <typename Body>
void run(benchmark::State& state, const std::string& name, const Body& body)
{
  const int n = int(state.range(0));
  try {
    describe(state, name, n); // loads the mesh and computes the GEDT, untimed
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  for(auto _ : state) body(n);
}

void GEDT(benchmark::State& state, const std::string& name)
{
  run(state, name, [&](int n) {
    Grid f = ST::gaussian_distance_transform(mesh(name), CGAL::parameters::grid_resolution(n));
    benchmark::DoNotOptimize(f.values().data());
  });
}

void PST(benchmark::State& state, const std::string& name)
{
  run(state, name, [&](int n) {
    auto pst = ST::point_symmetry_transform(gedt(name, n));
    benchmark::DoNotOptimize(pst.grid().values().data());
  });
}

void PRST_exact(benchmark::State& state, const std::string& name)
{
  run(state, name, [&](int n) {
    auto prst = ST::reflective_symmetry_transform(
      gedt(name, n), CGAL::parameters::prst_method(ST::Reflective_symmetry_method::EXACT));
    benchmark::DoNotOptimize(prst.values().data());
  });
}

// The default Monte Carlo estimator (STRATIFIED_LINES) with 2e6 samples.
void PRST_monte_carlo(benchmark::State& state, const std::string& name)
{
  run(state, name, [&](int n) {
    auto prst = ST::reflective_symmetry_transform(gedt(name, n), CGAL::parameters::number_of_samples(monte_carlo_samples));
    benchmark::DoNotOptimize(prst.values().data());
  });
  state.counters["samples"] = double(monte_carlo_samples);
}

// End to end from the mesh: what a user calling reflective_symmetry_transform(tm, np) waits.
void GEDT_plus_PRST_monte_carlo(benchmark::State& state, const std::string& name)
{
  run(state, name, [&](int n) {
    auto prst = ST::reflective_symmetry_transform(
      mesh(name), CGAL::parameters::grid_resolution(n).number_of_samples(monte_carlo_samples));
    benchmark::DoNotOptimize(prst.values().data());
  });
  state.counters["samples"] = double(monte_carlo_samples);
}

// The machine these figures come from is shared with other builds: besides the mean, median
// and standard deviation of the repetitions, report their minimum, the least disturbed.
double minimum(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// Fast operations: enough iterations for 1 s per repetition, 5 repetitions.
#define ST_FAST_BENCHMARK(function, label, file)                                                  \
  BENCHMARK_CAPTURE(function, label, std::string(file))                                           \
    ->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->MinTime(1.)        \
    ->Repetitions(5)->ComputeStatistics("min", minimum)->ReportAggregatesOnly(true)

ST_FAST_BENCHMARK(GEDT, bull, "bull.off");
ST_FAST_BENCHMARK(GEDT, armadillo, "armadillo.off");
ST_FAST_BENCHMARK(PST, bull, "bull.off");
ST_FAST_BENCHMARK(PST, armadillo, "armadillo.off");
ST_FAST_BENCHMARK(PRST_monte_carlo, bull, "bull.off");
ST_FAST_BENCHMARK(PRST_monte_carlo, armadillo, "armadillo.off");
ST_FAST_BENCHMARK(GEDT_plus_PRST_monte_carlo, bull, "bull.off");
ST_FAST_BENCHMARK(GEDT_plus_PRST_monte_carlo, armadillo, "armadillo.off");

// The exact PRST: 32^3 as the others; 64^3 takes seconds, so 3 single-iteration repetitions.
BENCHMARK_CAPTURE(PRST_exact, bull, std::string("bull.off"))
  ->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->MinTime(1.)->Repetitions(5)
  ->ComputeStatistics("min", minimum)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(PRST_exact, armadillo, std::string("armadillo.off"))
  ->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->MinTime(1.)->Repetitions(5)
  ->ComputeStatistics("min", minimum)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(PRST_exact, bull, std::string("bull.off"))
  ->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1)->Repetitions(3)
  ->ComputeStatistics("min", minimum)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(PRST_exact, armadillo, std::string("armadillo.off"))
  ->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1)->Repetitions(3)
  ->ComputeStatistics("min", minimum)->ReportAggregatesOnly(true);

// 128^3: one iteration, minutes each; only on request (see the head of this file).
const bool exact_128_registered = [] {
  if(std::getenv("SYMMETRY_TRANSFORM_BENCHMARK_EXACT_128") == nullptr) return false;
  for(const char* file : {"bull.off", "armadillo.off"}) {
    const std::string name(file);
    benchmark::RegisterBenchmark(("PRST_exact/" + name.substr(0, name.find('.'))).c_str(),
                                 [name](benchmark::State& state) { PRST_exact(state, name); })
      ->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
  }
  return true;
}();

} // namespace

BENCHMARK_MAIN();
