// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planes of symmetry of a regular icosahedron, with named parameters of CGAL and of the
// package chained: at least three planes, each a perfect symmetry.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace ST = CGAL::Symmetry_transform;

int main()
{
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::make_icosahedron(mesh, K::Point_3(3., -2., 1.), 2.);
  const auto planes = ST::detect_principal_symmetries(
    mesh, CGAL::parameters::geom_traits(K()).grid_resolution(32).max_number_of_planes(3));
  for(const ST::Principal_symmetry<K>& s : planes) std::cout << "plane " << s.plane << ", symmetry " << s.symmetry << "\n";
  if(planes.size() < 3) return 1;
  for(const ST::Principal_symmetry<K>& s : planes)
    if(s.symmetry < 0.95) return 1;
  return 0;
}
