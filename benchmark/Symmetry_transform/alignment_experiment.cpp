// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The alignment experiment of the thesis (section 4.1.3) on CGAL's sample meshes: how far the
// frame of a partial scan is from the frame of the whole mesh, for the symmetry frame (centre of
// symmetry, principal symmetry axes) and for the PCA frame (centre of mass, principal axes).
//
// Per mesh, 8 virtual range scans: a scanner at each corner of a cube around the mesh, at twice
// the diagonal of the bounding box from its centre, looking at the centre, with a field of view
// of 0.4 radian sampled by a square grid of rays (--rays per side); each ray that hits the mesh
// (first intersection in a CGAL::AABB_tree) gives a point. Errors of a scan's frame against the
// whole mesh's: translational, |c_scan - c_mesh| / R (R the radius of the mesh); rotational, the
// largest angle between corresponding axes, each axis taken as a line (no sign), in the order of
// the frames and, as equally strong planes may come in either order, for the best pairing of the
// axes (the smallest largest angle over the 6 permutations). Prints a row per
// mesh, the histograms of both errors, and the fraction of scans where the centre of symmetry is
// closer to its whole-mesh value than the centre of mass is to its own (the thesis: 90 %, and
// 1.5 times closer on average).
//
// usage: alignment_experiment [--meshes a.off,b.off,...] [--resolution N] [--rays N]
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmark_utilities.h"

namespace {

using benchmark_utilities::split;
using benchmark_utilities::mesh_path;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
typedef CGAL::Symmetry_transform::Symmetry_frame<K> Frame;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

const char* default_meshes = "bull.off,cow.off,camel.off,dino.off,elephant.off,triceratops.off,homer.off,"
                             "lion.off,bear.off,armadillo.off,man.off,mannequin-devil.off,diplodocus.off,"
                             "couplingdown.off,fandisk.off,rotor_small.off";

int positive(const std::string& option, const std::string& text)
{
  if(text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos || std::stoi(text) < 1)
    throw std::invalid_argument(option + " expects a positive integer, not '" + text + "'");
  return std::stoi(text);
}

// The points of a range scan from `eye` looking at `target`: a rays x rays grid over a square
// field of view of 0.4 radian.
std::vector<K::Point_3> range_scan(const Tree& tree, const K::Point_3& eye, const K::Point_3& target, int rays)
{
  const K::Vector_3 forward = (target - eye) / std::sqrt((target - eye).squared_length());
  K::Vector_3 right = CGAL::cross_product(forward, std::abs(forward.z()) < 0.9 ? K::Vector_3(0, 0, 1) : K::Vector_3(1, 0, 0));
  right = right / std::sqrt(right.squared_length());
  const K::Vector_3 up = CGAL::cross_product(right, forward);
  const double half_width = std::tan(0.2);
  std::vector<K::Point_3> points;
  for(int i = 0; i < rays; ++i)
    for(int j = 0; j < rays; ++j) {
      const double u = half_width * (2. * (i + 0.5) / rays - 1.), v = half_width * (2. * (j + 0.5) / rays - 1.);
      const auto hit = tree.first_intersection(K::Ray_3(eye, forward + u * right + v * up));
      if(hit)
        if(const K::Point_3* p = boost::get<K::Point_3>(&hit->first)) points.push_back(*p);
    }
  return points;
}

// The largest angle, in degrees, between the axes of a and the axes of b in the order `order`,
// taken as lines.
double axes_angle(const Frame& a, const Frame& b, const std::array<int, 3>& order = {0, 1, 2})
{
  double worst = 0.;
  for(int k = 0; k < 3; ++k) {
    const double c = std::abs(a.axes[std::size_t(k)] * b.axes[std::size_t(order[std::size_t(k)])]);
    worst = std::max(worst, std::acos(std::min(1., c)) * 180. / CGAL_PI);
  }
  return worst;
}

// The same for the best pairing of the axes.
double unordered_axes_angle(const Frame& a, const Frame& b)
{
  std::array<int, 3> order = {0, 1, 2};
  double best = 180.;
  do best = std::min(best, axes_angle(a, b, order));
  while(std::next_permutation(order.begin(), order.end()));
  return best;
}

struct Histogram
{
  std::vector<double> edges; // bins [edges[i], edges[i+1]), the last one open
  std::vector<int> counts;
  explicit Histogram(std::vector<double> e) : edges(std::move(e)), counts(edges.size(), 0) {}
  void add(double x)
  {
    std::size_t i = edges.size() - 1;
    while(i > 0 && x < edges[i]) --i;
    ++counts[i];
  }
};

void print_histograms(const std::string& what, const Histogram& symmetry, const Histogram& pca, const std::string& unit)
{
  std::cout << "\n" << what << " | symmetry frame | PCA frame |\n|---|---:|---:|\n";
  for(std::size_t i = 0; i < symmetry.edges.size(); ++i) {
    std::ostringstream bin;
    if(i + 1 < symmetry.edges.size())
      bin << "[" << symmetry.edges[i] << ", " << symmetry.edges[i + 1] << ") " << unit;
    else
      bin << ">= " << symmetry.edges[i] << " " << unit;
    std::cout << "| " << bin.str() << " | " << symmetry.counts[i] << " | " << pca.counts[i] << " |\n";
  }
}

} // namespace

