// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Symmetrization: meshes symmetric by construction (tessellation included) perturbed on one side
// (vertex noise, a smooth bump, a smooth warp) and moved at random become symmetric to 1e-6 of
// the diagonal under their detected plane, a cube under its nine planes, a propeller under its
// axis; the displacement is the least possible (the orthogonal projection onto the symmetric
// positions: a mirror pair meets halfway); faces keep their orientation and no self-intersection
// appears; a mesh whose vertices are not paired becomes far more symmetric; results move with
// the mesh, do not depend on the threads, agree on Surface_mesh and Polyhedron_3; a cancel leaves
// the mesh; bad input is rejected.

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetrization.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "Rotational_symmetry_test_shapes.h"
#include "Symmetry_transform_test_shapes.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Symmetry_transform/internal/common/cgal_aabb.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <boost/property_map/function_property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef ST::Rotational_symmetry<K> Rotation;
template <typename Mesh>
using Tree = CGAL::AABB_tree<ST::internal::AABB_traits_3<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

enum class Perturbation { noise, bump, warp };

// Moves the vertices on the positive side of `plane` (unit normal): Gaussian noise of 0.5 % of
// the radius (root mean square length), a bump of 1 % along the direction from the centre, or a
// warp of 0.5 % by a field of sines of random directions. Returns the displacement of each vertex.
template <typename Mesh>
std::vector<Vector_3> perturb_one_side(Mesh& mesh, const Plane_3& plane, Perturbation kind, CGAL::Random& rng,
                                       double scale = 1.)
{
  const auto [center, radius] = center_and_radius(mesh);
  const Vector_3 n = unit_normal(plane);
  std::vector<Vector_3> waves;
  for(int i = 0; i < 3; ++i) waves.emplace_back(rng.get_double(-2, 2), rng.get_double(-2, 2), rng.get_double(-2, 2));
  Point_3 peak = center;
  auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh))
    if((get(vpm, v) - center) * n > (peak - center) * n) peak = get(vpm, v);
  std::vector<Vector_3> moves;
  for(auto v : vertices(mesh)) {
    const Point_3 p = get(vpm, v);
    Vector_3 d(0, 0, 0);
    if(plane.oriented_side(p) == CGAL::ON_POSITIVE_SIDE && std::abs((p - plane.point()) * n) > 1e-9 * radius) {
      const Vector_3 r = (p - center) / radius;
      if(kind == Perturbation::noise)
        d = 0.005 * radius / std::sqrt(3.) * Vector_3(gaussian(rng), gaussian(rng), gaussian(rng));
      else if(kind == Perturbation::bump)
        d = 0.01 * radius * std::exp(-(p - peak).squared_length() / CGAL::square(0.4 * radius)) * r / std::sqrt(r * r);
      else
        d = 0.005 * radius * Vector_3(std::sin(waves[0] * r + 0.3), std::sin(waves[1] * r + 1.1), std::sin(waves[2] * r));
    }
    put(vpm, v, p + scale * d);
    moves.push_back(scale * d);
  }
  return moves;
}

template <typename Mesh>
std::vector<Point_3> points_of(const Mesh& mesh)
{
  std::vector<Point_3> points;
  for(auto v : vertices(mesh)) points.push_back(get(CGAL::vertex_point, mesh, v));
  return points;
}

double sum_of_squared_lengths(const std::vector<Vector_3>& moves)
{
  double sum = 0.;
  for(const Vector_3& m : moves) sum += m.squared_length();
  return sum;
}

std::vector<Vector_3> differences(const std::vector<Point_3>& a, const std::vector<Point_3>& b)
{
  std::vector<Vector_3> d;
  for(std::size_t i = 0; i < a.size(); ++i) d.push_back(a[i] - b[i]);
  return d;
}

