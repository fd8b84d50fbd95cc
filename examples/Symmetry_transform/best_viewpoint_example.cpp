// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
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

  // The views are scored from the principal symmetries of the mesh.
  const std::vector<ST::Principal_symmetry<K>> symmetries =
    ST::detect_principal_symmetries(mesh, CGAL::parameters::grid_resolution(32));

  // The best view shows the least of the mesh twice (mirror halves seen side by side).
  std::vector<ST::Viewpoint<K>> views; // best first
  ST::best_viewpoints(symmetries, std::back_inserter(views));
  const ST::Viewpoint<K> worst = ST::worst_viewpoint(symmetries);

  std::cout.precision(3);
  std::cout << symmetries.size() << " principal symmetries, " << views.size() << " good views" << std::endl;
  for(const ST::Viewpoint<K>& v : views)
    std::cout << "view along (" << v.direction << ")  score " << v.score << std::endl;
  std::cout << "worst view along (" << worst.direction << ")  score " << worst.score << std::endl;

  return EXIT_SUCCESS;
}
