// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Quality of the Monte Carlo PRST against the exact one: the thesis's Figure 3.4 as a table.
//
// For each mesh and grid resolution: the GEDT, the exact PRST once (the reference), then for
// each Monte Carlo estimator and number of samples the time of the PRST alone (GEDT excluded)
// and, over all n^3 bins,
//   - the relative L2 error ||mc - exact|| / ||exact|| of the symmetry measure SM,
//   - the same on the thesis's transform value sqrt((1 + SM)/2),
//   - the sum of the Monte Carlo values over the exact ones (1 = no global bias of scale),
//   - whether the global maximum bin is the exact one ("yes"), one of its 26 neighbours
//     ("neighbour") or elsewhere ("no"); with several seeds, the counts exact/neighbour-or-exact/seeds;
//   - the exact SM of the bin the Monte Carlo transform ranks first divided by the exact
//     maximum (1 = an equally good plane; mean over the seeds).
// Times are wall-clock; "CPU" is the CPU time of the process over all threads (std::clock),
// which tells a run disturbed by other programs (wall time well above CPU / threads).
// Prints Markdown tables on std::cout, progress on std::cerr.
//
// Usage: prst_monte_carlo_error [--meshes bull.off,armadillo.off] [--resolutions 32,64]
//          [--estimators stratified,pair,bounded] [--samples 250000,500000,...]
//          [--seeds 1] [--threads T] [--top K]
// A mesh given as a bare name is looked for in SYMMETRY_TRANSFORM_DATA_DIR/meshes/; a name
// with a '/' is a path. --seeds K repeats each run with seeds 0..K-1 and reports the mean
// error (and the mean time). --top K lists, after each table, the K largest bins of each
// Monte Carlo transform (seed 0) with their exact values: where the error comes from.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::split;
using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Reflective_symmetry_transform<K> PRST;

struct Estimator_choice
{
  const char* name;
  ST::Monte_carlo_estimator estimator;
};

const Estimator_choice all_estimators[] = {{"stratified", ST::Monte_carlo_estimator::STRATIFIED_LINES},
                                           {"pair", ST::Monte_carlo_estimator::PAIR_JACOBIAN},
                                           {"bounded", ST::Monte_carlo_estimator::BOUNDED_WEIGHT}};

const char* long_name(ST::Monte_carlo_estimator e)
{
  switch(e) {
  case ST::Monte_carlo_estimator::STRATIFIED_LINES: return "STRATIFIED_LINES";
  case ST::Monte_carlo_estimator::PAIR_JACOBIAN: return "PAIR_JACOBIAN";
  case ST::Monte_carlo_estimator::BOUNDED_WEIGHT: return "BOUNDED_WEIGHT";
  }
  return "?";
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double transform_value(double sm) { return ST::symmetry_transform_value((std::max)(sm, -1.)); }

struct Errors
{
  double sm = 0., value = 0., sum_ratio = 0.;
};

Errors relative_l2(const std::vector<double>& mc, const std::vector<double>& exact)
{
  double d_sm = 0., n_sm = 0., d_v = 0., n_v = 0., s_mc = 0., s_exact = 0.;
  for(std::size_t b = 0; b < exact.size(); ++b) {
    d_sm += (mc[b] - exact[b]) * (mc[b] - exact[b]);
    n_sm += exact[b] * exact[b];
    const double a = transform_value(mc[b]), e = transform_value(exact[b]);
    d_v += (a - e) * (a - e);
    n_v += e * e;
    s_mc += mc[b];
    s_exact += exact[b];
  }
  return {std::sqrt(d_sm / n_sm), std::sqrt(d_v / n_v), s_mc / s_exact};
}

std::size_t argmax(const std::vector<double>& v)
{
  return std::size_t(std::max_element(v.begin(), v.end()) - v.begin());
}

std::string format(const char* fmt, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, x);
  return buffer;
}

