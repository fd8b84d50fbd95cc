// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Symmetry-based segmentation against CGAL's SDF segmentation, on CGAL's sample meshes: the
// wall-clock time and the number of segments of segment_by_symmetry at depths 1, 2 and 3 (with
// no segment-count limit, and with at most 2^depth segments, the thesis's Figure 5.11), next to
// the time and the number of segments of CGAL::sdf_values + CGAL::segmentation_from_sdf_values
// with their defaults (25 rays, 5 clusters, lambda 0.26). The runs alternate, ours then CGAL's,
// mesh by mesh and repetition by repetition, so that a change in the machine's load affects
// both; each time is the median over the repetitions.
//
// usage: segmentation_comparison [--meshes a.off,b.off,...] [--resolution N] [--repeats R]
//          [--threads T]
// Figures and the command that produced them: RESULTS.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::split;
using benchmark_utilities::median;
using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

const char* default_meshes = "bull.off,cow.off,dino.off,elephant.off,camel.off,homer.off";

template <typename F>
double seconds_of(const F& f)
{
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One configuration of ours: a depth, with or without the 2^depth cap.
struct Configuration
{
  std::size_t depth;
  bool capped;
};

} // namespace

int main(int argc, char** argv)
try {
  std::string meshes = default_meshes;
  int resolution = 32;
  std::size_t repeats = 3;
  unsigned threads = ST::internal::default_number_of_threads();
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--meshes") meshes = value;
    else if(arg == "--resolution") resolution = std::stoi(value);
    else if(arg == "--repeats") repeats = std::size_t(std::stoul(value));
    else if(arg == "--threads") threads = unsigned(std::stoul(value));
    else throw std::invalid_argument("unknown option: " + arg);
  }
  const std::vector<Configuration> configurations = {{1, false}, {2, false}, {3, false}, {1, true}, {2, true}, {3, true}};

  std::cout << "segment_by_symmetry (grid " << resolution << "^3, " << threads << " threads, seed 0) against "
            << "CGAL's SDF segmentation (defaults); wall-clock seconds, median of " << repeats << " alternated runs\n\n";
  std::cout << "| mesh | faces | depth 1 | depth 2 | depth 3 | <= 2 segments | <= 4 | <= 8 | CGAL SDF | depth 3 / SDF | "
               "<= 8 / SDF |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& name : split(meshes)) {
    Mesh mesh;
    const std::string file = mesh_path(name);
    if(!PMP::IO::read_polygon_mesh(file, mesh) || is_empty(mesh)) throw std::runtime_error("cannot read " + file);
    if(!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);

    std::vector<std::vector<double>> ours(configurations.size());
    std::vector<std::size_t> our_counts(configurations.size());
    std::vector<double> sdf;
    std::size_t sdf_count = 0;
    auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
    auto sdf_values = mesh.add_property_map<Mesh::Face_index, double>("f:sdf", 0.).first;
    for(std::size_t r = 0; r < repeats; ++r) {
      for(std::size_t c = 0; c < configurations.size(); ++c) {
        const auto np = CGAL::parameters::grid_resolution(resolution).number_of_threads(threads)
                          .max_segmentation_depth(configurations[c].depth);
        ours[c].push_back(seconds_of([&] {
          our_counts[c] = configurations[c].capped
                            ? ST::segment_by_symmetry(mesh, segment, np.max_number_of_segments(std::size_t(1) << configurations[c].depth))
                            : ST::segment_by_symmetry(mesh, segment, np);
        }));
        if(c % 2 == 1 || c + 1 == configurations.size()) // CGAL's between ours: 3 runs per repetition
          sdf.push_back(seconds_of([&] {
            CGAL::sdf_values(mesh, sdf_values);
            sdf_count = CGAL::segmentation_from_sdf_values(mesh, sdf_values, segment);
          }));
      }
    }
    const double sdf_time = median(sdf);
    std::cout << std::fixed << std::setprecision(2) << "| " << name << " | " << num_faces(mesh);
    for(std::size_t c = 0; c < configurations.size(); ++c)
      std::cout << " | " << median(ours[c]) << " s (" << our_counts[c] << ")";
    std::cout << " | " << sdf_time << " s (" << sdf_count << ") | " << median(ours[2]) / sdf_time << " | "
              << median(ours[5]) / sdf_time << " |" << std::endl;
  }
  std::cout << "\n(n): number of segments. \"<= k segments\": max_number_of_segments(k) with depth log2(k).\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