// The largest distance from where each vertex was moved to the midpoint of it and the mirror
// image of its counterpart (the vertex nearest to its image before), about `plane`.
double distance_to_halfway(const std::vector<Point_3>& before, const std::vector<Point_3>& after, const Plane_3& plane)
{
  double worst = 0.;
  for(std::size_t i = 0; i < before.size(); ++i) {
    const Point_3 image = reflect(before[i], plane);
    std::size_t partner = 0;
    for(std::size_t j = 1; j < before.size(); ++j)
      if(CGAL::squared_distance(image, before[j]) < CGAL::squared_distance(image, before[partner])) partner = j;
    const Point_3 halfway = CGAL::midpoint(before[i], reflect(before[partner], plane));
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(after[i], halfway)));
  }
  return worst;
}

template <typename Mesh>
double diagonal(const Mesh& mesh)
{
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

template <typename Mesh>
std::vector<Vector_3> face_normals(const Mesh& mesh)
{
  std::vector<Vector_3> normals;
  for(auto f : faces(mesh)) normals.push_back(PMP::compute_face_normal(f, mesh));
  return normals;
}

// Faces keep their orientation (each normal turns by less than 90 degrees), the mesh stays valid,
// and no self-intersection appears.
template <typename Mesh>
void expect_sound(const Mesh& before, const Mesh& after)
{
  const std::vector<Vector_3> a = face_normals(before), b = face_normals(after);
  for(std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_GT(a[i] * b[i], 0.) << "face " << i << " turned over";
  }
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(after));
  if(!PMP::does_self_intersect(before)) {
    EXPECT_FALSE(PMP::does_self_intersect(after));
  }
}

double motion_scale(const Motion& m) { return std::sqrt(m.transform(Vector_3(1, 0, 0)).squared_length()); }

const Plane_3& nearest_plane(const std::vector<ST::Principal_symmetry<K>>& found, const Plane_3& known)
{
  const ST::Principal_symmetry<K>* best = &found.front();
  for(const auto& s : found)
    if(angle_between(s.plane, known) < angle_between(best->plane, known)) best = &s;
  return best->plane;
}

class OnePlane : public ::testing::TestWithParam<Perturbation>
{};

TEST_P(OnePlane, PerturbedSideMeetsItsMirrorHalfwayUnderTheDetectedPlane)
{
  for(unsigned seed = 1; seed <= 3; ++seed) {
    CGAL::Random rng(seed);
    Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.8, 0.6);
    const std::vector<Vector_3> moves = perturb_one_side(shape.mesh, shape.planes[0], GetParam(), rng);
    const Motion motion = random_motion(rng);
    shape = moved(shape, motion);
    const Surface_mesh before = shape.mesh;
    const auto found = ST::detect_principal_symmetries(shape.mesh, CGAL::parameters::grid_resolution(32));
    ASSERT_FALSE(found.empty());
    const Plane_3 detected = nearest_plane(found, shape.planes[0]);
    const ST::Symmetrization<K> result = ST::symmetrize(shape.mesh, std::vector<Plane_3>{detected});
    ASSERT_EQ(result.planes.size(), 1u);
    EXPECT_EQ(result.group_size, 2u);
    EXPECT_EQ(result.paired_vertices, num_vertices(shape.mesh));
    EXPECT_LT(angle_between(result.planes[0], detected), 1.); // a warp turns its side by tenths of a degree
    EXPECT_LE(ST::symmetry_distance_error(shape.mesh, result.planes[0]), 1e-6);
    const double moved = sum_of_squared_lengths(differences(points_of(shape.mesh), points_of(before)));
    const double perturbed = CGAL::square(motion_scale(motion)) * sum_of_squared_lengths(moves);
    // The pairs meet halfway about the plane that fits them best: no more than about the plane
    // of the construction, where the perturbed side moves halfway back (a half of the squares).
    EXPECT_LE(distance_to_halfway(points_of(before), points_of(shape.mesh), result.planes[0]), 1e-12 * diagonal(before));
    EXPECT_LE(moved, 0.501 * perturbed) << "seed " << seed;
    expect_sound(before, shape.mesh);
  }
}

