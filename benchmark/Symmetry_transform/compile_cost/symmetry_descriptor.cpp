// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The symmetry descriptor of a mesh, and its distance to itself (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/symmetry_descriptor.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  const auto d = ST::symmetry_descriptor(mesh);
  std::cout << ST::descriptor_distance(d, d) << std::endl;
}
