// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_INPUT_FILES_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_INPUT_FILES_H

// Reading the input of an example, with a message that says what went wrong and what to do:
// - any mesh file a user has (OFF, PLY, OBJ, STL), read as a polygon soup (web-sourced files
//   often are no valid polygon mesh: double-sided faces, duplicated vertices, non-manifold
//   edges, inconsistent orientation), repaired with CGAL's soup repair and its polygons
//   triangulated; the functions of the package take the soup as it is;
// - a polygon mesh made of that soup, for the algorithms that need a FaceListGraph (remeshing,
//   segmentation, descriptors) and for the PLY files the examples write;
// - a point set (XYZ, PWN, OFF, PLY, LAS), with its normals if the file has some.

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace examples {

// Throws if `filename` is no file, naming it. (The default file of an example, when none is
// given, is checked by Command_line_options::validate(), which says where it is looked for.)
inline void check_exists(const std::string& filename)
{
  if(std::filesystem::is_directory(filename)) throw std::runtime_error("'" + filename + "' is a folder, not a file");
  if(!std::filesystem::is_regular_file(filename)) throw std::runtime_error("no such file: '" + filename + "'");
}

// The error of a file that can be read but has no polygon: a point set, perhaps.
struct No_polygon : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A triangle soup as the functions `..._of_triangle_soup()` of the package take it.
template <typename Point>
struct Triangle_soup
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

// What reading a soup repaired, in the order it was done.
struct Soup_repairs
{
  std::size_t read_points = 0, read_polygons = 0; // as read from the file
  std::size_t merged_points = 0;       // duplicates of another point, merged into it
  std::size_t removed_polygons = 0;    // degenerate (repeated corners), or the copy of another (a double-sided face)
  std::size_t removed_points = 0;      // used by no polygon
  std::size_t split_polygons = 0;      // polygons of more than three corners, triangulated
  std::size_t zero_area_triangles = 0; // left in the soup: the package ignores them

  std::string text() const
  {
    std::ostringstream out;
    const char* separator = "";
    auto item = [&](std::size_t count, const char* what) {
      if(count == 0) return;
      out << separator << count << ' ' << what;
      separator = ", ";
    };
    item(merged_points, "duplicate points merged");
    item(removed_polygons, "degenerate or repeated polygons removed (a double-sided face keeps one side)");
    item(removed_points, "unused points removed");
    item(split_polygons, "polygons triangulated");
    item(zero_area_triangles, "zero-area triangles left (ignored)");
    return out.str().empty() ? std::string("nothing") : out.str();
  }
};

// Refuses coordinates that are not finite and indices out of range: no repair can use them.
template <typename Point, typename Polygons>
void check_soup(const std::string& filename, const std::vector<Point>& points, const Polygons& polygons)
{
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(CGAL::to_double(points[i].x())) || !std::isfinite(CGAL::to_double(points[i].y())) ||
       !std::isfinite(CGAL::to_double(points[i].z())))
      throw std::runtime_error("'" + filename + "': point " + std::to_string(i) + " has a NaN or infinite coordinate");
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      if(i >= points.size())
        throw std::runtime_error("'" + filename + "': a polygon refers to point " + std::to_string(i) + " of " +
                                 std::to_string(points.size()));
}

// The triangles of a polygon: those of CGAL's minimal-area triangulation of its boundary
// (non-convex polygons included), or a fan if it fails.
template <typename Point>
void add_triangles_of_polygon(const std::vector<Point>& points, const std::vector<std::size_t>& polygon,
                              std::vector<std::array<std::size_t, 3>>& triangles)
{
  if(polygon.size() == 3) {
    triangles.push_back({polygon[0], polygon[1], polygon[2]});
    return;
  }
  std::vector<Point> boundary;
  for(std::size_t i : polygon) boundary.push_back(points[i]);
  std::vector<CGAL::Triple<int, int, int>> patch;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(boundary, std::back_inserter(patch));
  if(patch.size() + 2 != polygon.size()) {
    patch.clear();
    for(int i = 1; i + 1 < int(polygon.size()); ++i) patch.emplace_back(0, i, i + 1);
  }
  for(const auto& t : patch)
    triangles.push_back({polygon[std::size_t(t.first)], polygon[std::size_t(t.second)], polygon[std::size_t(t.third)]});
}

