// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Symmetric remeshing against CGAL's Variational Shape Approximation on CGAL's sample meshes
// (thesis, Section 5.1.3): per mesh, its strongest principal plane(s) are detected (timed apart),
// then, for K proxies, the symmetric VSA with K proxies is run side by side with CGAL's
// approximate_triangle_mesh with K and with 2K proxies (a symmetric proxy has up to two
// patches), all with CGAL's default settings otherwise (hierarchical seeding, 5 relaxations,
// 20 iterations, mesh extraction with subdivision ratio 5). Runs alternate (ours, CGAL K,
// CGAL 2K, ours, ...) and each time is the median of --repeats runs, so that the ratio is fair
// on a shared machine. Measured on each output:
// - geometric error: RMS of the two-sided sampled distances to the input (approximation_error),
// - symmetry error: RMS distance from the mirror images of output samples to the output, over
//   the region where the input is symmetric (the mirror images within 2% of the diagonal of
//   the input; symmetry_error with a reference mesh); the whole-surface value is printed too,
// both in units of 1e-3 of the bounding-box diagonal;
// - validity: border edges (an edge of one triangle only) and non-manifold vertices (whose
//   triangles are not one fan), per case on stderr and in all at the end.
// The input's own symmetry error is printed first. With --symmetrization-cost 1, the program
// only charts, per mesh, what making the input itself more symmetric costs in geometric error
// (the input moved a quarter, half, ... of the way to its symmetrized shape, see
// partly_symmetrized()): an estimate of the symmetry that an output close to the input can gain.
//
// usage: remeshing_comparison [--meshes a.off,b.off,...] [--proxies 50,100,200] [--planes P]
//          [--resolution N] [--alpha A] [--repeats R] [--symmetrization-cost 0|1]
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Symmetry_transform/internal/common/cgal_aabb.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/remeshing_metrics.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmark_utilities.h"
// Shared with test_symmetric_remeshing: the manifold defects of a triangle soup.
#include "Symmetry_transform_soup_defects.h" // test/Symmetry_transform/include

namespace {

using benchmark_utilities::split;
using benchmark_utilities::median;
using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace VSA = CGAL::Surface_mesh_approximation;

const char* default_meshes = "bull.off,cow.off,elephant.off,triceratops.off,homer.off,mannequin-devil.off";

struct Soup
{
  std::vector<K::Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

Mesh mesh_of(Soup s)
{
  Mesh out;
  if(!PMP::is_polygon_soup_a_polygon_mesh(s.triangles)) PMP::orient_polygon_soup(s.points, s.triangles);
  PMP::polygon_soup_to_polygon_mesh(s.points, s.triangles, out);
  return out;
}

// The symmetrized position s(x) = (x + R(q)) / 2 of each vertex x, q the point of the input
// nearest to the mirror image R(x): halfway to its mirror partner is the smallest move that makes
// a pair symmetric.
std::vector<K::Point_3> symmetrized_positions(const Mesh& mesh, const K::Plane_3& plane)
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  CGAL::AABB_tree<CGAL::Symmetry_transform::internal::AABB_traits_3<K, Primitive>> tree(faces(mesh).first, faces(mesh).second, mesh);
  const K::Vector_3 n = plane.orthogonal_vector();
  const auto reflect = [&](const K::Point_3& p) {
    return p - 2. * (n * (p - CGAL::ORIGIN) + plane.d()) / n.squared_length() * n;
  };
  std::vector<K::Point_3> out;
  for(auto v : vertices(mesh)) {
    const K::Point_3& x = mesh.point(v);
    out.push_back(CGAL::midpoint(x, reflect(tree.closest_point(reflect(x)))));
  }
  return out;
}

// The input with each vertex moved the fraction t of the way to its symmetrized position: these
// shapes chart the geometric error that a given gain in symmetry costs an output that has no
// error of its own.
Mesh partly_symmetrized(const Mesh& mesh, const std::vector<K::Point_3>& symmetrized, double t)
{
  Mesh out = mesh;
  for(auto v : vertices(mesh)) out.point(v) = mesh.point(v) + t * (symmetrized[std::size_t(v)] - mesh.point(v));
  return out;
}

struct Run
{
  std::vector<double> seconds;
  Soup soup;
};

} // namespace