INSTANTIATE_TEST_SUITE_P(Symmetrization, OnePlane,
                         ::testing::Values(Perturbation::noise, Perturbation::bump, Perturbation::warp));

// A cube whose faces are grids of squares, each split into four triangles at its centre: every
// one of its 48 symmetries maps the tessellation onto itself.
Surface_mesh tessellated_cube(int n)
{
  std::vector<Point_3> points;
  std::map<Point_3, std::size_t> index;
  std::vector<std::array<std::size_t, 3>> triangles;
  auto point = [&](int axis, double s, double u, double v) {
    double c[3];
    c[axis] = s, c[(axis + 1) % 3] = u, c[(axis + 2) % 3] = v;
    const auto [at, added] = index.emplace(Point_3(c[0], c[1], c[2]), points.size());
    if(added) points.push_back(at->first);
    return at->second;
  };
  for(int axis = 0; axis < 3; ++axis)
    for(double s : {-1., 1.})
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j) {
          const double u0 = -1. + 2. * i / n, u1 = -1. + 2. * (i + 1) / n, v0 = -1. + 2. * j / n, v1 = -1. + 2. * (j + 1) / n;
          const std::size_t a = point(axis, s, u0, v0), b = point(axis, s, u1, v0), c = point(axis, s, u1, v1),
                            d = point(axis, s, u0, v1), m = point(axis, s, (u0 + u1) / 2, (v0 + v1) / 2);
          const std::array<std::size_t, 5> q{a, b, c, d, a};
          for(int k = 0; k < 4; ++k)
            triangles.push_back(s > 0 ? std::array<std::size_t, 3>{q[k], q[k + 1], m} : std::array<std::size_t, 3>{q[k + 1], q[k], m});
        }
  Surface_mesh mesh;
  mesh_from_triangle_soup(points, triangles, mesh);
  return mesh;
}

std::vector<Plane_3> cube_planes()
{
  std::vector<Plane_3> planes = coordinate_planes();
  for(int a = 0; a < 3; ++a)
    for(double s : {-1., 1.}) {
      double c[3] = {0, 0, 0};
      c[a] = 1., c[(a + 1) % 3] = s;
      planes.push_back(unit_plane(Plane_3(c[0], c[1], c[2], 0.)));
    }
  return planes;
}

// A plane turned by `degrees` about a random axis through `center`.
Plane_3 tilted(const Plane_3& plane, const Point_3& center, double degrees, CGAL::Random& rng)
{
  return rotated_plane(plane, center, Vector_3(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1)), degrees);
}

TEST(Symmetrization, CubeBecomesSymmetricUnderItsNineDetectedPlanesWithTheLeastDisplacement)
{
  CGAL::Random rng(11);
  Surface_mesh mesh = tessellated_cube(3);
  const std::vector<Vector_3> moves = perturb_one_side(mesh, Plane_3(1, 0, 0, 0), Perturbation::noise, rng);
  const Motion motion = random_motion(rng);
  PMP::transform(motion, mesh);
  std::vector<Plane_3> detected; // off by a hundredth of a degree, as a detection
  for(const Plane_3& p : cube_planes())
    detected.push_back(tilted(moved(p, motion), motion.transform(CGAL::ORIGIN), 0.01, rng));
  const Surface_mesh perturbed = mesh;
  const ST::Symmetrization<K> result = ST::symmetrize(mesh, detected);
  EXPECT_EQ(result.group_size, 48u);
  EXPECT_EQ(result.paired_vertices, num_vertices(mesh));
  ASSERT_EQ(result.planes.size(), 9u);
  for(std::size_t i = 0; i < 9; ++i) {
    EXPECT_LT(angle_between(result.planes[i], detected[i]), 0.1) << "plane " << i;
    EXPECT_LE(ST::symmetry_distance_error(mesh, result.planes[i]), 1e-6) << "plane " << i;
  }
  // No farther than the cube before the noise: a symmetric position.
  const double moved_squares = sum_of_squared_lengths(differences(points_of(mesh), points_of(perturbed)));
  EXPECT_LE(moved_squares, CGAL::square(motion_scale(motion)) * sum_of_squared_lengths(moves));
  expect_sound(perturbed, mesh);
}

