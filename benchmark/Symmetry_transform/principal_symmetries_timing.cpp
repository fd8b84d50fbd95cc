// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Time of detect_principal_symmetries() and its split into stages (issue 3).
//
// For each mesh, with the default parameters except grid_resolution, each timed alone (wall
// clock, median of --repeats runs, default number_of_threads = hardware_concurrency):
//   - total: detect_principal_symmetries(mesh, np);
//   - GEDT: the Gaussian distance transform with the closest triangles of the voxels of its band
//     (internal::gaussian_distance_transform_of_triangles, as detect computes it);
//   - PRST: internal::detection_transform(gedt, np), i.e. the Monte Carlo PRST with detect's
//     5e5 samples;
//   - maxima: internal::symmetry_candidates(prst, 0.1, 0.1) (smoothing and candidate extraction);
//   - tree: internal::triangles_of_mesh, the internal::Triangle_matcher (AABB tree) and the
//     internal::Closest_triangle_field (ISP walks with it);
//   - ISP stage: internal::refine_candidates(gedt, prst, surface_samples, matcher, np, &field), which
//     draws the 1e4 samples, extracts the candidates again and refines them, strongest first,
//     until max_number_of_planes (10) are accepted or its cap on candidates is reached; with
//     the number of candidates (all of them, before that cap) and of planes returned.
// Total ~ GEDT + PRST + tree + ISP stage (the maxima are inside the ISP stage).
// Then one ISP refinement (both phases, 1e4 samples) per returned plane P, from P rotated by
// 2 degrees about a random axis orthogonal to its normal through the shape's centre projected
// on P, and shifted by 1 % of the shape radius: min / median / max over the planes of the
// per-plane median time, median number of iterations, and the angle between the result and P.
// Prints Markdown tables on std::cout, progress on std::cerr.
//
// Usage: principal_symmetries_timing [--meshes bull.off,refined_elephant.off] [--resolution 64]
//          [--repeats 3] [--seed 1]
// A mesh given as a bare name is looked for in SYMMETRY_TRANSFORM_DATA_DIR/meshes/; a name
// with a '/' is a path. --seed sets the random axes of the perturbed starting planes.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Random.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::split;
using benchmark_utilities::median;
using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace STI = CGAL::Symmetry_transform::internal;

std::string format(const char* fmt, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, x);
  return buffer;
}

// Median wall time in seconds of `repeats` calls of f.
template <typename F>
double median_time(unsigned repeats, F f)
{
  std::vector<double> times;
  for(unsigned r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return median(times);
}

double angle_degrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::acos((std::min)(1., std::abs(a.normalized().dot(b.normalized())))) * 180. / CGAL_PI;
}

[[noreturn]] void fail(const char* program, const std::string& message)
{
  std::cerr << program << ": " << message << "\nusage: " << program
            << " [--meshes bull.off,refined_elephant.off] [--resolution 64] [--repeats 3] [--seed 1]\n";
  std::exit(2);
}

