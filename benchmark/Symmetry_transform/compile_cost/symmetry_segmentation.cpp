// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mesh segmented by symmetry (compile_cost.py times its compilation).

#include "program.h"

#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

int main(int argc, char** argv)
{
  Mesh mesh = mesh_of_arguments(argc, argv);
  auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  std::cout << ST::segment_by_symmetry(mesh, segment, CGAL::parameters::grid_resolution(32)) << std::endl;
}