// Whether bin b is `best` or one of its 26 neighbours (through the wraps of the plane space).
bool is_neighbour(const PRST& t, std::size_t best, std::size_t b)
{
  const long n = long(t.resolution());
  const long i = long(best) / (n * n), j = long(best) / n % n, k = long(best) % n;
  for(long di = -1; di <= 1; ++di)
    for(long dj = -1; dj <= 1; ++dj)
      for(long dk = -1; dk <= 1; ++dk)
        if(k + dk >= 0 && k + dk < n && t.bins().wrapped_index(i + di, j + dj, k + dk) == b) return true;
  return false;
}

std::string bin_string(const PRST& t, std::size_t b)
{
  const std::size_t n = t.resolution();
  return "(" + std::to_string(b / (n * n)) + "," + std::to_string(b / n % n) + "," + std::to_string(b % n) + ")";
}

[[noreturn]] void usage(const char* program)
{
  std::cerr << "usage: " << program
            << " [--meshes bull.off,armadillo.off] [--resolutions 32,64]"
               " [--estimators stratified,pair,bounded] [--samples 250000,500000,1000000,2000000,4000000,8000000]"
               " [--seeds 1] [--threads T] [--top K]\n";
  std::exit(2);
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> meshes = {"bull.off", "armadillo.off"};
  std::vector<int> resolutions = {32, 64};
  std::vector<Estimator_choice> estimators(std::begin(all_estimators), std::end(all_estimators));
  std::vector<std::size_t> samples = {250000, 500000, 1000000, 2000000, 4000000, 8000000};
  unsigned seeds = 1, threads = (std::max)(1u, std::thread::hardware_concurrency());
  std::size_t top = 0;

  for(int a = 1; a < argc; ++a) {
    const std::string option = argv[a];
    if(a + 1 >= argc) usage(argv[0]);
    const std::string value = argv[++a];
    if(option == "--meshes")
      meshes = split(value);
    else if(option == "--resolutions") {
      resolutions.clear();
      for(const std::string& s : split(value)) resolutions.push_back(std::stoi(s));
    } else if(option == "--estimators") {
      estimators.clear();
      for(const std::string& s : split(value)) {
        const auto e = std::find_if(std::begin(all_estimators), std::end(all_estimators),
                                    [&](const Estimator_choice& c) { return s == c.name; });
        if(e == std::end(all_estimators)) usage(argv[0]);
        estimators.push_back(*e);
      }
    } else if(option == "--samples") {
      samples.clear();
      for(const std::string& s : split(value)) samples.push_back(std::size_t(std::stod(s)));
    } else if(option == "--seeds")
      seeds = unsigned((std::max)(1, std::stoi(value)));
    else if(option == "--threads")
      threads = unsigned((std::max)(1, std::stoi(value)));
    else if(option == "--top")
      top = std::size_t((std::max)(0, std::stoi(value)));
    else
      usage(argv[0]);
  }

  std::cout << "Threads: " << threads << "; seeds per run: " << seeds
            << "; errors are ||mc - exact|| / ||exact|| over all bins; time: the PRST alone (GEDT excluded).\n";
  for(const std::string& name : meshes) {
    const std::string path =
      mesh_path(name);
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
      std::cerr << "cannot read " << path << " (run scripts/setup.sh)\n";
      return 1;
    }
    for(int n : resolutions) {
      auto start = std::chrono::steady_clock::now();
      const ST::Voxel_grid<K> f = ST::gaussian_distance_transform(
        mesh, CGAL::parameters::grid_resolution(n).number_of_threads(threads));
      const double gedt_time = seconds_since(start);
      std::size_t non_zero = 0;
      for(double v : f.values()) non_zero += v != 0.;

      std::cerr << name << " " << n << "^3: exact PRST..." << std::endl;
      start = std::chrono::steady_clock::now();
      const std::clock_t exact_cpu_start = std::clock();
      const PRST exact = ST::reflective_symmetry_transform(
        f, CGAL::parameters::prst_method(ST::Reflective_symmetry_method::EXACT).number_of_threads(threads));
      const double exact_time = seconds_since(start);
      const double exact_cpu = double(std::clock() - exact_cpu_start) / CLOCKS_PER_SEC;
      const std::size_t exact_best = argmax(exact.values());
      const double exact_max = exact.values()[exact_best];

      std::cout << "\n### " << name << " (" << num_faces(mesh) << " faces), " << n << "^3\n\n"
                << "GEDT " << format("%.3f", gedt_time) << " s (" << non_zero << " non-zero voxels); exact PRST "
                << format("%.2f", exact_time) << " s (CPU " << format("%.2f", exact_cpu) << " s); exact maximum SM " << format("%.4f", exact_max) << " at bin "
                << bin_string(exact, exact_best) << ".\n\n"
                << "| estimator | samples | time (s) | CPU (s) | GEDT + PRST (s) | rel. L2 error SM | rel. L2 error sqrt((1+SM)/2) "
                   "| sum mc / sum exact | max bin vs exact | exact SM at MC max / exact max |\n"
                << "|---|---:|---:|---:|---:|---:|---:|---:|:---:|---:|\n"
                << std::flush;
      std::string largest_bins;
      for(const Estimator_choice& e : estimators)
        for(std::size_t N : samples) {
          double time = 0., cpu = 0.;
          Errors mean;
          unsigned same_max = 0, near_max = 0;
          double chosen = 0.;
          for(unsigned seed = 0; seed < seeds; ++seed) {
            start = std::chrono::steady_clock::now();
            const std::clock_t cpu_start = std::clock();
            const PRST mc = ST::reflective_symmetry_transform(
              f, CGAL::parameters::number_of_samples(N).monte_carlo_estimator(e.estimator).random_seed(seed)
                   .number_of_threads(threads));
            time += seconds_since(start);
            cpu += double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
            const Errors err = relative_l2(mc.values(), exact.values());
            mean.sm += err.sm;
            mean.value += err.value;
            mean.sum_ratio += err.sum_ratio;
            const std::size_t best = argmax(mc.values());
            same_max += best == exact_best;
            near_max += is_neighbour(exact, exact_best, best);
            chosen += exact.values()[best] / exact_max;
            if(seed == 0 && top > 0) {
              std::vector<std::size_t> order(mc.values().size());
              for(std::size_t b = 0; b < order.size(); ++b) order[b] = b;
              const std::size_t k = (std::min)(top, order.size());
              std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(k), order.end(),
                                [&](std::size_t a, std::size_t b) { return mc.values()[a] > mc.values()[b]; });
              largest_bins += std::string("- ") + long_name(e.estimator) + ", " + std::to_string(N) + " samples:";
              for(std::size_t r = 0; r < k; ++r)
                largest_bins += " " + bin_string(exact, order[r]) + " " + format("%.3f", mc.values()[order[r]]) +
                                " (exact " + format("%.3f", exact.values()[order[r]]) + ")" + (r + 1 < k ? ";" : "");
              largest_bins += "\n";
            }
          }
          const double k = double(seeds);
          std::cout << "| " << long_name(e.estimator) << " | " << N << " | " << format("%.3f", time / k) << " | "
                    << format("%.3f", cpu / k) << " | " << format("%.3f", gedt_time + time / k) << " | "
                    << format("%.2f %%", 100. * mean.sm / k) << " | "
                    << format("%.2f %%", 100. * mean.value / k) << " | " << format("%.4f", mean.sum_ratio / k) << " | "
                    << (seeds == 1 ? (same_max ? "yes" : near_max ? "neighbour" : "no")
                                   : std::to_string(same_max) + "/" + std::to_string(near_max) + "/" +
                                       std::to_string(seeds))
                    << " | " << format("%.4f", chosen / k) << " |\n"
                    << std::flush;
        }
      if(top > 0)
        std::cout << "\nLargest Monte Carlo bins (seed 0), bin (i,j,k) value (exact value):\n\n" << largest_bins;
    }
  }
  return 0;
}
