// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SHAPE_INPUT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SHAPE_INPUT_H

// Reading a mesh or a point set into plain double geometry, with the checks of the bad-input
// contract (DESIGN.md): every public entry point goes through here.

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/centroid.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Centre of mass and radius: the frame every grid and every plane offset is expressed in.
struct Shape_frame
{
  Dpoint center;
  double radius;
};

// The vertex point map of a mesh, from the named parameters: the one place where it is read.
template <typename TriangleMesh, typename NamedParameters>
typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type
vertex_point_map(const TriangleMesh& tm, const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, tm));
}

// The corners of the triangle of halfedge h.
template <typename TriangleMesh, typename VertexPointMap>
Dtriangle triangle_of_face(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm,
                           const VertexPointMap& vpm)
{
  return Dtriangle(to_dpoint(get(vpm, source(h, tm))), to_dpoint(get(vpm, target(h, tm))),
                   to_dpoint(get(vpm, target(next(h, tm), tm))));
}

// The triangles of a FaceListGraph, with degenerate ones (zero area) left out: they carry no
// surface. Throws on an empty mesh, a non-triangle face, a non-finite coordinate, or a mesh
// whose faces are all degenerate.
template <typename TriangleMesh, typename NamedParameters>
std::vector<Dtriangle> triangles_of_mesh(const TriangleMesh& tm, const NamedParameters& np)
{
  const auto vpm = vertex_point_map(tm, np);
  std::vector<Dtriangle> triangles;
  triangles.reserve(num_faces(tm)); // grown by doubling, a million triangles would hold 151 MB for 87
  std::size_t number_of_faces = 0;
  for(auto f : faces(tm)) {
    if(++number_of_faces % sequential_items_per_report == 0) poll_progress(); // a million faces take 0.2 s
    const auto h = halfedge(f, tm);
    if(!CGAL::is_triangle(h, tm))
      throw std::invalid_argument("Symmetry_transform: the mesh has a face that is not a triangle "
                                  "(triangulate it first, e.g. with "
                                  "CGAL::Polygon_mesh_processing::triangulate_faces)");
    const Dtriangle t = triangle_of_face(h, tm, vpm);
    if(t.squared_area() > 0.) triangles.push_back(t);
  }
  if(number_of_faces == 0) throw std::invalid_argument("Symmetry_transform: the mesh has no face");
  if(triangles.empty())
    throw std::invalid_argument("Symmetry_transform: all faces of the mesh are degenerate (zero area)");
  return triangles;
}

// The corner of a soup's triangle at index `i` of `points`; throws if `i` is out of range.
template <typename PointRange, typename PointMap>
Dpoint soup_corner(const PointRange& points, const PointMap& point_map, std::size_t i, std::size_t triangle)
{
  if(i >= std::size(points))
    throw std::invalid_argument("Symmetry_transform: triangle " + std::to_string(triangle) + " of the soup refers to point " +
                                std::to_string(i) + ", but the soup has " + std::to_string(std::size(points)) + " points");
  return to_dpoint(get(point_map, *(std::begin(points) + std::ptrdiff_t(i))));
}

// Every triangle of a soup (as CGAL::Polygon_mesh_processing::sample_triangle_soup() takes it: a
// random-access range of points, read through `point_map`, and a range of index triples), in its
// order, degenerate ones included. Throws on an index out of range, a polygon that is not a
// triangle, or a non-finite coordinate of a corner; points that no triangle uses are not read.
template <typename PointRange, typename TriangleRange, typename PointMap>
std::vector<Dtriangle> all_triangles_of_soup(const PointRange& points, const TriangleRange& triangles,
                                             const PointMap& point_map)
{
  std::vector<Dtriangle> result;
  typedef decltype(std::begin(triangles)) Triangle_iterator;
  if constexpr(std::is_convertible<typename std::iterator_traits<Triangle_iterator>::iterator_category,
                                   std::forward_iterator_tag>::value) // counted without being used up
    result.reserve(std::size_t(std::distance(std::begin(triangles), std::end(triangles))));
  for(const auto& triangle : triangles) {
    if(std::size(triangle) != 3)
      throw std::invalid_argument("Symmetry_transform: polygon " + std::to_string(result.size()) +
                                  " of the soup is not a triangle (triangulate it first)");
    auto corner = std::begin(triangle);
    Dpoint p[3];
    for(int i = 0; i < 3; ++i, ++corner) p[i] = soup_corner(points, point_map, std::size_t(*corner), result.size());
    result.emplace_back(p[0], p[1], p[2]);
  }
  return result;
}

