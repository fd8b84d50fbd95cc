// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Invariance (DESIGN.md, "Invariance by design"), as metamorphic relations on shapes built in code:
// - the thread count changes no bit of any result (1, 2, 3 and 8 threads);
// - a shape moved a million radii away in a random direction, or scaled by 1e-6 or 1e6, gives the
//   moved result: its exact planes and axes, its frame and centres within 1e-6 (normals) and 1e-6
//   of the radius (positions, measured at the shape's centre), measures, supports and the
//   descriptor within 1e-6, the same segments; under a rigid motion too, the exact planes;
// - a triangle soup and a Polyhedron_3 give the planes of the Surface_mesh they are made of.
// Approximate symmetries (ridges of the transform, not symmetries of the shape) are left out of
// the comparisons: where a ridge is flat, a change of the input at the rounding level moves the
// plane ISP stops on (the manual, section Invariance and Determinism).

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include "Symmetry_transform_test_shapes.h"

#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace ST = CGAL::Symmetry_transform;
using namespace st_test;

namespace {

typedef ST::Principal_symmetry<K> Symmetry;
typedef ST::Rotational_symmetry<K> Axis;

const std::array<unsigned, 4> thread_counts = {1, 2, 3, 8};
// A shape a million radii from the origin: its coordinates keep about ten digits of its size.
constexpr double far_radii = 1e6;
// As far as a shape may be (beyond 4.5e9 radii, it is refused): its coordinates keep about seven
// digits of its size, and a sum of squares of them none.
constexpr double farthest_radii = 1e9;
// What "the moved result" means here: normals to 1e-6, positions to 1e-6 of the radius.
constexpr double invariance_tolerance = 1e-6;
// What it means for a Monte Carlo transform (relative L2 error), whose own error is about 1e-2.
constexpr double monte_carlo_invariance_tolerance = 1e-4;

const auto grid_32 = CGAL::parameters::grid_resolution(32).random_seed(1);

// A hull symmetric about one plane only, moved off the coordinate axes: no plane of symmetry is
// a coordinate plane, and no bin of the transform is special.
Shape<Surface_mesh> test_shape()
{
  CGAL::Random rng(7);
  return moved(one_plane_hull<Surface_mesh>(4), random_motion(rng));
}

Shape<Surface_mesh> test_box()
{
  CGAL::Random rng(8);
  return moved(box<Surface_mesh>(), random_motion(rng, true, true, false));
}

// A scale, then a translation of `radii` radii in a random direction (the grids of the
// transforms are aligned with the axes: a rotation samples the shape anew, see RigidMotion).
Motion far_motion(CGAL::Random& rng, double radii, double radius, double scale = 1.)
{
  Vector_3 direction(gaussian(rng), gaussian(rng), gaussian(rng));
  direction = direction / std::sqrt(direction.squared_length());
  const Motion shift(CGAL::TRANSLATION, direction * (radii * radius));
  return shift * Motion(CGAL::SCALING, scale);
}

// ---------------------------------------------------------------------------------------------
// Comparisons.
// ---------------------------------------------------------------------------------------------

std::vector<double> coefficients(const std::vector<Symmetry>& planes)
{
  std::vector<double> c;
  for(const Symmetry& s : planes)
    for(double x : {s.plane.a(), s.plane.b(), s.plane.c(), s.plane.d(), s.symmetry, s.support}) c.push_back(x);
  return c;
}

std::vector<double> coefficients(const std::vector<Axis>& axes)
{
  std::vector<double> c;
  for(const Axis& a : axes) {
    const Point_3 p = a.axis.point();
    const Vector_3 v = a.axis.to_vector();
    for(double x : {p.x(), p.y(), p.z(), v.x(), v.y(), v.z(), double(a.order), a.symmetry, a.support}) c.push_back(x);
  }
  return c;
}

// Every plane of `expected` has one in `found` within the tolerance (normals up to sign; offsets
// as signed distances to `center`, over `radius`), and both have as many.
::testing::AssertionResult same_planes(const std::vector<Plane_3>& expected, const std::vector<Plane_3>& found,
                                       const Point_3& center, double radius)
{
  if(expected.size() != found.size())
    return ::testing::AssertionFailure() << expected.size() << " planes expected, " << found.size() << " found";
  for(const Plane_3& e : expected) {
    double best = std::numeric_limits<double>::infinity();
    for(const Plane_3& f : found)
      best = (std::min)(best, std::max(std::sin(angle_between(e, f) * CGAL_PI / 180.),
                                       offset_between(e, f, center) / radius));
    if(!(best <= invariance_tolerance))
      return ::testing::AssertionFailure() << "plane " << e << " missing: nearest off by " << best;
  }
  return ::testing::AssertionSuccess();
}

std::vector<Plane_3> planes_of(const std::vector<Symmetry>& symmetries, const Motion& m = Motion(CGAL::IDENTITY))
{
  std::vector<Plane_3> planes;
  for(const Symmetry& s : symmetries) planes.push_back(moved(s.plane, m));
  return planes;
}

// The planes of `found` that are planes of symmetry of the shape by construction (`exact`, of
// which none may be missing), within the tolerance.
::testing::AssertionResult finds_exact_planes(const std::vector<Plane_3>& exact, const std::vector<Symmetry>& found,
                                              const Point_3& center, double radius)
{
  std::vector<Plane_3> matched;
  for(const Plane_3& e : exact)
    for(const Symmetry& f : found)
      if(same_planes({e}, {f.plane}, center, radius)) {
        matched.push_back(f.plane);
        break;
      }
  return same_planes(exact, matched, center, radius);
}

// The exact planes of `shape` moved by m are found on the moved shape, and all its planes when
// all are exact (a box).
void expect_planes_move_with(const Shape<Surface_mesh>& shape, const Motion& m)
{
  const Shape<Surface_mesh> far = moved(shape, m);
  const Center_and_radius cr = center_and_radius(far.mesh);
  const std::vector<Symmetry> here = ST::detect_principal_symmetries(shape.mesh, grid_32),
                              there = ST::detect_principal_symmetries(far.mesh, grid_32);
  EXPECT_TRUE(finds_exact_planes(far.planes, there, cr.center, cr.radius));
  if(here.size() == shape.planes.size()) {
    EXPECT_TRUE(same_planes(planes_of(here, m), planes_of(there), cr.center, cr.radius));
  }
}

// Axes equal up to orientation: directions within the tolerance, and `center` as far from both.
::testing::AssertionResult same_axis(const Axis& a, const Axis& b, const Point_3& center, double radius)
{
  Vector_3 u = a.axis.to_vector(), v = b.axis.to_vector();
  u = u / std::sqrt(u.squared_length());
  v = v / std::sqrt(v.squared_length());
  const double sine = std::sqrt(CGAL::cross_product(u, v).squared_length());
  const double apart = std::abs(std::sqrt(CGAL::squared_distance(center, a.axis)) -
                                std::sqrt(CGAL::squared_distance(center, b.axis))) / radius;
  if(a.order == b.order && sine <= invariance_tolerance && apart <= invariance_tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "axes " << a.axis << " (order " << a.order << ") and " << b.axis
                                       << " (order " << b.order << "): sine " << sine << ", apart " << apart;
}

// The forms other than a mesh: its vertices and triangles as a soup, points sampled on it (with
// the normal of their face, for the oriented forms).
struct Soup
{
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

Soup soup_of(const Surface_mesh& mesh)
{
  Soup soup;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, soup.points, soup.triangles);
  return soup;
}

typedef std::pair<Point_3, Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

// `per_face` points uniform on each triangle (same seed, same points), with its unit normal.
std::vector<Point_with_normal> oriented_samples(const Surface_mesh& mesh, int per_face)
{
  CGAL::Random rng(19);
  std::vector<Point_with_normal> result;
  for(auto f : faces(mesh)) {
    std::vector<Point_3> corners;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) corners.push_back(mesh.point(v));
    Vector_3 normal = CGAL::normal(corners[0], corners[1], corners[2]);
    normal = normal / std::sqrt(normal.squared_length());
    for(int k = 0; k < per_face; ++k) {
      double u = rng.get_double(), v = rng.get_double();
      if(u + v > 1.) std::tie(u, v) = std::make_pair(1. - u, 1. - v);
      result.emplace_back(corners[0] + u * (corners[1] - corners[0]) + v * (corners[2] - corners[0]), normal);
    }
  }
  return result;
}

std::vector<Point_with_normal> moved(std::vector<Point_with_normal> points, const Motion& m)
{
  for(Point_with_normal& p : points) p = {m.transform(p.first), m.transform(p.second)};
  return points;
}

std::vector<Point_3> positions(const std::vector<Point_with_normal>& points)
{
  std::vector<Point_3> result;
  for(const Point_with_normal& p : points) result.push_back(p.first);
  return result;
}

// Distance between points over the radius.
double apart(const Point_3& a, const Point_3& b, double radius)
{
  return std::sqrt(CGAL::squared_distance(a, b)) / radius;
}

// The sine of the angle between the expected frame axes (moved) and the found ones, the largest.
double largest_axis_sine(const ST::Symmetry_frame<K>& expected, const ST::Symmetry_frame<K>& found)
{
  double sine = 0.;
  for(std::size_t i = 0; i < 3; ++i)
    sine = (std::max)(sine, std::sqrt(CGAL::cross_product(expected.axes[i], found.axes[i]).squared_length() /
                                      (expected.axes[i].squared_length() * found.axes[i].squared_length())));
  return sine;
}

ST::Symmetry_frame<K> moved(ST::Symmetry_frame<K> frame, const Motion& m)
{
  frame.center = m.transform(frame.center);
  for(Vector_3& a : frame.axes) a = m.transform(a);
  return frame;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// The thread count changes no bit.
// ---------------------------------------------------------------------------------------------

// Runs f(threads) for each thread count and expects the same vector of doubles, to the bit.
template <typename F>
void expect_same_for_every_thread_count(const F& f)
{
  const std::vector<double> one = f(1u);
  ASSERT_FALSE(one.empty());
  for(unsigned threads : thread_counts) {
    const std::vector<double> other = f(threads);
    ASSERT_EQ(one.size(), other.size()) << threads << " threads";
    for(std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], other[i]) << threads << " threads, value " << i;
  }
}

TEST(ThreadCount, ChangesNoBitOfThePlanesOfAMesh)
{
  const Shape<Surface_mesh> s = test_shape();
  expect_same_for_every_thread_count(
    [&](unsigned t) { return coefficients(ST::detect_principal_symmetries(s.mesh, grid_32.number_of_threads(t))); });
}

// The detection measures each plane it keeps on its threads: the terms are computed per layer of
// the grid and summed in one order, so the value is that of the public, one-thread measure.
TEST(ThreadCount, ChangesNoBitOfTheMeasureOfAPlane)
{
  const Shape<Surface_mesh> s = test_shape();
  const auto gedt = ST::gaussian_distance_transform(s.mesh, grid_32);
  const std::vector<Plane_3> planes = {Plane_3(gedt.center(), Vector_3(1., 0., 0.)),
                                       Plane_3(gedt.center(), Vector_3(0.3, -0.5, 0.8)),
                                       Plane_3(gedt.center(), Vector_3(0., 1., 1.))};
  std::vector<double> public_measures;
  for(const Plane_3& p : planes) public_measures.push_back(ST::symmetry_measure(gedt, p));
  for(double m : public_measures) ASSERT_GT(m, 0.05); // planes through the shape: many terms
  expect_same_for_every_thread_count([&](unsigned t) {
    std::vector<double> measures;
    for(const Plane_3& p : planes) measures.push_back(ST::internal::plane_symmetry_measure(gedt, p, t));
    return measures;
  });
  for(std::size_t i = 0; i < planes.size(); ++i)
    EXPECT_EQ(ST::internal::plane_symmetry_measure(gedt, planes[i], 3), public_measures[i]) << "plane " << i;
}

TEST(ThreadCount, ChangesNoBitOfThePlanesOfAPointSet)
{
  const Shape<Surface_mesh> s = test_shape();
  std::vector<Point_3> points(s.mesh.points().begin(), s.mesh.points().end());
  expect_same_for_every_thread_count([&](unsigned t) {
    return coefficients(ST::detect_principal_symmetries_of_points(points, grid_32.number_of_threads(t)));
  });
}

TEST(ThreadCount, ChangesNoBitOfTheAxesOfABox)
{
  const Shape<Surface_mesh> s = test_box();
  expect_same_for_every_thread_count(
    [&](unsigned t) { return coefficients(ST::detect_rotational_symmetries(s.mesh, grid_32.number_of_threads(t))); });
}

TEST(ThreadCount, ChangesNoBitOfTheVotingEstimatorsOrOfTheGrids)
{
  const Shape<Surface_mesh> s = test_shape();
  for(ST::Monte_carlo_estimator e : {ST::Monte_carlo_estimator::PAIR_JACOBIAN, ST::Monte_carlo_estimator::BOUNDED_WEIGHT})
    expect_same_for_every_thread_count([&](unsigned t) {
      return ST::reflective_symmetry_transform(s.mesh, grid_32.number_of_threads(t).monte_carlo_estimator(e)).values();
    });
  expect_same_for_every_thread_count(
    [&](unsigned t) { return ST::gaussian_distance_transform(s.mesh, grid_32.number_of_threads(t)).values(); });
  expect_same_for_every_thread_count(
    [&](unsigned t) { return ST::point_symmetry_transform(s.mesh, grid_32.number_of_threads(t)).grid().values(); });
}

TEST(ThreadCount, ChangesNoBitOfTheFrameTheSegmentsOrTheErrors)
{
  const Shape<Surface_mesh> s = test_shape();
  expect_same_for_every_thread_count([&](unsigned t) {
    const ST::Symmetry_frame<K> f = ST::symmetry_frame(s.mesh, grid_32.number_of_threads(t));
    std::vector<double> c = {f.center.x(), f.center.y(), f.center.z()};
    for(const Vector_3& a : f.axes) c.insert(c.end(), {a.x(), a.y(), a.z()});
    return c;
  });
  expect_same_for_every_thread_count([&](unsigned t) {
    std::vector<std::size_t> ids(num_faces(s.mesh));
    ST::segment_by_symmetry(s.mesh, CGAL::make_property_map(ids), grid_32.number_of_threads(t).max_segmentation_depth(1));
    return std::vector<double>(ids.begin(), ids.end());
  });
  expect_same_for_every_thread_count([&](unsigned t) {
    return std::vector<double>{ST::symmetry_distance_error(s.mesh, s.planes.front(), CGAL::parameters::number_of_threads(t))};
  });
}

// ---------------------------------------------------------------------------------------------
// Far from the origin, at any scale, under rigid motions.
// ---------------------------------------------------------------------------------------------

TEST(Position, PlanesMoveWithAShapeAMillionRadiiAway)
{
  CGAL::Random rng(11);
  for(const Shape<Surface_mesh>& s : {test_shape(), test_box()}) {
    const double radius = center_and_radius(s.mesh).radius;
    for(int trial = 0; trial < 2; ++trial) expect_planes_move_with(s, far_motion(rng, far_radii, radius));
  }
}

TEST(Position, PlanesScaleWithTheShapeFromAMillionthToAMillionTimes)
{
  CGAL::Random rng(12);
  const Shape<Surface_mesh> s = test_shape();
  for(double scale : {1e-6, 1e6}) expect_planes_move_with(s, far_motion(rng, 3., center_and_radius(s.mesh).radius, scale));
}

TEST(Position, ExactPlanesMoveWithAShapeUnderRigidMotionsAMillionRadiiAway)
{
  CGAL::Random rng(18);
  for(const Shape<Surface_mesh>& s : {test_shape(), test_box()})
    for(int trial = 0; trial < 2; ++trial)
      expect_planes_move_with(s, far_motion(rng, far_radii, center_and_radius(s.mesh).radius) *
                                   random_motion(rng, true, false, false));
}

TEST(Position, AxesMoveWithABoxAMillionRadiiAway)
{
  CGAL::Random rng(13);
  const Shape<Surface_mesh> s = test_box();
  const Motion m = far_motion(rng, far_radii, center_and_radius(s.mesh).radius);
  const Shape<Surface_mesh> far = moved(s, m);
  const Center_and_radius cr = center_and_radius(far.mesh);
  const std::vector<Axis> here = ST::detect_rotational_symmetries(s.mesh, grid_32),
                          there = ST::detect_rotational_symmetries(far.mesh, grid_32);
  ASSERT_EQ(here.size(), 3u); // the box's three axes of order 2
  ASSERT_EQ(there.size(), here.size());
  for(const Axis& a : here) {
    Axis expected = a;
    expected.axis = a.axis.transform(m);
    EXPECT_TRUE(std::any_of(there.begin(), there.end(), [&](const Axis& b) { return same_axis(expected, b, cr.center, cr.radius); }));
  }
}

TEST(Position, FrameCentreAndDescriptorMoveWithABoxAMillionRadiiAway)
{
  CGAL::Random rng(14);
  const Shape<Surface_mesh> s = test_box();
  const Motion m = far_motion(rng, far_radii, center_and_radius(s.mesh).radius);
  const Shape<Surface_mesh> far = moved(s, m);
  const double radius = center_and_radius(far.mesh).radius;
  const ST::Symmetry_frame<K> here = ST::symmetry_frame(s.mesh, grid_32), there = ST::symmetry_frame(far.mesh, grid_32);
  EXPECT_LE(std::sqrt(CGAL::squared_distance(m.transform(here.center), there.center)) / radius, invariance_tolerance);
  for(int i = 0; i < 3; ++i) {
    const Vector_3 expected = m.transform(here.axes[std::size_t(i)]);
    const double sine = std::sqrt(CGAL::cross_product(expected, there.axes[std::size_t(i)]).squared_length() /
                                  expected.squared_length());
    EXPECT_LE(sine, invariance_tolerance) << "axis " << i;
  }
  const ST::Point_symmetry_transform<K> pst_here = ST::point_symmetry_transform(s.mesh, grid_32),
                                        pst_there = ST::point_symmetry_transform(far.mesh, grid_32);
  EXPECT_LE(std::sqrt(CGAL::squared_distance(m.transform(pst_here.center_of_symmetry()), pst_there.center_of_symmetry())) / radius,
            invariance_tolerance);
  EXPECT_LE(ST::descriptor_distance(ST::symmetry_descriptor(s.mesh, grid_32), ST::symmetry_descriptor(far.mesh, grid_32)),
            invariance_tolerance);
}

TEST(Position, ErrorsSupportsAndSegmentsDoNotChangeAMillionRadiiAway)
{
  CGAL::Random rng(15);
  const Shape<Surface_mesh> s = test_shape();
  const Motion m = far_motion(rng, far_radii, center_and_radius(s.mesh).radius);
  const Shape<Surface_mesh> far = moved(s, m);
  const Plane_3 turned = rotated_plane(s.planes.front(), center_and_radius(s.mesh).center, Vector_3(0, 0, 1), 5.);
  EXPECT_NEAR(ST::symmetry_distance_error(far.mesh, moved(turned, m)), ST::symmetry_distance_error(s.mesh, turned),
              invariance_tolerance);
  std::vector<double> supports_here(num_faces(s.mesh)), supports_there(num_faces(far.mesh));
  EXPECT_NEAR(ST::symmetry_support(far.mesh, moved(turned, m), CGAL::make_property_map(supports_there)),
              ST::symmetry_support(s.mesh, turned, CGAL::make_property_map(supports_here)), invariance_tolerance);
  for(std::size_t f = 0; f < supports_here.size(); ++f) EXPECT_NEAR(supports_here[f], supports_there[f], invariance_tolerance);
  std::vector<std::size_t> here(num_faces(s.mesh)), there(num_faces(far.mesh));
  ST::segment_by_symmetry(s.mesh, CGAL::make_property_map(here), grid_32.max_segmentation_depth(1));
  ST::segment_by_symmetry(far.mesh, CGAL::make_property_map(there), grid_32.max_segmentation_depth(1));
  EXPECT_EQ(here, there);
}

TEST(Position, RefinedPlaneMovesWithAShapeAMillionRadiiAway)
{
  CGAL::Random rng(16);
  const Shape<Surface_mesh> s = test_shape();
  const Center_and_radius cr = center_and_radius(s.mesh);
  const Motion m = far_motion(rng, far_radii, cr.radius);
  const Shape<Surface_mesh> far = moved(s, m);
  const Plane_3 start = rotated_plane(s.planes.front(), cr.center, Vector_3(1, 1, 0), 4.);
  const Plane_3 here = ST::refine_symmetry_plane(s.mesh, start, grid_32),
                there = ST::refine_symmetry_plane(far.mesh, moved(start, m), grid_32);
  const Center_and_radius far_cr = center_and_radius(far.mesh);
  EXPECT_TRUE(same_planes({moved(here, m)}, {there}, far_cr.center, far_cr.radius));
  EXPECT_TRUE(same_planes({far.planes.front()}, {there}, far_cr.center, far_cr.radius));
}

TEST(Position, AShapeTooFarForItsCoordinatesIsRefusedUnderItsDistance)
{
  const Shape<Surface_mesh> s = test_box();
  const double radius = center_and_radius(s.mesh).radius;
  const Shape<Surface_mesh> far = moved(s, Motion(CGAL::TRANSLATION, Vector_3(1e10 * radius, 0, 0)));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::detect_principal_symmetries(far.mesh, grid_32); },
                                                         "radii from the origin"));
  std::vector<Point_3> points(far.mesh.points().begin(), far.mesh.points().end());
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::symmetry_frame_of_points(points, grid_32); },
                                                         "radii from the origin"));
}

