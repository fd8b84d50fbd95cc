// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Shapes built in code whose symmetries are known by construction, seeded random similarity
// transformations (rotation, translation, uniform scale) that move a shape together with its
// planes and centre of symmetry, and the few helpers the test suites share.

#ifndef CGAL_SYMMETRY_TRANSFORM_TEST_SHAPES_H
#define CGAL_SYMMETRY_TRANSFORM_TEST_SHAPES_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Random.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/convex_hull_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace st_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef K::Plane_3 Plane_3;
typedef K::Aff_transformation_3 Motion;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef CGAL::Symmetry_transform::Voxel_grid<K> Grid;

// A triangle mesh and the symmetries it has by construction.
template <typename Mesh>
struct Shape
{
  Mesh mesh;
  std::vector<Plane_3> planes;   // planes of reflective symmetry, unit normals
  std::optional<Point_3> center; // centre of point symmetry, if any
};

inline Plane_3 unit_plane(const Plane_3& p)
{
  const double l = std::sqrt(CGAL::square(p.a()) + CGAL::square(p.b()) + CGAL::square(p.c()));
  return Plane_3(p.a() / l, p.b() / l, p.c() / l, p.d() / l);
}

inline Vector_3 unit_normal(const Plane_3& p)
{
  return unit_plane(p).orthogonal_vector();
}

inline Point_3 reflect(const Point_3& x, const Plane_3& plane)
{
  const Plane_3 p = unit_plane(plane);
  const double s = p.a() * x.x() + p.b() * x.y() + p.c() * x.z() + p.d();
  return x - 2. * s * p.orthogonal_vector();
}

// The plane through `center` (a point of `plane`) obtained by rotating `plane` by `degrees`
// about the axis `axis` (a vector of the plane).
inline Plane_3 rotated_plane(const Plane_3& plane, const Point_3& center, Vector_3 axis, double degrees)
{
  axis = axis / std::sqrt(axis.squared_length());
  const Vector_3 n = unit_normal(plane), m = CGAL::cross_product(axis, n);
  const double a = degrees * CGAL_PI / 180.;
  return Plane_3(center, std::cos(a) * n + std::sin(a) * m);
}

// Two unit vectors spanning `plane`.
inline std::array<Vector_3, 2> in_plane_axes(const Plane_3& plane)
{
  Vector_3 u = unit_plane(plane).base1(), v = unit_plane(plane).base2();
  return {u / std::sqrt(u.squared_length()), v / std::sqrt(v.squared_length())};
}

// ---------------------------------------------------------------------------------------------
// Shapes, centred on the origin (the hulls: their symmetry elements through the origin).
// ---------------------------------------------------------------------------------------------

inline std::vector<Plane_3> coordinate_planes()
{
  return {Plane_3(1, 0, 0, 0), Plane_3(0, 1, 0, 0), Plane_3(0, 0, 1, 0)};
}

// Box [-a,a]x[-b,b]x[-c,c], triangulated: three planes of symmetry (a, b, c different) and a centre.
template <typename Mesh>
Shape<Mesh> box(double a = 1., double b = 0.7, double c = 0.45)
{
  Shape<Mesh> s;
  CGAL::make_hexahedron(Point_3(-a, -b, -c), Point_3(a, -b, -c), Point_3(a, b, -c), Point_3(-a, b, -c),
                        Point_3(-a, b, c), Point_3(-a, -b, c), Point_3(a, -b, c), Point_3(a, b, c), s.mesh);
  CGAL::Polygon_mesh_processing::triangulate_faces(s.mesh);
  s.planes = coordinate_planes();
  s.center = CGAL::ORIGIN;
  return s;
}

