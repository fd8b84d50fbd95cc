// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Symmetry_transform/point_symmetry_transform.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The symmetry measure of the central symmetry through every point of a 32^3 grid.
  const ST::Point_symmetry_transform<K> pst =
    ST::point_symmetry_transform(mesh, CGAL::parameters::grid_resolution(32));

  // The most symmetric point, and the centre of mass for comparison.
  const K::Point_3& center = pst.center_of_symmetry();
  const K::Point_3 centroid = PMP::centroid(mesh);

  std::cout.precision(3);
  std::cout << "centre of symmetry: " << center << "  symmetry " << pst.value(center) << std::endl;
  std::cout << "centre of mass:     " << centroid << "  symmetry " << pst.value(centroid) << std::endl;

  return EXIT_SUCCESS;
}
