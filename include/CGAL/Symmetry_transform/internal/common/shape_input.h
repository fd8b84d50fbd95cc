// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SHAPE_INPUT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SHAPE_INPUT_H

// Reading a mesh or a point set into plain double geometry, with the checks of the bad-input
// contract (DESIGN.md): every public entry point goes through here.

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/centroid.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <stdexcept>
#include <string>
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
  std::size_t number_of_faces = 0;
  for(auto f : faces(tm)) {
    ++number_of_faces;
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

inline void check_radius(double radius)
{
  if(!(radius > 0.))
    throw std::invalid_argument("Symmetry_transform: the input is a single point (zero radius)");
}

// Area-weighted centroid of the surface and largest distance from it to a vertex.
inline Shape_frame frame_of_triangles(const std::vector<Dtriangle>& triangles)
{
  const Dpoint center = CGAL::centroid(triangles.begin(), triangles.end(), Dkernel(), CGAL::Dimension_tag<2>());
  double r2 = 0.;
  for(const Dtriangle& t : triangles)
    for(int i = 0; i < 3; ++i) r2 = (std::max)(r2, CGAL::squared_distance(center, t[i]));
  check_radius(std::sqrt(r2));
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

// Mean of the points and largest distance from it to a point.
inline Shape_frame frame_of_points(const std::vector<Dpoint>& points)
{
  const Dpoint center = CGAL::centroid(points.begin(), points.end(), Dkernel(), CGAL::Dimension_tag<0>());
  double r2 = 0.;
  for(const Dpoint& p : points) r2 = (std::max)(r2, CGAL::squared_distance(center, p));
  check_radius(std::sqrt(r2));
  return {center, std::sqrt(r2)};
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SHAPE_INPUT_H
