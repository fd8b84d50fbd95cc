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

#include "Symmetry_transform_test_shapes.h"

#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace ST = CGAL::Symmetry_transform;
using namespace st_test;

namespace {

typedef ST::Principal_symmetry<K> Symmetry;
typedef ST::Rotational_symmetry<K> Axis;

const std::array<unsigned, 4> thread_counts = {1, 2, 3, 8};
// A shape a million radii from the origin: its coordinates keep about ten digits of its size.
constexpr double far_radii = 1e6;
// What "the moved result" means here: normals to 1e-6, positions to 1e-6 of the radius.
constexpr double invariance_tolerance = 1e-6;

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
  if(here.size() == shape.planes.size()) EXPECT_TRUE(same_planes(planes_of(here, m), planes_of(there), cr.center, cr.radius));
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
