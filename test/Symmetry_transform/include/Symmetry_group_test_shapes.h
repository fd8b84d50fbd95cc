// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Shapes built in code whose whole symmetry group is known: regular prisms and antiprisms, the
// five Platonic solids, boxes, flat regular polygons and rectangles. Their mirror planes and
// rotation axes are computed from their vertices (a polytope's symmetries are those of its
// vertex set), not written by hand.

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_GROUP_TEST_SHAPES_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_GROUP_TEST_SHAPES_H

#include "Symmetry_transform_test_shapes.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <cmath>
#include <string>
#include <vector>

namespace st_test {

typedef K::Line_3 Line_3;

// An axis of rotational symmetry of order `order` (the largest k with the turn by 2 pi / k).
struct Known_axis
{
  Line_3 axis;
  int order;
};

// A shape and its whole group of symmetries.
struct Group_shape
{
  std::string name;
  Surface_mesh mesh;
  std::vector<Plane_3> planes;   // the mirror planes that stand alone
  std::vector<Known_axis> axes;  // order 0: a continuous axis
  std::vector<Line_3> pencils;   // lines every plane through which is a mirror (a surface of revolution)
};

// Relative to the size of the vertex set: the points built here are exact to about 1e-15.
constexpr double group_tolerance = 1e-9;

inline double set_radius(const std::vector<Point_3>& points)
{
  double r = 0.;
  for(const Point_3& p : points) r = (std::max)(r, std::sqrt((p - CGAL::ORIGIN).squared_length()));
  return r;
}

// Whether `image` maps every point onto one of the points.
template <typename Image>
bool maps_onto_itself(const std::vector<Point_3>& points, const Image& image)
{
  const double tolerance = group_tolerance * (1. + set_radius(points));
  return std::all_of(points.begin(), points.end(), [&](const Point_3& p) {
    const Point_3 q = image(p);
    return std::any_of(points.begin(), points.end(),
                       [&](const Point_3& r) { return CGAL::squared_distance(q, r) < tolerance * tolerance; });
  });
}

inline bool same_known_plane(const Plane_3& a, const Plane_3& b)
{
  return angle_between(a, b) < 1e-6 && offset_between(a, b, CGAL::ORIGIN) < 1e-6;
}

// The mirror planes of a vertex set centred at the origin: each one that is not the plane of a
// flat set swaps two vertices, so it is the bisector of a pair.
inline std::vector<Plane_3> mirror_planes_of(const std::vector<Point_3>& points)
{
  std::vector<Plane_3> candidates, planes;
  for(std::size_t i = 0; i < points.size(); ++i)
    for(std::size_t j = i + 1; j < points.size(); ++j)
      candidates.push_back(unit_plane(Plane_3(CGAL::midpoint(points[i], points[j]), points[i] - points[j])));
  // The plane of a flat set, through three of its points that are not on a line.
  for(std::size_t k = 2; k < points.size(); ++k)
    if(!CGAL::collinear(points[0], points[1], points[k])) {
      const Plane_3 plane = unit_plane(Plane_3(points[0], points[1], points[k]));
      if(std::all_of(points.begin(), points.end(),
                     [&](const Point_3& p) { return std::abs(plane.a() * p.x() + plane.b() * p.y() + plane.c() * p.z() + plane.d()) < group_tolerance; }))
        candidates.push_back(plane);
      break;
    }
  for(const Plane_3& c : candidates)
    if(maps_onto_itself(points, [&](const Point_3& p) { return reflect(p, c); }) &&
       std::none_of(planes.begin(), planes.end(), [&](const Plane_3& p) { return same_known_plane(p, c); }))
      planes.push_back(c);
  return planes;
}

inline Point_3 turned(const Point_3& p, const Vector_3& unit_axis, double angle)
{
  // Rodrigues' formula about the axis through the origin.
  const Vector_3 v = p - CGAL::ORIGIN;
  const double c = std::cos(angle), s = std::sin(angle);
  return CGAL::ORIGIN + c * v + s * CGAL::cross_product(unit_axis, v) + (1. - c) * (unit_axis * v) * unit_axis;
}

// The rotation axes of a vertex set centred at the origin, with their orders up to `max_order`:
// an axis of a polytope passes through a vertex, the middle of an edge or the centre of a face,
// so the candidate directions are those of the vertices, of the middles of pairs and the normals
// of the faces of `mesh`.
inline std::vector<Known_axis> rotation_axes_of(const std::vector<Point_3>& points, const Surface_mesh& mesh,
                                                int max_order = 12)
{
  std::vector<Vector_3> directions;
  for(std::size_t i = 0; i < points.size(); ++i) {
    directions.push_back(points[i] - CGAL::ORIGIN);
    for(std::size_t j = i + 1; j < points.size(); ++j) directions.push_back(CGAL::midpoint(points[i], points[j]) - CGAL::ORIGIN);
  }
  for(auto f : faces(mesh)) directions.push_back(CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh));
  std::vector<Known_axis> axes;
  for(Vector_3 d : directions) {
    if(d.squared_length() < 1e-12) continue;
    d = d / std::sqrt(d.squared_length());
    const Line_3 line(CGAL::ORIGIN, d);
    if(std::any_of(axes.begin(), axes.end(), [&](const Known_axis& a) {
         return std::abs(std::abs(a.axis.to_vector() * d) / std::sqrt(a.axis.to_vector().squared_length()) - 1.) < 1e-9;
       }))
      continue;
    for(int k = max_order; k >= 2; --k)
      if(maps_onto_itself(points, [&](const Point_3& p) { return turned(p, d, 2. * CGAL_PI / double(k)); })) {
        axes.push_back({line, k});
        break;
      }
  }
  return axes;
}

