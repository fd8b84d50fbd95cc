// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace ST = CGAL::Symmetry_transform;
typedef ST::Reflective_symmetry_transform<K> PRST;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The symmetry measure of every plane, on 32 x 32 x 32 bins of (theta, phi, r),
  // estimated by Monte Carlo sampling.
  const PRST prst = ST::reflective_symmetry_transform(mesh, CGAL::parameters::grid_resolution(32));

  std::vector<PRST::Bin> maxima; // the local maxima, strongest first
  prst.local_maxima(std::back_inserter(maxima));

  const PRST::Bin best = prst.maximum();
  std::cout.precision(3);
  std::cout << prst.resolution() << "^3 bins, " << maxima.size() << " local maxima" << std::endl;
  std::cout << "strongest bin (" << best[0] << ", " << best[1] << ", " << best[2]
            << "): symmetry " << prst.value(best) << std::endl;
  std::cout << "its plane: " << prst.plane(best) << std::endl;

  return EXIT_SUCCESS;
}
