// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/point_symmetry_transform.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <vector>

const char* const usage = R"(usage: point_symmetry_transform [MESH] [--resolution N] [--output FILE]

Computes the Point Symmetry Transform (PST) of a mesh, prints its centre of symmetry and writes
three slices of the transform through that centre, coloured by symmetry.

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    GEDT and PST samples per axis (default 64)
  --output FILE     the three slices, .ply (default point_symmetry_transform.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;

// The PST is a function of space: three orthogonal slices of its grid through the sample
// `through`, as triangles between samples, coloured by value from dark (0) to bright (the
// maximum), where it exceeds `maximum / 20` (the rest would hide the mesh). Opened together with
// the input mesh, they show where the shape is point-symmetric and how fast that fades. (The
// PST at the vertices of the mesh would mostly show their distance to the centre of symmetry.)
Mesh slices(const ST::Voxel_grid<K>& pst, const std::array<std::size_t, 3>& through, double maximum)
{
  Mesh result;
  auto colour = result.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  auto symmetry = result.add_property_map<Mesh::Vertex_index, float>("v:symmetry", 0.f).first;
  const std::size_t n = pst.resolution();
  for(int axis = 0; axis < 3; ++axis) { // the slice orthogonal to `axis`
    std::vector<Mesh::Vertex_index> v;
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = 0; b < n; ++b) {
        std::array<std::size_t, 3> ijk = through;
        ijk[(axis + 1) % 3] = a;
        ijk[(axis + 2) % 3] = b;
        v.push_back(result.add_vertex(pst.point(ijk[0], ijk[1], ijk[2])));
        symmetry[v.back()] = float(pst(ijk[0], ijk[1], ijk[2]));
        colour[v.back()] = examples::dark_to_bright(symmetry[v.back()] / maximum);
      }
    for(std::size_t a = 0; a + 1 < n; ++a)
      for(std::size_t b = 0; b + 1 < n; ++b) {
        const Mesh::Vertex_index q[4] = {v[a * n + b], v[(a + 1) * n + b], v[(a + 1) * n + b + 1],
                                         v[a * n + b + 1]};
        if(std::all_of(q, q + 4, [&](Mesh::Vertex_index x) { return symmetry[x] > maximum / 20.; })) {
          result.add_face(q[0], q[1], q[2]);
          result.add_face(q[0], q[2], q[3]);
        }
      }
  }
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(result);
  result.collect_garbage();
  return result;
}

// A perfect point symmetry can only be about the centre of mass; the distance from it to the
// centre of symmetry, and their symmetries, tell how far the shape is from one.
void print_centres(const ST::Point_symmetry_transform<K>& pst)
{
  const K::Point_3 center = pst.grid().center(), symmetry_center = pst.center_of_symmetry();
  std::cout << "\nCentre of mass      (" << center << "), symmetry " << pst.value(center) << "\n"
            << "Centre of symmetry  (" << symmetry_center << "), symmetry " << pst.value(symmetry_center) << "\n"
            << "Distance between them: " << std::sqrt(CGAL::squared_distance(center, symmetry_center)) / pst.grid().radius()
            << " R, with R = " << pst.grid().radius() << " the radius of the shape\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64);
  const std::string output = options.text("--output", "point_symmetry_transform.ply");
  options.validate();
  const examples::Triangle_soup<K::Point_3> soup = examples::read_triangle_soup<K::Point_3>(filename); // repaired

  CGAL::Real_timer timer;
  timer.start();
  const ST::Point_symmetry_transform<K> pst = ST::point_symmetry_transform_of_triangle_soup(soup.points, soup.triangles,
    CGAL::parameters::grid_resolution(int(resolution))); // the GEDT on resolution^3 samples, then its PST by FFT
  std::cout << std::setprecision(3) << "PST of " << resolution << "^3 samples in " << timer.time()
            << " s, distance transform included\n";
  print_centres(pst);

  // Slice through the strongest sample, which center_of_symmetry() refines below the voxel size.
  const std::vector<double>& values = pst.grid().values();
  const std::size_t best = std::size_t(std::max_element(values.begin(), values.end()) - values.begin());
  const std::size_t n = pst.grid().resolution(); // in values(), i varies fastest
  examples::write_PLY(output, slices(pst.grid(), {best % n, best / n % n, best / (n * n)}, values[best]),
                      "three slices of the point symmetry transform; colour: dark = weak");
  std::cout << "\nWrote " << output << ": three slices of the PST through the centre of symmetry, coloured from\n"
            << "  dark (symmetry 0) to bright (" << values[best] << "); open it together with the mesh\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