// ---------------------------------------------------------------------------------------------
// Input forms.
// ---------------------------------------------------------------------------------------------

TEST(InputForm, SoupAndPolyhedronGiveThePlanesOfTheirMeshFarFromTheOrigin)
{
  CGAL::Random rng(17);
  const Shape<Surface_mesh> s = test_box();
  const Shape<Surface_mesh> far = moved(s, far_motion(rng, far_radii, center_and_radius(s.mesh).radius));
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(far.mesh, points, triangles);
  const Center_and_radius cr = center_and_radius(far.mesh);
  EXPECT_TRUE(same_planes(planes_of(ST::detect_principal_symmetries(far.mesh, grid_32)),
                          planes_of(ST::detect_principal_symmetries_of_triangle_soup(points, triangles, grid_32)),
                          cr.center, cr.radius));
  Polyhedron polyhedron;
  CGAL::copy_face_graph(far.mesh, polyhedron);
  EXPECT_TRUE(same_planes(planes_of(ST::detect_principal_symmetries(far.mesh, grid_32)),
                          planes_of(ST::detect_principal_symmetries(polyhedron, grid_32)), cr.center, cr.radius));
}

// ---------------------------------------------------------------------------------------------
// The remeshing, the axes from known planes, the viewpoints, and the point-set, oriented-point
// and soup forms.
// ---------------------------------------------------------------------------------------------

