// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The viewpoint experiment of the thesis (section 4.3.3: on 22 models, "the best viewpoint was
// always 20-35 degrees off-axis"): on CGAL's sample meshes, the angle between the best view of
// best_viewpoints() and the nearest axis of the symmetry frame of the same detection. With
// --diagnostics 1, per mesh, the principal planes (measure, support, angle to the nearest frame
// axis) and the best view's angle when the planes are given otherwise: near-duplicate normals
// counted once, the weights multiplied by the supports, only the frame's planes; the thesis's W
// (every local maximum of the PRST, or the detection's candidates, weighted by the transform);
// the measures raised to a power (sharper contrast between the planes); the measures less a
// quantile of the transform's directions' best values; the measures times the planes' prominence
// over the planes tilted around them.
//
// usage: viewpoint_experiment [--meshes a.off,...] [--resolution N] [--cache DIR] [--diagnostics 1]
// Figures and the commands that produced them: RESULTS.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmark_utilities.h"
#include "detection_cache.h"

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Symmetry_transform::Principal_symmetry<K> Symmetry;
namespace ST = CGAL::Symmetry_transform;
namespace STI = CGAL::Symmetry_transform::internal;
namespace PMP = CGAL::Polygon_mesh_processing;

const char* default_meshes = "bull.off,cow.off,camel.off,dino.off,elephant.off,triceratops.off,homer.off,"
                             "lion.off,bear.off,armadillo.off,man.off,mannequin-devil.off,diplodocus.off,"
                             "couplingdown.off,fandisk.off,rotor_small.off,elk.off,pig.off,helmet.off,"
                             "mushroom.off,spool.off,anchor.off";

// The angle in degrees between the view v and the nearest axis of the frame, as lines.
double off_axis(const Eigen::Vector3d& v, const STI::Eigen_frame& frame)
{
  double c = 0.;
  for(const Eigen::Vector3d& a : frame.axes) c = std::max(c, std::abs(a.dot(v.normalized())));
  return std::acos(std::min(1., c)) * 180. / CGAL_PI;
}

Eigen::Vector3d best_view(const std::vector<Symmetry>& symmetries)
{
  std::vector<ST::Viewpoint<K>> views;
  ST::best_viewpoints(symmetries, std::back_inserter(views));
  if(views.empty()) return Eigen::Vector3d::UnitZ();
  const K::Vector_3& d = views.front().direction;
  return {d.x(), d.y(), d.z()};
}

// The planes with normals within `degrees` of a stronger one's left out.
std::vector<Symmetry> distinct_normals(const std::vector<Symmetry>& symmetries, double degrees)
{
  std::vector<Symmetry> kept;
  for(const Symmetry& s : symmetries) {
    const Eigen::Vector3d n = STI::to_dplane(s.plane).normal;
    bool duplicate = false;
    for(const Symmetry& k : kept)
      duplicate = duplicate || std::abs(n.dot(STI::to_dplane(k.plane).normal)) > std::cos(degrees * CGAL_PI / 180.);
    if(!duplicate) kept.push_back(s);
  }
  return kept;
}

// The `count` strongest planes whose normals are at least `degrees` apart.
std::vector<Symmetry> strongest_distinct(const std::vector<Symmetry>& symmetries, std::size_t count, double degrees)
{
  std::vector<Symmetry> kept = distinct_normals(symmetries, degrees);
  if(kept.size() > count) kept.resize(count);
  return kept;
}

// The planes' measures less the weakest one's (the symmetry above that of any plane found).
std::vector<Symmetry> contrasted(std::vector<Symmetry> symmetries)
{
  double weakest = 1.;
  for(const Symmetry& s : symmetries) weakest = std::min(weakest, s.symmetry);
  for(Symmetry& s : symmetries) s.symmetry -= weakest;
  return symmetries;
}

std::vector<Symmetry> support_weighted(std::vector<Symmetry> symmetries)
{
  for(Symmetry& s : symmetries) s.symmetry *= s.support;
  return symmetries;
}

// The thesis's W (section 4.3): every local maximum of the PRST, weighted by its value; with
// `thresholds`, only the maxima that the detection refines (its candidates).
std::vector<Symmetry> transform_maxima(const ST::Reflective_symmetry_transform<K>& prst, bool thresholds)
{
  std::vector<std::array<std::size_t, 3>> maxima;
  if(thresholds) {
    const STI::Candidate_settings c = STI::candidate_settings(CGAL::parameters::default_values());
    maxima = STI::symmetry_candidates(prst, c.symmetry_threshold, c.laplacian_threshold);
  } else {
    prst.local_maxima(std::back_inserter(maxima));
  }
  std::vector<Symmetry> planes;
  for(const auto& b : maxima) planes.push_back({prst.plane(b), prst.value(b), 1.});
  return planes;
}

// The measures raised to `power`: a stronger contrast between the planes.
std::vector<Symmetry> sharpened(std::vector<Symmetry> symmetries, double power)
{
  for(Symmetry& s : symmetries) s.symmetry = std::pow(s.symmetry, power);
  return symmetries;
}

