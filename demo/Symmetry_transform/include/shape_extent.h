// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_SHAPE_EXTENT_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_SHAPE_EXTENT_H

// Where a shape is and how large, to place what an example draws beside it (a plane's square, a
// score sphere): its centre of mass and radius, as the package defines them (the area-weighted
// centroid of the triangles of a mesh or a soup, the mean of a point set; the largest distance
// from there to the shape).

#include <CGAL/Surface_mesh.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace examples {

template <typename Point>
struct Extent
{
  Point center;
  double radius;
};

// The extent of a triangle soup: its area-weighted centroid and the largest distance from there
// to a corner of a triangle.
template <typename Point>
Extent<Point> extent_of_soup(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3>>& triangles)
{
  typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 sum = CGAL::NULL_VECTOR;
  double area = 0.;
  for(const auto& t : triangles) {
    const double a = std::sqrt(CGAL::squared_area(points[t[0]], points[t[1]], points[t[2]]));
    sum = sum + a * (CGAL::centroid(points[t[0]], points[t[1]], points[t[2]]) - CGAL::ORIGIN);
    area += a;
  }
  Extent<Point> extent{CGAL::ORIGIN + sum / area, 0.};
  for(const auto& t : triangles)
    for(std::size_t i : t) extent.radius = std::max(extent.radius, std::sqrt(CGAL::squared_distance(extent.center, points[i])));
  return extent;
}

// The same for a mesh, through the soup of its faces.
template <typename Point>
Extent<Point> extent_of(const CGAL::Surface_mesh<Point>& mesh)
{
  std::vector<Point> points(mesh.points().begin(), mesh.points().end());
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    triangles.push_back({std::size_t(source(h, mesh)), std::size_t(target(h, mesh)), std::size_t(target(next(h, mesh), mesh))});
  }
  return extent_of_soup(points, triangles);
}

// The same for a point set: the mean of the points, and the largest distance from it to a point.
template <typename PointRange, typename PointMap>
auto extent_of_points(const PointRange& points, const PointMap& point_map)
{
  typedef typename boost::property_traits<PointMap>::value_type Point;
  typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 sum = CGAL::NULL_VECTOR;
  for(const auto& p : points) sum = sum + (get(point_map, p) - CGAL::ORIGIN);
  Extent<Point> extent{CGAL::ORIGIN + sum / double(points.size()), 0.};
  for(const auto& p : points)
    extent.radius = std::max(extent.radius, std::sqrt(CGAL::squared_distance(extent.center, get(point_map, p))));
  return extent;
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_SHAPE_EXTENT_H
