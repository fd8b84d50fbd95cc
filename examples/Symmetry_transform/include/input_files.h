// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_INPUT_FILES_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_INPUT_FILES_H

// Reading the input of an example: a triangle mesh (the functions of the package take
// triangles, so polygons are split first) or a point set, with a message that says what went
// wrong and what to do.

#include <CGAL/IO/read_points.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace examples {

// Where CGAL's sample data comes from when no file is given.
inline const char* data_hint()
{
  return "with no file given, set CGAL_DATA_DIR to the folder of CGAL's sample data (package libcgal-demo)";
}

// Reads a polygon mesh (OFF, PLY, OBJ or STL) and triangulates its faces if needed; prints its
// size unless `quiet`.
template <typename Mesh>
Mesh read_triangle_mesh(const std::string& filename, bool quiet = false)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
    throw std::runtime_error("cannot read a polygon mesh from '" + filename + "' (OFF, PLY, OBJ or STL; " +
                             data_hint() + ")");
  if(!quiet) std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  if(!CGAL::is_triangle_mesh(mesh)) {
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw std::runtime_error("some faces of '" + filename + "' could not be triangulated");
    if(!quiet) std::cout << "Triangulated the polygons: " << num_faces(mesh) << " triangles\n";
  }
  return mesh;
}

// Reads a point set file (XYZ, PWN, OFF, PLY or LAS) into values of type `Value`, through the
// property maps of `np` (`point_map`, `normal_map`), as CGAL::IO::read_points() does.
template <typename Value, typename NamedParameters>
std::vector<Value> read_point_set(const std::string& filename, const NamedParameters& np)
{
  std::vector<Value> points;
  if(!CGAL::IO::read_points(filename, std::back_inserter(points), np) || points.empty())
    throw std::runtime_error("cannot read points from '" + filename + "' (XYZ, PWN, OFF, PLY or LAS; " +
                             data_hint() + ")");
  std::cout << filename << ": " << points.size() << " points\n";
  return points;
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_INPUT_FILES_H
