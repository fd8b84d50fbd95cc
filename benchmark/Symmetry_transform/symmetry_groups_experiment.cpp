// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Whole symmetry groups: shapes built in code whose mirror planes and rotation axes are known
// (regular prisms and antiprisms, Platonic solids, boxes, flat polygons and a flat rectangle, two
// cubes far apart, a cylinder and a cone),
// each under --motions seeded random similarities, against detect_principal_symmetries() and
// detect_rotational_symmetries() with their defaults.
//
// For each shape, over its motions: the mirror planes found (a found plane within --tolerance
// degrees and --tolerance/100 of the radius of a true one) out of those that exist; the largest
// angle between a true plane and the one found for it (degrees); the false planes (near no true
// one) and, among them, those stronger than the weakest true plane found; the planes found twice;
// the same for the axes, whose order must be the true one (on a surface of revolution, the flips
// about its continuous axis count as neither); the pencils of mirrors (every plane through a
// line) found as such, and the largest angle of their lines; the point group named from what was
// found (point_group()), right on how many motions, against the one named from the true symmetries.
// With --mirrored, instead: each sample mesh given and its mirror image, their centres
// --distances radii apart, under the same motions: the rank of the mirror between them among the
// planes found, its deviation, and how far the symmetry frame's centre lies from their midpoint.
// usage: symmetry_groups_experiment [--shapes prisms,antiprisms,platonic,boxes,flat,apart,revolution] [--motions 5]
//          [--tolerance 5] [--rotations 0|1] [--verbose 0|1]
//        symmetry_groups_experiment --mirrored bull.off,cactus.off [--distances 0.5,5,50,500] [--motions 5]

#include <CGAL/Symmetry_transform/point_group.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include "Symmetry_group_test_shapes.h"
#include "benchmark_utilities.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
namespace bu = benchmark_utilities;

struct Options
{
  std::vector<std::string> families = {"prisms", "antiprisms", "platonic", "boxes", "flat", "apart", "revolution"};
  int motions = 5;
  double tolerance = 5.; // degrees, and hundredths of the radius
  bool rotations = true;
  bool verbose = false;
  std::vector<std::string> mirrored; // sample meshes, for the parts-apart table
  std::vector<double> distances = {0.5, 5., 50., 500.};
};

Options parse(int argc, char** argv)
{
  Options o;
  for(const auto& [option, value] : bu::option_pairs(argc, argv)) {
    if(option == "--shapes") o.families = bu::split(value);
    else if(option == "--motions") o.motions = std::stoi(value);
    else if(option == "--tolerance") o.tolerance = std::stod(value);
    else if(option == "--rotations") o.rotations = value != "0";
    else if(option == "--verbose") o.verbose = value != "0";
    else if(option == "--mirrored") o.mirrored = bu::split(value);
    else if(option == "--distances") {
      o.distances.clear();
      for(const std::string& d : bu::split(value)) o.distances.push_back(std::stod(d));
    }
    else throw std::invalid_argument("unknown option " + option);
  }
  return o;
}

std::vector<Group_shape> shapes_of(const std::string& family)
{
  std::vector<Group_shape> shapes;
  if(family == "prisms")
    for(int n = 3; n <= 12; ++n) shapes.push_back(regular_prism(n));
  else if(family == "antiprisms")
    for(int n = 3; n <= 12; ++n) shapes.push_back(regular_antiprism(n));
  else if(family == "platonic") shapes = platonic_solids();
  else if(family == "boxes") shapes = {box_shape(1., 1., 1.6), box_shape(1., 0.7, 0.45)};
  else if(family == "flat") {
    for(int n : {3, 4, 5, 6, 8}) shapes.push_back(flat_polygon(n));
    shapes.push_back(flat_rectangle());
  } else if(family == "apart") {
    shapes.push_back(cubes_apart(1e4));
  } else if(family == "revolution") {
    shapes = {cylinder(), cone()};
  } else
    throw std::invalid_argument("unknown shape family " + family);
  return shapes;
}

// What was found of one kind of symmetry (planes or axes), summed over the motions.
struct Tally
{
  std::size_t truth = 0, found = 0, wrong_order = 0, false_ones = 0, false_above = 0, twice = 0;
  double worst_degrees = 0.;
};

double angle_degrees(const Vector_3& a, const Vector_3& b)
{
  const double c = std::abs(a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::clamp(c, 0., 1.)) * 180. / CGAL_PI;
}

