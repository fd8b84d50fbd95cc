// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The point symmetry transform of a mesh (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/point_symmetry_transform.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  const auto pst = ST::point_symmetry_transform(mesh, CGAL::parameters::grid_resolution(32));
  std::cout << pst.grid().resolution() << std::endl;
}