int main(int argc, char** argv)
try {
  std::string meshes = default_meshes;
  int resolution = 64, rays = 120;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(a + 1 == argc) throw std::invalid_argument(arg + " expects a value");
    const std::string value = argv[++a];
    if(arg == "--meshes") meshes = value;
    else if(arg == "--resolution") resolution = positive(arg, value);
    else if(arg == "--rays") rays = positive(arg, value);
    else throw std::invalid_argument("unknown option: " + arg);
  }
  std::cout << "Command: `alignment_experiment --meshes " << meshes << " --resolution " << resolution << " --rays "
            << rays << "`\n\n| mesh | faces | scans | points per scan | centre of symmetry closer | mean translational "
            << "error, symmetry / PCA (% R) | mean rotational error, symmetry / PCA (deg) | the same, axes paired "
            << "at best (deg) |\n|---|---:|---:|---:|---:|---:|---:|---:|\n" << std::fixed << std::setprecision(2);
  const auto np = CGAL::parameters::grid_resolution(resolution).random_seed(1);
  Histogram translation_symmetry({0, 1, 2, 5, 10, 20}), translation_pca({0, 1, 2, 5, 10, 20});
  Histogram rotation_symmetry({0, 1, 5, 15, 45}), rotation_pca({0, 1, 5, 15, 45});
  int scans = 0, symmetry_closer = 0;
  double sum_symmetry = 0., sum_pca = 0.;
  for(const std::string& name : split(meshes)) {
    Mesh mesh;
    const std::string path = mesh_path(name);
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh)) {
      std::cerr << "skipped " << path << ": cannot read it\n";
      continue;
    }
    if(!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);
    const Frame whole_symmetry = ST::symmetry_frame(mesh, np), whole_pca = ST::pca_frame(mesh);
    double radius = 0.;
    for(const auto v : vertices(mesh))
      radius = std::max(radius, std::sqrt(CGAL::squared_distance(whole_pca.center, mesh.point(v))));
    const CGAL::Bbox_3 box = PMP::bbox(mesh);
    const K::Point_3 center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    Tree tree(faces(mesh).first, faces(mesh).second, mesh);
    int mesh_scans = 0, mesh_closer = 0;
    double mesh_translation[2] = {0., 0.}, mesh_rotation[2] = {0., 0.}, mesh_unordered[2] = {0., 0.};
    std::size_t points_total = 0;
    for(int corner = 0; corner < 8; ++corner) {
      const K::Vector_3 direction((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
      const K::Point_3 eye = center + (2. * diagonal / std::sqrt(3.)) * direction;
      const std::vector<K::Point_3> scan = range_scan(tree, eye, center, rays);
      if(scan.size() < 100) continue;
      const Frame scan_symmetry = ST::symmetry_frame_of_points(scan, np), scan_pca = ST::pca_frame_of_points(scan);
      const double t_symmetry = 100. * std::sqrt(CGAL::squared_distance(scan_symmetry.center, whole_symmetry.center)) / radius;
      const double t_pca = 100. * std::sqrt(CGAL::squared_distance(scan_pca.center, whole_pca.center)) / radius;
      const double r_symmetry = axes_angle(scan_symmetry, whole_symmetry), r_pca = axes_angle(scan_pca, whole_pca);
      translation_symmetry.add(t_symmetry);
      translation_pca.add(t_pca);
      rotation_symmetry.add(r_symmetry);
      rotation_pca.add(r_pca);
      mesh_closer += t_symmetry < t_pca;
      mesh_translation[0] += t_symmetry;
      mesh_translation[1] += t_pca;
      mesh_rotation[0] += r_symmetry;
      mesh_rotation[1] += r_pca;
      mesh_unordered[0] += unordered_axes_angle(scan_symmetry, whole_symmetry);
      mesh_unordered[1] += unordered_axes_angle(scan_pca, whole_pca);
      points_total += scan.size();
      ++mesh_scans;
    }
    if(mesh_scans == 0) continue;
    std::cout << "| " << name << " | " << num_faces(mesh) << " | " << mesh_scans << " | " << points_total / mesh_scans
              << " | " << mesh_closer << " / " << mesh_scans << " | " << mesh_translation[0] / mesh_scans << " / "
              << mesh_translation[1] / mesh_scans << " | " << mesh_rotation[0] / mesh_scans << " / "
              << mesh_rotation[1] / mesh_scans << " | " << mesh_unordered[0] / mesh_scans << " / "
              << mesh_unordered[1] / mesh_scans << " |" << std::endl;
    scans += mesh_scans;
    symmetry_closer += mesh_closer;
    sum_symmetry += mesh_translation[0];
    sum_pca += mesh_translation[1];
  }
  if(scans == 0) throw std::runtime_error("no scan (are the meshes in " SYMMETRY_TRANSFORM_DATA_DIR "/meshes?)");
  print_histograms("translational error", translation_symmetry, translation_pca, "% R");
  print_histograms("rotational error", rotation_symmetry, rotation_pca, "deg");
  std::cout << "\nCentre of symmetry closer than the centre of mass in " << symmetry_closer << " of " << scans
            << " scans (" << 100. * symmetry_closer / scans << " %); mean translational error " << sum_symmetry / scans
            << " % R (symmetry) vs " << sum_pca / scans << " % R (PCA): " << sum_pca / sum_symmetry
            << " times closer on average.\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