namespace {

const auto proxies_24 = CGAL::parameters::max_number_of_proxies(24);

// A shape moved far away by a translation (its coordinates rounded there), and the moved shape
// brought back: the translation of a double by a much longer one, back, is exact (Sterbenz), so
// the two are exact translates of each other, the same shape. A result that depends on the shape
// to the last bit (a choice among equal values, a flat ridge) must then still move with it.
template <typename S>
struct Translates
{
  S here, there;
  Motion motion; // from here to there
};

template <typename S>
Translates<S> exact_translates(const S& shape, const Motion& translation)
{
  const S there = moved(shape, translation);
  return {moved(there, translation.inverse()), there, translation};
}

// The anchors (their coordinates, moved back by the inverse of m) and the triangles of the remeshing.
std::vector<double> remeshing_of(const Surface_mesh& mesh, const std::vector<Plane_3>& planes, const Motion& m, unsigned threads)
{
  std::vector<Point_3> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  ST::symmetric_approximate_triangle_mesh(mesh, planes, proxies_24.number_of_threads(threads)
                                                          .anchors(std::back_inserter(anchors))
                                                          .triangles(std::back_inserter(triangles)));
  std::vector<double> c;
  for(const Point_3& p : anchors) {
    const Point_3 back = m.inverse().transform(p);
    c.insert(c.end(), {back.x(), back.y(), back.z()});
  }
  for(const auto& t : triangles) c.insert(c.end(), {double(t[0]), double(t[1]), double(t[2])});
  return c;
}

} // namespace