// Reads any polygon file (OFF, PLY, OBJ or STL) as a soup, repairs it with CGAL's soup repair
// and triangulates its polygons; `repairs` receives what was done. Throws a std::runtime_error
// that says why on a file that cannot be used.
template <typename Point>
Triangle_soup<Point> read_triangle_soup(const std::string& filename, Soup_repairs& repairs)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  check_exists(filename);
  if(!CGAL::IO::read_polygon_soup(filename, points, polygons))
    throw std::runtime_error("cannot read polygons from '" + filename + "' (OFF, PLY, OBJ or STL)");
  if(polygons.empty())
    throw No_polygon("'" + filename + "' has no polygon (a point set? principal_symmetries_of_points reads those)");
  check_soup(filename, points, polygons);
  repairs = Soup_repairs{points.size(), polygons.size()};
  repairs.merged_points = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  const std::size_t merged_points = points.size();
  PMP::repair_polygon_soup(points, polygons); // also splits polygons that visit a point twice
  repairs.removed_polygons = repairs.read_polygons > polygons.size() ? repairs.read_polygons - polygons.size() : 0;
  repairs.removed_points = merged_points - points.size();
  Triangle_soup<Point> soup;
  for(const std::vector<std::size_t>& polygon : polygons) {
    if(polygon.size() > 3) ++repairs.split_polygons;
    add_triangles_of_polygon(points, polygon, soup.triangles);
  }
  for(const auto& t : soup.triangles) repairs.zero_area_triangles += CGAL::collinear(points[t[0]], points[t[1]], points[t[2]]);
  soup.points = std::move(points);
  if(soup.triangles.size() == repairs.zero_area_triangles)
    throw std::runtime_error("'" + filename + "': every polygon is degenerate (zero area)");
  return soup;
}

// The same, printing the size of the file and what was repaired unless `quiet`.
template <typename Point>
Triangle_soup<Point> read_triangle_soup(const std::string& filename, bool quiet = false)
{
  Soup_repairs repairs;
  Triangle_soup<Point> soup = read_triangle_soup<Point>(filename, repairs);
  if(!quiet)
    std::cout << filename << ": " << repairs.read_points << " points, " << repairs.read_polygons << " polygons; repaired: "
              << repairs.text() << "; " << soup.points.size() << " points, " << soup.triangles.size() << " triangles\n";
  return soup;
}

// A polygon mesh of the soup, whose face i is triangle i: its orientation made consistent and,
// where the soup is no surface (an edge of more than two triangles, a vertex whose triangles do
// not form one fan), points duplicated by CGAL::Polygon_mesh_processing::orient_polygon_soup().
template <typename Mesh, typename Point>
Mesh mesh_of_soup(Triangle_soup<Point> soup, bool quiet = false)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(!PMP::is_polygon_soup_a_polygon_mesh(soup.triangles)) {
    const std::size_t before = soup.points.size();
    PMP::orient_polygon_soup(soup.points, soup.triangles);
    if(!quiet)
      std::cout << "Made a polygon mesh of the soup: orientation made consistent, " << soup.points.size() - before
                << " points duplicated at non-manifold vertices and edges\n";
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(soup.triangles))
    throw std::runtime_error("cannot make a polygon mesh of the soup, even with its non-manifold points duplicated");
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, mesh);
  return mesh;
}

// For the examples that need a FaceListGraph: the repaired soup of the file, made a mesh.
template <typename Mesh>
Mesh read_triangle_mesh(const std::string& filename, bool quiet = false)
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  return mesh_of_soup<Mesh>(read_triangle_soup<Point>(filename, quiet), quiet);
}

// Reads a point set file (XYZ, PWN, OFF, PLY or LAS) into values of type `Value`, through the
// property maps of `np` (`point_map`, `normal_map`), as CGAL::IO::read_points() does.
template <typename Value, typename NamedParameters>
std::vector<Value> read_point_set(const std::string& filename, const NamedParameters& np)
{
  std::vector<Value> points;
  check_exists(filename);
  if(!CGAL::IO::read_points(filename, std::back_inserter(points), np) || points.empty())
    throw std::runtime_error("cannot read points from '" + filename + "' (XYZ, PWN, OFF, PLY or LAS)");
  return points;
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_INPUT_FILES_H