// Matches found symmetries to true ones: `near(found, true)` says whether they are the same
// symmetry, `degrees(found, true)` their angle, `strength(found)` its measure.
template <typename Found, typename Truth, typename Near, typename Degrees, typename Same_kind>
void tally(const std::vector<Found>& found, const std::vector<Truth>& truth, const Near& near, const Degrees& degrees,
           const Same_kind& same_kind, Tally& t)
{
  t.truth += truth.size();
  double weakest_true = 2.;
  std::vector<bool> false_found(found.size(), true);
  for(const Truth& s : truth) {
    std::size_t matches = 0;
    for(std::size_t i = 0; i < found.size(); ++i)
      if(near(found[i], s)) {
        false_found[i] = false;
        if(!same_kind(found[i], s)) continue;
        if(++matches == 1) {
          t.worst_degrees = (std::max)(t.worst_degrees, degrees(found[i], s));
          weakest_true = (std::min)(weakest_true, double(found[i].symmetry));
        }
      }
    if(matches > 0) ++t.found;
    if(matches > 1) ++t.twice;
    if(matches == 0 && std::any_of(found.begin(), found.end(), [&](const Found& f) { return near(f, s); })) ++t.wrong_order;
  }
  for(std::size_t i = 0; i < found.size(); ++i)
    if(false_found[i]) {
      ++t.false_ones;
      if(double(found[i].symmetry) > weakest_true) ++t.false_above;
    }
}

void tally_planes(const std::vector<ST::Principal_symmetry<K>>& found, const std::vector<Plane_3>& truth,
                  const Point_3& center, double radius, double tolerance, Tally& t)
{
  auto near = [&](const ST::Principal_symmetry<K>& f, const Plane_3& p) {
    return angle_degrees(f.plane.orthogonal_vector(), p.orthogonal_vector()) < tolerance &&
           offset_between(unit_plane(f.plane), p, center) < tolerance / 100. * radius;
  };
  auto degrees = [](const ST::Principal_symmetry<K>& f, const Plane_3& p) {
    return angle_degrees(f.plane.orthogonal_vector(), p.orthogonal_vector());
  };
  std::vector<ST::Principal_symmetry<K>> single;
  for(const auto& f : found)
    if(f.family == ST::Mirror_family::ONE_PLANE) single.push_back(f);
  tally(single, truth, near, degrees, [](const auto&, const auto&) { return true; }, t);
}

// The pencils of mirrors found as such (EVERY_PLANE_THROUGH_AXIS), against the true ones.
void tally_pencils(const std::vector<ST::Principal_symmetry<K>>& found, const std::vector<Line_3>& truth, double radius,
                   double tolerance, Tally& t)
{
  std::vector<ST::Principal_symmetry<K>> pencils;
  for(const auto& f : found)
    if(f.family != ST::Mirror_family::ONE_PLANE) pencils.push_back(f);
  auto near = [&](const ST::Principal_symmetry<K>& f, const Line_3& line) {
    return f.family == ST::Mirror_family::EVERY_PLANE_THROUGH_AXIS &&
           angle_degrees(f.axis.to_vector(), line.to_vector()) < tolerance &&
           std::sqrt(CGAL::squared_distance(line, f.axis.point())) < tolerance / 100. * radius;
  };
  auto degrees = [](const ST::Principal_symmetry<K>& f, const Line_3& line) {
    return angle_degrees(f.axis.to_vector(), line.to_vector());
  };
  tally(pencils, truth, near, degrees, [](const auto&, const auto&) { return true; }, t);
}

// A flip about a continuous axis of `truth` that has a mirror across it (a cylinder's): one of
// infinitely many, which the detection reports one of.
bool flip_of_continuous(const ST::Rotational_symmetry<K>& f, const std::vector<Known_axis>& truth,
                        const std::vector<Plane_3>& planes, double radius, double tolerance)
{
  return f.order == 2 && std::any_of(truth.begin(), truth.end(), [&](const Known_axis& a) {
    const Vector_3 d = a.axis.to_vector();
    return a.order == 0 && std::abs(90. - angle_degrees(f.axis.to_vector(), d)) < tolerance &&
           std::sqrt(CGAL::squared_distance(a.axis, f.axis.point())) < tolerance / 100. * radius &&
           std::any_of(planes.begin(), planes.end(), [&](const Plane_3& p) { return angle_degrees(p.orthogonal_vector(), d) < tolerance; });
  });
}