TEST(ThreadCount, ChangesNoBitOfTheRemeshingTheAxesFromPlanesOrThePointsWithNormals)
{
  const Shape<Surface_mesh> e = ellipsoid<Surface_mesh>();
  expect_same_for_every_thread_count(
    [&](unsigned t) { return remeshing_of(e.mesh, e.planes, Motion(CGAL::IDENTITY), t); });
  const Shape<Surface_mesh> b = test_box();
  const std::vector<Symmetry> planes = ST::detect_principal_symmetries(b.mesh, grid_32);
  expect_same_for_every_thread_count(
    [&](unsigned t) { return coefficients(ST::rotational_symmetries(b.mesh, planes, grid_32.number_of_threads(t))); });
  const std::vector<Point_with_normal> points = oriented_samples(test_shape().mesh, 8);
  expect_same_for_every_thread_count([&](unsigned t) {
    return coefficients(ST::detect_principal_symmetries_of_points(
      points, grid_32.point_map(Point_map()).normal_map(Normal_map()).number_of_threads(t)));
  });
}

// The anchors move with the shape within 1e-6 of its radius, and the triangles are the same. The
// ellipsoid is symmetric to the last bit, and its moved copy is not (its coordinates are rounded
// to a millionth of the radius's digits): the seeds of the proxies, chosen among faces of equal
// error, may then differ. The copy brought back to the origin is its exact translate (see
// exact_translates()): the remeshing of the two must agree, there and as far as a shape may be.
TEST(Position, RemeshingMovesWithAShapeAMillionAndABillionRadiiAway)
{
  CGAL::Random rng(20);
  const Shape<Surface_mesh> e = ellipsoid<Surface_mesh>();
  const double radius = center_and_radius(e.mesh).radius;
  for(double radii : {far_radii, farthest_radii}) {
    const Translates<Shape<Surface_mesh>> t = exact_translates(e, far_motion(rng, radii, radius));
    const std::vector<double> here = remeshing_of(t.here.mesh, t.here.planes, Motion(CGAL::IDENTITY), 2),
                              there = remeshing_of(t.there.mesh, t.there.planes, t.motion, 2);
    ASSERT_EQ(here.size(), there.size()) << radii << " radii away";
    ASSERT_FALSE(here.empty());
    double worst = 0.;
    for(std::size_t i = 0; i < here.size(); ++i) worst = (std::max)(worst, std::abs(here[i] - there[i]));
    EXPECT_LE(worst / radius, invariance_tolerance) << radii << " radii away";
  }
}

