// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Aligns a mesh to its symmetry frame (thesis, section 4.1): computes the centre of symmetry
// and the principal symmetry axes, prints them next to the classical frame (centre of mass and
// principal axes, PCA), and writes the mesh moved so that its symmetry frame is the canonical
// one: centre at the origin, first axis (normal of the strongest plane of symmetry) along x,
// second along y, third along z.
//
// usage: align_to_symmetry_frame [mesh.off|.ply|.obj|.stl] [--resolution N] [--samples N]
//          [--seed S] [--output FILE.ply|.off]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <stdexcept>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

std::size_t integer(const std::string& option, const std::string& text, std::size_t minimum = 1)
{
  if(text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos ||
     std::stoull(text) < minimum)
    throw std::invalid_argument(option + " expects an integer >= " + std::to_string(minimum) + ", not '" + text + "'");
  return std::size_t(std::stoull(text));
}

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

int main(int argc, char** argv)
try {
  std::string filename, output = "align_to_symmetry_frame.ply";
  std::size_t resolution = 64, samples = 500000, seed = 0; // samples: detection's default
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg.rfind("--", 0) != 0) { filename = arg; continue; }
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--resolution") resolution = integer(arg, value);
    else if(arg == "--samples") samples = integer(arg, value);
    else if(arg == "--seed") seed = integer(arg, value, 0);
    else if(arg == "--output") output = value;
    else throw std::invalid_argument("unknown option: " + arg);
  }
  if(filename.empty()) filename = CGAL::data_file_path("meshes/bull.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh)) {
    std::cerr << "Cannot read a polygon mesh from '" << filename << "' (OFF, PLY, OBJ or STL; with no "
              << "argument, set CGAL_DATA_DIR to the directory holding meshes/bull.off)." << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  if(!CGAL::is_triangle_mesh(mesh)) {
    if(!PMP::triangulate_faces(mesh)) throw std::runtime_error("some faces could not be triangulated");
    std::cout << "Triangulated the polygons: " << num_faces(mesh) << " triangles\n";
  }

  // Principal symmetries on resolution^3 grids, then the frame they define.
  const auto np = CGAL::parameters::grid_resolution(int(resolution)).number_of_samples(samples).random_seed(unsigned(seed));
  const auto start = std::chrono::steady_clock::now();
  const ST::Symmetry_frame<K> frame = ST::symmetry_frame(mesh, np);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ST::Symmetry_frame<K> pca = ST::pca_frame(mesh);

  std::cout << std::setprecision(4) << "Symmetry frame in " << seconds << " s (grid " << resolution << "^3, "
            << samples << " Monte Carlo samples)\n";
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

  // The mesh in its canonical frame.
  PMP::transform(ST::to_canonical(frame), mesh);
  if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("cannot write " + output);
  std::cout << "Wrote " << output << ": the mesh moved to its symmetry frame (centre at the origin, axes x, y, z)\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
