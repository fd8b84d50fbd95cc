// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rotational symmetries of a mesh (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/rotational_symmetries.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  std::cout << ST::detect_rotational_symmetries(mesh).size() << std::endl;
}
