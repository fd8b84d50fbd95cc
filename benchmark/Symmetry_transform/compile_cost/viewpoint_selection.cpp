// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The best viewpoint of a mesh, from its planes of symmetry (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include <vector>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  std::vector<ST::Viewpoint<K>> views;
  ST::best_viewpoints(ST::detect_principal_symmetries(mesh), std::back_inserter(views));
  std::cout << views.size() << std::endl;
}
