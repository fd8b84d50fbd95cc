// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A program calling segmentation and symmetric remeshing (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include <vector>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  std::cout << ST::segment_by_symmetry(mesh, segment, CGAL::parameters::grid_resolution(32)) << " segments\n";
  std::vector<K::Plane_3> planes;
  for(const auto& s : ST::detect_principal_symmetries(mesh)) planes.push_back(s.plane);
  Mesh remeshed;
  ST::symmetric_approximate_triangle_mesh(mesh, planes, CGAL::parameters::max_number_of_proxies(50).output_mesh(&remeshed));
  std::cout << num_faces(remeshed) << " faces" << std::endl;
}