TEST(Position, AxesFromKnownPlanesMoveWithABoxAMillionRadiiAway)
{
  CGAL::Random rng(21);
  const Shape<Surface_mesh> s = test_box();
  const Motion m = far_motion(rng, far_radii, center_and_radius(s.mesh).radius);
  const Shape<Surface_mesh> far = moved(s, m);
  const Center_and_radius cr = center_and_radius(far.mesh);
  std::vector<Symmetry> planes_here, planes_there;
  for(const Plane_3& p : s.planes) planes_here.push_back({p, 1., 1.});
  for(const Plane_3& p : far.planes) planes_there.push_back({p, 1., 1.});
  const std::vector<Axis> here = ST::rotational_symmetries(s.mesh, planes_here, grid_32),
                          there = ST::rotational_symmetries(far.mesh, planes_there, grid_32);
  ASSERT_EQ(here.size(), 3u);
  ASSERT_EQ(there.size(), here.size());
  for(const Axis& a : here) {
    Axis expected = a;
    expected.axis = a.axis.transform(m);
    EXPECT_TRUE(std::any_of(there.begin(), there.end(), [&](const Axis& b) { return same_axis(expected, b, cr.center, cr.radius); }));
  }
}

// Scored views depend on the normals and measures only: the same views for the planes found on a
// box and on the box a million radii away or scaled by 1e-6 and 1e6.
TEST(Position, ViewpointsDoNotChangeAMillionRadiiAwayOrAtAnyScale)
{
  CGAL::Random rng(22);
  const Shape<Surface_mesh> s = test_box();
  const double radius = center_and_radius(s.mesh).radius;
  auto views_of = [](const Surface_mesh& mesh) {
    std::vector<ST::Viewpoint<K>> views;
    ST::best_viewpoints(ST::detect_principal_symmetries(mesh, grid_32), std::back_inserter(views));
    return views;
  };
  const std::vector<ST::Viewpoint<K>> here = views_of(s.mesh);
  ASSERT_FALSE(here.empty());
  for(const Motion& m : {far_motion(rng, far_radii, radius), far_motion(rng, 3., radius, 1e-6), far_motion(rng, 3., radius, 1e6)}) {
    const std::vector<ST::Viewpoint<K>> there = views_of(moved(s, m).mesh);
    ASSERT_EQ(here.size(), there.size());
    for(const ST::Viewpoint<K>& v : here) // views of equal scores (the box's) may come in either order
      EXPECT_TRUE(std::any_of(there.begin(), there.end(), [&](const ST::Viewpoint<K>& w) {
        return std::sqrt((v.direction - w.direction).squared_length()) <= invariance_tolerance &&
               std::abs(v.score - w.score) <= invariance_tolerance;
      })) << "view " << v.direction << " (score " << v.score << ") missing";
  }
}

