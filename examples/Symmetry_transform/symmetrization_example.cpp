// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetrization.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace ST = CGAL::Symmetry_transform;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/cow.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The strongest plane of mirror symmetry, then the least displacement that makes it exact.
  const std::vector<ST::Principal_symmetry<K>> planes =
    ST::detect_principal_symmetries(mesh, CGAL::parameters::max_number_of_planes(1));
  const double error_before = ST::symmetry_distance_error(mesh, planes.front().plane);
  const ST::Symmetrization<K> result = ST::symmetrize(mesh, planes);

  std::cout << "plane " << result.planes.front() << std::endl;
  std::cout << result.paired_vertices << " of " << num_vertices(mesh) << " vertices paired" << std::endl;
  std::cout << "displacement: mean " << result.mean_displacement << ", max " << result.max_displacement << std::endl;
  std::cout << "symmetry distance error: " << error_before << " before, "
            << ST::symmetry_distance_error(mesh, result.planes.front()) << " after" << std::endl;

  if(argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Cannot write " << argv[2] << std::endl;
    return EXIT_FAILURE;
  }

  return EXIT_SUCCESS;
}
