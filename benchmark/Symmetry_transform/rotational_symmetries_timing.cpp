// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Time of detect_rotational_symmetries() against detect_principal_symmetries() on the same mesh,
// in the same run, and the axes found.
//
// For each mesh, with the default parameters except grid_resolution and random_seed, the two
// detections are run alternately --repeats times; each call is timed by the wall clock and by
// the CPU time of the process (both threads count: number_of_threads defaults to
// hardware_concurrency). The medians and their ratios are printed as a Markdown table on
// std::cout, then every axis found (order, direction, point nearest to the centre of mass,
// symmetry, support); progress on std::cerr. On a shared machine the CPU times are the steadier
// figure: other programs lengthen the wall clock of both detections alike, not their CPU time.
//
// Usage: rotational_symmetries_timing [--meshes pinion.off,rotor.off,...] [--resolution 64]
//          [--repeats 3] [--seed 0] [--verbose 1] (the stages of the rotational detection, on stderr)
// A mesh given as a bare name is looked for in SYMMETRY_TRANSFORM_DATA_DIR/meshes/; a name with
// a '/' is a path.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::median;
using benchmark_utilities::mesh_path;
using benchmark_utilities::split;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

const char* default_meshes = "pinion.off,cross.off,rotor.off,turbine.off,spool.off,dragknob.off,mushroom.off,pipe.off,"
                             "cylinder.off,blade.off,couplingdown.off,joint.off,anchor.off,bull.off";

std::string format(const char* fmt, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, x);
  return buffer;
}

struct Times
{
  std::vector<double> wall, cpu;
};

// Calls f, adds its wall and CPU times (seconds) to `times`, returns its result.
template <typename F>
auto timed(Times& times, F f)
{
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu = std::clock();
  auto result = f();
  times.cpu.push_back(double(std::clock() - cpu) / CLOCKS_PER_SEC);
  times.wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return result;
}

// "10, 2 x10": the orders found, 0 written "inf" (continuous), repeated ones counted.
std::string orders(const std::vector<ST::Rotational_symmetry<K>>& symmetries)
{
  if(symmetries.empty()) return "none";
  std::map<int, int, std::greater<int>> count;
  for(const auto& s : symmetries) ++count[s.order == 0 ? 1000 : s.order];
  std::ostringstream out;
  bool first = true;
  for(const auto& [order, n] : count) {
    out << (first ? "" : ", ") << (order == 1000 ? std::string("continuous") : std::to_string(order))
        << (n > 1 ? " x" + std::to_string(n) : std::string());
    first = false;
  }
  return out.str();
}

std::string axis_rows(const std::string& name, const std::vector<ST::Rotational_symmetry<K>>& symmetries)
{
  std::ostringstream out;
  for(const auto& s : symmetries) {
    const K::Vector_3 d = s.axis.to_vector();
    const K::Point_3 p = s.axis.point();
    out << "| " << name << " | " << (s.order == 0 ? std::string("continuous") : std::to_string(s.order)) << " | ("
        << format("%.3f", d.x()) << ", " << format("%.3f", d.y()) << ", " << format("%.3f", d.z()) << ") | ("
        << format("%.3g", p.x()) << ", " << format("%.3g", p.y()) << ", " << format("%.3g", p.z()) << ") | "
        << format("%.3f", s.symmetry) << " | " << format("%.3f", s.support) << " |\n";
  }
  return out.str();
}

} // namespace

int main(int argc, char** argv)
try {
  std::string meshes = default_meshes;
  int resolution = 64;
  unsigned repeats = 3, seed = 0;
  bool verbose = false;
  for(int a = 1; a + 1 < argc; a += 2) {
    const std::string arg = argv[a], value = argv[a + 1];
    if(arg == "--meshes") meshes = value;
    else if(arg == "--resolution") resolution = std::stoi(value);
    else if(arg == "--repeats") repeats = unsigned(std::stoul(value));
    else if(arg == "--seed") seed = unsigned(std::stoul(value));
    else if(arg == "--verbose") verbose = value != "0";
    else throw std::invalid_argument("unknown option " + arg);
  }
  const auto np = CGAL::parameters::grid_resolution(resolution).random_seed(seed).verbose(verbose);
  std::cout << "| mesh | faces | orders found | rotations: wall | CPU | planes: wall | CPU | ratio wall | ratio CPU |\n"
            << "|---|---:|---|---:|---:|---:|---:|---:|---:|\n";
  std::string axes = "| mesh | order | direction | point nearest to the centre | symmetry | support |\n|---|---:|---|---|---:|---:|\n";
  for(const std::string& name : split(meshes)) {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(mesh_path(name), mesh) || is_empty(mesh)) {
      std::cerr << "cannot read " << mesh_path(name) << "\n";
      return EXIT_FAILURE;
    }
    if(!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
    Times rotations, planes;
    std::vector<ST::Rotational_symmetry<K>> found;
    for(unsigned r = 0; r < repeats; ++r) {
      std::cerr << name << ": run " << r + 1 << " of " << repeats << "\n";
      found = timed(rotations, [&] { return ST::detect_rotational_symmetries(mesh, np); });
      timed(planes, [&] { return ST::detect_principal_symmetries(mesh, np); });
    }
    const double rw = median(rotations.wall), rc = median(rotations.cpu), pw = median(planes.wall), pc = median(planes.cpu);
    std::cout << "| " << name << " | " << num_faces(mesh) << " | " << orders(found) << " | " << format("%.2f s", rw) << " | "
              << format("%.2f s", rc) << " | " << format("%.2f s", pw) << " | " << format("%.2f s", pc) << " | "
              << format("%.2f", rw / pw) << " | " << format("%.2f", rc / pc) << " |\n"
              << std::flush;
    axes += axis_rows(name, found);
  }
  std::cout << "\n" << axes;
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