// Points sampled on a box (each with the normal of its face for the oriented form), a million
// radii away and scaled: the frame, the centre of the PST, the descriptor, the error of a plane
// and the planes of the oriented points move with them.
TEST(Position, PointSetFormsMoveWithTheirPointsAMillionRadiiAwayAndAtAnyScale)
{
  CGAL::Random rng(23);
  const Shape<Surface_mesh> s = test_box();
  const std::vector<Point_with_normal> oriented = oriented_samples(s.mesh, 40);
  const std::vector<Point_3> points = positions(oriented);
  const double radius = center_and_radius(s.mesh).radius;
  const auto with_normals = grid_32.point_map(Point_map()).normal_map(Normal_map());
  const ST::Symmetry_frame<K> frame = ST::symmetry_frame_of_points(points, grid_32);
  const Point_3 pst_center = ST::point_symmetry_transform_of_points(points, grid_32).center_of_symmetry();
  const auto descriptor = ST::symmetry_descriptor_of_points(points, grid_32);
  const Plane_3 turned = rotated_plane(s.planes.front(), center_and_radius(s.mesh).center, Vector_3(0, 0, 1), 5.);
  const double error = ST::symmetry_distance_error_of_points(points, turned);
  for(const Motion& m : {far_motion(rng, far_radii, radius), far_motion(rng, 3., radius, 1e-6), far_motion(rng, 3., radius, 1e6)}) {
    const std::vector<Point_3> far_points = positions(moved(oriented, m));
    const Shape<Surface_mesh> far = moved(s, m);
    const Center_and_radius cr = center_and_radius(far.mesh);
    const ST::Symmetry_frame<K> far_frame = ST::symmetry_frame_of_points(far_points, grid_32);
    EXPECT_LE(apart(moved(frame, m).center, far_frame.center, cr.radius), invariance_tolerance);
    EXPECT_LE(largest_axis_sine(moved(frame, m), far_frame), invariance_tolerance);
    EXPECT_LE(apart(m.transform(pst_center), ST::point_symmetry_transform_of_points(far_points, grid_32).center_of_symmetry(),
                    cr.radius),
              invariance_tolerance);
    EXPECT_LE(ST::descriptor_distance(descriptor, ST::symmetry_descriptor_of_points(far_points, grid_32)), invariance_tolerance);
    EXPECT_NEAR(ST::symmetry_distance_error_of_points(far_points, moved(turned, m)), error, invariance_tolerance);
  }
  // The planes of oriented samples are approximate (the samples near an edge have mirror images
  // on the next face): exact translates, a million radii apart, give the same planes.
  const Translates<std::vector<Point_with_normal>> t = exact_translates(oriented, far_motion(rng, far_radii, radius));
  const Center_and_radius cr = center_and_radius(moved(s, t.motion).mesh);
  const std::vector<Symmetry> here = ST::detect_principal_symmetries_of_points(t.here, with_normals);
  ASSERT_EQ(here.size(), 3u);
  EXPECT_TRUE(same_planes(planes_of(here, t.motion), planes_of(ST::detect_principal_symmetries_of_points(t.there, with_normals)),
                          cr.center, cr.radius));
}