void tally_axes(const std::vector<ST::Rotational_symmetry<K>>& all_found, const std::vector<Known_axis>& truth,
                const std::vector<Plane_3>& planes, double radius, double tolerance, Tally& t)
{
  std::vector<ST::Rotational_symmetry<K>> found;
  for(const auto& f : all_found)
    if(!flip_of_continuous(f, truth, planes, radius, tolerance)) found.push_back(f);
  auto near = [&](const ST::Rotational_symmetry<K>& f, const Known_axis& a) {
    const Vector_3 d = a.axis.to_vector();
    return angle_degrees(f.axis.to_vector(), d) < tolerance &&
           std::sqrt(CGAL::squared_distance(a.axis, f.axis.point())) < tolerance / 100. * radius;
  };
  auto degrees = [](const ST::Rotational_symmetry<K>& f, const Known_axis& a) {
    return angle_degrees(f.axis.to_vector(), a.axis.to_vector());
  };
  tally(found, truth, near, degrees, [](const auto& f, const Known_axis& a) { return f.order == a.order; }, t);
}

Line_3 moved(const Line_3& line, const Motion& m)
{
  return Line_3(m.transform(line.point()), m.transform(line.to_vector()));
}

// A plane through `line`, standing for every such plane.
ST::Principal_symmetry<K> pencil_of(const Line_3& line)
{
  const Plane_3 plane(line.point(), line.point() + line.to_vector(), line.point() + line.perpendicular_plane(line.point()).base1());
  return {plane, 1., 1., ST::Mirror_family::EVERY_PLANE_THROUGH_AXIS, line};
}

std::vector<Known_axis> moved(const std::vector<Known_axis>& axes, const Motion& m)
{
  std::vector<Known_axis> result;
  for(const Known_axis& a : axes) result.push_back({Line_3(m.transform(a.axis.point()), m.transform(a.axis.to_vector())), a.order});
  return result;
}

std::string cell(const Tally& t, bool with_order)
{
  std::ostringstream s;
  s << t.found << "/" << t.truth;
  if(with_order) s << ", " << t.wrong_order;
  s << ", " << std::setprecision(2) << t.worst_degrees << ", " << t.false_ones << " (" << t.false_above << "), " << t.twice;
  return s.str();
}

void print_row(const Group_shape& shape, const Options& o)
{
  CGAL::Random rng(1);
  Tally planes, axes, pencils;
  int right_groups = 0;
  std::vector<ST::Principal_symmetry<K>> true_planes_found;
  std::vector<ST::Rotational_symmetry<K>> true_axes_found;
  for(const Plane_3& p : shape.planes) true_planes_found.push_back({p, 1., 1.});
  for(const Line_3& line : shape.pencils) true_planes_found.push_back(pencil_of(line));
  for(const Known_axis& a : shape.axes) true_axes_found.push_back({a.axis, a.order, 1., 1.});
  const std::string true_group = ST::point_group(true_planes_found, true_axes_found).name;
  const double shape_radius = set_radius(std::vector<Point_3>(shape.mesh.points().begin(), shape.mesh.points().end()));
  for(int i = 0; i < o.motions; ++i) {
    const Motion m = random_motion(rng);
    Surface_mesh mesh = shape.mesh;
    CGAL::Polygon_mesh_processing::transform(m, mesh);
    const double radius = shape_radius * std::sqrt(m.transform(Vector_3(1, 0, 0)).squared_length());
    const Point_3 center = m.transform(CGAL::ORIGIN);
    std::vector<Plane_3> true_planes;
    for(const Plane_3& p : shape.planes) true_planes.push_back(st_test::moved(p, m));
    const auto found = ST::detect_principal_symmetries(mesh, CGAL::parameters::verbose(o.verbose));
    tally_planes(found, true_planes, center, radius, o.tolerance, planes);
    std::vector<Line_3> true_pencils;
    for(const Line_3& line : shape.pencils) true_pencils.push_back(moved(line, m));
    tally_pencils(found, true_pencils, radius, o.tolerance, pencils);
    if(o.verbose)
      for(const auto& f : found) std::cerr << shape.name << " motion " << i << ": plane M " << f.symmetry << " support " << f.support << "\n";
    if(!o.rotations) continue;
    const auto found_axes = ST::detect_rotational_symmetries(mesh, CGAL::parameters::verbose(o.verbose));
    if(o.verbose)
      for(const auto& f : found_axes)
        std::cerr << shape.name << " motion " << i << ": axis " << f.axis.to_vector() << " order " << f.order << " symmetry "
                  << f.symmetry << "\n";
    tally_axes(found_axes, moved(shape.axes, m), true_planes, radius, o.tolerance, axes);
    right_groups += ST::point_group(found, found_axes).name == true_group ? 1 : 0;
  }
  std::cout << "| " << shape.name << " | " << shape.planes.size() << " | " << cell(planes, false) << " | "
            << shape.axes.size() << " | " << (o.rotations ? cell(axes, true) : std::string("—")) << " | "
            << pencils.found << "/" << pencils.truth << ", " << std::setprecision(2) << pencils.worst_degrees << " | " << true_group
            << " | " << (o.rotations ? std::to_string(right_groups) + "/" + std::to_string(o.motions) : std::string("—"))
            << " |" << std::endl;
}