// Ellipsoid of half-axes a, b, c: an icosahedron Loop-subdivided, projected to the unit sphere
// and scaled. The icosahedron of make_icosahedron is symmetric about the coordinate planes.
template <typename Mesh>
Shape<Mesh> ellipsoid(double a = 1., double b = 0.6, double c = 0.35, int subdivisions = 3)
{
  Shape<Mesh> s;
  CGAL::make_icosahedron(s.mesh, Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(s.mesh, CGAL::parameters::number_of_iterations(subdivisions));
  auto vpm = get(CGAL::vertex_point, s.mesh);
  for(auto v : vertices(s.mesh)) {
    const Point_3 p = get(vpm, v);
    const double l = std::sqrt(CGAL::square(p.x()) + CGAL::square(p.y()) + CGAL::square(p.z()));
    put(vpm, v, Point_3(a * p.x() / l, b * p.y() / l, c * p.z() / l));
  }
  s.planes = coordinate_planes();
  s.center = CGAL::ORIGIN;
  return s;
}

// Convex hull of `points` and of their images.
template <typename Mesh>
Mesh hull_with_images(std::vector<Point_3> points, const std::function<Point_3(const Point_3&)>& image)
{
  const std::size_t count = points.size();
  for(std::size_t i = 0; i < count; ++i) points.push_back(image(points[i]));
  Mesh mesh;
  CGAL::convex_hull_3(points.begin(), points.end(), mesh);
  return mesh;
}

// Exactly one plane of symmetry, `plane`: the hull of 40 random points in a wedge (its height
// falls along y, so no plane y = const or z = const is a symmetry) and their mirror images.
template <typename Mesh>
Shape<Mesh> one_plane_hull(unsigned seed = 1, const Plane_3& plane = Plane_3(1, 0, 0, 0))
{
  CGAL::Random rng(seed);
  std::vector<Point_3> points;
  for(int i = 0; i < 40; ++i) {
    const double y = rng.get_double(-1., 1.);
    points.emplace_back(rng.get_double(0., 0.7), y, rng.get_double(0., 0.1 + 0.45 * (1. - y)));
  }
  Shape<Mesh> s;
  s.mesh = hull_with_images<Mesh>(points, [&](const Point_3& p) { return reflect(p, plane); });
  s.planes = {unit_plane(plane)};
  return s;
}

// A centre of symmetry, the origin, and no plane of symmetry: the hull of 40 random points in
// a skewed parallelepiped and their point reflections.
template <typename Mesh>
Shape<Mesh> centrally_symmetric_hull(unsigned seed = 2)
{
  CGAL::Random rng(seed);
  const Vector_3 e[3] = {Vector_3(1, 0, 0), Vector_3(0.5, 0.7, 0), Vector_3(0.3, -0.2, 0.5)};
  std::vector<Point_3> points;
  for(int i = 0; i < 40; ++i)
    points.push_back(CGAL::ORIGIN + rng.get_double(-1., 1.) * e[0] + rng.get_double(-1., 1.) * e[1] +
                     rng.get_double(-1., 1.) * e[2]);
  Shape<Mesh> s;
  s.mesh = hull_with_images<Mesh>(points, [](const Point_3& p) { return CGAL::ORIGIN - (p - CGAL::ORIGIN); });
  s.center = CGAL::ORIGIN;
  return s;
}

// `mesh` becomes the mesh of a triangle soup, each face starting at the first corner of its
// triangle (a Polyhedron_3 may start its faces at other halfedges, and so may copy_face_graph):
// the surface samples, drawn triangle by triangle from the first corner, are then the same for
// every mesh type.
template <typename Mesh>
void mesh_from_triangle_soup(const std::vector<Point_3>& points, const std::vector<std::array<std::size_t, 3>>& triangles,
                             Mesh& mesh)
{
  CGAL::clear(mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  std::size_t i = 0;
  for(auto f : faces(mesh)) {
    const Point_3& first = points[triangles[i++][0]];
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      if(get(CGAL::vertex_point, mesh, source(h, mesh)) == first) {
        set_halfedge(f, h, mesh);
        break;
      }
  }
}

// `mesh` rebuilt with its vertices and faces in lexicographic order, each face starting at its
// smallest vertex. convex_hull_3 (CGAL 5.5) orders its output through a std::map keyed by vertex
// handles, i.e. by heap addresses: the same points can give the faces in another order from one
// run to the next, and with them other surface samples.
template <typename Mesh>
void make_canonical(Mesh& mesh)
{
  std::vector<std::array<Point_3, 3>> triangles;
  for(auto f : faces(mesh)) {
    std::array<Point_3, 3> t;
    auto h = halfedge(f, mesh);
    for(Point_3& p : t) {
      p = get(CGAL::vertex_point, mesh, source(h, mesh));
      h = next(h, mesh);
    }
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  std::vector<Point_3> points;
  for(const auto& t : triangles) points.insert(points.end(), t.begin(), t.end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::vector<std::array<std::size_t, 3>> polygons;
  for(const auto& t : triangles) {
    std::array<std::size_t, 3> polygon;
    for(int i = 0; i < 3; ++i)
      polygon[i] = std::size_t(std::lower_bound(points.begin(), points.end(), t[i]) - points.begin());
    polygons.push_back(polygon);
  }
  CGAL::clear(mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
}

// No symmetry at all: the convex hull of `count` random points in the cube [-1,1]^3 (in a
// canonical order, see make_canonical).
template <typename Mesh>
Shape<Mesh> random_hull(unsigned seed = 3, int count = 30)
{
  CGAL::Random rng(seed);
  std::vector<Point_3> points;
  for(int i = 0; i < count; ++i)
    points.emplace_back(rng.get_double(-1., 1.), rng.get_double(-1., 1.), rng.get_double(-1., 1.));
  Shape<Mesh> s;
  CGAL::convex_hull_3(points.begin(), points.end(), s.mesh);
  make_canonical(s.mesh);
  return s;
}

// The disjoint union of two shapes in one mesh, with the planes of both.
template <typename Mesh>
Shape<Mesh> merged(const Shape<Mesh>& a, const Shape<Mesh>& b)
{
  Shape<Mesh> s = a;
  CGAL::copy_face_graph(b.mesh, s.mesh);
  s.planes.insert(s.planes.end(), b.planes.begin(), b.planes.end());
  s.center.reset();
  return s;
}

// `count` points uniformly distributed on the surface of a triangle mesh, drawn from `rng` alone.
// (CGAL 5.5's Random_points_in_triangle_mesh_3 picks the triangle with the given generator but
// the point in it with CGAL::get_default_random(), whose state depends on what ran before.)
template <typename Mesh>
std::vector<Point_3> surface_points(const Mesh& mesh, std::size_t count, CGAL::Random& rng)
{
  std::vector<std::array<Point_3, 3>> triangles;
  std::vector<double> cumulative_area;
  double total = 0.;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    triangles.push_back({get(CGAL::vertex_point, mesh, source(h, mesh)), get(CGAL::vertex_point, mesh, target(h, mesh)),
                         get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh))});
    const auto& t = triangles.back();
    cumulative_area.push_back(total += std::sqrt(CGAL::squared_area(t[0], t[1], t[2])));
  }
  std::vector<Point_3> points;
  for(std::size_t i = 0; i < count; ++i) {
    const std::size_t f = std::size_t(
      std::upper_bound(cumulative_area.begin(), cumulative_area.end() - 1, rng.get_double(0., total)) -
      cumulative_area.begin());
    double u = rng.get_double(), v = rng.get_double();
    if(u + v > 1.) {
      u = 1. - u;
      v = 1. - v;
    }
    const auto& t = triangles[f];
    points.push_back(t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]));
  }
  return points;
}