// Exact translates (see exact_translates()) a million radii apart: the transforms, the centre of
// the PST, the descriptor, the error and the supports of a plane and the segments of the one are
// those of the other, moved. (The refined planes, axes and frames of approximate symmetries are
// not compared: their refinements still query closest points in the input's coordinates, and a
// flat ridge turns a change at that rounding level into one of up to 1e-4; the manual, section
// Invariance and Determinism.)
TEST(Position, ExactTranslatesAMillionRadiiApartGiveTheSameTransformsErrorsAndSegments)
{
  CGAL::Random rng(25);
  for(const Shape<Surface_mesh>& s : {test_shape(), test_box()}) {
    const double radius = center_and_radius(s.mesh).radius;
    const Translates<Shape<Surface_mesh>> t = exact_translates(s, far_motion(rng, far_radii, radius));
    const ST::Point_symmetry_transform<K> here = ST::point_symmetry_transform(t.here.mesh, grid_32),
                                          there = ST::point_symmetry_transform(t.there.mesh, grid_32);
    EXPECT_LE(max_abs_difference(here.grid().values(), there.grid().values()), invariance_tolerance);
    EXPECT_LE(apart(t.motion.transform(here.center_of_symmetry()), there.center_of_symmetry(), radius), invariance_tolerance);
    // A Monte Carlo vote drawn at the edge of its voxel's probability interval may go to the
    // next voxel (the GEDTs differ by 1e-10): the transforms agree far within their error (1e-2).
    EXPECT_LE(relative_l2_error(ST::reflective_symmetry_transform(t.here.mesh, grid_32).values(),
                                ST::reflective_symmetry_transform(t.there.mesh, grid_32).values()),
              monte_carlo_invariance_tolerance);
    EXPECT_LE(ST::descriptor_distance(ST::symmetry_descriptor(t.here.mesh, grid_32), ST::symmetry_descriptor(t.there.mesh, grid_32)),
              invariance_tolerance);
    const Plane_3 turned = rotated_plane(t.here.planes.front(), center_and_radius(t.here.mesh).center, Vector_3(0, 0, 1), 5.);
    EXPECT_NEAR(ST::symmetry_distance_error(t.there.mesh, moved(turned, t.motion)), ST::symmetry_distance_error(t.here.mesh, turned),
                invariance_tolerance);
    std::vector<double> supports_here(num_faces(t.here.mesh)), supports_there(num_faces(t.there.mesh));
    EXPECT_NEAR(ST::symmetry_support(t.there.mesh, moved(turned, t.motion), CGAL::make_property_map(supports_there)),
                ST::symmetry_support(t.here.mesh, turned, CGAL::make_property_map(supports_here)), invariance_tolerance);
    EXPECT_LE(max_abs_difference(supports_here, supports_there), invariance_tolerance);
    std::vector<std::size_t> segments_here(num_faces(t.here.mesh)), segments_there(num_faces(t.there.mesh));
    ST::segment_by_symmetry(t.here.mesh, CGAL::make_property_map(segments_here), grid_32.max_segmentation_depth(1));
    ST::segment_by_symmetry(t.there.mesh, CGAL::make_property_map(segments_there), grid_32.max_segmentation_depth(1));
    EXPECT_EQ(segments_here, segments_there);
  }
}