// The largest distance from a rotated vertex to the nearest vertex, over the diagonal.
double rotation_error(const Surface_mesh& mesh, const CGAL::Aff_transformation_3<K>& rotation)
{
  const std::vector<Point_3> points = points_of(mesh);
  double worst = 0.;
  for(const Point_3& p : points) {
    double nearest = std::numeric_limits<double>::infinity();
    for(const Point_3& q : points) nearest = (std::min)(nearest, CGAL::squared_distance(rotation.transform(p), q));
    worst = (std::max)(worst, std::sqrt(nearest));
  }
  return worst / diagonal(mesh);
}

CGAL::Aff_transformation_3<K> rotation_about(const CGAL::Line_3<K>& axis, int order)
{
  const Vector_3 u = axis.to_vector() / std::sqrt(axis.to_vector().squared_length());
  const double a = 2. * CGAL_PI / order, c = std::cos(a), s = std::sin(a);
  const CGAL::Aff_transformation_3<K> to_origin(CGAL::TRANSLATION, CGAL::ORIGIN - axis.point(0));
  const CGAL::Aff_transformation_3<K> turn(c + u.x() * u.x() * (1 - c), u.x() * u.y() * (1 - c) - u.z() * s,
                                           u.x() * u.z() * (1 - c) + u.y() * s, u.y() * u.x() * (1 - c) + u.z() * s,
                                           c + u.y() * u.y() * (1 - c), u.y() * u.z() * (1 - c) - u.x() * s,
                                           u.z() * u.x() * (1 - c) - u.y() * s, u.z() * u.y() * (1 - c) + u.x() * s,
                                           c + u.z() * u.z() * (1 - c));
  return to_origin.inverse() * turn * to_origin;
}

TEST(Symmetrization, PropellerBecomesSymmetricAboutItsAxisWithTheLeastDisplacement)
{
  CGAL::Random rng(5);
  Surface_mesh mesh = propeller<Surface_mesh>(5);
  const std::vector<Vector_3> moves = perturb_one_side(mesh, Plane_3(0, 1, 0, 0), Perturbation::warp, rng);
  const Motion motion = random_motion(rng);
  PMP::transform(motion, mesh);
  const Surface_mesh perturbed = mesh;
  const Rotation given{moved(z_axis(), motion), 5, 1., 1.};
  const ST::Symmetrization<K> result = ST::symmetrize(mesh, std::vector<Plane_3>(), std::vector<Rotation>{given});
  EXPECT_EQ(result.group_size, 5u);
  EXPECT_EQ(result.paired_vertices, num_vertices(mesh));
  ASSERT_EQ(result.rotations.size(), 1u);
  EXPECT_EQ(result.rotations[0].order, 5);
  EXPECT_LE(rotation_error(mesh, rotation_about(result.rotations[0].axis, 5)), 1e-9);
  const double moved_squares = sum_of_squared_lengths(differences(points_of(mesh), points_of(perturbed)));
  EXPECT_LE(moved_squares, CGAL::square(motion_scale(motion)) * sum_of_squared_lengths(moves));
  expect_sound(perturbed, mesh);
}

// The faces with a corner at x > 0 remeshed: the two sides are tessellated differently.
void remesh_one_side(Surface_mesh& mesh)
{
  std::vector<Surface_mesh::Face_index> side;
  for(auto f : faces(mesh))
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      if(mesh.point(v).x() > 0.) {
        side.push_back(f);
        break;
      }
  PMP::isotropic_remeshing(side, 0.07, mesh, CGAL::parameters::number_of_iterations(3));
  mesh.collect_garbage();
}

