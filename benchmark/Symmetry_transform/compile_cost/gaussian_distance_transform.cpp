// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Gaussian-blurred distance transform of a mesh (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  std::cout << ST::gaussian_distance_transform(mesh, CGAL::parameters::grid_resolution(32)).resolution() << std::endl;
}
