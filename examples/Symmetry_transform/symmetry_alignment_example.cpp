// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/transform.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>

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

  // The centre of symmetry and the normals of the principal planes, as a right-handed frame.
  const ST::Symmetry_frame<K> frame = ST::symmetry_frame(mesh, CGAL::parameters::grid_resolution(32));

  std::cout.precision(3);
  std::cout << "centre " << frame.center << std::endl;
  for(int i = 0; i < 3; ++i)
    std::cout << "axis " << i << ": " << frame.axes[i] << std::endl;

  // Moves the mesh so that the frame becomes the origin and the x, y, z axes.
  PMP::transform(ST::to_canonical(frame), mesh);
  std::cout << "bounding box once aligned: " << PMP::bbox(mesh) << std::endl;

  if(argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Cannot write " << argv[2] << std::endl;
    return EXIT_FAILURE;
  }

  return EXIT_SUCCESS;
}