TEST(Symmetrization, UnpairedVerticesFollowTheSurfaceToNearSymmetry)
{
  CGAL::Random rng(3);
  Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.8, 0.6);
  remesh_one_side(shape.mesh);
  // What the two tessellations alone leave: the floor of any symmetrization that keeps them.
  const double tessellation_error = ST::symmetry_distance_error(shape.mesh, shape.planes[0]);
  perturb_one_side(shape.mesh, shape.planes[0], Perturbation::bump, rng, 4.);
  const Surface_mesh before = shape.mesh;
  const double error_before = ST::symmetry_distance_error(shape.mesh, shape.planes[0]);
  const ST::Symmetrization<K> result = ST::symmetrize(shape.mesh, std::vector<Plane_3>{shape.planes[0]});
  EXPECT_LT(result.paired_vertices, num_vertices(shape.mesh) / 2);
  const double error_after = ST::symmetry_distance_error(shape.mesh, result.planes[0]);
  std::cout << "unpaired: SDE " << error_before << " -> " << error_after << ", tessellations alone "
            << tessellation_error << std::endl;
  EXPECT_LT(error_after, error_before / 3.);
  EXPECT_LT(error_after, 2. * tessellation_error);
  expect_sound(before, shape.mesh);
}

TEST(Symmetrization, OnlyTheSupportMovesUnlessTheWholeMeshIsAsked)
{
  CGAL::Random rng(8);
  Shape<Surface_mesh> symmetric = ellipsoid<Surface_mesh>(1., 0.8, 0.6);
  perturb_one_side(symmetric.mesh, symmetric.planes[0], Perturbation::noise, rng);
  Shape<Surface_mesh> part = box<Surface_mesh>(0.3, 0.2, 0.2); // beside it on one side: no counterpart
  PMP::transform(Motion(CGAL::TRANSLATION, Vector_3(1.6, 0.3, 0)), part.mesh);
  const std::size_t first_part_vertex = num_vertices(symmetric.mesh);
  Shape<Surface_mesh> shape = merged(symmetric, part);
  const double radius = center_and_radius(shape.mesh).radius;
  const Surface_mesh before = shape.mesh;
  const auto result = ST::symmetrize(shape.mesh, std::vector<Plane_3>{Plane_3(1, 0, 0, 0)});
  const std::vector<Point_3> a = points_of(before), b = points_of(shape.mesh);
  for(std::size_t i = first_part_vertex; i < a.size(); ++i)
    ASSERT_LT(std::sqrt(CGAL::squared_distance(a[i], b[i])), 1e-3 * radius) << "vertex " << i << " of the part";
  std::vector<Point_3> symmetric_part(b.begin(), b.begin() + std::ptrdiff_t(first_part_vertex));
  std::vector<Point_3> symmetric_before(a.begin(), a.begin() + std::ptrdiff_t(first_part_vertex));
  EXPECT_LE(distance_to_halfway(symmetric_before, symmetric_part, result.planes[0]), 1e-12 * radius);
  Surface_mesh whole = before;
  ST::symmetrize(whole, std::vector<Plane_3>{Plane_3(1, 0, 0, 0)}, CGAL::parameters::whole_mesh(true));
  const std::vector<Point_3> c = points_of(whole);
  double moved = 0.;
  for(std::size_t i = first_part_vertex; i < a.size(); ++i) moved = (std::max)(moved, std::sqrt(CGAL::squared_distance(a[i], c[i])));
  EXPECT_GT(moved, 0.1 * radius);
}

