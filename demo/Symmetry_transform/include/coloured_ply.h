// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COLOURED_PLY_H
#define CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COLOURED_PLY_H

// Writing the results of the examples as PLY files that any mesh viewer opens: Surface_mesh's
// PLY writer stores a map "f:color" or "v:color" as red/green/blue/alpha, and the other maps of
// arithmetic type as scalar properties (for viewers that colour by a scalar).

#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace examples {

// `name` without a final ".ply": the prefix of the files of an example that writes several.
inline std::string without_ply_extension(std::string name)
{
  if(name.size() > 4 && name.compare(name.size() - 4, 4, ".ply") == 0) name.resize(name.size() - 4);
  return name;
}

template <typename Mesh>
void write_PLY(const std::string& file, const Mesh& mesh, const std::string& comment)
{
  if(!CGAL::IO::write_PLY(file, mesh, comment)) throw std::runtime_error("cannot write " + file);
}

// A copy of `mesh` whose faces carry the colours colour_of_face(f), in a map "f:color".
template <typename Point, typename FaceColour>
CGAL::Surface_mesh<Point> with_face_colours(const CGAL::Surface_mesh<Point>& mesh, const FaceColour& colour_of_face)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  Mesh coloured = mesh;
  auto colour = coloured.template add_property_map<typename Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(typename Mesh::Face_index f : faces(coloured)) colour[f] = colour_of_face(f);
  return coloured;
}

// Appends to a mesh with face colours the square of side `size` in `plane`, centred on the
// projection of `center`, as two triangles of colour `colour`.
template <typename Point, typename Plane>
void add_plane_square(CGAL::Surface_mesh<Point>& mesh, const Plane& plane, const Point& center, double size,
                      const CGAL::IO::Color& colour)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  const Point o = plane.projection(center);
  auto u = plane.base1(), v = plane.base2();
  u = u * (size / 2. / std::sqrt(u.squared_length()));
  v = v * (size / 2. / std::sqrt(v.squared_length()));
  const typename Mesh::Vertex_index a = mesh.add_vertex(o - u - v), b = mesh.add_vertex(o + u - v),
                                    c = mesh.add_vertex(o + u + v), d = mesh.add_vertex(o - u + v);
  auto face_colour = mesh.template add_property_map<typename Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(typename Mesh::Face_index f : {mesh.add_face(a, b, c), mesh.add_face(a, c, d)}) face_colour[f] = colour;
}

// Appends to a mesh with face colours the cylinder of radius `radius` along `axis`, from
// `half_length` before axis.point() to `half_length` after it, as 24 triangles of colour `colour`.
template <typename Point, typename Line>
void add_axis_cylinder(CGAL::Surface_mesh<Point>& mesh, const Line& axis, double half_length, double radius,
                       const CGAL::IO::Color& colour)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  const auto d = axis.to_vector() / std::sqrt(axis.to_vector().squared_length());
  auto u = axis.perpendicular_plane(CGAL::ORIGIN).base1();
  u = u / std::sqrt(u.squared_length());
  const auto v = CGAL::cross_product(d, u);
  constexpr int sides = 12;
  typename Mesh::Vertex_index ring[2][sides];
  for(int end = 0; end < 2; ++end)
    for(int i = 0; i < sides; ++i) {
      const double a = 2. * CGAL_PI * i / sides;
      ring[end][i] =
        mesh.add_vertex(axis.point() + (end ? half_length : -half_length) * d + radius * (std::cos(a) * u + std::sin(a) * v));
    }
  auto face_colour = mesh.template add_property_map<typename Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(int i = 0; i < sides; ++i) {
    const int j = (i + 1) % sides;
    face_colour[mesh.add_face(ring[0][i], ring[0][j], ring[1][j])] = colour;
    face_colour[mesh.add_face(ring[0][i], ring[1][j], ring[1][i])] = colour;
  }
}

} // namespace examples

#endif // CGAL_SYMMETRY_TRANSFORM_EXAMPLES_COLOURED_PLY_H