// ---------------------------------------------------------------------------------------------
// Perturbations.
// ---------------------------------------------------------------------------------------------

// A standard normal deviate from `rng` (Box-Muller: the same sequence on every platform,
// unlike std::normal_distribution).
inline double gaussian(CGAL::Random& rng)
{
  const double u = 1. - rng.get_double(), v = rng.get_double(); // u in (0, 1]
  return std::sqrt(-2. * std::log(u)) * std::cos(2. * CGAL_PI * v);
}

// Every vertex moved by an isotropic Gaussian of standard deviation `sigma` per coordinate.
template <typename Mesh>
void add_vertex_noise(Mesh& mesh, double sigma, CGAL::Random& rng)
{
  auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh)) {
    const Point_3 p = get(vpm, v);
    put(vpm, v, Point_3(p.x() + sigma * gaussian(rng), p.y() + sigma * gaussian(rng), p.z() + sigma * gaussian(rng)));
  }
}

// The mesh with the part on the positive side of the plane through `normal` (not necessarily
// unit) that leaves `fraction` of the area there cut away (faces split along the plane, the
// cut left open); the offset of the plane is found by bisection.
template <typename Mesh>
Mesh cut_away(const Mesh& mesh, const Vector_3& normal, double fraction)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Vector_3 n = normal / std::sqrt(normal.squared_length());
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for(auto v : vertices(mesh)) {
    const double h = (get(CGAL::vertex_point, mesh, v) - CGAL::ORIGIN) * n;
    lo = (std::min)(lo, h);
    hi = (std::max)(hi, h);
  }
  const double total = PMP::area(mesh);
  Mesh kept;
  for(int step = 0; step < 40; ++step) { // the kept area grows with the offset
    const double offset = 0.5 * (lo + hi);
    kept = mesh;
    PMP::clip(kept, Plane_3(n.x(), n.y(), n.z(), -offset));
    (PMP::area(kept) < (1. - fraction) * total ? lo : hi) = offset;
  }
  return kept;
}

// ---------------------------------------------------------------------------------------------
// Comparisons of planes.
// ---------------------------------------------------------------------------------------------

// Area-weighted centroid of a triangle mesh and the largest distance from it to a vertex: the
// centre and radius of the package (DESIGN.md), computed independently.
struct Center_and_radius
{
  Point_3 center;
  double radius;
};

template <typename Mesh>
Center_and_radius center_and_radius(const Mesh& mesh)
{
  const auto vpm = get(CGAL::vertex_point, mesh);
  double area = 0.;
  Vector_3 sum(0, 0, 0);
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const Point_3 a = get(vpm, source(h, mesh)), b = get(vpm, target(h, mesh)), c = get(vpm, target(next(h, mesh), mesh));
    const double w = std::sqrt(CGAL::squared_area(a, b, c));
    area += w;
    sum = sum + w * (CGAL::centroid(a, b, c) - CGAL::ORIGIN);
  }
  const Point_3 center = CGAL::ORIGIN + sum / area;
  double r2 = 0.;
  for(auto v : vertices(mesh)) r2 = (std::max)(r2, CGAL::squared_distance(center, get(vpm, v)));
  return {center, std::sqrt(r2)};
}