// The highest PRST value over the planes of normal `n` whose offsets from the transform's centre lie
// within `reach` of `offset`.
double best_offset_value(const ST::Reflective_symmetry_transform<K>& prst, const Eigen::Vector3d& n, double offset,
                         double reach)
{
  const K::Point_3& c = prst.center();
  double best = 0.;
  for(double t = offset - reach; t <= offset + reach; t += 0.5 * 2. * prst.radius() / double(prst.resolution())) {
    if(std::abs(t) >= prst.radius()) continue;
    const K::Vector_3 u(n.x(), n.y(), n.z());
    best = std::max(best, prst.value(K::Plane_3(c + t * u, u)));
  }
  return best;
}

// The planes weighted by how far their PRST value rises above that of the planes tilted by
// `degrees` (the mean over a ring of tilts, each at its best offset): a maximum in a flat transform
// weighs little, a sharp symmetry its full measure.
std::vector<Symmetry> prominent(std::vector<Symmetry> symmetries, const ST::Reflective_symmetry_transform<K>& prst,
                                double degrees)
{
  const double tilt = degrees * CGAL_PI / 180., reach = 0.25 * prst.radius();
  const int ring = 16;
  for(Symmetry& s : symmetries) {
    const Eigen::Vector3d n = STI::to_dplane(s.plane).normal;
    const K::Point_3& c = prst.center();
    const double offset = -(s.plane.a() * c.x() + s.plane.b() * c.y() + s.plane.c() * c.z() + s.plane.d()) /
                          std::sqrt(s.plane.orthogonal_vector().squared_length());
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    double around = 0.;
    for(int a = 0; a < ring; ++a) {
      const double alpha = 2. * CGAL_PI * a / ring;
      const Eigen::Vector3d m = std::cos(tilt) * n + std::sin(tilt) * (std::cos(alpha) * e1 + std::sin(alpha) * e2);
      around += best_offset_value(prst, m, offset * m.dot(n), reach) / ring;
    }
    const double peak = best_offset_value(prst, n, offset, 0.5 * prst.radius() / prst.resolution());
    s.symmetry = peak > 0. ? s.symmetry * std::max(0., peak - around) / peak : 0.;
  }
  return symmetries;
}

// The `fraction` quantile, over the directions of the transform (weighted by their solid angle),
// of the best PRST value of each direction: the symmetry that planes in general position have.
double direction_quantile(const ST::Reflective_symmetry_transform<K>& prst, double fraction)
{
  const std::size_t n = prst.resolution();
  std::vector<std::pair<double, double>> best;  // (value, solid angle)
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j) {
      double v = 0.;
      for(std::size_t k = 0; k < n; ++k) v = std::max(v, prst.value(i, j, k));
      best.push_back({v, std::sin(prst.theta(i))});
    }
  std::sort(best.begin(), best.end());
  double total = 0., seen = 0.;
  for(const auto& b : best) total += b.second;
  for(const auto& b : best) if((seen += b.second) >= fraction * total) return b.first;
  return best.back().first;
}

std::vector<Symmetry> above(std::vector<Symmetry> symmetries, double baseline, double power)
{
  for(Symmetry& s : symmetries) s.symmetry = std::pow(std::max(0., s.symmetry - baseline), power);
  return symmetries;
}

std::string fixed(double x, int digits = 1)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << x;
  return out.str();
}

struct Options
{
  std::string meshes = default_meshes, cache;
  int resolution = 64;
  bool diagnostics = false;
};

Options parse(int argc, char** argv)
{
  Options o;
  for(const auto& [arg, value] : benchmark_utilities::option_pairs(argc, argv)) {
    if(arg == "--meshes") o.meshes = value;
    else if(arg == "--resolution") o.resolution = std::stoi(value);
    else if(arg == "--cache") o.cache = value;
    else if(arg == "--diagnostics") o.diagnostics = value != "0";
    else throw std::invalid_argument("unknown option: " + arg);
  }
  return o;
}

void print_planes(const std::vector<Symmetry>& symmetries, const STI::Eigen_frame& frame)
{
  std::cout << "  planes (M, support, angle of the normal to the nearest frame axis):";
  for(const Symmetry& s : symmetries)
    std::cout << " " << fixed(s.symmetry, 2) << "/" << fixed(s.support, 2) << "/"
              << fixed(off_axis(STI::to_dplane(s.plane).normal, frame)) << ";";
  std::cout << "\n";
}

} // namespace

