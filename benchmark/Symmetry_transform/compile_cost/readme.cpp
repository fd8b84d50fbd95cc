// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The README's program: the three strongest planes of symmetry of a mesh (compile_cost.py times its compilation).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ST = CGAL::Symmetry_transform;

int main(int argc, char** argv)
{
  CGAL::Surface_mesh<K::Point_3> mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh)) return 1;
  for(const ST::Principal_symmetry<K>& s :
      ST::detect_principal_symmetries(mesh, CGAL::parameters::grid_resolution(64).max_number_of_planes(3)))
    std::cout << "plane " << s.plane << ", symmetry " << s.symmetry << ", support " << s.support << std::endl;
}
