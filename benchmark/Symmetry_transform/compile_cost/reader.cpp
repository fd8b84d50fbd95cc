// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The baseline: a Surface_mesh read from a file, what every program here also does (compile_cost.py times its compilation).

#include "program.h"

int main(int argc, char** argv)
{
  const Mesh mesh = mesh_of_arguments(argc, argv);
  std::cout << num_faces(mesh) << " faces" << std::endl;
}
