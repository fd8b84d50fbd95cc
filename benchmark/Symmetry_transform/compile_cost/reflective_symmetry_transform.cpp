// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reflective symmetry transform of a mesh (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  const auto prst = ST::reflective_symmetry_transform(mesh, CGAL::parameters::grid_resolution(32));
  std::cout << prst.resolution() << std::endl;
}
