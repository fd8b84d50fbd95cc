// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Real_timer.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>

#include "command_line_options.h"
#include "input_files.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>

const char* const usage = R"(usage: align_to_symmetry_frame [MESH] [--resolution N] [--samples N] [--seed S] [--output FILE]

Aligns a mesh to its symmetry frame (thesis, section 4.1): computes the centre of symmetry and the
principal symmetry axes, prints them next to the classical frame (centre of mass and principal
axes, PCA), and writes the mesh moved so that its symmetry frame is the canonical one: centre at
the origin, first axis (normal of the strongest plane of symmetry) along x, second along y, third
along z.

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    GEDT samples and PRST bins per axis (default 64)
  --samples N       Monte Carlo samples of the PRST (default 500000)
  --seed S          random seed: the same seed, the same frame (default 0)
  --output FILE     the moved mesh, .ply or .off (default align_to_symmetry_frame.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef examples::Triangle_soup<K::Point_3> Soup;
namespace ST = CGAL::Symmetry_transform;

void print(const std::string& name, const ST::Symmetry_frame<K>& frame)
{
  std::cout << name << "\n  centre (" << frame.center << ")\n";
  for(int i = 0; i < 3; ++i) std::cout << "  axis " << i + 1 << " (" << frame.axes[i] << ")\n";
}

double degrees_between_lines(const K::Vector_3& a, const K::Vector_3& b)
{
  const double d = std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b) * 180. / CGAL_PI;
  return std::min(d, 180. - d);
}

// The symmetry frame next to the PCA frame (centre of mass, axes of largest variance first),
// which it replaces where the variances of a shape are close.
void print_with_pca_frame(const ST::Symmetry_frame<K>& frame, const Soup& soup)
{
  const ST::Symmetry_frame<K> pca = ST::pca_frame_of_triangle_soup(soup.points, soup.triangles);
  print("Symmetry frame (centre of symmetry, principal symmetry axes):", frame);
  print("PCA frame (centre of mass, principal axes, largest variance first):", pca);
  std::cout << "Centres " << std::sqrt(CGAL::squared_distance(frame.center, pca.center)) << " apart; each symmetry axis "
            << "makes with the nearest PCA axis:";
  for(const K::Vector_3& a : frame.axes) {
    double best = 90.;
    for(const K::Vector_3& b : pca.axes) best = std::min(best, degrees_between_lines(a, b));
    std::cout << " " << best;
  }
  std::cout << " deg\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64), samples = options.integer("--samples", 500000),
                    seed = options.integer("--seed", 0, 0);
  const std::string output = options.text("--output", "align_to_symmetry_frame.ply");
  options.validate();
  Soup soup = examples::read_triangle_soup<K::Point_3>(filename); // any mesh file, repaired as a soup

  CGAL::Real_timer timer;
  timer.start();
  const ST::Symmetry_frame<K> frame = ST::symmetry_frame_of_triangle_soup(soup.points, soup.triangles,
    CGAL::parameters::grid_resolution(int(resolution)). // GEDT samples and PRST bins per axis
                      number_of_samples(samples).       // Monte Carlo samples of the PRST
                      random_seed(unsigned(seed)));     // the same seed, the same frame
  std::cout << std::setprecision(4) << "Symmetry frame in " << timer.time() << " s (grid " << resolution << "^3, "
            << samples << " Monte Carlo samples)\n";
  print_with_pca_frame(frame, soup);

  const K::Aff_transformation_3 to_canonical = ST::to_canonical(frame); // the symmetry frame becomes x, y, z
  for(K::Point_3& p : soup.points) p = to_canonical.transform(p);
  if(!CGAL::IO::write_polygon_soup(output, soup.points, soup.triangles, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write " + output);
  std::cout << "Wrote " << output << ": the surface moved to its symmetry frame (centre at the origin, axes x, y, z)\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
