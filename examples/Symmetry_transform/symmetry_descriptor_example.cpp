// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/transform.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace ST = CGAL::Symmetry_transform;

int main(int argc, char** argv)
{
  const std::string filenames[2] = {(argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off"),
                                    (argc > 2) ? argv[2] : CGAL::data_file_path("meshes/cow.off")};

  ST::Symmetry_descriptor<K> descriptors[2];
  for(int i = 0; i < 2; ++i)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(filenames[i], mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      std::cerr << "Invalid input file: " << filenames[i] << std::endl;
      return EXIT_FAILURE;
    }
    const auto np = CGAL::parameters::grid_resolution(32); // 32^3 bins
    // Descriptors are compared in the shapes' own coordinates: align each mesh first.
    CGAL::Polygon_mesh_processing::transform(ST::to_canonical(ST::symmetry_frame(mesh, np)), mesh);
    // Its reflective symmetry transform and its distance transform.
    descriptors[i] = ST::symmetry_descriptor(mesh, np);
  }

  // 0 for equal descriptors; the smaller, the more alike the two shapes.
  std::cout.precision(3);
  std::cout << "distance of the symmetries: "
            << ST::reflective_symmetry_descriptor_distance(descriptors[0], descriptors[1]) << std::endl;
  std::cout << "distance of the shapes:     " << ST::gedt_distance(descriptors[0], descriptors[1]) << std::endl;
  std::cout << "descriptor distance:        " << ST::descriptor_distance(descriptors[0], descriptors[1]) << std::endl;

  return EXIT_SUCCESS;
}