TEST(Symmetrization, ResultMovesWithTheMeshAndDoesNotDependOnTheThreads)
{
  CGAL::Random rng(9);
  Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.8, 0.6);
  remesh_one_side(shape.mesh);
  perturb_one_side(shape.mesh, shape.planes[0], Perturbation::warp, rng);
  const Motion motion = random_motion(rng);
  Shape<Surface_mesh> moved_shape = moved(shape, motion);
  Surface_mesh two_threads = shape.mesh;
  ST::symmetrize(shape.mesh, shape.planes, CGAL::parameters::number_of_threads(1));
  ST::symmetrize(two_threads, shape.planes, CGAL::parameters::number_of_threads(2));
  EXPECT_EQ(points_of(shape.mesh), points_of(two_threads));
  ST::symmetrize(moved_shape.mesh, moved_shape.planes);
  const std::vector<Point_3> a = points_of(shape.mesh), b = points_of(moved_shape.mesh);
  // The searches on the surface compare distances: rounding, which the motion changes, may pick
  // another of two equally near vertices to start from, and six steps carry the difference on.
  const double tolerance = 1e-7 * diagonal(moved_shape.mesh);
  for(std::size_t i = 0; i < a.size(); ++i) ASSERT_LT(std::sqrt(CGAL::squared_distance(motion.transform(a[i]), b[i])), tolerance);
}

TEST(Symmetrization, PolyhedronAgreesWithSurfaceMeshAndDisplacementsAreWritten)
{
  CGAL::Random rng(4);
  Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.8, 0.6, 2);
  perturb_one_side(shape.mesh, shape.planes[0], Perturbation::noise, rng);
  Polyhedron polyhedron;
  CGAL::copy_face_graph(shape.mesh, polyhedron);
  const std::vector<Point_3> before = points_of(shape.mesh);
  auto displacement = shape.mesh.add_property_map<Surface_mesh::Vertex_index, Vector_3>("v:displacement").first;
  const auto a = ST::symmetrize(shape.mesh, shape.planes, CGAL::parameters::vertex_displacement_map(displacement));
  const auto b = ST::symmetrize(polyhedron, shape.planes);
  std::vector<Point_3> on_mesh = points_of(shape.mesh), on_polyhedron = points_of(polyhedron);
  std::sort(on_mesh.begin(), on_mesh.end());
  std::sort(on_polyhedron.begin(), on_polyhedron.end());
  ASSERT_EQ(on_mesh.size(), on_polyhedron.size());
  for(std::size_t i = 0; i < on_mesh.size(); ++i) EXPECT_LT(std::sqrt(CGAL::squared_distance(on_mesh[i], on_polyhedron[i])), 1e-12);
  EXPECT_NEAR(a.max_displacement, b.max_displacement, 1e-12);
  std::size_t i = 0;
  for(auto v : vertices(shape.mesh)) {
    EXPECT_LT(std::sqrt((displacement[v] - (shape.mesh.point(v) - before[i++])).squared_length()), 1e-12);
  }
}

TEST(Symmetrization, AnyVertexIndexMapAndUncollectedGarbageGiveTheSameMeshAndBadIndicesAreRefused)
{
  CGAL::Random rng(6);
  Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.8, 0.6, 2);
  perturb_one_side(shape.mesh, shape.planes[0], Perturbation::noise, rng);
  Surface_mesh reversed = shape.mesh;
  const std::size_t n = num_vertices(reversed);
  const auto reverse = boost::make_function_property_map<Surface_mesh::Vertex_index, std::size_t>(
    [n](Surface_mesh::Vertex_index v) { return n - 1 - std::size_t(v); });
  ST::symmetrize(shape.mesh, shape.planes);
  ST::symmetrize(reversed, shape.planes, CGAL::parameters::vertex_index_map(reverse));
  for(auto v : vertices(reversed)) {
    EXPECT_LT(std::sqrt(CGAL::squared_distance(shape.mesh.point(v), reversed.point(v))), 1e-12);
  }
  Surface_mesh with_garbage = shape.mesh; // a removed vertex, not collected: the last index is num_vertices
  const auto removed = with_garbage.add_vertex(Point_3(0, 0, 0));
  with_garbage.add_vertex(Point_3(0, 0, 0.1));
  with_garbage.remove_vertex(removed);
  Surface_mesh collected = with_garbage;
  collected.collect_garbage();
  const auto beyond = boost::make_function_property_map<Surface_mesh::Vertex_index, std::size_t>(
    [n](Surface_mesh::Vertex_index v) { return n + std::size_t(v); });
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetrize(collected, shape.planes, CGAL::parameters::vertex_index_map(beyond)); }, "vertex_index_map"));
  ST::symmetrize(with_garbage, shape.planes);
  ST::symmetrize(collected, shape.planes);
  const std::vector<Point_3> a = points_of(with_garbage), b = points_of(collected);
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i) EXPECT_LT(std::sqrt(CGAL::squared_distance(a[i], b[i])), 1e-12);
}

