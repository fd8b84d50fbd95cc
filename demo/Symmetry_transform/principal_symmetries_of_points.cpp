// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "shape_extent.h"

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

const char* const usage = R"(usage: principal_symmetries_of_points [POINTS] [--resolution N] [--planes K] [--samples N]
         [--seed S] [--ignore-normals] [--output FILE]

Finds the principal symmetries of a point set (its planes of reflective symmetry, refined), with
the normals of the points if the file has some (most scans do: XYZ with six columns, PWN, PLY
with nx ny nz), prints them with their symmetry distance error, and writes the points with each
plane drawn as a square, as one PLY file.

  POINTS            an XYZ, PWN, PLY, OFF or LAS file; default: points_3/oni.pwn of CGAL's
                    sample data, in the folder $CGAL_DATA_DIR
  --resolution N    GEDT samples and PRST bins per axis (default 64)
  --planes K        at most K planes, strongest first (default 6)
  --samples N       Monte Carlo samples of the PRST (default 500000)
  --seed S          random seed: the same seed, the same planes (default 0)
  --ignore-normals  detects from the points alone, even if the file has normals
  --output FILE     the points and the planes, .ply (default principal_symmetries_of_points.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Point_with_normal; // as Point_set_processing_3's examples
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

// Prints the planes and writes the points (as vertices) with each plane as a square of two
// blue faces, sized and placed by the points' centre and radius.
void write_planes(const std::vector<Point_with_normal>& points, const std::vector<ST::Principal_symmetry<K>>& symmetries,
                  const std::string& output)
{
  const examples::Extent<K::Point_3> extent = examples::extent_of_points(points, Point_map());
  Mesh out;
  for(const Point_with_normal& p : points) out.add_vertex(p.first);
  out.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color");
  std::ostringstream comment;
  std::cout << "Planes n.x + d = 0 with |n| = 1, strongest first; support: the fraction of the points that\n"
            << "the reflection maps onto the point set; SDE: mean distance from the mirrored points to the\n"
            << "nearest point, over the bounding box diagonal.\n"
            << "   #   plane (a b c d)                      symmetry  support       SDE\n";
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const K::Plane_3& plane = symmetries[i].plane;
    std::cout << std::setw(4) << i + 1 << "   " << std::fixed << std::setprecision(3) << std::setw(6) << plane.a() << ' '
              << std::setw(6) << plane.b() << ' ' << std::setw(6) << plane.c() << ' ' << std::setw(6) << plane.d()
              << "   " << std::setw(10) << symmetries[i].symmetry << std::setw(9) << symmetries[i].support
              << std::setw(10) << std::setprecision(5)
              << ST::symmetry_distance_error_of_points(points, plane, CGAL::parameters::point_map(Point_map())) << "\n";
    examples::add_plane_square(out, plane, extent.center, 2.2 * extent.radius, examples::plane_colour());
    comment << (i == 0 ? "" : "; ") << "plane " << i + 1 << ": " << plane;
  }
  examples::write_PLY(output, out, comment.str());
  std::cout << "\nWrote " << output << ": the points, and each plane as a blue square (two faces per plane)\n";
}

// The detection, with the normals of the points if they have some: ISP then fits the plane to
// the tangent planes of the points (point to plane), as on a mesh, instead of to the points.
template <typename NamedParameters>
std::vector<ST::Principal_symmetry<K>> detect(const std::vector<Point_with_normal>& points, bool with_normals,
                                              const NamedParameters& np)
{
  std::cout << points.size() << " points, " << (with_normals ? "with normals: ISP fits point to plane"
                                                             : "without normals: ISP fits point to point") << "\n";
  if(with_normals) return ST::detect_principal_symmetries_of_points(points, np.normal_map(Normal_map()));
  return ST::detect_principal_symmetries_of_points(points, np);
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage, {"--ignore-normals"});
  const std::string filename = options.input_file("points_3/oni.pwn");
  const std::size_t resolution = options.integer("--resolution", 64), planes = options.integer("--planes", 6),
                    samples = options.integer("--samples", 500000), seed = options.integer("--seed", 0, 0);
  const std::string output = options.text("--output", "principal_symmetries_of_points.ply");
  const bool ignore_normals = options.flag("--ignore-normals");
  options.validate();
  const std::vector<Point_with_normal> points = examples::read_point_set<Point_with_normal>(filename,
    CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())); // a file without normals leaves them zero
  const bool with_normals = !ignore_normals && std::any_of(points.begin(), points.end(),
    [](const Point_with_normal& p) { return p.second != CGAL::NULL_VECTOR; });

  CGAL::Real_timer timer;
  timer.start();
  const std::vector<ST::Principal_symmetry<K>> symmetries = detect(points, with_normals,
    CGAL::parameters::point_map(Point_map()).              // where the points are
                      grid_resolution(int(resolution)).    // GEDT samples and PRST bins per axis
                      max_number_of_planes(planes).        // at most this many, strongest first
                      number_of_samples(samples).          // Monte Carlo samples of the PRST
                      random_seed(unsigned(seed)));        // the same seed, the same planes
  std::cout << std::setprecision(3) << symmetries.size() << " principal symmetries (grid " << resolution << "^3, "
            << samples << " Monte Carlo samples) in " << timer.time() << " s\n";
  write_planes(points, symmetries, output);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
