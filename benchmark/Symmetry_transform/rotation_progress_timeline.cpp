// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// How evenly detect_rotational_symmetries() reports its progress: for each mesh, the fraction of
// the run's wall time at which the value passed to the callback first reaches 0.25, 0.5, 0.75,
// 0.95 and 1 (a bar that grows with the time spent gives about 0.25, 0.5, 0.75, 0.95).
//
// Usage: rotation_progress_timeline mesh.off [mesh.off ...] (bare names are looked for in
// SYMMETRY_TRANSFORM_DATA_DIR/meshes/)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/rotational_symmetries.h>

#include <chrono>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "benchmark_utilities.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
using benchmark_utilities::mesh_path;

int main(int argc, char** argv)
{
  const std::vector<double> marks{0.25, 0.5, 0.75, 0.95, 1.};
  std::cout << "| mesh | wall (s) | calls | time at 0.25 | 0.5 | 0.75 | 0.95 | 1 |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for(int a = 1; a < argc; ++a) {
    CGAL::Surface_mesh<K::Point_3> mesh;
    if(!CGAL::IO::read_polygon_mesh(mesh_path(argv[a]), mesh) || is_empty(mesh)) {
      std::cerr << "cannot read " << mesh_path(argv[a]) << "\n";
      return 1;
    }
    if(!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
    std::vector<std::pair<double, double>> calls; // (seconds since the start, value)
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    auto record = [&](double value) {
      calls.emplace_back(seconds(), value);
      return true;
    };
    CGAL::Symmetry_transform::detect_rotational_symmetries(mesh, CGAL::parameters::callback(record));
    const double total = seconds();
    std::cout << "| " << argv[a] << " | " << total << " | " << calls.size();
    for(double mark : marks) {
      double first = -1.;
      for(const auto& [time, value] : calls)
        if(value >= mark - 1e-12) {
          first = time / total;
          break;
        }
      std::cout << " | " << first;
    }
    std::cout << " |\n";
  }
}
