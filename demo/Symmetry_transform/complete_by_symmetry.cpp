// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetrization.h>

#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "progress_bar.h"
#include "shape_extent.h"

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

const char* const usage = R"(usage: complete_by_symmetry [POINTS] [--resolution N] [--planes K] [--coverage D]
         [--output FILE]

Completes a point set that misses part of a symmetric shape (a scan that did not see its far
side): detects its K strongest planes of mirror symmetry and adds the mirror images of the points
whose image has no point nearby, nothing where the set already has points. Prints the planes
used and how many points were added. Writes the input points first, unchanged and in order, then
the added ones, with normals if the input has some (images of the normals).

  POINTS            an XYZ, PWN, PLY, OFF or LAS file, with normals or not; default:
                    points_3/oni.pwn of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    grid resolution of the plane detection, at least 8 (default 64)
  --planes K        how many detected planes to complete with (default 1)
  --coverage D      an image with a point within D (in radii of the point set) is not added
                    (default: 3 times the median distance between neighbouring points)
  --output FILE     .ply: the points with normals, the input grey and the added points orange;
                    .xyz, .pwn or any other extension that CGAL writes: points and normals
                    (default completed.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

// The points as the vertices of a mesh without faces, with normals, coloured: the first `input`
// grey, the others orange.
void write_coloured(const std::string& file, const std::vector<Point_with_normal>& points, std::size_t input)
{
  Mesh cloud;
  auto normal = cloud.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  auto colour = cloud.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Mesh::Vertex_index v = cloud.add_vertex(points[i].first);
    normal[v] = points[i].second;
    colour[v] = i < input ? CGAL::IO::Color(190, 190, 190) : CGAL::IO::Color(255, 140, 20);
  }
  examples::write_PLY(file, cloud, "vertex colour: grey the input, orange the points added by symmetry");
}

void write_points(const std::string& file, const std::vector<Point_with_normal>& points, std::size_t input)
{
  if(examples::without_ply_extension(file) != file) write_coloured(file, points, input);
  else if(!CGAL::IO::write_points(file, points, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())
                                                   .stream_precision(17)))
    throw std::runtime_error("cannot write " + file);
  std::cout << "Wrote " << file << "\n";
}

template <typename NamedParameters>
std::vector<K::Plane_3> detected_planes(const std::vector<Point_with_normal>& points, std::size_t resolution,
                                        std::size_t count, const NamedParameters& np)
{
  std::vector<K::Plane_3> planes;
  for(const auto& s : ST::detect_principal_symmetries_of_points(points, np.grid_resolution(int(resolution))
                                                                          .max_number_of_planes(count)))
    planes.push_back(s.plane);
  if(planes.empty()) throw std::runtime_error("no plane of symmetry found");
  for(const K::Plane_3& p : planes) std::cout << "  plane " << std::setprecision(6) << p << "\n";
  return planes;
}

// The completion, with the normals if the points have some, and the coverage distance if given.
template <typename NamedParameters>
std::vector<Point_with_normal> added_points(const std::vector<Point_with_normal>& points,
                                            const std::vector<K::Plane_3>& planes, double coverage,
                                            const NamedParameters& np)
{
  std::vector<Point_with_normal> added;
  const auto with_progress = np.callback(examples::progress_bar("Completing"));
  if(coverage > 0.) ST::complete_by_symmetry_of_points(points, planes, std::back_inserter(added), with_progress.coverage_distance(coverage));
  else ST::complete_by_symmetry_of_points(points, planes, std::back_inserter(added), with_progress);
  return added;
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("points_3/oni.pwn");
  const std::size_t resolution = options.integer("--resolution", 64, 8), count = options.integer("--planes", 1);
  const double coverage = options.real("--coverage", 0.);
  const std::string output = options.text("--output", "completed.ply");
  options.validate();
  std::vector<Point_with_normal> points = examples::read_point_set<Point_with_normal>(filename,
    CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())); // a file without normals leaves them zero
  const bool with_normals = std::any_of(points.begin(), points.end(),
                                        [](const Point_with_normal& p) { return p.second != CGAL::NULL_VECTOR; });
  const double radius = examples::extent_of_points(points, Point_map()).radius;
  std::cout << points.size() << " points" << (with_normals ? " with normals" : "") << "; planes used:\n";

  const auto np = CGAL::parameters::point_map(Point_map());
  const std::vector<K::Plane_3> planes = with_normals ? detected_planes(points, resolution, count, np.normal_map(Normal_map()))
                                                      : detected_planes(points, resolution, count, np);
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<Point_with_normal> added = with_normals
    ? added_points(points, planes, coverage * radius, np.normal_map(Normal_map()))
    : added_points(points, planes, coverage * radius, np);
  std::cout << "completed in " << std::setprecision(3) << timer.time() << " s: " << added.size() << " points added to "
            << points.size() << "\n";
  const std::size_t input = points.size();
  points.insert(points.end(), added.begin(), added.end());
  write_points(output, points, input);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
