// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_SHAPE_EXTENT_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_SHAPE_EXTENT_H

// Where a shape is and how large, to place what an example draws beside it (a plane's square, a
// score sphere): its centre of mass and radius, as the package defines them (the area-weighted
// centroid of the triangles of a mesh, the mean of a point set; the largest distance from there
// to the shape).

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <cmath>

namespace examples {

template <typename Point>
struct Extent
{
  Point center;
  double radius;
};

template <typename Point>
Extent<Point> extent_of(const CGAL::Surface_mesh<Point>& mesh)
{
  typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 sum = CGAL::NULL_VECTOR;
  double area = 0.;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const Point centroid = CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                          mesh.point(target(next(h, mesh), mesh)));
    sum = sum + CGAL::Polygon_mesh_processing::face_area(f, mesh) * (centroid - CGAL::ORIGIN);
    area += CGAL::Polygon_mesh_processing::face_area(f, mesh);
  }
  Extent<Point> extent{CGAL::ORIGIN + sum / area, 0.};
  for(auto v : vertices(mesh))
    extent.radius = std::max(extent.radius, std::sqrt(CGAL::squared_distance(extent.center, mesh.point(v))));
  return extent;
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
