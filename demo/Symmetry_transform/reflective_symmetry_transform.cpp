// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// What the program does, its arguments and options: `usage` below, which --help prints.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

const char* const usage = R"(usage: reflective_symmetry_transform [MESH] [--resolution N] [--planes K]
         [--method monte-carlo|exact] [--samples N] [--seed S] [--output FILE]

Computes the Planar Reflective Symmetry Transform (PRST) of a mesh, prints its strongest planes
and writes the mesh coloured by the strongest symmetry of any plane through each vertex.

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    GEDT samples and PRST bins (theta, phi, r) per axis (default 64)
  --planes K        how many of the strongest planes to print (default 5)
  --method M        monte-carlo, or exact: the exact convolution, a slow reference
                    (default monte-carlo)
  --samples N       Monte Carlo samples: the noise falls as 1/sqrt(N) (default 2000000)
  --seed S          random seed: the same seed, the same transform (default 0)
  --output FILE     the coloured mesh, .ply (default reflective_symmetry_transform.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Reflective_symmetry_transform<K> PRST;

ST::Reflective_symmetry_method method_of(const std::string& name)
{
  if(name != "monte-carlo" && name != "exact")
    throw std::invalid_argument("--method expects monte-carlo or exact, not '" + name + "'");
  return name == "exact" ? ST::Reflective_symmetry_method::EXACT : ST::Reflective_symmetry_method::MONTE_CARLO;
}

// The strongest local maxima of the PRST, at most `count`. Monte Carlo noise splits one peak
// into neighbouring maxima, and round-off makes maxima of value ~0 far from the shape: keep a
// bin only if no stronger kept one lies within 10 degrees and R/10, and if it exceeds a tenth
// of the strongest (the threshold of the thesis).
std::vector<PRST::Bin> strongest_planes(const PRST& prst, std::size_t count)
{
  std::vector<PRST::Bin> maxima, kept;
  prst.local_maxima(std::back_inserter(maxima));
  for(const PRST::Bin& b : maxima) {
    auto near = [&](const PRST::Bin& q) {
      const double c = prst.plane(b).orthogonal_vector() * prst.plane(q).orthogonal_vector(); // cosine
      return std::abs(c) > std::cos(CGAL_PI / 18.) &&
             std::abs(prst.offset(b[2]) - std::copysign(prst.offset(q[2]), c)) < prst.radius() / 10.;
    };
    if(kept.size() < count && prst.value(b) > prst.value(maxima[0]) / 10. &&
       std::none_of(kept.begin(), kept.end(), near))
      kept.push_back(b);
  }
  return kept;
}

void print_strongest_planes(const PRST& prst, std::size_t count)
{
  const std::vector<PRST::Bin> best = strongest_planes(prst, count);
  const double R = prst.radius(), degrees = 180. / CGAL_PI;
  std::cout << "\nCentre of mass c = (" << prst.center() << "), radius R = " << R << "\n"
            << "Strongest planes n.(x - c) = r, raw bins before refinement:\n"
            << "   #  symmetry   normal n (x y z)             r      r/R   theta    phi\n" << std::fixed;
  for(std::size_t m = 0; m < best.size(); ++m) {
    const PRST::Bin& b = best[m];
    const K::Vector_3 n = prst.plane(b).orthogonal_vector();
    std::cout << std::setw(4) << m + 1 << std::setprecision(3) << std::setw(10) << prst.value(b) << "   ("
              << std::setw(6) << n.x() << ' ' << std::setw(6) << n.y() << ' ' << std::setw(6) << n.z() << ") "
              << std::setw(8) << prst.offset(b[2]) << std::setprecision(2) << std::setw(8) << prst.offset(b[2]) / R
              << std::setprecision(1) << std::setw(7) << prst.theta(b[0]) * degrees << std::setw(7)
              << prst.phi(b[1]) * degrees << "\n";
  }
}

// For each vertex p, the strongest symmetry of any plane through p (the thesis's Figure 3.5):
// for every bin direction n, the plane through p has offset r = n.(p - c); interpolate between
// the two bins around r. Reading the bins directly costs a few operations per direction, where
// prst.value(plane) would also search for the direction of the plane.
Mesh::Property_map<Mesh::Vertex_index, float> strongest_symmetry_through_vertices(const PRST& prst, Mesh& mesh)
{
  const std::size_t n = prst.resolution();
  std::vector<K::Vector_3> normals; // direction ij = i n + j; its bins are values()[ij n + k]
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j) normals.push_back(prst.plane(i, j, 0).orthogonal_vector());
  const std::vector<double>& values = prst.values();
  auto symmetry = mesh.add_property_map<Mesh::Vertex_index, float>("v:symmetry", 0.f).first;
  for(Mesh::Vertex_index v : vertices(mesh)) {
    const K::Vector_3 d = mesh.point(v) - prst.center();
    double best = 0.;
    for(std::size_t ij = 0; ij < n * n; ++ij) {
      // continuous bin index of r (bin k is centred on r = -R + (k + 1/2) 2R/n)
      const double r = normals[ij] * d;
      const double t = std::clamp((r / prst.radius() + 1.) * double(n) / 2. - 0.5, 0., double(n - 1));
      const std::size_t k = std::min(std::size_t(t), n - 2);
      const double* bins = &values[ij * n + k];
      best = std::max(best, bins[0] + (t - double(k)) * (bins[1] - bins[0]));
    }
    symmetry[v] = float(best);
  }
  return symmetry;
}

