// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BATCH_SHAPE_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BATCH_SHAPE_H

// What the batch command does with one file: reads it (a mesh file as a repaired triangle soup, a
// point set with its normals if it has some), detects its principal symmetries, measures each
// plane's symmetry distance error, and returns the JSON Lines record of the file (see the
// manual, section "Real-World Input", for the fields); writes the SHREC 2023 result file if asked.
// A file that cannot be used gives a record with status "error" and the reason.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "input_files.h"
#include "json_lines.h"
#include "shape_extent.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace examples {
namespace batch {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

// The options of a run, the same for every shape: its results do not depend on the order or on
// the number of jobs.
struct Settings
{
  int resolution = 64;
  std::size_t max_planes = 10;
  std::size_t monte_carlo_samples = 500000; // the detection's default
  std::size_t sde_samples = 20000;          // the default of symmetry_distance_error()
  unsigned seed = 0;
  unsigned threads_per_shape = 1;
  std::string shrec_folder;                 // empty: no SHREC 2023 files
};

// A plane as the record gives it: unit normal n, offset (n.x = offset), the projection of the
// centre of mass on it, and its measures.
struct Plane_record
{
  K::Vector_3 normal;
  double offset;
  K::Point_3 point;
  double symmetry, support, sde;
};

// What a shape gives: the members of its record that depend on its kind, its planes.
struct Shape_result
{
  Json_object members;
  std::vector<Plane_record> planes;
};

template <typename SDE>
std::vector<Plane_record> plane_records(const std::vector<CGAL::Symmetry_transform::Principal_symmetry<K>>& symmetries,
                                        const K::Point_3& center, const SDE& sde)
{
  std::vector<Plane_record> planes;
  for(const auto& s : symmetries) {
    const K::Vector_3 n = s.plane.orthogonal_vector() / std::sqrt(s.plane.orthogonal_vector().squared_length());
    const double offset = -s.plane.d() / std::sqrt(s.plane.orthogonal_vector().squared_length());
    planes.push_back({n, offset, s.plane.projection(center), s.symmetry, s.support, sde(s.plane)});
  }
  return planes;
}

inline std::string json_of(const Plane_record& p)
{
  return Json_object()
    .add("normal", json_array({p.normal.x(), p.normal.y(), p.normal.z()}))
    .add("offset", json_number(p.offset))
    .add("point", json_array({p.point.x(), p.point.y(), p.point.z()}))
    .add("symmetry", json_number(p.symmetry, 6))
    .add("support", json_number(p.support, 6))
    .add("sde", json_number(p.sde, 6))
    .text();
}

template <typename NamedParameters>
Shape_result soup_result(const std::string& file, const Settings& settings, const NamedParameters& np)
{
  namespace ST = CGAL::Symmetry_transform;
  Soup_repairs repairs;
  const Triangle_soup<K::Point_3> soup = read_triangle_soup<K::Point_3>(file, repairs);
  const auto symmetries = ST::detect_principal_symmetries_of_triangle_soup(soup.points, soup.triangles, np);
  const auto sde_np = CGAL::parameters::number_of_points_on_faces(settings.sde_samples).random_seed(settings.seed)
                        .number_of_threads(settings.threads_per_shape);
  Shape_result r;
  r.planes = plane_records(symmetries, extent_of_soup(soup.points, soup.triangles).center, [&](const K::Plane_3& plane) {
    return ST::symmetry_distance_error_of_triangle_soup(soup.points, soup.triangles, plane, sde_np);
  });
  r.members.add("kind", json_string("mesh"))
    .add("points", std::to_string(repairs.read_points))
    .add("polygons", std::to_string(repairs.read_polygons))
    .add("triangles", std::to_string(soup.triangles.size()))
    .add("repairs", Json_object()
                      .add("merged_points", std::to_string(repairs.merged_points))
                      .add("removed_polygons", std::to_string(repairs.removed_polygons))
                      .add("removed_points", std::to_string(repairs.removed_points))
                      .add("triangulated_polygons", std::to_string(repairs.split_polygons))
                      .add("zero_area_triangles", std::to_string(repairs.zero_area_triangles))
                      .text());
  return r;
}

template <typename NamedParameters>
Shape_result point_set_result(const std::string& file, const Settings& settings, const NamedParameters& np)
{
  namespace ST = CGAL::Symmetry_transform;
  const std::vector<Point_with_normal> points =
    read_point_set<Point_with_normal>(file, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  const bool normals = std::any_of(points.begin(), points.end(), [](const auto& p) { return p.second != CGAL::NULL_VECTOR; });
  const auto with_points = np.point_map(Point_map());
  const auto symmetries = normals ? ST::detect_principal_symmetries_of_points(points, with_points.normal_map(Normal_map()))
                                  : ST::detect_principal_symmetries_of_points(points, with_points);
  const auto sde_np = CGAL::parameters::point_map(Point_map()).number_of_points_on_faces(settings.sde_samples)
                        .random_seed(settings.seed).number_of_threads(settings.threads_per_shape);
  Shape_result r;
  r.planes = plane_records(symmetries, extent_of_points(points, Point_map()).center, [&](const K::Plane_3& plane) {
    return ST::symmetry_distance_error_of_points(points, plane, sde_np);
  });
  r.members.add("kind", json_string("points"))
    .add("points", std::to_string(points.size()))
    .add("normals", normals ? "true" : "false");
  return r;
}

// Point set files by their extension; the others are read as polygons first, and as points if
// they have none (an OFF or PLY file of points).
inline bool is_point_set_file(const std::string& file)
{
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".xyz" || extension == ".pwn" || extension == ".las" || extension == ".laz";
}

template <typename NamedParameters>
Shape_result shape_result(const std::string& file, const Settings& settings, const NamedParameters& np)
{
  if(!std::filesystem::is_regular_file(file)) throw std::runtime_error("no such file");
  if(is_point_set_file(file)) return point_set_result(file, settings, np);
  try {
    return soup_result(file, settings, np);
  } catch(const No_polygon&) {
    return point_set_result(file, settings, np);
  }
}

// The SHREC 2023 result of a shape: the number of planes, then per plane "nx ny nz px py pz
// confidence" (the symmetry measure), in <folder>/<stem>-res.txt.
inline void write_shrec(const std::string& file, const std::vector<Plane_record>& planes, const Settings& settings)
{
  const std::filesystem::path out =
    std::filesystem::path(settings.shrec_folder) / (std::filesystem::path(file).stem().string() + "-res.txt");
  std::ofstream os(out);
  os.precision(9);
  os << planes.size() << "\n";
  for(const Plane_record& p : planes)
    os << p.normal.x() << ' ' << p.normal.y() << ' ' << p.normal.z() << ' ' << p.point.x() << ' ' << p.point.y() << ' '
       << p.point.z() << ' ' << p.symmetry << "\n";
  if(!os) throw std::runtime_error("cannot write " + out.string());
}

// The record of one file, one line of JSON without its end of line.
inline std::string shape_record(const std::string& file, const Settings& settings)
{
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const auto np = CGAL::parameters::grid_resolution(settings.resolution)
                    .max_number_of_planes(settings.max_planes)
                    .number_of_samples(settings.monte_carlo_samples)
                    .random_seed(settings.seed)
                    .number_of_threads(settings.threads_per_shape);
  Json_object record;
  record.add("file", json_string(file));
  std::vector<Plane_record> planes;
  try {
    Shape_result r = shape_result(file, settings, np);
    planes = r.planes;
    std::string list;
    for(const Plane_record& p : planes) list += (list.empty() ? "" : ",") + json_of(p);
    record.add("status", json_string("ok")).add("shape", r.members.text()).add("planes", "[" + list + "]");
  } catch(const std::bad_alloc&) {
    record.add("status", json_string("error")).add("reason", json_string("out of memory"));
  } catch(const std::exception& e) {
    record.add("status", json_string("error")).add("reason", json_string(e.what()));
  }
  if(!settings.shrec_folder.empty()) write_shrec(file, planes, settings);
  record.add("seconds", json_number(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 4))
    .add("cpu_seconds", json_number(double(std::clock() - cpu_start) / CLOCKS_PER_SEC, 4));
  return record.text();
}

} // namespace batch
} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_BATCH_SHAPE_H