// Over the motions of two mirrored copies of `part` `distance` radii apart: the worst rank of
// the mirror among the planes found (0: the strongest; the plane count if missing), the worst
// deviation of the plane found for it (sine of the angle; offset over the copies' radius), and the
// farthest the frame's centre lies from the copies' midpoint (over their radius).
void print_mirrored_row(const std::string& name, const Surface_mesh& part, double distance, const Options& o)
{
  CGAL::Random rng(1);
  const Shape<Surface_mesh> pair = mirrored_copies(part, distance);
  const Center_and_radius copy = center_and_radius(part);
  const Point_3 midpoint = pair.planes.front().projection(copy.center);
  std::size_t worst_rank = 0;
  double worst_deviation = 0., worst_center = 0.;
  for(int i = 0; i < o.motions; ++i) {
    const Motion m = random_motion(rng);
    Surface_mesh mesh = pair.mesh;
    CGAL::Polygon_mesh_processing::transform(m, mesh);
    const double scale = std::sqrt(m.transform(Vector_3(1, 0, 0)).squared_length()), radius = scale * copy.radius;
    const Plane_3 mirror = st_test::moved(pair.planes.front(), m);
    const auto found = ST::detect_principal_symmetries(mesh);
    std::size_t rank = found.size();
    double deviation = 1.;
    for(std::size_t r = 0; r < found.size() && rank == found.size(); ++r) {
      const double d = (std::max)(std::sin(angle_degrees(found[r].plane.orthogonal_vector(), mirror.orthogonal_vector()) * CGAL_PI / 180.),
                                  offset_between(unit_plane(found[r].plane), mirror, m.transform(midpoint)) / radius);
      if(d < o.tolerance / 100.) rank = r, deviation = d;
    }
    worst_rank = (std::max)(worst_rank, rank);
    worst_deviation = (std::max)(worst_deviation, deviation);
    const Point_3 center = ST::symmetry_frame(mesh).center;
    worst_center = (std::max)(worst_center, std::sqrt(CGAL::squared_distance(center, m.transform(midpoint))) / radius);
  }
  std::cout << "| " << name << " | " << distance << " | " << worst_rank << " | " << std::setprecision(2) << worst_deviation
            << " | " << worst_center << " |" << std::endl;
}

void print_mirrored_table(const Options& o)
{
  std::cout << "| mesh | distance of the copies (radii) | worst rank of the mirror (0 = strongest) | its worst "
               "deviation | frame centre from the midpoint (radii) |\n|---|---:|---:|---:|---:|\n";
  for(const std::string& name : o.mirrored) {
    Surface_mesh part;
    if(!CGAL::IO::read_polygon_mesh(bu::mesh_path(name), part) || faces(part).empty())
      throw std::invalid_argument("cannot read " + name);
    CGAL::Polygon_mesh_processing::triangulate_faces(part);
    for(double distance : o.distances) print_mirrored_row(name, part, distance, o);
  }
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const Options o = parse(argc, argv);
    if(!o.mirrored.empty()) {
      print_mirrored_table(o);
      return 0;
    }
    std::cout << "| shape | mirror planes | planes: found/true, worst angle (deg), false (above the weakest true), twice "
                 "| rotation axes | axes: found with the order/true, other order, worst angle, false (above), twice "
                 "| pencils of mirrors: found/true, worst angle | point group | named right |\n"
                 "|---|---:|---|---:|---|---|---|---:|\n";
    for(const std::string& family : o.families)
      for(const Group_shape& shape : shapes_of(family)) print_row(shape, o);
  } catch(const std::exception& e) {
    std::cerr << "symmetry_groups_experiment: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