typedef std::pair<Point_3, Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

// Points with normals on a shape symmetric about plane 0 of `shape`: its vertices with their
// normals (`paired`: sampled alike on both sides), or `count` points drawn independently on its
// surface with the normals of their faces.
std::vector<Point_with_normal> samples(const Shape<Surface_mesh>& shape, bool paired, CGAL::Random& rng,
                                       std::size_t count = 3000)
{
  std::vector<Point_with_normal> points;
  if(paired) {
    for(auto v : vertices(shape.mesh)) points.emplace_back(shape.mesh.point(v), PMP::compute_vertex_normal(v, shape.mesh));
    return points;
  }
  const Tree<Surface_mesh> tree(faces(shape.mesh).first, faces(shape.mesh).second, shape.mesh);
  for(const Point_3& p : surface_points(shape.mesh, count, rng))
    points.emplace_back(p, PMP::compute_face_normal(tree.closest_point_and_primitive(p).second, shape.mesh));
  return points;
}

// The root mean square distance from the points to the surface of `mesh`.
double rms_distance_to(const Surface_mesh& mesh, const std::vector<Point_with_normal>& points)
{
  const Tree<Surface_mesh> tree(faces(mesh).first, faces(mesh).second, mesh);
  double sum = 0.;
  for(const auto& p : points) sum += CGAL::squared_distance(p.first, tree.closest_point(p.first));
  return std::sqrt(sum / double(points.size()));
}

double squared_moves(const std::vector<Point_with_normal>& before, const std::vector<Point_with_normal>& after)
{
  double sum = 0.;
  for(std::size_t i = 0; i < before.size(); ++i) sum += CGAL::squared_distance(before[i].first, after[i].first);
  return sum;
}

