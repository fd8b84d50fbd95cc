// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Finds the principal symmetries of a point set (its planes of reflective symmetry, refined),
// prints them, and writes the points with each plane drawn as a square, as one PLY file.
//
// usage: principal_symmetries_of_points [points.xyz|.pwn|.ply|.off|.las] [--resolution N]
//          [--planes K] [--samples N] [--seed S] [--output FILE.ply]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "shape_extent.h"

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
            << "the reflection maps onto the point set.\n   #   plane (a b c d)                      symmetry  support\n";
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const K::Plane_3& plane = symmetries[i].plane;
    std::cout << std::setw(4) << i + 1 << "   " << std::fixed << std::setprecision(3) << std::setw(6) << plane.a() << ' '
              << std::setw(6) << plane.b() << ' ' << std::setw(6) << plane.c() << ' ' << std::setw(6) << plane.d()
              << "   " << std::setw(10) << symmetries[i].symmetry << std::setw(9) << symmetries[i].support << "\n";
    examples::add_plane_square(out, plane, extent.center, 2.2 * extent.radius, examples::plane_colour());
    comment << (i == 0 ? "" : "; ") << "plane " << i + 1 << ": " << plane;
  }
  examples::write_PLY(output, out, comment.str());
  std::cout << "\nWrote " << output << ": the points, and each plane as a blue square (two faces per plane)\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv);
  const std::string filename = options.input_file("points_3/oni.pwn");
  const std::size_t resolution = options.integer("--resolution", 64), planes = options.integer("--planes", 6),
                    samples = options.integer("--samples", 500000), seed = options.integer("--seed", 0, 0);
  const std::string output = options.text("--output", "principal_symmetries_of_points.ply");
  options.reject_unknown();
  const std::vector<Point_with_normal> points = examples::read_point_set<Point_with_normal>(filename,
    CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));

  CGAL::Real_timer timer;
  timer.start();
  const std::vector<ST::Principal_symmetry<K>> symmetries = ST::detect_principal_symmetries_of_points(points,
    CGAL::parameters::point_map(Point_map()).              // where the points are (the normals are not read)
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
