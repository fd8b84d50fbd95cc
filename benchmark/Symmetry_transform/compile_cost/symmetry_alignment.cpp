// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The symmetry frame of a mesh (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/symmetry_alignment.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  std::cout << ST::symmetry_frame(mesh).center << std::endl;
}
