// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The `callback` named parameter measured on a large mesh, for detection, symmetric remeshing and
// segmentation: the CPU time of a run with a callback that always returns true against a run
// without (the overhead), the longest time between two calls of the callback (how long a user
// may wait before the work can notice a cancel), and the latency of cancels at the first call and
// 10 %, 30 %, 50 %, 70 % and 90 % into the run (from the callback's false to the return).
//
//   progress_callback_latency [--mesh FILE] [--loop K] [--functions detection,remeshing,segmentation]
//                             [--threads 2] [--repeats 2] [--single none|true]
//
// --loop K Loop-subdivides the mesh K times first (bunny00.off twice: 1.2M faces).
// --single runs each function once, without a callback or with one that returns true, and
// stops: for instruction counts (valgrind --tool=callgrind), which the load of a shared
// machine does not disturb.

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include "benchmark_utilities.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace ST = CGAL::Symmetry_transform;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::chrono::steady_clock Clock;

double cpu_seconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// One run: the calls of the callback, and the cancel if any.
struct Run
{
  double cancel_at = 2.; // the first value at or above it returns false
  std::vector<double> values;
  std::vector<Clock::time_point> times;
  Clock::time_point cancelled, returned;
  bool was_cancelled = false;
  double wall = 0., cpu = 0.;

  std::function<bool(double)> callback()
  {
    return [this](double p) {
      values.push_back(p);
      times.push_back(Clock::now());
      if(p >= cancel_at && p < 1.) {
        was_cancelled = true;
        cancelled = times.back();
        return false;
      }
      return true;
    };
  }
  double longest_gap() const
  {
    double gap = 0.;
    for(std::size_t i = 1; i < times.size(); ++i) gap = (std::max)(gap, seconds(times[i - 1], times[i]));
    return gap;
  }
};

// Runs `work(callback)` (an empty callback: none) and times it.
template <typename Work>
void timed(Run& run, const Work& work, bool with_callback)
{
  const double cpu = cpu_seconds();
  const Clock::time_point start = Clock::now();
  work(with_callback ? run.callback() : std::function<bool(double)>());
  run.returned = Clock::now();
  run.wall = seconds(start, run.returned);
  run.cpu = cpu_seconds() - cpu;
}

// The values that a complete run reported `fraction` of its time in.
double value_at(const Run& complete, double fraction)
{
  std::size_t i = 0;
  while(i + 2 < complete.values.size() && seconds(complete.times.front(), complete.times[i]) < fraction * complete.wall) ++i;
  return complete.values[i];
}

template <typename Work>
void measure(const std::string& name, std::size_t repeats, const std::string& single, const Work& work)
{
  if(!single.empty()) {
    Run run;
    timed(run, work, single == "true");
    std::cout << name << " once, " << (single == "true" ? "with" : "without") << " callback: " << run.wall << " s\n";
    return;
  }
  double cpu_without = 1e300, cpu_with = 1e300, wall_without = 1e300, gap = 0.;
  Run complete;
  for(std::size_t r = 0; r < repeats; ++r) { // alternated, the smallest CPU time of each
    Run without, with;
    timed(without, work, false);
    timed(with, work, true);
    cpu_without = (std::min)(cpu_without, without.cpu);
    wall_without = (std::min)(wall_without, without.wall);
    cpu_with = (std::min)(cpu_with, with.cpu);
    gap = (std::max)(gap, with.longest_gap());
    complete = with;
  }
  std::cout << std::fixed << std::setprecision(3) << name << ": " << wall_without << " s wall, CPU " << cpu_without
            << " s without callback, " << cpu_with << " s with (overhead " << std::setprecision(2)
            << 100. * (cpu_with / cpu_without - 1.) << " %), " << complete.values.size() << " calls, longest gap "
            << std::setprecision(3) << gap << " s\n";
  double worst = 0.;
  for(double fraction : {0., 0.1, 0.3, 0.5, 0.7, 0.9}) {
    Run cancelled;
    cancelled.cancel_at = fraction == 0. ? 0. : value_at(complete, fraction);
    timed(cancelled, work, true);
    const double latency = seconds(cancelled.cancelled, cancelled.returned);
    worst = (std::max)(worst, latency);
    std::cout << "  cancel at " << std::setprecision(3) << cancelled.cancel_at << " (" << int(100. * fraction)
              << " % of the time): " << (cancelled.was_cancelled ? "" : "NOT CANCELLED, ") << "returned after "
              << std::setprecision(2) << 1000. * latency << " ms\n";
  }
  std::cout << "  largest latency " << std::setprecision(2) << 1000. * worst << " ms\n";
}

} // namespace

int main(int argc, char** argv)
{
  std::string file = benchmark_utilities::mesh_path("bunny00.off"), functions = "detection,remeshing,segmentation", single;
  int loop = 0;
  unsigned threads = 2;
  std::size_t repeats = 2;
  for(const auto& [key, value] : benchmark_utilities::option_pairs(argc, argv)) {
    if(key == "--mesh") file = value;
    else if(key == "--loop") loop = std::atoi(value.c_str());
    else if(key == "--functions") functions = value;
    else if(key == "--threads") threads = unsigned(std::atoi(value.c_str()));
    else if(key == "--repeats") repeats = std::size_t(std::atoi(value.c_str()));
    else if(key == "--single") single = value;
  }
  Mesh mesh;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(file, mesh)) {
    std::cerr << "cannot read " << file << "\n";
    return EXIT_FAILURE;
  }
  if(loop > 0) CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(loop));
  std::cout << file << " (Loop " << loop << "): " << num_faces(mesh) << " faces, " << threads << " threads\n";
  const auto np = CGAL::parameters::number_of_threads(threads).random_seed(1);
  for(const std::string& f : benchmark_utilities::split(functions)) {
    if(f == "detection")
      measure(f, repeats, single, [&](const std::function<bool(double)>& cb) { ST::detect_principal_symmetries(mesh, np.callback(cb)); });
    else if(f == "remeshing")
      measure(f, repeats, single, [&](const std::function<bool(double)>& cb) {
        std::vector<K::Point_3> anchors;
        ST::symmetric_approximate_triangle_mesh(mesh, std::vector<K::Plane_3>{K::Plane_3(1, 0, 0, 0)},
                                                np.callback(cb).anchors(std::back_inserter(anchors)));
      });
    else if(f == "segmentation")
      measure(f, repeats, single, [&](const std::function<bool(double)>& cb) {
        auto ids = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
        ST::segment_by_symmetry(mesh, ids, np.callback(cb));
      });
  }
  return EXIT_SUCCESS;
}
