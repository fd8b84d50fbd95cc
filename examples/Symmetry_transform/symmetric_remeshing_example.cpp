// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>

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

  // The plane of symmetry to keep: the strongest principal symmetry.
  std::vector<K::Plane_3> planes;
  for(const ST::Principal_symmetry<K>& s :
      ST::detect_principal_symmetries(mesh, CGAL::parameters::grid_resolution(32).max_number_of_planes(1)))
    planes.push_back(s.plane);

  // Variational Shape Approximation whose proxies also cover the mirror images of their patches.
  Mesh remeshed;
  ST::symmetric_approximate_triangle_mesh(mesh, planes,
    CGAL::parameters::max_number_of_proxies(50). // each with a patch and its mirror image
                      output_mesh(&remeshed));   // the coarse mesh

  std::cout << "input: " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces; "
            << planes.size() << " plane(s) kept" << std::endl;
  std::cout << "remeshed: " << num_vertices(remeshed) << " vertices, " << num_faces(remeshed) << " faces" << std::endl;

  if(argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], remeshed, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Cannot write " << argv[2] << std::endl;
    return EXIT_FAILURE;
  }

  return EXIT_SUCCESS;
}
