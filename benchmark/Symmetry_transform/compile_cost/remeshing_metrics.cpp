// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The approximation error between two meshes (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/remeshing_metrics.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  std::cout << ST::approximation_error(mesh, mesh).rms << std::endl;
}
