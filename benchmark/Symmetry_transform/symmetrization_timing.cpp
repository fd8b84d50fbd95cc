// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The cost of symmetrize() against the plane detection it follows, on the same mesh in one run:
//
//   symmetrization_timing [--meshes cow.off,bull.off] [--loop 0] [--planes 1] [--whole 0|1] [--complete 0|1]
//
// For each mesh (Loop-subdivided --loop times: bunny00.off with --loop 2 has 1.2M faces): wall
// seconds of detect_principal_symmetries() with its defaults and at most --planes planes, of
// symmetrize() with them (on their support, or with --whole 1 on the whole mesh), their ratio, the paired vertices, the symmetry distance error of the
// strongest plane before and after, and the peak resident memory of the process so far.
// With --complete 1, the completion instead: the faces on the positive side of the strongest plane
// and above the centroid along the plane's second axis (a quarter of the surface) cut away, then
// wall seconds of the detection on the cut mesh, of complete_by_symmetry() on it with the plane
// (added as separate components, then with stitch_borders(true), with the border edges left),
// and of complete_by_symmetry_of_points() on its vertices with their normals.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
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
#include <array>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

const char* const usage_options = " [--meshes cow.off,bull.off] [--loop 0] [--planes 1] [--whole 0|1] [--complete 0|1]\n";

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

// The mesh without the faces whose centroid lies on the positive side of `plane` and above the
// centroid of the mesh along a direction in the plane: about a quarter of a symmetric surface.
Mesh cut_quarter(const Mesh& mesh, const K::Plane_3& plane)
{
  const K::Vector_3 across = plane.base1() / std::sqrt(plane.base1().squared_length());
  std::vector<K::Point_3> points(mesh.points().begin(), mesh.points().end());
  const K::Point_3 center = CGAL::centroid(points.begin(), points.end());
  std::vector<std::array<std::size_t, 3>> kept;
  for(auto f : faces(mesh)) {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = std::size_t(v);
    const K::Point_3 c = CGAL::centroid(points[t[0]], points[t[1]], points[t[2]]);
    if(plane.oriented_side(c) != CGAL::ON_POSITIVE_SIDE || (c - center) * across < 0.) kept.push_back(t);
  }
  Mesh cut;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, kept, cut);
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(cut);
  cut.collect_garbage();
  return cut;
}

void time_completion(const std::string& name, unsigned loop)
{
  Mesh whole;
  if(!read_mesh(name, loop, whole)) return;
  const auto found = ST::detect_principal_symmetries(whole, CGAL::parameters::max_number_of_planes(1));
  if(found.empty()) return;
  Mesh mesh = cut_quarter(whole, found.front().plane);
  CGAL::Real_timer timer;
  timer.start();
  ST::detect_principal_symmetries(mesh, CGAL::parameters::max_number_of_planes(1));
  const double detection = timer.time();
  std::vector<std::pair<K::Point_3, K::Vector_3>> points;
  for(auto v : vertices(mesh)) points.emplace_back(mesh.point(v), CGAL::Polygon_mesh_processing::compute_vertex_normal(v, mesh));
  const std::size_t faces_before = num_faces(mesh);
  Mesh stitched = mesh;
  std::vector<Mesh::Face_index> added_faces, stitched_faces;
  timer.reset();
  ST::complete_by_symmetry(mesh, found, std::back_inserter(added_faces));
  const double mesh_completion = timer.time();
  timer.reset();
  ST::complete_by_symmetry(stitched, found, std::back_inserter(stitched_faces), CGAL::parameters::stitch_borders(true));
  const double stitched_completion = timer.time();
  const auto border_edges = [](const Mesh& m) {
    std::size_t count = 0;
    for(auto h : halfedges(m)) count += is_border(h, m);
    return count;
  };
  std::vector<std::pair<K::Point_3, K::Vector_3>> added_points;
  timer.reset();
  ST::complete_by_symmetry_of_points(points, found, std::back_inserter(added_points),
                                     CGAL::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<K::Point_3, K::Vector_3>>())
                                       .normal_map(CGAL::Second_of_pair_property_map<std::pair<K::Point_3, K::Vector_3>>()));
  const double point_completion = timer.time();
  std::cout << std::setprecision(3) << "| " << name << " | " << faces_before << " | " << detection << " | "
            << mesh_completion << " (" << added_faces.size() << " faces) | " << mesh_completion / detection << " | "
            << stitched_completion << " (" << stitched_faces.size() << " faces; border halfedges " << border_edges(stitched)
            << ", " << border_edges(mesh) << " unstitched) | " << stitched_completion / detection << " | "
            << point_completion << " (" << added_points.size() << " of " << points.size() << " points) | "
            << point_completion / detection << " | " << peak_megabytes() << " |" << std::endl;
}

int main(int argc, char** argv)
try {
  std::string meshes = "cow.off,bull.off";
  unsigned loop = 0, planes = 1, whole = 0, complete = 0;
  for(const auto& [option, value] : benchmark_utilities::option_pairs(argc, argv)) {
    if(option == "--meshes") meshes = value;
    else if(option == "--loop") loop = benchmark_utilities::natural_option(argv[0], usage_options, option, value, true);
    else if(option == "--planes") planes = benchmark_utilities::natural_option(argv[0], usage_options, option, value, false);
    else if(option == "--whole") whole = benchmark_utilities::natural_option(argv[0], usage_options, option, value, true);
    else if(option == "--complete") complete = benchmark_utilities::natural_option(argv[0], usage_options, option, value, true);
    else benchmark_utilities::fail_with_usage(argv[0], usage_options, "unknown option " + option);
  }
  if(complete != 0) {
    std::cout << "| mesh | faces left | detection (s) | mesh completion (s) | ratio | stitched (s) | ratio"
                 " | point completion (s) | ratio | peak memory (MB) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for(const std::string& name : benchmark_utilities::split(meshes)) time_completion(name, loop);
    return EXIT_SUCCESS;
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