// A point set on an ellipsoid, sampled alike on both sides of its plane x = 0 (its vertices) with
// one side perturbed (noise of 0.5 % of the radius) and moved at random: exactly symmetric
// afterwards, each pair met halfway; sampled independently on the whole surface, it comes nearer
// to the surface, as near as pairs meeting halfway would (0.71 times as far in root mean square;
// the symmetry distance error of independent samples is that of their spacing); the result does
// not depend on the threads.
TEST(Symmetrization, PointSetsBecomeSymmetricWithTheLeastDisplacement)
{
  CGAL::Random rng(3806);
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  for(bool paired : {true, false}) {
    const Motion m = random_motion(rng);
    const Shape<Surface_mesh> hull = moved(ellipsoid<Surface_mesh>(1., 0.6, 0.35, 3), m);
    const double radius = center_and_radius(hull.mesh).radius;
    std::vector<Point_with_normal> points = samples(hull, paired, rng, 20000); // the tangent planes within the noise
    double perturbation = 0.;
    for(Point_with_normal& p : points)
      if(hull.planes[0].oriented_side(p.first) == CGAL::ON_POSITIVE_SIDE) {
        const Vector_3 d = 0.005 * radius / std::sqrt(3.) * Vector_3(gaussian(rng), gaussian(rng), gaussian(rng));
        p.first = p.first + d;
        perturbation += d.squared_length();
      }
    const std::vector<Point_with_normal> before = points;
    const double error_before = ST::symmetry_distance_error_of_points(points, hull.planes[0], np);
    const double off_before = rms_distance_to(hull.mesh, points);
    const std::vector<Plane_3> plane{hull.planes[0]};
    const auto result = ST::symmetrize_point_set(points, plane, np.whole_mesh(true));
    const double error_after = ST::symmetry_distance_error_of_points(points, result.planes[0], np);
    const double off_after = rms_distance_to(hull.mesh, points);
    std::cout << (paired ? "paired" : "independent") << " samples: SDE " << error_before << " -> " << error_after
              << ", RMS distance to the surface " << off_before / radius << " -> " << off_after / radius << " R, "
              << result.paired_vertices << " of " << points.size() << " paired, sum of squared moves "
              << squared_moves(before, points) / perturbation << " of the perturbation's\n";
    std::vector<Point_with_normal> one_thread = before;
    ST::symmetrize_point_set(one_thread, plane, np.whole_mesh(true).number_of_threads(1));
    for(std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(one_thread[i].first, points[i].first);
    if(paired) {
      EXPECT_EQ(result.paired_vertices, points.size());
      EXPECT_LE(error_after, 1e-6);
      EXPECT_LE(squared_moves(before, points), 0.55 * perturbation);
    } else {
      EXPECT_LE(off_after, 0.8 * off_before);
    }
  }
}

TEST(Symmetrization, PointSetMovesWithItsMotionAndBadPointSetsAreRejected)
{
  CGAL::Random rng(3807);
  const Shape<Surface_mesh> hull = one_plane_hull<Surface_mesh>();
  std::vector<Point_with_normal> here = samples(hull, false, rng);
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  const Motion m = random_motion(rng);
  std::vector<Point_with_normal> there;
  for(const auto& p : here) there.emplace_back(m.transform(p.first), m.transform(p.second));
  ST::symmetrize_point_set(here, hull.planes, np);
  ST::symmetrize_point_set(there, std::vector<Plane_3>{moved(hull.planes[0], m)}, np);
  double farthest = 0.;
  for(std::size_t i = 0; i < here.size(); ++i)
    farthest = (std::max)(farthest, std::sqrt(CGAL::squared_distance(m.transform(here[i].first), there[i].first)));
  EXPECT_LT(farthest, 1e-9 * center_and_radius(hull.mesh).radius * motion_scale(m));
  std::vector<Point_3> none;
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::symmetrize_point_set(none, hull.planes); }, "empty"));
  std::vector<Point_3> points{Point_3(0, 0, 0), Point_3(1, 0, 0)};
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetrize_point_set(points, std::vector<Plane_3>()); }, "no symmetry given"));
}

TEST(Symmetrization, CancelLeavesTheMeshUnchanged)
{
  Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>();
  const std::vector<Point_3> before = points_of(shape.mesh);
  const auto result = ST::symmetrize(shape.mesh, shape.planes, CGAL::parameters::callback([](double) { return false; }));
  EXPECT_TRUE(result.planes.empty());
  EXPECT_EQ(result.group_size, 0u);
  EXPECT_EQ(points_of(shape.mesh), before);
}

TEST(Symmetrization, BadInputIsRejected)
{
  Shape<Surface_mesh> shape = ellipsoid<Surface_mesh>(1., 0.8, 0.6, 1);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::symmetrize(shape.mesh, std::vector<Plane_3>()); },
                                                 "no symmetry given"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetrize(shape.mesh, std::vector<Plane_3>(), std::vector<Rotation>{{z_axis(), 0, 1., 1.}}); },
    "order 0"));
  const std::vector<Plane_3> no_group{Plane_3(1, 0, 0, 0), rotated_plane(Plane_3(1, 0, 0, 0), CGAL::ORIGIN, Vector_3(0, 0, 1), 10.3)};
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::symmetrize(shape.mesh, no_group); }, "no finite group"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::symmetrize(shape.mesh, std::vector<Plane_3>{Plane_3(0, 0, 0, 1)}); },
                                                 "degenerate plane"));
  Surface_mesh quad;
  CGAL::make_quad(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0), quad);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::symmetrize(quad, std::vector<Plane_3>{Plane_3(1, 0, 0, -0.5)}); },
                                                 "not a triangle"));
}

} // namespace