unsigned positive(const char* program, const std::string& option, const std::string& value)
{
  std::size_t end = 0;
  long v = 0;
  try { v = std::stol(value, &end); } catch(const std::exception&) { end = 0; }
  if(end != value.size() || v <= 0) fail(program, option + " needs a positive integer, not '" + value + "'");
  return unsigned(v);
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> meshes = {"bull.off", "refined_elephant.off"};
  unsigned resolution = 64, repeats = 3, seed = 1;
  for(int a = 1; a < argc; a += 2) {
    const std::string option = argv[a];
    if(option != "--meshes" && option != "--resolution" && option != "--repeats" && option != "--seed")
      fail(argv[0], "unknown option '" + option + "'");
    if(a + 1 >= argc) fail(argv[0], option + " needs a value");
    const std::string value = argv[a + 1];
    if(option == "--meshes") meshes = split(value);
    else if(option == "--resolution") resolution = positive(argv[0], option, value);
    else if(option == "--repeats") repeats = positive(argv[0], option, value);
    else seed = positive(argv[0], option, value);
  }
  if(meshes.empty()) fail(argv[0], "--meshes names no mesh");

  std::string command = argv[0];
  for(int a = 1; a < argc; ++a) command += std::string(" ") + argv[a];
  std::cout << "Command: `" << command << "`; hardware_concurrency " << std::thread::hardware_concurrency()
            << "; grid " << resolution << "^3, other parameters default; times: median of " << repeats
            << " runs.\n\n"
            << "| mesh | faces | total (s) | GEDT (s) | PRST 5e5 (s) | maxima (s) | tree (s) | ISP stage (s) "
               "| candidates | planes | ISP stage / plane (ms) |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::string isp_table;
  const auto np = CGAL::parameters::grid_resolution(resolution);
  for(const std::string& name : meshes) {
    const std::string path =
      mesh_path(name);
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
      std::cerr << "cannot read " << path << " (run scripts/setup.sh)\n";
      return 1;
    }
    if(!CGAL::is_triangle_mesh(mesh) && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh)) {
      std::cerr << "cannot triangulate " << path << "\n";
      return 1;
    }
    std::cerr << name << ": detection..." << std::endl;
    const double total = median_time(repeats, [&] { ST::detect_principal_symmetries(mesh, np); });

    std::cerr << name << ": stages..." << std::endl;
    std::optional<ST::Voxel_grid<K>> gedt_holder; // no default constructors
    std::vector<std::int32_t> closest_triangles;
    const std::vector<STI::Dtriangle> mesh_triangles = STI::triangles_of_mesh(mesh, CGAL::parameters::default_values());
    const double gedt_time = median_time(repeats, [&] {
      gedt_holder.emplace(STI::gaussian_distance_transform_of_triangles<K>(mesh_triangles, np, &closest_triangles));
    });
    const ST::Voxel_grid<K>& gedt = *gedt_holder;
    std::optional<ST::Reflective_symmetry_transform<K>> prst_holder;
    const double prst_time = median_time(repeats, [&] { prst_holder.emplace(STI::detection_transform(gedt, np)); });
    const ST::Reflective_symmetry_transform<K>& prst = *prst_holder;
    std::size_t candidates = 0;
    const double maxima_time = median_time(repeats, [&] { candidates = STI::symmetry_candidates(prst, 0.1, 0.1).size(); });
    std::vector<STI::Dtriangle> triangles;
    std::optional<STI::Triangle_matcher> matcher_holder; // its tree points into `triangles`
    std::optional<STI::Closest_triangle_field> field_holder; // and so does the field
    const double tree_time = median_time(repeats, [&] {
      field_holder.reset();
      matcher_holder.reset();
      triangles = STI::triangles_of_mesh(mesh, CGAL::parameters::default_values());
      matcher_holder.emplace(triangles);
      field_holder.emplace(triangles, *matcher_holder, closest_triangles, gedt.origin(), gedt.voxel_size(),
                           gedt.resolution());
    });
    const STI::Triangle_matcher& matcher = *matcher_holder;
    const STI::Closest_triangle_field& field = *field_holder;
    std::vector<ST::Principal_symmetry<K>> planes;
    const double isp_time = median_time(repeats, [&] {
      planes = STI::refine_candidates(gedt, prst, STI::surface_samples(triangles, np), matcher, np, &field);
    });
    std::cout << "| " << name << " | " << num_faces(mesh) << " | " << format("%.3f", total) << " | "
              << format("%.3f", gedt_time) << " | " << format("%.3f", prst_time) << " | " << format("%.3f", maxima_time)
              << " | " << format("%.3f", tree_time) << " | " << format("%.3f", isp_time) << " | " << candidates << " | "
              << planes.size() << " | "
              << (planes.empty() ? std::string("-") : format("%.0f", 1000. * isp_time / double(planes.size())))
              << " |\n"
              << std::flush;

    // One ISP refinement per returned plane, from a perturbed start.
    std::cerr << name << ": one ISP per plane..." << std::endl;
    const std::vector<Eigen::Vector3d> samples = STI::surface_samples(triangles, np);
    const STI::Isp_settings settings = STI::isp_settings(np, gedt);
    const Eigen::Vector3d center(gedt.center().x(), gedt.center().y(), gedt.center().z());
    CGAL::Random random(seed);
    std::vector<double> times, iterations, angles;
    for(const ST::Principal_symmetry<K>& p : planes) {
      const STI::Dplane P = STI::to_dplane(p.plane);
      Eigen::Vector3d axis;
      do {
        axis = Eigen::Vector3d(random.get_double(-1., 1.), random.get_double(-1., 1.), random.get_double(-1., 1.));
        axis -= axis.dot(P.normal) * P.normal;
      } while(axis.norm() < 1e-3);
      axis.normalize();
      const double a = 2. * CGAL_PI / 180.;
      const Eigen::Vector3d pivot = center - (P.normal.dot(center) - P.offset) * P.normal; // centre projected on P
      const Eigen::Vector3d n = std::cos(a) * P.normal + std::sin(a) * axis.cross(P.normal);
      const K::Plane_3 start(n.x(), n.y(), n.z(), -(n.dot(pivot) + 0.01 * gedt.radius()));
      STI::Dplane found = P;
      unsigned steps = 0;
      times.push_back(median_time(repeats, [&] {
        const STI::Isp_result result = STI::iterative_symmetric_points(samples, STI::to_dplane(start), matcher, settings,
                                                                       STI::Isp_phase::BOTH, {}, &field);
        found = result.plane;
        steps = result.iterations;
      }));
      iterations.push_back(double(steps));
      angles.push_back(angle_degrees(found.normal, P.normal));
    }
    isp_table += "| " + name + " | " + std::to_string(planes.size()) + " | " + std::to_string(samples.size()) + " | ";
    if(planes.empty())
      isp_table += "- | - | - | - | - | - |\n";
    else
      isp_table += format("%.1f", 1000. * *std::min_element(times.begin(), times.end())) + " | " +
                   format("%.1f", 1000. * median(times)) + " | " +
                   format("%.1f", 1000. * *std::max_element(times.begin(), times.end())) + " | " +
                   format("%.1f", median(iterations)) + " | " + format("%.3f", median(angles)) + " | " +
                   format("%.3f", *std::max_element(angles.begin(), angles.end())) + " |\n";
  }
  std::cout << "\nOne ISP refinement (both phases) per returned plane P, from P rotated by 2 degrees and shifted by "
               "1 % of the radius (seed "
            << seed << "); time: per plane the median of " << repeats << " runs, then min / median / max over the planes.\n\n"
            << "| mesh | planes | samples | min (ms) | median (ms) | max (ms) | median iterations "
               "| angle to P, median (deg) | angle to P, max (deg) |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
            << isp_table;
  return 0;
}
