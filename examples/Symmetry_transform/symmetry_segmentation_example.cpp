// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;

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

  // Receives the segment id of each face.
  Mesh::Property_map<face_descriptor, std::size_t> segment_ids =
    mesh.add_property_map<face_descriptor, std::size_t>("f:segment", 0).first;

  // Splits the mesh, level by level, where its parts have different symmetries.
  const std::size_t number_of_segments =
    ST::segment_by_symmetry(mesh, segment_ids,
                            CGAL::parameters::grid_resolution(32).       // of each segment's detection
                                              max_segmentation_depth(3)); // levels of splits

  std::vector<std::size_t> faces_of_segment(number_of_segments, 0);
  for(face_descriptor f : faces(mesh))
    ++faces_of_segment[get(segment_ids, f)];

  std::cout << number_of_segments << " segments" << std::endl;
  for(std::size_t id = 0; id < number_of_segments; ++id)
    std::cout << "segment " << id << ": " << faces_of_segment[id] << " faces" << std::endl;

  return EXIT_SUCCESS;
}
