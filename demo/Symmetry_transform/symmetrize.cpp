// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetrization.h>
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
#include <string>
#include <vector>

const char* const usage = R"(usage: symmetrize [MESH] [--resolution N] [--planes K] [--whole] [--output FILE]

Makes a mesh symmetric: detects its K strongest planes of mirror symmetry and moves its vertices,
each as little as possible, so that the surface becomes symmetric under them (every vertex and
the mirror images of its counterparts meet at their mean) where they hold, or everywhere with
--whole. Prints the planes used, the displacement and the symmetry distance error before and
after. Writes the mesh with the input's vertices in the same order and the same faces.

  MESH              an OFF, PLY, OBJ or STL triangle mesh (a file that is no valid mesh is read as
                    a polygon soup and repaired, its vertices then renumbered); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    grid resolution of the plane detection, at least 8 (default 64)
  --planes K        how many detected planes to make exact (default 1)
  --whole           moves every vertex, also where the planes do not hold (a part with no
                    counterpart is then moved onto the mirror image of what lies there)
  --output FILE     the symmetrized mesh: a .ply file has its vertices coloured by their
                    displacement (dark blue 0 to yellow 1% of the radius or more), and the input,
                    coloured alike, goes to FILE_before.ply; any other extension that CGAL
                    writes (.off, .obj, .stl) is written plain (default symmetrized.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

// The vertex colours range from dark blue (no displacement) to yellow (this fraction of the
// radius or more).
constexpr double displacement_scale = 0.01;

// The file as it is when it is a triangle mesh (its vertices and faces kept in order), else repaired.
Mesh read_mesh(const std::string& filename)
{
  examples::check_exists(filename);
  Mesh mesh;
  if(CGAL::IO::read_polygon_mesh(filename, mesh) && CGAL::is_triangle_mesh(mesh) && !is_empty(mesh)) return mesh;
  std::cout << filename << " is no valid triangle mesh: read as a soup and repaired\n";
  return examples::read_triangle_mesh<Mesh>(filename);
}

void print_errors(const char* when, const Mesh& mesh, const std::vector<K::Plane_3>& planes)
{
  std::cout << "symmetry distance error " << when << ":";
  for(const K::Plane_3& p : planes) std::cout << " " << ST::symmetry_distance_error(mesh, p);
  std::cout << "\n";
}

// `mesh` with its vertices coloured by the displacement `moves` (indexed as its vertices).
void write_coloured(const std::string& file, Mesh mesh, const std::vector<K::Vector_3>& moves, double radius)
{
  auto colour = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(auto v : vertices(mesh))
    colour[v] = examples::blue_to_yellow(std::sqrt(moves[v].squared_length()) / (displacement_scale * radius));
  examples::write_PLY(file, mesh, "vertex colour: displacement, dark blue 0 to yellow >= 1% of the radius");
  std::cout << "Wrote " << file << "\n";
}

void write_meshes(const std::string& file, const Mesh& input, const Mesh& mesh, const std::vector<K::Vector_3>& moves,
                  double radius)
{
  if(examples::without_ply_extension(file) != file) {
    write_coloured(file, mesh, moves, radius);
    write_coloured(examples::without_ply_extension(file) + "_before.ply", input, moves, radius);
  } else if(CGAL::IO::write_polygon_mesh(file, mesh, CGAL::parameters::stream_precision(17))) {
    std::cout << "Wrote " << file << "\n";
  } else {
    throw std::runtime_error("cannot write " + file);
  }
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64, 8), count = options.integer("--planes", 1);
  const std::string output = options.text("--output", "symmetrized.ply");
  const bool whole = options.flag("--whole");
  options.validate();
  Mesh mesh = read_mesh(filename);
  const double radius = examples::extent_of(mesh).radius;

  std::vector<K::Plane_3> detected;
  for(const auto& s : ST::detect_principal_symmetries(mesh, CGAL::parameters::grid_resolution(int(resolution))
                                                              .max_number_of_planes(count)))
    detected.push_back(s.plane);
  if(detected.empty()) throw std::runtime_error("no plane of symmetry found");
  print_errors("before", mesh, detected);

  const Mesh input = mesh;
  std::vector<K::Vector_3> moves(num_vertices(mesh)); // by vertex index
  CGAL::Real_timer timer;
  timer.start();
  const ST::Symmetrization<K> result = ST::symmetrize(mesh, detected,
    CGAL::parameters::whole_mesh(whole).                            // or only where the planes hold
                      vertex_displacement_map(CGAL::make_property_map(moves)). // how far each vertex moved
                      callback(examples::progress_bar("Symmetrizing"))); // a progress bar on a terminal
  std::cout << "symmetrized in " << std::setprecision(3) << timer.time() << " s: group of " << result.group_size
            << " motions, " << result.paired_vertices << " of " << num_vertices(mesh) << " vertices paired\n";
  for(const K::Plane_3& p : result.planes) std::cout << "  plane " << std::setprecision(6) << p << "\n";
  std::cout << "displacement over the radius: mean " << result.mean_displacement / radius << ", max "
            << result.max_displacement / radius << "\n";
  print_errors("after", mesh, result.planes);
  write_meshes(output, input, mesh, moves, radius);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
