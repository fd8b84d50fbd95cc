// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Finds the principal symmetries of a mesh (its planes of reflective symmetry, refined),
// prints them, and writes one PLY file per plane: the mesh with each face coloured by how much
// the reflection through the plane maps it onto the surface, and the plane drawn as a square.
//
// usage: principal_symmetries [mesh.off|.ply|.obj|.stl] [--resolution N] [--planes K]
//          [--samples N] [--seed S] [--output PREFIX]
// writes PREFIX_1.ply, PREFIX_2.ply, ... (strongest plane first; a trailing ".ply" of PREFIX is dropped)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "shape_extent.h"

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

// Per plane: prints it with its support (thesis, Figure 3.7) and writes PREFIX_<rank>.ply, the
// mesh with its faces coloured by support and the plane as a square (its last two faces).
template <typename NamedParameters>
void write_planes(const Mesh& mesh, const std::vector<ST::Principal_symmetry<K>>& symmetries, const std::string& prefix,
                  const NamedParameters& np)
{
  const examples::Extent<K::Point_3> extent = examples::extent_of(mesh);
  std::cout << "Centre of mass c = (" << extent.center << "), radius R = " << extent.radius << "\n"
            << "Planes n.x + d = 0 with |n| = 1, strongest first; r = -(n.c + d): n.(x - c) = r;\n"
            << "support: the fraction of the area that the reflection maps onto the surface.\n"
            << "   #   normal n (x y z)             d      r/R  symmetry  support\n" << std::fixed;
  Mesh supported = mesh; // the mesh with the support map, which the files leave out
  auto support = supported.add_property_map<Mesh::Face_index, double>("f:support", 0.).first;
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const K::Plane_3& plane = symmetries[i].plane;
    const double fraction = ST::symmetry_support(supported, plane, support, np);
    const K::Vector_3 n = plane.orthogonal_vector();
    std::cout << std::setw(4) << i + 1 << "   (" << std::setprecision(3) << std::setw(6) << n.x() << ' '
              << std::setw(6) << n.y() << ' ' << std::setw(6) << n.z() << ") " << std::setw(8) << plane.d()
              << std::setw(9) << -(n * (extent.center - CGAL::ORIGIN) + plane.d()) / extent.radius << std::setw(10)
              << symmetries[i].symmetry << std::setw(9) << fraction << "\n";
    Mesh out = examples::with_face_colours(mesh, [&](Mesh::Face_index f) { return examples::dark_to_bright(support[f]); });
    examples::add_plane_square(out, plane, extent.center, 2.2 * extent.radius, examples::plane_colour());
    std::ostringstream comment;
    comment << std::setprecision(4) << "plane " << i + 1 << ": " << plane << "; symmetry " << symmetries[i].symmetry
            << "; support " << fraction << "; face colour: support (dark 0, bright 1); last 2 faces: the plane";
    examples::write_PLY(prefix + "_" + std::to_string(i + 1) + ".ply", out, comment.str());
  }
  if(symmetries.empty()) { std::cout << "No plane found: nothing written.\n"; return; }
  std::cout << "\nWrote " << prefix << "_1.ply" << (symmetries.size() > 1 ? " ... " + prefix + "_" +
                                                   std::to_string(symmetries.size()) + ".ply" : std::string())
            << ": per plane, the mesh with faces coloured by support,\n  from dark (none) to bright (full), "
            << "and the plane as a blue square\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64), planes = options.integer("--planes", 6),
                    samples = options.integer("--samples", 500000), seed = options.integer("--seed", 0, 0);
  const std::string prefix = examples::without_ply_extension(options.text("--output", "principal_symmetries"));
  options.reject_unknown();
  const Mesh mesh = examples::read_triangle_mesh<Mesh>(filename);

  const auto np = CGAL::parameters::grid_resolution(int(resolution)). // GEDT samples and PRST bins per axis
                                    max_number_of_planes(planes).     // at most this many, strongest first
                                    number_of_samples(samples).       // Monte Carlo samples of the PRST
                                    random_seed(unsigned(seed));      // the same seed, the same planes
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<ST::Principal_symmetry<K>> symmetries = ST::detect_principal_symmetries(mesh, np);
  std::cout << std::setprecision(3) << symmetries.size() << " principal symmetries (grid " << resolution << "^3, "
            << samples << " Monte Carlo samples) in " << timer.time() << " s\n";
  write_planes(mesh, symmetries, prefix, np);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