// Angle in degrees between the normals of two planes, up to orientation: in [0, 90].
inline double angle_between(const Plane_3& a, const Plane_3& b)
{
  const double c = std::abs(unit_normal(a) * unit_normal(b));
  const Vector_3 s = CGAL::cross_product(unit_normal(a), unit_normal(b));
  return std::atan2(std::sqrt(s.squared_length()), c) * 180. / CGAL_PI;
}

// Difference of the signed distances from `center` to two planes, the second plane oriented
// as the first: how far apart the planes are near `center`.
inline double offset_between(const Plane_3& a, const Plane_3& b, const Point_3& center)
{
  const Plane_3 ua = unit_plane(a), ub = unit_plane(b);
  const double sign = ua.orthogonal_vector() * ub.orthogonal_vector() < 0. ? -1. : 1.;
  const auto height = [&](const Plane_3& p) { return p.a() * center.x() + p.b() * center.y() + p.c() * center.z() + p.d(); };
  return std::abs(height(ua) - sign * height(ub));
}

// ---------------------------------------------------------------------------------------------
// Similarity transformations.
// ---------------------------------------------------------------------------------------------

// x -> scale * R x + t, with R from a random unit quaternion (uniform on the 3-sphere, by
// rejection), t in [-3,3]^3 and scale in [0.5, 2] (or the given ones).
inline Motion random_motion(CGAL::Random& rng, bool rotate = true, bool translate = true, bool scale = true)
{
  double q[4], l2 = 0.;
  do {
    l2 = 0.;
    for(double& c : q) l2 += CGAL::square(c = rng.get_double(-1., 1.));
  } while(l2 > 1. || l2 < 1e-2);
  for(double& c : q) c /= std::sqrt(l2);
  const double w = rotate ? q[0] : 1., x = rotate ? q[1] : 0., y = rotate ? q[2] : 0., z = rotate ? q[3] : 0.;
  const double s = scale ? rng.get_double(0.5, 2.) : 1.;
  double t[3];
  for(double& c : t) c = translate ? rng.get_double(-3., 3.) : 0.;
  return Motion(s * (1 - 2 * (y * y + z * z)), s * 2 * (x * y - w * z), s * 2 * (x * z + w * y), t[0],
                s * 2 * (x * y + w * z), s * (1 - 2 * (x * x + z * z)), s * 2 * (y * z - w * x), t[1],
                s * 2 * (x * z - w * y), s * 2 * (y * z + w * x), s * (1 - 2 * (x * x + y * y)), t[2]);
}

// A plane moved by a similarity, with a unit normal.
inline Plane_3 moved(const Plane_3& plane, const Motion& m)
{
  return unit_plane(Plane_3(m.transform(plane.point()), m.transform(plane.orthogonal_vector())));
}

template <typename Mesh>
Shape<Mesh> moved(Shape<Mesh> s, const Motion& m)
{
  CGAL::Polygon_mesh_processing::transform(m, s.mesh);
  for(Plane_3& p : s.planes) p = moved(p, m);
  if(s.center) s.center = m.transform(*s.center);
  return s;
}

// ---------------------------------------------------------------------------------------------
// Helpers shared by the suites.
// ---------------------------------------------------------------------------------------------

// Success if `f()` throws an `Exception` whose message contains `part`.
template <typename Exception, typename F>
::testing::AssertionResult throws_with_message(const F& f, const std::string& part)
{
  try {
    f();
  } catch(const Exception& e) {
    if(std::string(e.what()).find(part) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the message \"" << e.what() << "\" does not contain \"" << part << "\"";
  } catch(const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception type: " << e.what();
  }
  return ::testing::AssertionFailure() << "did not throw";
}

inline double sum_of_squares(const std::vector<double>& v)
{
  double s = 0.;
  for(double x : v) s += x * x;
  return s;
}

inline double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b)
{
  double m = 0.;
  for(std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// ||a - b|| / ||b||.
inline double relative_l2_error(const std::vector<double>& a, const std::vector<double>& b)
{
  double e = 0.;
  for(std::size_t i = 0; i < a.size(); ++i) e += CGAL::square(a[i] - b[i]);
  return std::sqrt(e / sum_of_squares(b));
}

} // namespace st_test

#endif // CGAL_SYMMETRY_TRANSFORM_TEST_SHAPES_H
