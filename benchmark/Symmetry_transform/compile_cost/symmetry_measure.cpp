// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The symmetry distance error of a plane (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/symmetry_measure.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  std::cout << ST::symmetry_distance_error(mesh, K::Plane_3(1., 0., 0., 0.)) << std::endl;
}