inline Group_shape group_shape(const std::string& name, const std::vector<Point_3>& points, Surface_mesh mesh)
{
  Group_shape s{name, std::move(mesh), mirror_planes_of(points), {}, {}};
  s.axes = rotation_axes_of(points, s.mesh);
  return s;
}

inline Group_shape hull_shape(const std::string& name, const std::vector<Point_3>& points)
{
  Surface_mesh mesh;
  CGAL::convex_hull_3(points.begin(), points.end(), mesh);
  return group_shape(name, points, std::move(mesh));
}

// n points on the circle of radius r at height z, the first at angle `phase`.
inline std::vector<Point_3> regular_polygon(int n, double r, double z, double phase)
{
  std::vector<Point_3> points;
  for(int i = 0; i < n; ++i) {
    const double a = phase + 2. * CGAL_PI * double(i) / double(n);
    points.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
  return points;
}

// A regular n-gonal prism of circumradius 1 and height 1.3 (no cube for n = 4): group D_nh.
inline Group_shape regular_prism(int n)
{
  std::vector<Point_3> points = regular_polygon(n, 1., -0.65, 0.);
  for(const Point_3& p : regular_polygon(n, 1., 0.65, 0.)) points.push_back(p);
  return hull_shape("prism " + std::to_string(n), points);
}

// A regular n-gonal antiprism of circumradius 1 and height 0.9 (no octahedron for n = 3): D_nd.
inline Group_shape regular_antiprism(int n)
{
  std::vector<Point_3> points = regular_polygon(n, 1., -0.45, 0.);
  for(const Point_3& p : regular_polygon(n, 1., 0.45, CGAL_PI / double(n))) points.push_back(p);
  return hull_shape("antiprism " + std::to_string(n), points);
}

// The points (x, y, z) of `generators` with every change of signs (an even number of them only if
// `even_signs_only`), and their cyclic permutations if `cyclic`.
inline std::vector<Point_3> signed_cyclic(const std::vector<std::array<double, 3>>& generators, bool even_signs_only = false,
                                          bool cyclic = true)
{
  std::vector<Point_3> points;
  for(const auto& g : generators)
    for(int shift = 0; shift < (cyclic ? 3 : 1); ++shift)
      for(int s = 0; s < 8; ++s) {
        const int minus = (s & 1) + ((s >> 1) & 1) + ((s >> 2) & 1);
        if(even_signs_only && minus % 2 == 1) continue;
        double c[3];
        for(int i = 0; i < 3; ++i) c[i] = (s >> i & 1 ? -1. : 1.) * g[std::size_t((i + shift) % 3)];
        const Point_3 p(c[0], c[1], c[2]);
        if(std::none_of(points.begin(), points.end(), [&](const Point_3& q) { return CGAL::squared_distance(p, q) < 1e-20; }))
          points.push_back(p);
      }
  return points;
}

inline std::vector<Group_shape> platonic_solids()
{
  const double phi = (1. + std::sqrt(5.)) / 2.;
  return {hull_shape("tetrahedron", signed_cyclic({{1, 1, 1}}, true)),
          hull_shape("cube", signed_cyclic({{1, 1, 1}})),
          hull_shape("octahedron", signed_cyclic({{1, 0, 0}})),
          hull_shape("dodecahedron", signed_cyclic({{1, 1, 1}, {0, 1 / phi, phi}})),
          hull_shape("icosahedron", signed_cyclic({{0, 1, phi}}))};
}

// A box of half-sides a, b, c.
inline Group_shape box_shape(double a, double b, double c)
{
  auto text = [](double x) { return std::to_string(x).substr(0, 4); };
  return hull_shape("box " + text(a) + " " + text(b) + " " + text(c), signed_cyclic({{a, b, c}}, false, false));
}

// A flat regular n-gon of zero thickness: a fan of triangles about its centre.
inline Group_shape flat_polygon(int n)
{
  std::vector<Point_3> points = regular_polygon(n, 1., 0., 0.);
  points.push_back(CGAL::ORIGIN);
  std::vector<std::array<std::size_t, 3>> triangles;
  for(int i = 0; i < n; ++i) triangles.push_back({std::size_t(n), std::size_t(i), std::size_t((i + 1) % n)});
  Surface_mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return group_shape("flat " + std::to_string(n) + "-gon", points, std::move(mesh));
}

// A flat rectangle of zero thickness, 2 by 1.2, as a grid of 4 by 2 squares.
inline Group_shape flat_rectangle()
{
  std::vector<Point_3> points;
  for(int j = 0; j <= 2; ++j)
    for(int i = 0; i <= 4; ++i) points.emplace_back(-1. + 0.5 * i, -0.6 + 0.6 * j, 0.);
  std::vector<std::array<std::size_t, 3>> triangles;
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 4; ++i) {
      const std::size_t a = std::size_t(j * 5 + i), b = a + 1, c = a + 6, d = a + 5;
      // Diagonals mirrored across x = 0 and y = 0, so that the tessellation keeps the symmetries.
      if((i < 2) == (j < 1)) {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
      } else {
        triangles.push_back({a, b, d});
        triangles.push_back({b, c, d});
      }
    }
  Surface_mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return group_shape("flat rectangle", points, std::move(mesh));
}