// The mesh with the map "v:symmetry" (a scalar property `symmetry` in the PLY file) and a vertex
// colour stretched over the range found on this mesh, so that its contrasts show.
void write_symmetry_through_vertices(const PRST& prst, Mesh mesh, const std::string& output)
{
  auto symmetry = strongest_symmetry_through_vertices(prst, mesh);
  const auto range = std::minmax_element(symmetry.begin(), symmetry.end());
  const float low = *range.first, high = std::max(*range.second, low + 1e-6f);
  auto colour = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(Mesh::Vertex_index v : vertices(mesh)) colour[v] = examples::dark_to_bright((symmetry[v] - low) / (high - low));
  examples::write_PLY(output, mesh, "vertex colour: strongest symmetry of a plane through the vertex");
  std::cout << std::setprecision(3) << "\nWrote " << output << ": the mesh coloured by the strongest symmetry of "
            << "a plane through each vertex,\n  from dark (" << low << ") to bright (" << high << ")\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64), samples = options.integer("--samples", 2000000),
                    seed = options.integer("--seed", 0, 0), planes = options.integer("--planes", 5);
  const ST::Reflective_symmetry_method method = method_of(options.text("--method", "monte-carlo"));
  const std::string output = options.text("--output", "reflective_symmetry_transform.ply");
  options.validate();
  const examples::Triangle_soup<K::Point_3> soup = examples::read_triangle_soup<K::Point_3>(filename); // repaired

  CGAL::Real_timer timer;
  timer.start();
  const PRST prst = ST::reflective_symmetry_transform_of_triangle_soup(soup.points, soup.triangles,
    CGAL::parameters::grid_resolution(int(resolution)). // GEDT samples and PRST bins (theta, phi, r) per axis
                      prst_method(method).              // Monte Carlo, or the exact convolution (reference)
                      number_of_samples(samples).       // Monte Carlo samples: noise falls as 1/sqrt(samples)
                      random_seed(unsigned(seed)));     // the same seed, the same transform
  std::cout << std::setprecision(3) << "PRST of " << resolution << "^3 bins ("
            << (method == ST::Reflective_symmetry_method::EXACT ? std::string("exact")
                                                                : std::to_string(samples) + " Monte Carlo samples")
            << ") in " << timer.time() << " s, distance transform included\n";

  print_strongest_planes(prst, planes);
  write_symmetry_through_vertices(prst, examples::mesh_of_soup<Mesh>(soup, true), output); // a mesh for the file
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