// The triangles of a soup with the degenerate ones left out, as in triangles_of_mesh(). Throws
// on a soup with no triangle or only degenerate ones.
inline std::vector<Dtriangle> non_degenerate_triangles_of_soup(std::vector<Dtriangle> triangles)
{
  if(triangles.empty()) throw std::invalid_argument("Symmetry_transform: the soup has no triangle");
  triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                                 [](const Dtriangle& t) { return !(t.squared_area() > 0.); }),
                  triangles.end());
  if(triangles.empty())
    throw std::invalid_argument("Symmetry_transform: all triangles of the soup are degenerate (zero area)");
  return triangles;
}

// The non-degenerate triangles of a soup, its points read through the `point_map` of the named
// parameters (default: the identity). Nothing else needs a repair: orientation, duplicated or
// unreferenced points, non-manifold edges and components do not matter to a set of triangles.
// Throws as all_triangles_of_soup() and non_degenerate_triangles_of_soup().
template <typename PointRange, typename TriangleRange, typename NamedParameters>
std::vector<Dtriangle> triangles_of_soup(const PointRange& points, const TriangleRange& triangles, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  return non_degenerate_triangles_of_soup(all_triangles_of_soup(points, triangles, NP_helper::get_const_point_map(points, np)));
}

// Beyond this distance from the origin, in radii of the shape, a double coordinate is known to
// less than a millionth of the radius (2^-52 times the distance): the package's tolerances.
constexpr double farthest_center_in_radii = 1e-6 / 0x1p-52;

// The radii whose squares and cubes (areas times coordinates in the centroid, squared distances
// in voxels of 1/8 radius and less) are normal doubles, with margin: the sums of the package then
// hold no infinity, no NaN and no loss to denormals.
constexpr double smallest_radius = 1e-100;
constexpr double largest_radius = 1e100;

// `radius`: NaN where the sums that give the centre overflowed.
inline std::invalid_argument size_out_of_range(double radius)
{
  std::ostringstream message;
  message << "Symmetry_transform: the input's radius " << radius << " lies out of [" << smallest_radius << ", "
          << largest_radius << "], where the squares of its distances leave the range of doubles: scale it first";
  return std::invalid_argument(message.str());
}

inline void check_radius(double radius)
{
  if(!(radius > 0.))
    throw std::invalid_argument("Symmetry_transform: the input is a single point (zero radius)");
  if(!(radius >= smallest_radius && radius <= largest_radius)) throw size_out_of_range(radius);
}

// Refuses a shape so far from the origin for its size that its coordinates cannot hold the
// answer (DESIGN.md, invariance): it is said, never answered wrongly.
inline void check_frame(const Dpoint& center, double radius)
{
  if(!std::isfinite(center.x()) || !std::isfinite(center.y()) || !std::isfinite(center.z()))
    throw size_out_of_range(std::numeric_limits<double>::quiet_NaN());
  check_radius(radius);
  const double distance = std::sqrt((center - CGAL::ORIGIN).squared_length());
  if(distance > farthest_center_in_radii * radius)
    throw std::invalid_argument("Symmetry_transform: the input lies " + std::to_string(distance / radius) +
                                " radii from the origin, beyond the " + std::to_string(farthest_center_in_radii) +
                                " at which its coordinates hold a millionth of its radius: translate it nearer to "
                                "the origin first");
}

