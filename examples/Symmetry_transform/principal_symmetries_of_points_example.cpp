// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/property_map.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

namespace ST = CGAL::Symmetry_transform;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("points_3/oni.pwn");

  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points),
                            CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())) || points.empty())
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points with normals" << std::endl;

  // With the normals, the refinement fits each plane to the tangent planes of the points.
  const std::vector<ST::Principal_symmetry<K>> symmetries =
    ST::detect_principal_symmetries_of_points(points,
      CGAL::parameters::point_map(Point_map()).
                        normal_map(Normal_map()).
                        grid_resolution(32).        // bins per axis
                        max_number_of_planes(3));   // the 3 strongest

  std::cout << symmetries.size() << " principal symmetries, strongest first" << std::endl;
  std::cout.precision(3);
  for(const ST::Principal_symmetry<K>& s : symmetries)
    std::cout << "plane " << s.plane << "  symmetry " << s.symmetry
              << "  support " << s.support << std::endl;

  return EXIT_SUCCESS;
}
