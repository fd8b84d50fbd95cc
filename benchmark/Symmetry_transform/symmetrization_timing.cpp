// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The cost of symmetrize() against the plane detection it follows, on the same mesh in one run:
//
//   symmetrization_timing [--meshes cow.off,bull.off] [--loop 0] [--planes 1] [--whole 0|1]
//
// For each mesh (Loop-subdivided --loop times: bunny00.off with --loop 2 has 1.2M faces): wall
// seconds of detect_principal_symmetries() with its defaults and at most --planes planes, of
// symmetrize() with them (on their support, or with --whole 1 on the whole mesh), their ratio, the paired vertices, the symmetry distance error of the
// strongest plane before and after, and the peak resident memory of the process so far.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetrization.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "benchmark_utilities.h"

#include <sys/resource.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

const char* const usage_options = " [--meshes cow.off,bull.off] [--loop 0] [--planes 1] [--whole 0|1]\n";

double peak_megabytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

bool read_mesh(const std::string& name, unsigned loop, Mesh& mesh)
{
  const std::string path = benchmark_utilities::mesh_path(name);
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty() ||
     (!CGAL::is_triangle_mesh(mesh) && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh))) {
    std::cerr << "cannot read " << path << " as a triangle mesh (run scripts/setup.sh)\n";
    return false;
  }
  if(loop > 0) CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(loop));
  return true;
}

void time_mesh(const std::string& name, unsigned loop, unsigned planes, bool whole)
{
  Mesh mesh;
  if(!read_mesh(name, loop, mesh)) return;
  CGAL::Real_timer timer;
  timer.start();
  const auto found = ST::detect_principal_symmetries(mesh, CGAL::parameters::max_number_of_planes(planes));
  const double detection = timer.time();
  if(found.empty()) {
    std::cout << "| " << name << " | " << num_faces(mesh) << " | no plane found |\n";
    return;
  }
  const double before = ST::symmetry_distance_error(mesh, found.front().plane);
  timer.reset();
  const ST::Symmetrization<K> result = ST::symmetrize(mesh, found, CGAL::parameters::whole_mesh(whole));
  const double symmetrization = timer.time();
  const double after = ST::symmetry_distance_error(mesh, result.planes.front());
  std::cout << std::setprecision(3) << "| " << name << " | " << num_faces(mesh) << " | " << detection << " | "
            << symmetrization << " | " << symmetrization / detection << " | " << result.paired_vertices << " of "
            << num_vertices(mesh) << " | " << before << " | " << after << " | " << peak_megabytes() << " |"
            << std::endl;
}

int main(int argc, char** argv)
try {
  std::string meshes = "cow.off,bull.off";
  unsigned loop = 0, planes = 1, whole = 0;
  for(const auto& [option, value] : benchmark_utilities::option_pairs(argc, argv)) {
    if(option == "--meshes") meshes = value;
    else if(option == "--loop") loop = benchmark_utilities::natural_option(argv[0], usage_options, option, value, true);
    else if(option == "--planes") planes = benchmark_utilities::natural_option(argv[0], usage_options, option, value, false);
    else if(option == "--whole") whole = benchmark_utilities::natural_option(argv[0], usage_options, option, value, true);
    else benchmark_utilities::fail_with_usage(argv[0], usage_options, "unknown option " + option);
  }
  std::cout << "| mesh | faces | detection (s) | symmetrization (s) | ratio | paired vertices | SDE before | SDE after"
               " | peak memory (MB) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& name : benchmark_utilities::split(meshes)) time_mesh(name, loop, planes, whole != 0);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << argv[0] << ": " << e.what() << std::endl;
  return EXIT_FAILURE;
}
