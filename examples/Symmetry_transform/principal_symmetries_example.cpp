// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace ST = CGAL::Symmetry_transform;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The local maxima of the reflective symmetry transform, refined on the mesh: the planes of
  // (partial) mirror symmetry, strongest first.
  const std::vector<ST::Principal_symmetry<K>> symmetries =
    ST::detect_principal_symmetries(mesh, CGAL::parameters::grid_resolution(32).      // bins per axis
                                                            max_number_of_planes(3)); // the 3 strongest

  std::cout << symmetries.size() << " principal symmetries, strongest first" << std::endl;
  std::cout.precision(3);
  for(const ST::Principal_symmetry<K>& s : symmetries)
  {
    // The plane a x + b y + c z + d = 0 (unit normal); symmetry 1 is a perfect mirror;
    // support: the fraction of the surface that the reflection maps onto the surface.
    std::cout << "plane " << s.plane << "  symmetry " << s.symmetry
              << "  support " << s.support << std::endl;
  }

  return EXIT_SUCCESS;
}
