// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/point_group.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace ST = CGAL::Symmetry_transform;

int main(int argc, char** argv)
{
  // A gear: a 10-fold axis, and 10 axes of 2-fold flips perpendicular to it.
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/pinion.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The axes about which rotations map the mesh onto itself, with their orders up to 12.
  const auto np = CGAL::parameters::grid_resolution(32).max_order(12);
  const std::vector<ST::Rotational_symmetry<K>> symmetries = ST::detect_rotational_symmetries(mesh, np);

  std::cout << symmetries.size() << " rotational symmetries, strongest first" << std::endl;
  std::cout.precision(3);
  for(const ST::Rotational_symmetry<K>& s : symmetries)
  {
    // Order 0: a surface of revolution, symmetric under every angle.
    std::cout << (s.order == 0 ? std::string("continuous") : std::to_string(s.order) + "-fold")
              << " axis through (" << s.axis.point() << ") along (" << s.axis.to_vector()
              << ")  symmetry " << s.symmetry << "  support " << s.support << std::endl;
  }

  // The group of the exact symmetries, from the axes and the planes of mirror symmetry.
  const ST::Point_group group = ST::point_group(ST::detect_principal_symmetries(mesh, np), symmetries);
  std::cout << "point group " << group.name << " (" << group.order << " elements)" << std::endl;

  return EXIT_SUCCESS;
}