int main(int argc, char** argv)
try {
  const Options o = parse(argc, argv);
  std::cout << "Command: `viewpoint_experiment --meshes " << o.meshes << " --resolution " << o.resolution << "`\n\n"
            << "| mesh | planes | best view's angle to the nearest frame axis (deg) | normals within 10 deg counted once "
            << "| weights M x support | both | 3 strongest normals 10 deg apart | 3 strongest 30 deg apart | M less the "
            << "weakest M | the same, merged | all PRST maxima | PRST candidates | M^2 | M^3 | M^4 "
            << "| M less the 50 % quantile | its square | 75 % | its square | 90 % | its square "
            << "| M x prominence over 5 deg tilts | over 30 deg tilts |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto np = CGAL::parameters::grid_resolution(o.resolution).random_seed(1);
  int in_range = 0, in_range_maxima = 0, in_range_candidates = 0, count = 0, in_range_sharpened[3] = {0, 0, 0};
  std::map<int, int> in_range_prominent, in_range_quantile;
  for(const std::string& name : benchmark_utilities::split(o.meshes)) {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(benchmark_utilities::mesh_path(name), mesh) || is_empty(mesh)) {
      std::cerr << "skipped " << name << "\n";
      continue;
    }
    if(!CGAL::is_triangle_mesh(mesh)) PMP::triangulate_faces(mesh);
    const std::string key = "demo_" + name + "_" + std::to_string(o.resolution) + "_whole";
    const STI::Detection<K> d = detection_cache::cached(o.cache, key, [&] { return STI::detection_of_mesh(mesh, np); });
    const STI::Eigen_frame frame = STI::symmetry_frame(STI::mass_of_mesh(mesh, np), d.symmetries, d.prst);
    const double angle = off_axis(best_view(d.symmetries), frame);
    const double merged = off_axis(best_view(distinct_normals(d.symmetries, 10.)), frame);
    const double weighted = off_axis(best_view(support_weighted(d.symmetries)), frame);
    const double both = off_axis(best_view(distinct_normals(support_weighted(d.symmetries), 10.)), frame);
    const double three = off_axis(best_view(strongest_distinct(d.symmetries, 3, 10.)), frame);
    const double three30 = off_axis(best_view(strongest_distinct(d.symmetries, 3, 30.)), frame);
    const double contrast = off_axis(best_view(contrasted(d.symmetries)), frame);
    const double contrast_merged = off_axis(best_view(distinct_normals(contrasted(d.symmetries), 10.)), frame);
    const double maxima = off_axis(best_view(transform_maxima(d.prst, false)), frame);
    const double candidates = off_axis(best_view(transform_maxima(d.prst, true)), frame);
    std::cout << "| " << name << " | " << d.symmetries.size() << " | " << fixed(angle) << " | " << fixed(merged) << " | "
              << fixed(weighted) << " | " << fixed(both) << " | " << fixed(three) << " | " << fixed(three30) << " | "
              << fixed(contrast) << " | " << fixed(contrast_merged) << " | " << fixed(maxima) << " | " << fixed(candidates);
    for(const double power : {2., 3., 4.}) {
      const double sharp = off_axis(best_view(sharpened(d.symmetries, power)), frame);
      std::cout << " | " << fixed(sharp);
      in_range_sharpened[int(power) - 2] += sharp >= 15. && sharp <= 40.;
    }
    for(const double q : {0.5, 0.75, 0.9}) {
      const double b = direction_quantile(d.prst, q);
      for(const double power : {1., 2.}) {
        const std::vector<Symmetry> p = above(d.symmetries, b, power);
        const double a = off_axis(best_view(p), frame);
        std::cout << " | " << fixed(a);
        in_range_quantile[int(100 * q) * 10 + int(power)] += a >= 15. && a <= 40.;
        if(o.diagnostics) { std::cout << " (b " << fixed(b, 2) << ": "; for(const Symmetry& x : p) std::cout << fixed(x.symmetry, 2) << " "; std::cout << ")"; }
      }
    }
    for(const double degrees : {5., 30.}) {
      const std::vector<Symmetry> p = prominent(d.symmetries, d.prst, degrees);
      const double a = off_axis(best_view(p), frame);
      std::cout << " | " << fixed(a);
      in_range_prominent[int(degrees)] += a >= 15. && a <= 40.;
      if(o.diagnostics) { std::cout << " ("; for(const Symmetry& x : p) std::cout << fixed(x.symmetry, 2) << " "; std::cout << ")"; }
    }
    std::cout << " |\n";
    in_range_maxima += maxima >= 15. && maxima <= 40.;
    in_range_candidates += candidates >= 15. && candidates <= 40.;
    if(o.diagnostics) print_planes(d.symmetries, frame);
    in_range += angle >= 15. && angle <= 40.;
    ++count;
  }
  std::cout << "\nBest view 15 to 40 degrees from the nearest frame axis on " << in_range << " of " << count
            << " meshes; with all PRST maxima " << in_range_maxima << ", with the PRST candidates " << in_range_candidates
            << "; with M^2, M^3, M^4 " << in_range_sharpened[0] << ", " << in_range_sharpened[1] << ", "
            << in_range_sharpened[2] << ".\n";
  for(const auto& [q, n] : in_range_quantile)
    std::cout << "M less the " << q / 10 << " % quantile, power " << q % 10 << ": " << n << " of " << count << "\n";
  for(const auto& [d, n] : in_range_prominent)
    std::cout << "M x prominence over tilts of " << d << " deg: " << n << " of " << count << "\n";
  return EXIT_SUCCESS;
}
catch(const std::exception& e) {
  std::cerr << "Error: " << e.what() << std::endl;
  return EXIT_FAILURE;
}