// Segments about the z axis of the surfaces of revolution below: a 128-fold symmetry, which the
// rotation detection cannot tell from a continuous one.
constexpr int revolution_segments = 128;

// A closed surface of revolution about the z axis: the vertices `profile` (r, z), from a pole
// (r = 0) to a pole, turned in revolution_segments steps.
inline Surface_mesh revolution(const std::vector<std::array<double, 2>>& profile)
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> rings;
  for(const auto& [r, z] : profile) {
    rings.emplace_back();
    const int steps = r > 0. ? revolution_segments : 1;
    for(int i = 0; i < steps; ++i) {
      rings.back().push_back(points.size());
      const double a = 2. * CGAL_PI * double(i) / double(revolution_segments);
      points.emplace_back(r * std::cos(a), r * std::sin(a), z);
    }
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  for(std::size_t k = 0; k + 1 < rings.size(); ++k)
    for(int i = 0; i < revolution_segments; ++i) {
      const std::vector<std::size_t>&p = rings[k], &q = rings[k + 1];
      auto at = [](const std::vector<std::size_t>& ring, int j) { return ring[std::size_t(j) % ring.size()]; };
      if(p.size() > 1) triangles.push_back({at(p, i), at(p, i + 1), at(q, i)});
      if(q.size() > 1) triangles.push_back({at(p, i + 1), at(q, i + 1), at(q, i)});
    }
  Surface_mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

// A closed cylinder of radius 1 and height 1.6 about the z axis: its pencil of mirrors through
// the axis, its cross-section plane z = 0, its continuous axis (group D_inf_h).
inline Group_shape cylinder()
{
  const Line_3 z(CGAL::ORIGIN, Vector_3(0, 0, 1));
  return {"cylinder", revolution({{0., -0.8}, {1., -0.8}, {1., 0.8}, {0., 0.8}}), {Plane_3(0, 0, 1, 0)}, {{z, 0}}, {z}};
}

// A closed cone of base radius 1 and height 1.5 about the z axis: its pencil of mirrors and its
// continuous axis (C_inf_v).
inline Group_shape cone()
{
  const Line_3 z(CGAL::ORIGIN, Vector_3(0, 0, 1));
  return {"cone", revolution({{0., -0.5}, {1., -0.5}, {0., 1.}}), {}, {{z, 0}}, {z}};
}

// `part` and its mirror image across a plane of normal x, their centres `distance` apart (in
// radii of `part`, from its centre of area); the one plane is that mirror.
inline Shape<Surface_mesh> mirrored_copies(const Surface_mesh& part, double distance)
{
  const Center_and_radius frame = center_and_radius(part);
  const Plane_3 mirror(1., 0., 0., -(frame.center.x() + 0.5 * distance * frame.radius));
  Shape<Surface_mesh> s;
  s.mesh = part;
  Surface_mesh image = part;
  for(auto v : vertices(image)) image.point(v) = reflect(image.point(v), mirror);
  CGAL::Polygon_mesh_processing::reverse_face_orientations(image);
  s.mesh.join(image);
  s.planes = {mirror};
  return s;
}

// Two unit cubes whose centres lie `distance` apart along x: the group of a square prism (D4h),
// its five mirrors (the bisector among them), its four-fold axis through the centres and four
// two-fold axes in the bisector.
inline Group_shape cubes_apart(double distance)
{
  const Group_shape cube = box_shape(0.5, 0.5, 0.5);
  Surface_mesh mesh = cube.mesh, copy = cube.mesh;
  for(auto v : vertices(copy)) copy.point(v) = copy.point(v) + Vector_3(distance, 0., 0.);
  mesh.join(copy);
  const Point_3 middle(0.5 * distance, 0., 0.);
  std::vector<Known_axis> axes = {{Line_3(middle, Vector_3(1, 0, 0)), 4}};
  for(const Vector_3& d : {Vector_3(0, 1, 0), Vector_3(0, 0, 1), Vector_3(0, 1, 1), Vector_3(0, 1, -1)})
    axes.push_back({Line_3(middle, d), 2});
  return {"two cubes 1e4 apart", std::move(mesh),
          {Plane_3(1, 0, 0, -middle.x()), Plane_3(0, 1, 0, 0), Plane_3(0, 0, 1, 0), unit_plane(Plane_3(0, 1, 1, 0)),
           unit_plane(Plane_3(0, 1, -1, 0))},
          std::move(axes),
          {}};
}

} // namespace st_test

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_GROUP_TEST_SHAPES_H
