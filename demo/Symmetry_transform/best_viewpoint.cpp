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
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include "colour_ramps.h"
#include "coloured_ply.h"
#include "command_line_options.h"
#include "input_files.h"
#include "shape_extent.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

const char* const usage = R"(usage: best_viewpoint [MESH] [--resolution N] [--samples N] [--seed S] [--views K] [--output FILE]

Chooses the best views of a mesh from its symmetries (thesis, section 4.3): finds its principal
planes of symmetry, scores each view direction v by S(v) = sum |v.u| M(u) over the planes (unit
normals u, symmetry M(u)), prints the best views (local maxima of S: the views wasting the least
of the image on mirror-redundant content) and the worst one, and writes the score as a sphere
coloured from dark (worst) to bright (best), centred on the mesh and of its radius, to be viewed
with the mesh.

  MESH              an OFF, PLY, OBJ or STL file, read as a polygon soup and repaired (duplicate
                    points merged, degenerate faces removed, polygons triangulated); default:
                    meshes/bull.off of CGAL's sample data, in the folder $CGAL_DATA_DIR
  --resolution N    GEDT samples and PRST bins per axis of the plane detection (default 64)
  --samples N       Monte Carlo samples of the PRST (default 500000)
  --seed S          random seed: the same seed, the same planes (default 0)
  --views K         how many best views to print (default 5)
  --output FILE     the score sphere, .ply (default best_viewpoint.ply)
)";

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef examples::Triangle_soup<K::Point_3> Soup;
namespace ST = CGAL::Symmetry_transform;

std::string direction(const K::Vector_3& v)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(3) << "(" << std::setw(6) << v.x() << ' ' << std::setw(6) << v.y() << ' '
    << std::setw(6) << v.z() << ")";
  return s.str();
}

// Each plane with its symmetry M(u) and its symmetry distance error.
void print_planes(const std::vector<ST::Principal_symmetry<K>>& symmetries, const Soup& soup)
{
  std::cout << "   #   normal u                   M(u)       SDE\n";
  for(std::size_t i = 0; i < symmetries.size(); ++i) {
    const K::Vector_3 n = symmetries[i].plane.orthogonal_vector();
    std::cout << std::setw(4) << i + 1 << "   " << direction(n / std::sqrt(n.squared_length())) << std::fixed
              << std::setw(10) << symmetries[i].symmetry << std::setprecision(5) << std::setw(10)
              << ST::symmetry_distance_error_of_triangle_soup(soup.points, soup.triangles, symmetries[i].plane)
              << std::defaultfloat << "\n";
  }
}

// The best views, each with its angle to the nearest plane normal, and the worst one.
void print_views(const std::vector<ST::Principal_symmetry<K>>& symmetries, const std::vector<ST::Viewpoint<K>>& best,
                 const ST::Viewpoint<K>& worst, std::size_t views)
{
  double total = 0.;
  for(const auto& s : symmetries) total += s.symmetry;
  if(best.empty()) {
    std::cout << "No plane of symmetry: every view scores S = 0, none is better than another.\n";
  } else {
    std::cout << "\nS(v) = sum |v.u| M(u), in [0, " << total << "]; v and -v are the same view (shown with z > 0).\n"
              << "Best views (local maxima of S), best first:\n" << std::fixed;
    for(std::size_t i = 0; i < std::min(best.size(), views); ++i) {
      double off = 90.; // angle to the nearest plane normal
      for(const auto& s : symmetries) {
        const K::Vector_3 n = s.plane.orthogonal_vector();
        const double c = std::abs(best[i].direction * n) / std::sqrt(n.squared_length());
        off = std::min(off, std::acos(std::min(1., c)) * 180. / CGAL_PI);
      }
      std::cout << std::setw(4) << i + 1 << "   v = " << direction(best[i].direction) << "   S = "
                << std::setprecision(3) << best[i].score << "   " << std::setprecision(1) << off
                << " deg from the nearest plane normal\n";
    }
    if(best.size() > views) std::cout << "     (" << best.size() - views << " more)\n";
  }
  std::cout << std::fixed << std::setprecision(3) << "Worst view (global minimum of S):   v = "
            << direction(worst.direction) << "   S = " << worst.score << "\n";
}

// The score sphere, placed on the mesh (centred on its centre of mass, of its radius) and
// coloured from dark (the worst score) to bright (the best).
void write_score_sphere(const std::vector<ST::Principal_symmetry<K>>& symmetries, const Soup& soup, double low,
                        double high, const std::string& filename, const std::string& output)
{
  Mesh sphere = ST::viewpoint_score_sphere(symmetries, 5);
  const examples::Extent<K::Point_3> extent = examples::extent_of_soup(soup.points, soup.triangles);
  const auto score = sphere.add_property_map<Mesh::Vertex_index, double>("v:score").first;
  auto colour = sphere.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(Mesh::Vertex_index v : vertices(sphere)) {
    colour[v] = examples::dark_to_bright(high > low ? (score[v] - low) / (high - low) : 0.);
    sphere.point(v) = extent.center + extent.radius * (sphere.point(v) - CGAL::ORIGIN);
  }
  std::ostringstream comment;
  comment << std::setprecision(4) << "viewpoint score S(v) of " << filename << " on a sphere of radius "
          << extent.radius << " centred at " << extent.center << "; vertex colour: S from dark " << low
          << " (worst) to bright " << high << " (best)";
  examples::write_PLY(output, sphere, comment.str());
  std::cout << "\nWrote " << output << ": " << num_vertices(sphere) << " vertices, the score sphere centred on the "
            << "mesh,\n  coloured from dark (worst view) to bright (best view)\n";
}

int main(int argc, char** argv)
try {
  const examples::Command_line_options options(argc, argv, usage);
  const std::string filename = options.input_file("meshes/bull.off");
  const std::size_t resolution = options.integer("--resolution", 64), samples = options.integer("--samples", 500000),
                    seed = options.integer("--seed", 0, 0), views = options.integer("--views", 5);
  const std::string output = options.text("--output", "best_viewpoint.ply");
  options.validate();
  const Soup soup = examples::read_triangle_soup<K::Point_3>(filename); // any mesh file, repaired as a soup

  // The views are scored by the principal planes: detect them first.
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<ST::Principal_symmetry<K>> symmetries = ST::detect_principal_symmetries_of_triangle_soup(soup.points, soup.triangles,
    CGAL::parameters::grid_resolution(int(resolution)). // GEDT samples and PRST bins per axis
                      number_of_samples(samples).       // Monte Carlo samples of the PRST
                      random_seed(unsigned(seed)));     // the same seed, the same planes
  std::cout << std::setprecision(3) << symmetries.size() << " principal symmetries (grid " << resolution
            << "^3) in " << timer.time() << " s:\n";
  print_planes(symmetries, soup);

  std::vector<ST::Viewpoint<K>> best; // local maxima of S, best first
  ST::best_viewpoints(symmetries, std::back_inserter(best));
  const ST::Viewpoint<K> worst = ST::worst_viewpoint(symmetries);
  print_views(symmetries, best, worst, views);
  write_score_sphere(symmetries, soup, worst.score, best.empty() ? worst.score : best.front().score, filename, output);
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
