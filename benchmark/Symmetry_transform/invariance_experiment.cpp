// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The planes of detect_principal_symmetries() on CGAL's sample meshes where they are, moved far
// from the origin, and with other thread counts.
//
// For each mesh (triangulated, default parameters but `--threads` and `--seed`, default 1):
//   - the planes at the mesh's own place; "exact" are those of support >= --exact-support;
//   - moved by (t, t, t) for each t of --shifts, and by D radii along (1, 1, 1) for each D of
//     --radii: how many planes, and for the planes at the mesh's place the largest deviation of
//     the nearest moved plane, max(sine of the angle, difference of the offsets at the mesh's
//     centre over its radius), over the exact planes and over all; 1 when none was found;
//   - with each thread count of --thread-counts: whether planes, measures and supports are the
//     same to the bit as with the first.
// usage: invariance_experiment [--meshes a.off,b.off|all] [--shifts 1e3,1e6] [--radii 1e4,1e6]
//          [--thread-counts 1,2,3,8] [--threads 2] [--seed 1] [--exact-support 0.99] [--exact-only 0|1]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>

#include "benchmark_utilities.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Symmetry_transform::Principal_symmetry<K> Symmetry;
namespace ST = CGAL::Symmetry_transform;
namespace bu = benchmark_utilities;

struct Options
{
  std::vector<std::string> meshes = {"bull.off", "cube.off"};
  std::vector<double> shifts = {1e3, 1e6}, radii = {1e4, 1e6};
  std::vector<unsigned> thread_counts = {1, 2, 3, 8};
  unsigned threads = 2;
  unsigned seed = 1;
  double exact_support = 0.99; // a plane that maps 99 % of the area onto the surface
  bool exact_only = false;     // list only the meshes whose strongest plane is exact
};

Options parse(int argc, char** argv)
{
  Options o;
  auto numbers = [](const std::string& list) {
    std::vector<double> v;
    for(const std::string& item : bu::split(list)) v.push_back(std::stod(item));
    return v;
  };
  for(const auto& [option, value] : bu::option_pairs(argc, argv)) {
    if(option == "--meshes") o.meshes = value == "all" ? bu::all_sample_meshes() : bu::split(value);
    else if(option == "--shifts") o.shifts = numbers(value);
    else if(option == "--radii") o.radii = numbers(value);
    else if(option == "--thread-counts") {
      o.thread_counts.clear();
      for(double t : numbers(value)) o.thread_counts.push_back(unsigned(t));
    } else if(option == "--threads") o.threads = unsigned(std::stoul(value));
    else if(option == "--seed") o.seed = unsigned(std::stoul(value));
    else if(option == "--exact-support") o.exact_support = std::stod(value);
    else if(option == "--exact-only") o.exact_only = value != "0";
    else throw std::invalid_argument("unknown option " + option);
  }
  return o;
}

std::optional<Mesh> read_mesh(const std::string& name)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(bu::mesh_path(name), mesh) || faces(mesh).empty()) return std::nullopt;
  if(!CGAL::is_triangle_mesh(mesh) && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh)) return std::nullopt;
  return mesh;
}

std::vector<Symmetry> planes_of(const Mesh& mesh, unsigned seed, unsigned threads)
{
  return ST::detect_principal_symmetries(mesh, CGAL::parameters::random_seed(seed).number_of_threads(threads));
}

// The vertices' mean and their largest distance from it.
std::pair<K::Point_3, double> center_and_radius(const Mesh& mesh)
{
  K::Vector_3 sum(0, 0, 0);
  for(auto v : vertices(mesh)) sum = sum + (mesh.point(v) - CGAL::ORIGIN);
  const K::Point_3 c = CGAL::ORIGIN + sum / double(num_vertices(mesh));
  double r2 = 0.;
  for(auto v : vertices(mesh)) r2 = (std::max)(r2, CGAL::squared_distance(c, mesh.point(v)));
  return {c, std::sqrt(r2)};
}