int main(int argc, char** argv)
try {
  std::vector<std::string> meshes = split(default_meshes);
  std::vector<std::size_t> proxies = {50, 100, 200};
  std::size_t planes_kept = 1, resolution = 64, repeats = 3;
  double alpha = 0.002; // the default of position_weight
  bool symmetrization_cost = false;
  for(int a = 1; a + 1 < argc; a += 2) {
    const std::string arg = argv[a], value = argv[a + 1];
    if(arg == "--meshes") meshes = split(value);
    else if(arg == "--proxies") {
      proxies.clear();
      for(const std::string& p : split(value)) proxies.push_back(std::stoul(p));
    } else if(arg == "--planes") planes_kept = std::stoul(value);
    else if(arg == "--resolution") resolution = std::stoul(value);
    else if(arg == "--alpha") alpha = std::stod(value);
    else if(arg == "--repeats") repeats = std::max<std::size_t>(1, std::stoul(value));
    else if(arg == "--symmetrization-cost") symmetrization_cost = value != "0";
    else throw std::invalid_argument("unknown option: " + arg);
  }

  std::cout << "Symmetric VSA (K proxies) vs CGAL's VSA (K and 2K proxies); errors in 1e-3 of the diagonal;\n"
            << "symmetry error over the input's symmetric region (whole surface in brackets); time: median of "
            << repeats << " alternating runs; alpha = " << alpha << "\n\n"
            << "| mesh | faces | K | method | vertices | RMS error | symmetry error | time (s) |\n"
            << "|---|---:|---:|---|---:|---:|---:|---:|\n"
            << std::fixed;
  std::size_t border[3] = {0, 0, 0}, non_manifold[3] = {0, 0, 0};
  std::vector<double> ratios, geometric_k, geometric_2k, symmetry_k, symmetry_2k;
  for(const std::string& name : meshes) {
    const std::string path = mesh_path(name);
    Mesh mesh;
    if(!PMP::IO::read_polygon_mesh(path, mesh) || is_empty(mesh)) throw std::runtime_error("cannot read " + path);
    if(!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);
    const CGAL::Bbox_3 box = PMP::bbox(mesh);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    auto start = std::chrono::steady_clock::now();
    std::vector<K::Plane_3> planes;
    for(const auto& s : ST::detect_principal_symmetries(
          mesh, CGAL::parameters::grid_resolution(int(resolution)).max_number_of_planes(planes_kept)))
      planes.push_back(s.plane);
    const double detection = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << name << ": " << planes.size() << " plane(s) detected in " << detection << " s\n";
    std::cout << "| " << name << " (" << planes.size() << " plane, detected in " << std::setprecision(1) << detection
              << " s) | " << num_faces(mesh) << " | | | | | | |\n";
    if(planes.empty()) continue;
    const auto metric_np = CGAL::parameters::number_of_points_on_faces(20000);
    // The input's own asymmetry: an output cannot be much more symmetric than the input without
    // moving away from it (pointwise, its symmetry error is at least the input's minus about
    // twice its distance to the input).
    std::cout << "| | | | input | " << num_vertices(mesh) << " | | " << std::setprecision(2)
              << 1e3 * ST::symmetry_error(mesh, planes.front(), mesh, 0.02 * diagonal, metric_np) / diagonal << " ("
              << 1e3 * ST::symmetry_error(mesh, planes.front(), metric_np) / diagonal << ") | |\n";
    if(symmetrization_cost) {
      const std::vector<K::Point_3> symmetrized = symmetrized_positions(mesh, planes.front());
      for(double t : {0.25, 0.5, 0.75, 1.}) {
        const Mesh moved = partly_symmetrized(mesh, symmetrized, t);
        std::cout << "| | | | input, " << t << " of the way to symmetric | | " << std::setprecision(2)
                  << 1e3 * ST::approximation_error(mesh, moved, metric_np).rms / diagonal << " | "
                  << 1e3 * ST::symmetry_error(moved, planes.front(), mesh, 0.02 * diagonal, metric_np) / diagonal
                  << " | |\n";
      }
      continue;
    }
    for(std::size_t k : proxies) {
      Run runs[3];
      for(std::size_t r = 0; r < repeats; ++r)
        for(int m = 0; m < 3; ++m) {
          Soup s;
          start = std::chrono::steady_clock::now();
          if(m == 0)
            ST::symmetric_approximate_triangle_mesh(mesh, planes, CGAL::parameters::max_number_of_proxies(k)
                                                                    .position_weight(alpha)
                                                                    .anchors(std::back_inserter(s.points))
                                                                    .triangles(std::back_inserter(s.triangles)));
          else
            VSA::approximate_triangle_mesh(mesh, CGAL::parameters::max_number_of_proxies(m == 1 ? k : 2 * k)
                                                   .anchors(std::back_inserter(s.points))
                                                   .triangles(std::back_inserter(s.triangles)));
          runs[m].seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
          runs[m].soup = std::move(s);
        }
      double geometric[3], symmetry[3];
      for(int m = 0; m < 3; ++m) {
        const Mesh out = mesh_of(runs[m].soup);
        geometric[m] = ST::approximation_error(mesh, out, metric_np).rms / diagonal;
        symmetry[m] = ST::symmetry_error(out, planes.front(), mesh, 0.02 * diagonal, metric_np) / diagonal;
        const double whole = ST::symmetry_error(out, planes.front(), metric_np) / diagonal;
        const char* method[3] = {"symmetric VSA, K", "CGAL VSA, K", "CGAL VSA, 2K"};
        const auto d = st_test::soup_defects(runs[m].soup.points.size(), runs[m].soup.triangles);
        border[m] += d.border_edges;
        non_manifold[m] += d.non_manifold_vertices;
        std::cerr << name << " K = " << k << ", " << method[m] << ": " << d.border_edges << " border edges, "
                  << d.non_manifold_vertices << " non-manifold vertices\n";
        std::cout << "| | | " << k << " | " << method[m] << " | " << runs[m].soup.points.size() << " | "
                  << std::setprecision(2) << 1e3 * geometric[m] << " | " << 1e3 * symmetry[m] << " (" << 1e3 * whole
                  << ") | " << std::setprecision(3) << median(runs[m].seconds) << " |\n";
      }
      ratios.push_back(median(runs[0].seconds) / median(runs[1].seconds));
      geometric_k.push_back(geometric[0] / geometric[1]);
      geometric_2k.push_back(geometric[0] / geometric[2]);
      symmetry_k.push_back(symmetry[0] / symmetry[1]);
      symmetry_2k.push_back(symmetry[0] / symmetry[2]);
      std::cout << std::flush;
    }
  }
  if(symmetrization_cost) return EXIT_SUCCESS;
  auto mean = [](const std::vector<double>& v) {
    double s = 0.;
    for(double x : v) s += x;
    return v.empty() ? 0. : s / double(v.size());
  };
  std::cout << std::setprecision(2) << "\nOver " << ratios.size() << " (mesh, K) cases, ours against CGAL's VSA:\n"
            << "  time ratio to CGAL K:        mean " << mean(ratios) << ", largest "
            << (ratios.empty() ? 0. : *std::max_element(ratios.begin(), ratios.end())) << "\n"
            << "  geometric error ratio:       " << mean(geometric_k) << " (to K), " << mean(geometric_2k) << " (to 2K)\n"
            << "  symmetry error ratio:        " << mean(symmetry_k) << " (to K), " << mean(symmetry_2k) << " (to 2K)\n"
            << "  border edges in all:         " << border[0] << " (CGAL K: " << border[1] << ", 2K: " << border[2] << ")\n"
            << "  non-manifold vertices:       " << non_manifold[0] << " (CGAL K: " << non_manifold[1] << ", 2K: "
            << non_manifold[2] << ")\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