// The soup of a box a million radii away: its frame, the centre of its PST, the error and the
// support of a plane move with it (the planes: InputForm below).
TEST(Position, SoupFormsMoveWithTheirPointsAMillionRadiiAway)
{
  CGAL::Random rng(24);
  const Shape<Surface_mesh> s = test_box();
  const Motion m = far_motion(rng, far_radii, center_and_radius(s.mesh).radius);
  const Shape<Surface_mesh> far = moved(s, m);
  const double radius = center_and_radius(far.mesh).radius;
  const Soup here = soup_of(s.mesh), there = soup_of(far.mesh);
  const ST::Symmetry_frame<K> frame = ST::symmetry_frame_of_triangle_soup(here.points, here.triangles, grid_32),
                              far_frame = ST::symmetry_frame_of_triangle_soup(there.points, there.triangles, grid_32);
  EXPECT_LE(apart(moved(frame, m).center, far_frame.center, radius), invariance_tolerance);
  EXPECT_LE(largest_axis_sine(moved(frame, m), far_frame), invariance_tolerance);
  EXPECT_LE(apart(m.transform(ST::point_symmetry_transform_of_triangle_soup(here.points, here.triangles, grid_32).center_of_symmetry()),
                  ST::point_symmetry_transform_of_triangle_soup(there.points, there.triangles, grid_32).center_of_symmetry(), radius),
            invariance_tolerance);
  const Plane_3 turned = rotated_plane(s.planes.front(), center_and_radius(s.mesh).center, Vector_3(0, 1, 0), 5.);
  EXPECT_NEAR(ST::symmetry_distance_error_of_triangle_soup(there.points, there.triangles, moved(turned, m)),
              ST::symmetry_distance_error_of_triangle_soup(here.points, here.triangles, turned), invariance_tolerance);
  std::vector<double> supports_here, supports_there;
  EXPECT_NEAR(ST::symmetry_support_of_triangle_soup(there.points, there.triangles, moved(turned, m), std::back_inserter(supports_there)),
              ST::symmetry_support_of_triangle_soup(here.points, here.triangles, turned, std::back_inserter(supports_here)),
              invariance_tolerance);
  ASSERT_EQ(supports_here.size(), supports_there.size());
  for(std::size_t f = 0; f < supports_here.size(); ++f) EXPECT_NEAR(supports_here[f], supports_there[f], invariance_tolerance);
}