// max(sine of the angle, |difference of the signed distances at c| / radius) of two planes.
double deviation(const K::Plane_3& a, const K::Plane_3& b, const K::Point_3& c, double radius)
{
  const K::Vector_3 u = a.orthogonal_vector() / std::sqrt(a.orthogonal_vector().squared_length()),
                    v = b.orthogonal_vector() / std::sqrt(b.orthogonal_vector().squared_length());
  const double sign = u * v < 0. ? -1. : 1.;
  const double sine = std::sqrt(CGAL::cross_product(u, v).squared_length());
  const double ha = (u * (c - CGAL::ORIGIN)) + a.d() / std::sqrt(a.orthogonal_vector().squared_length()),
               hb = (v * (c - CGAL::ORIGIN)) + b.d() / std::sqrt(b.orthogonal_vector().squared_length());
  return (std::max)(sine, std::abs(ha - sign * hb) / radius);
}

// The largest deviation of the planes `here` (moved by m), over the exact ones and over all, from
// their nearest in `there`; the centre c of the mesh at its place.
std::pair<double, double> largest_deviations(const std::vector<Symmetry>& here, const std::vector<Symmetry>& there,
                                             const K::Aff_transformation_3& m, const K::Point_3& c, double radius,
                                             double exact_support)
{
  double exact = 0., all = 0.;
  for(const Symmetry& s : here) {
    double nearest = 1.;
    for(const Symmetry& t : there) nearest = (std::min)(nearest, deviation(s.plane.transform(m), t.plane, m.transform(c), radius));
    all = (std::max)(all, nearest);
    if(s.support >= exact_support) exact = (std::max)(exact, nearest);
  }
  return {exact, all};
}

bool same_bits(const std::vector<Symmetry>& a, const std::vector<Symmetry>& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].plane != b[i].plane || a[i].symmetry != b[i].symmetry || a[i].support != b[i].support) return false;
  return true;
}

void print_header(const Options& o)
{
  std::cout << "| mesh | planes | exact |";
  for(double t : o.shifts) std::cout << " (t,t,t), t = " << t << ": planes, exact, all |";
  for(double d : o.radii) std::cout << " " << d << " radii: planes, exact, all |";
  std::cout << " same bits with " << o.thread_counts.size() << " thread counts |\n|---|---:|---:|";
  for(std::size_t i = 0; i < o.shifts.size() + o.radii.size(); ++i) std::cout << "---|";
  std::cout << "---|\n";
}

// One row; false if the mesh was left out.
bool print_row(const std::string& name, const Options& o)
{
  const std::optional<Mesh> mesh = read_mesh(name);
  if(!mesh) return false;
  const std::vector<Symmetry> here = planes_of(*mesh, o.seed, o.threads);
  const std::size_t exact = std::size_t(std::count_if(here.begin(), here.end(), [&](const Symmetry& s) { return s.support >= o.exact_support; }));
  if(o.exact_only && (here.empty() || here.front().support < o.exact_support)) return false;
  const auto [c, radius] = center_and_radius(*mesh);
  std::vector<K::Vector_3> moves;
  for(double t : o.shifts) moves.emplace_back(t, t, t);
  for(double d : o.radii) moves.push_back(K::Vector_3(1, 1, 1) * (d * radius / std::sqrt(3.)));
  std::cout << "| " << name << " | " << here.size() << " | " << exact << " |" << std::setprecision(2);
  for(const K::Vector_3& t : moves) {
    const K::Aff_transformation_3 m(CGAL::TRANSLATION, t);
    Mesh far = *mesh;
    CGAL::Polygon_mesh_processing::transform(m, far);
    const std::vector<Symmetry> there = planes_of(far, o.seed, o.threads);
    const auto [exact_deviation, all_deviation] = largest_deviations(here, there, m, c, radius, o.exact_support);
    std::cout << " " << there.size() << ", " << exact_deviation << ", " << all_deviation << " |";
  }
  const std::vector<Symmetry> first = planes_of(*mesh, o.seed, o.thread_counts.front());
  const bool same = std::all_of(o.thread_counts.begin(), o.thread_counts.end(),
                                [&](unsigned t) { return same_bits(first, planes_of(*mesh, o.seed, t)); });
  std::cout << " " << (same ? "yes" : "no") << " |" << std::endl;
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const Options o = parse(argc, argv);
    print_header(o);
    std::size_t rows = 0;
    for(const std::string& name : o.meshes) rows += print_row(name, o) ? 1 : 0;
    std::cout << rows << " meshes\n";
  } catch(const std::exception& e) {
    std::cerr << "invariance_experiment: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
