// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/point_group.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>

#include "bop_symmetries.h"
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

const char* const usage = R"(usage: rotational_symmetries [MESH] [--resolution N] [--max-order K] [--seed S] [--output FILE]

Finds the rotational symmetries of a mesh (axes and orders) and its mirror planes, prints the
axes and the point group (Schoenflies symbol: D6h for a hexagonal prism), and writes
- a PLY file: the mesh in grey with each axis drawn as a thin coloured cylinder;
- a JSON file with the fields of the BOP benchmark's models_info.json for this object, to
  paste into its entry: "symmetries_discrete" (the rotations by 2 pi j / k about each axis of
  order k, j = 1 ... k - 1, as row-major 4x4 matrices, translation in the mesh's units) and
  "symmetries_continuous" (the axis and a point on it, "offset", of each continuous symmetry),
  and "point_group", the Schoenflies symbol.

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/pinion.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    GEDT samples per axis (default 64)
  --max-order K     orders 2 ... K are tested, K >= 2 (default 12)
  --seed S          random seed: the same seed, the same axes (default 0)
  --output FILE     writes FILE.ply and FILE.json; a trailing .ply of FILE is dropped
                    (default rotational_symmetries)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

// A point or vector as "(x y z)", in fixed columns.
template <typename Triple>
std::string columns(const Triple& t)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "(" << std::setw(8) << t.x() << std::setw(8) << t.y() << std::setw(8)
      << t.z() << ")";
  return out.str();
}

void print_symmetries(const std::vector<ST::Rotational_symmetry<K>>& symmetries)
{
  std::cout << "order 0: continuous; support: the fraction of the area the rotation maps onto the surface\n"
            << "   #  order  point on the axis (nearest to the    direction                 symmetry  support\n"
            << "             centre of mass)\n" << std::fixed;
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const ST::Rotational_symmetry<K>& s = symmetries[i];
    std::cout << std::setw(4) << i + 1 << std::setw(7) << s.order << "  " << columns(s.axis.point()) << "  "
              << columns(s.axis.to_vector()) << std::setw(10) << s.symmetry << std::setw(9) << s.support << "\n";
  }
}

// The mesh in grey and each axis a cylinder of the segment palette, 1.2 radii on each side of
// its point; the PLY comment lists the axes with their colours.
void write_axes(const Mesh& mesh, const std::vector<ST::Rotational_symmetry<K>>& symmetries, const std::string& file)
{
  const examples::Extent<K::Point_3> extent = examples::extent_of(mesh);
  Mesh out = examples::with_face_colours(mesh, [](Mesh::Face_index) { return CGAL::IO::Color(200, 200, 200); });
  std::ostringstream comment;
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const CGAL::IO::Color c = examples::segment_colour(i);
    examples::add_axis_cylinder(out, symmetries[i].axis, 1.2 * extent.radius, 0.01 * extent.radius, c);
    comment << (i ? "\n" : "") << "axis " << i + 1 << ": order " << symmetries[i].order << "; symmetry "
            << symmetries[i].symmetry << "; support " << symmetries[i].support << "; colour " << int(c.r()) << " "
            << int(c.g()) << " " << int(c.b());
  }
  examples::write_PLY(file, out, comment.str());
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/pinion.off");
  const std::size_t resolution = options.integer("--resolution", 64), max_order = options.integer("--max-order", 12, 2),
                    seed = options.integer("--seed", 0, 0);
  const std::string base = examples::without_ply_extension(options.text("--output", "rotational_symmetries"));
  options.validate();
  const Mesh mesh = examples::read_triangle_mesh<Mesh>(filename);

  const auto np = CGAL::parameters::grid_resolution(int(resolution)). // GEDT samples per axis
                                    max_order(int(max_order)).        // orders 2 ... max_order tested
                                    random_seed(unsigned(seed));      // the same seed, the same axes
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<ST::Rotational_symmetry<K>> symmetries = ST::detect_rotational_symmetries(mesh, np);
  std::cout << std::setprecision(3) << symmetries.size() << " rotational symmetries (grid " << resolution << "^3) in "
            << timer.time() << " s\n";
  print_symmetries(symmetries);
  const ST::Point_group group = ST::point_group(ST::detect_principal_symmetries(mesh, np), symmetries);
  std::cout << "point group " << group.name << " (" << (group.order ? std::to_string(group.order) : "infinitely many")
            << " elements, from the exact axes and mirror planes)\n";
  write_axes(mesh, symmetries, base + ".ply");
  examples::write_bop_json(base + ".json", symmetries, group.name);
  std::cout << "\nWrote " << base << ".ply (the mesh, each axis a coloured cylinder) and " << base
            << ".json (BOP's symmetries_discrete and symmetries_continuous)\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