// Coordinates centred on the bounding box of the points that for_each_point(f) passes to f,
// checked as check_frame() does. The points are read where they are: a copy of the corners of a
// million triangles would take 80 MB and a tenth of a second.
template <typename ForEachPoint>
Local_coordinates local_coordinates_of_points(const Dpoint& first, const ForEachPoint& for_each_point)
{
  Bounding_box box(to_eigen(first));
  for_each_point([&](const Dpoint& p) { box.add(to_eigen(p)); });
  const Local_coordinates local{box.center()};
  double r2 = 0.;
  for_each_point([&](const Dpoint& p) { r2 = (std::max)(r2, local.to_local(to_eigen(p)).squaredNorm()); });
  check_frame(to_dpoint(local.center), std::sqrt(r2));
  return local;
}

// Those of `points`.
inline Local_coordinates local_coordinates_of(const std::vector<Dpoint>& points)
{
  return local_coordinates_of_points(points.front(), [&](const auto& f) {
    for(const Dpoint& p : points) f(p);
  });
}

// The same for the corners of `triangles`.
inline Local_coordinates local_coordinates_of(const std::vector<Dtriangle>& triangles)
{
  return local_coordinates_of_points(triangles.front()[0], [&](const auto& f) {
    for(const Dtriangle& t : triangles)
      for(int i = 0; i < 3; ++i) f(t[i]);
  });
}

// `shape` (points or triangles) in the coordinates `local`.
template <typename Item>
std::vector<Item> to_local(const Local_coordinates& local, std::vector<Item> shape)
{
  for(Item& item : shape) item = local.to_local(item);
  return shape;
}

// Area-weighted centroid of the surface and largest distance from it to a vertex.
inline Shape_frame frame_of_triangles(const std::vector<Dtriangle>& triangles)
{
  const Dpoint center = CGAL::centroid(triangles.begin(), triangles.end(), Dkernel(), CGAL::Dimension_tag<2>());
  double r2 = 0.;
  for(const Dtriangle& t : triangles)
    for(int i = 0; i < 3; ++i) r2 = (std::max)(r2, CGAL::squared_distance(center, t[i]));
  check_frame(center, std::sqrt(r2));
  return {center, std::sqrt(r2)};
}

// The points of a range, through a point map. Throws on an empty range or a non-finite coordinate.
template <typename PointRange, typename PointMap>
std::vector<Dpoint> points_of_range(const PointRange& points, const PointMap& point_map)
{
  std::vector<Dpoint> result;
  for(const auto& p : points) result.push_back(to_dpoint(get(point_map, p)));
  if(result.empty()) throw std::invalid_argument("Symmetry_transform: the point set is empty");
  return result;
}

// The unit normals of a range, through a normal map: a zero normal stays zero (no normal there).
// Throws on a non-finite coordinate.
template <typename PointRange, typename NormalMap>
std::vector<Eigen::Vector3d> unit_normals_of_range(const PointRange& points, const NormalMap& normal_map)
{
  std::vector<Eigen::Vector3d> result;
  for(const auto& p : points) {
    const auto n = get(normal_map, p);
    const Eigen::Vector3d v(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
    if(!v.allFinite()) throw std::invalid_argument("Symmetry_transform: the input has a NaN or infinite normal");
    result.push_back(v.squaredNorm() > 0. ? Eigen::Vector3d(v.normalized()) : v);
  }
  return result;
}

// Mean of the points and largest distance from it to a point.
inline Shape_frame frame_of_points(const std::vector<Dpoint>& points)
{
  const Dpoint center = CGAL::centroid(points.begin(), points.end(), Dkernel(), CGAL::Dimension_tag<0>());
  double r2 = 0.;
  for(const Dpoint& p : points) r2 = (std::max)(r2, CGAL::squared_distance(center, p));
  check_frame(center, std::sqrt(r2));
  return {center, std::sqrt(r2)};
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SHAPE_INPUT_H
