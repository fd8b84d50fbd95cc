// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "progress_bar.h"
#include "shape_extent.h"

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

const char* const usage = R"(usage: principal_symmetries [MESH] [--resolution N] [--planes K] [--samples N] [--seed S]
         [--output PREFIX]

Finds the principal symmetries of a mesh (its planes of reflective symmetry, refined), prints
them with their support and symmetry distance error, and writes one PLY file per plane: the
surface with each face coloured by how much the reflection through the plane maps it onto the
surface, and the plane drawn as a square.

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    GEDT samples and PRST bins per axis (default 64)
  --planes K        at most K planes, strongest first (default 6)
  --samples N       Monte Carlo samples of the PRST (default 500000)
  --seed S          random seed: the same seed, the same planes (default 0)
  --output PREFIX   writes PREFIX_1.ply, PREFIX_2.ply, ..., strongest plane first; a trailing
                    .ply of PREFIX is dropped (default principal_symmetries)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef examples::Triangle_soup<K::Point_3> Soup;
namespace ST = CGAL::Symmetry_transform;

// The columns printed for each plane.
void print_header(const examples::Extent<K::Point_3>& extent)
{
  std::cout << "Centre of mass c = (" << extent.center << "), radius R = " << extent.radius << "\n"
            << "Planes n.x + d = 0 with |n| = 1, strongest first; r = -(n.c + d): n.(x - c) = r;\n"
            << "support: the fraction of the area that the reflection maps onto the surface;\n"
            << "SDE: mean distance from the mirrored surface to the surface over the bounding box diagonal.\n"
            << "   #   normal n (x y z)             d      r/R  symmetry  support       SDE\n" << std::fixed;
}

void print_plane(std::size_t rank, const ST::Principal_symmetry<K>& s, const examples::Extent<K::Point_3>& extent,
                 double support, double sde)
{
  const K::Vector_3 n = s.plane.orthogonal_vector();
  std::cout << std::setw(4) << rank << "   (" << std::setprecision(3) << std::setw(6) << n.x() << ' ' << std::setw(6)
            << n.y() << ' ' << std::setw(6) << n.z() << ") " << std::setw(8) << s.plane.d() << std::setw(9)
            << -(n * (extent.center - CGAL::ORIGIN) + s.plane.d()) / extent.radius << std::setw(10) << s.symmetry
            << std::setw(9) << support << std::setw(10) << std::setprecision(5) << sde << "\n";
  // A surface of revolution or a sphere has infinitely many mirrors: one plane stands for them.
  const K::Point_3 p = s.axis.point();
  if(s.family == ST::Mirror_family::EVERY_PLANE_THROUGH_AXIS)
    std::cout << std::setprecision(3) << "        and every plane through the axis (" << p << ") + t ("
              << s.axis.to_vector() << ")\n";
  else if(s.family == ST::Mirror_family::EVERY_PLANE_THROUGH_POINT)
    std::cout << std::setprecision(3) << "        and every plane through (" << p << ")\n";
}

// Per plane: prints it with its support (thesis, Figure 3.7) and its SDE, and writes
// PREFIX_<rank>.ply, the surface with its faces coloured by support and the plane as a square
// (its last two faces).
template <typename NamedParameters>
void write_planes(const Soup& soup, const std::vector<ST::Principal_symmetry<K>>& symmetries, const std::string& prefix,
                  const NamedParameters& np)
{
  const examples::Extent<K::Point_3> extent = examples::extent_of_soup(soup.points, soup.triangles);
  print_header(extent);
  const Mesh mesh = examples::mesh_of_soup<Mesh>(soup, true); // for the files: face i is triangle i
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const K::Plane_3& plane = symmetries[i].plane;
    std::vector<double> support; // one value per triangle
    const double fraction =
      ST::symmetry_support_of_triangle_soup(soup.points, soup.triangles, plane, std::back_inserter(support), np);
    const double sde = ST::symmetry_distance_error_of_triangle_soup(soup.points, soup.triangles, plane, np);
    print_plane(i + 1, symmetries[i], extent, fraction, sde);
    Mesh out = examples::with_face_colours(mesh, [&](Mesh::Face_index f) { return examples::dark_to_bright(support[f]); });
    examples::add_plane_square(out, plane, extent.center, 2.2 * extent.radius, examples::plane_colour());
    std::ostringstream comment;
    comment << std::setprecision(4) << "plane " << i + 1 << ": " << plane << "; symmetry " << symmetries[i].symmetry
            << "; support " << fraction << "; SDE " << sde << "; face colour: support (dark 0, bright 1); last 2 faces: the plane";
    examples::write_PLY(prefix + "_" + std::to_string(i + 1) + ".ply", out, comment.str());
  }
  if(symmetries.empty()) { std::cout << "No plane found: nothing written.\n"; return; }
  std::cout << "\nWrote " << prefix << "_1.ply" << (symmetries.size() > 1 ? " ... " + prefix + "_" +
                                                   std::to_string(symmetries.size()) + ".ply" : std::string())
            << ": per plane, the surface with faces coloured by support,\n  from dark (none) to bright (full), "
            << "and the plane as a blue square\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64), planes = options.integer("--planes", 6),
                    samples = options.integer("--samples", 500000), seed = options.integer("--seed", 0, 0);
  const std::string prefix = examples::without_ply_extension(options.text("--output", "principal_symmetries"));
  options.validate();
  const Soup soup = examples::read_triangle_soup<K::Point_3>(filename); // any mesh file, repaired as a soup

  const auto np = CGAL::parameters::grid_resolution(int(resolution)). // GEDT samples and PRST bins per axis
                                    max_number_of_planes(planes).     // at most this many, strongest first
                                    number_of_samples(samples).       // Monte Carlo samples of the PRST
                                    random_seed(unsigned(seed));      // the same seed, the same planes
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<ST::Principal_symmetry<K>> symmetries =
    ST::detect_principal_symmetries_of_triangle_soup(soup.points, soup.triangles,
                                                     np.callback(examples::progress_bar("Detection"))); // on a terminal
  std::cout << std::setprecision(3) << symmetries.size() << " principal symmetries (grid " << resolution << "^3, "
            << samples << " Monte Carlo samples) in " << timer.time() << " s\n";
  write_planes(soup, symmetries, prefix, np);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
