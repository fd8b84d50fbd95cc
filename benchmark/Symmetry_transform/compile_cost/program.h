// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every program of this folder does besides calling the package, as reader.cpp does alone:
// a Surface_mesh read from the file given on the command line.

#ifndef SYMMETRY_TRANSFORM_COMPILE_COST_PROGRAM_H
#define SYMMETRY_TRANSFORM_COMPILE_COST_PROGRAM_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace CGAL::Symmetry_transform {}
namespace ST = CGAL::Symmetry_transform;

inline Mesh mesh_of_arguments(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh)) std::exit(1);
  return mesh;
}

#endif // SYMMETRY_TRANSFORM_COMPILE_COST_PROGRAM_H
