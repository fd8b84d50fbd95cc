// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Rotational symmetries: on shapes symmetric by construction (Rotational_symmetry_test_shapes.h),
// under random similarities, the axis is the true one to 0.1 degree and 0.1 % of the radius and
// the order exact, for k = 2 ... 8, with mirror planes (straight star solids) and without
// (twisted star solids, propellers); surfaces of revolution are continuous; a box of three
// different sides has its three 2-fold axes; 0.2 % vertex noise keeps the axis within 1 degree,
// a fifth of the surface cut away within 2 degrees, both with the exact order; shapes with no
// rotational symmetry (but a mirror plane, a centre of symmetry, or nothing) return nothing;
// max_order caps the order at a divisor; point sets work; Surface_mesh and Polyhedron_3 agree;
// runs are deterministic; symmetry_measure(grid, rotation) and rotation_about_axis() have their
// known values; bad input is rejected.
//
// Axis errors: the angle between the directions, up to orientation, and the distance from the
// found axis's point nearest to the centre (area-weighted centroid) to the true axis, over the
// radius R (largest distance from the centre to a vertex); both computed here
// (Symmetry_transform_test_shapes.h).

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/rotation/candidate_axes.h>
#include <CGAL/Symmetry_transform/point_group.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "Rotational_symmetry_test_shapes.h"
#include "Symmetry_group_test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Rotational_symmetry<K> Rotation;
typedef std::vector<Rotation> Rotations;

const auto defaults = CGAL::parameters::random_seed(1);

struct Axis_error
{
  double degrees = 1e9;
  double offset = 1e9; // fraction of the radius
};

Vector_3 unit(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

Axis_error axis_error(const Line_3& found, const Line_3& truth, const Center_and_radius& frame)
{
  const Vector_3 a = unit(found.to_vector()), b = unit(truth.to_vector());
  const double degrees = std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), std::abs(a * b)) * 180. / CGAL_PI;
  return {degrees, std::sqrt(CGAL::squared_distance(truth, found.projection(frame.center))) / frame.radius};
}

struct Worst
{
  double degrees = 0., offset = 0.;
  void add(const Axis_error& e)
  {
    degrees = (std::max)(degrees, e.degrees);
    offset = (std::max)(offset, e.offset);
  }
  std::string text() const
  {
    std::ostringstream out;
    out << degrees << " deg and " << 100. * offset << " % R";
    return out.str();
  }
};

std::string describe(const Rotations& found, const Center_and_radius& frame, const std::vector<Line_3>& truth = {})
{
  std::ostringstream out;
  for(const Rotation& r : found) {
    out << "  order " << r.order << " SM " << r.symmetry << " support " << r.support << " direction ("
        << unit(r.axis.to_vector()) << ")";
    for(const Line_3& t : truth) {
      const Axis_error e = axis_error(r.axis, t, frame);
      out << "  [" << e.degrees << " deg, " << 100. * e.offset << " % R]";
    }
    out << "\n";
  }
  return out.str();
}

// The shape moved by a random similarity; detection; exactly one axis expected, of order k,
// within the tolerance of the moved z axis. Returns its error; `found` receives the detection.
Axis_error expect_single_axis(const std::string& what, Surface_mesh mesh, int k, CGAL::Random& rng, double max_degrees,
                              double max_offset, Rotations* detected = nullptr)
{
  const Motion motion = random_motion(rng);
  CGAL::Polygon_mesh_processing::transform(motion, mesh);
  const Line_3 truth = moved(z_axis(), motion);
  const Center_and_radius frame = center_and_radius(mesh);
  const Rotations found = ST::detect_rotational_symmetries(mesh, defaults);
  if(detected != nullptr) *detected = found;
  std::cout << what << ":\n" << describe(found, frame, {truth});
  if(found.size() != 1) {
    ADD_FAILURE() << what << ": " << found.size() << " axes found, 1 expected\n" << describe(found, frame, {truth});
    return {};
  }
  const Axis_error e = axis_error(found.front().axis, truth, frame);
  EXPECT_EQ(found.front().order, k) << what;
  EXPECT_LE(e.degrees, max_degrees) << what;
  EXPECT_LE(e.offset, max_offset) << what;
  return e;
}

// ------------------------------------------------------------------------------------------
// k-fold shapes, exact
// ------------------------------------------------------------------------------------------

// The accuracy promised: 0.1 degree and 0.1 % of the radius, the order exact, one axis only.
void expect_exact_axes(const std::string& family, double twist_degrees, unsigned seed)
{
  CGAL::Random rng(seed);
  Worst worst;
  for(int k = 2; k <= 8; ++k)
    for(int trial = 0; trial < 2; ++trial)
      worst.add(expect_single_axis(family + " k = " + std::to_string(k) + ", motion " + std::to_string(trial),
                                   star_solid<Surface_mesh>(k, twist_degrees), k, rng, 0.1, 0.001));
  std::cout << family << ", k = 2 ... 8: axis at most " << worst.text() << " from the true one\n";
}

// Straight star solids: k mirror planes through the axis.
TEST(RotationalSymmetries, FindsAxisAndOrderOfStarSolidsWithMirrorPlanes)
{
  expect_exact_axes("star solid", 0., 1701);
}

// Twisted by 40 degrees: no mirror plane at all.
TEST(RotationalSymmetries, FindsAxisAndOrderOfTwistedStarSolidsWithoutMirrorPlanes)
{
  expect_exact_axes("twisted star solid", 40., 1702);
}

// Propellers: pitched and skewed blades on a tapered hub, no mirror plane.
TEST(RotationalSymmetries, FindsAxisAndOrderOfPropellers)
{
  CGAL::Random rng(1703);
  Worst worst;
  for(int k = 2; k <= 8; ++k)
    worst.add(expect_single_axis("propeller k = " + std::to_string(k), propeller<Surface_mesh>(k), k, rng, 0.1, 0.001));
  std::cout << "propellers, k = 2 ... 8: axis at most " << worst.text() << " from the true one\n";
}

// A vase turned in 96 sides, and the same with 0.2 % vertex noise: continuous (order 0).
TEST(RotationalSymmetries, ReportsSurfaceOfRevolutionAsContinuous)
{
  CGAL::Random rng(1704);
  Worst worst;
  for(int trial = 0; trial < 2; ++trial)
    worst.add(expect_single_axis("vase, motion " + std::to_string(trial), vase<Surface_mesh>(), 0, rng, 0.1, 0.001));
  Surface_mesh noisy = vase<Surface_mesh>();
  add_vertex_noise(noisy, 0.002 * center_and_radius(noisy).radius, rng);
  worst.add(expect_single_axis("vase with 0.2 % noise", noisy, 0, rng, 1., 0.01));
  std::cout << "vase: continuous axis at most " << worst.text() << " from the true one\n";
}

// A box of sides 2, 1.4 and 0.9: three 2-fold axes, each the meeting line of two of its planes.
TEST(RotationalSymmetries, BoxWithThreeDifferentSidesHasThreeTwoFoldAxes)
{
  CGAL::Random rng(1705);
  Worst worst;
  for(int trial = 0; trial < 2; ++trial) {
    const Motion motion = random_motion(rng);
    const Shape<Surface_mesh> s = moved(box<Surface_mesh>(), motion);
    const Center_and_radius frame = center_and_radius(s.mesh);
    std::vector<Line_3> truth;
    for(const Vector_3& d : {Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1)})
      truth.push_back(moved(Line_3(CGAL::ORIGIN, d), motion));
    const Rotations found = ST::detect_rotational_symmetries(s.mesh, defaults);
    std::cout << "box, motion " << trial << ":\n" << describe(found, frame, truth);
    ASSERT_EQ(found.size(), 3u) << describe(found, frame, truth);
    for(const Line_3& t : truth) {
      Axis_error best;
      for(const Rotation& r : found) {
        EXPECT_EQ(r.order, 2);
        const Axis_error e = axis_error(r.axis, t, frame);
        if(e.degrees < best.degrees) best = e;
      }
      EXPECT_LE(best.degrees, 0.1);
      EXPECT_LE(best.offset, 0.001);
      worst.add(best);
    }
  }
  std::cout << "box: each true axis found within " << worst.text() << "\n";
}

// ------------------------------------------------------------------------------------------
// Noise and missing parts
// ------------------------------------------------------------------------------------------

// Gaussian noise of 0.2 % of the radius on every vertex coordinate (star solids, straight for
// even k, twisted for odd k): within 1 degree and 1 % of the radius, the order exact.
TEST(RotationalSymmetries, AxisAndOrderSurviveGaussianVertexNoise)
{
  CGAL::Random rng(1706);
  Worst worst;
  for(int k = 2; k <= 8; ++k) {
    Surface_mesh mesh = star_solid<Surface_mesh>(k, k % 2 == 0 ? 0. : 40.);
    add_vertex_noise(mesh, 0.002 * center_and_radius(mesh).radius, rng);
    worst.add(expect_single_axis("star solid with noise, k = " + std::to_string(k), mesh, k, rng, 1., 0.01));
  }
  std::cout << "star solids with 0.2 % noise: axis at most " << worst.text() << " from the true one\n";
}

// A fifth of the area cut away by a plane oblique to the axis (normal (0.8, 0.3, 0.5) in the
// shape's frame: it takes a side and part of an end off, and moves the centre of mass off the
// axis), the cut left open. The cut must break the symmetry: the true rotation maps less than
// 0.95 of what is left onto it (checked; measured: see the output). Target: within 2 degrees
// and 2 % of the radius, the order exact.
TEST(RotationalSymmetries, AxisAndOrderSurviveAFifthOfTheSurfaceCutAway)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  CGAL::Random rng(1707);
  Worst worst;
  double most_supported = 0.;
  for(int k = 2; k <= 8; ++k) {
    const Surface_mesh whole = star_solid<Surface_mesh>(k, k % 2 == 0 ? 40. : 0.);
    const Surface_mesh cut = cut_away(whole, Vector_3(0.8, 0.3, 0.5), 0.2);
    EXPECT_NEAR(1. - PMP::area(cut) / PMP::area(whole), 0.2, 0.005);
    Rotations found;
    worst.add(expect_single_axis("star solid with a fifth cut away, k = " + std::to_string(k), cut, k, rng, 2., 0.02, &found));
    for(const Rotation& r : found) {
      most_supported = (std::max)(most_supported, double(r.support));
      EXPECT_LT(r.support, 0.95) << "k = " << k << ": the cut should break the symmetry";
    }
  }
  std::cout << "star solids with a fifth cut away (true rotation supported at most " << most_supported
            << "): axis at most " << worst.text() << " from the true one\n";
}

// ------------------------------------------------------------------------------------------
// No rotational symmetry
// ------------------------------------------------------------------------------------------

// Random convex hulls (no symmetry), a hull with one mirror plane and a hull with a centre of
// symmetry: neither a reflection nor the point reflection is a rotation, and nothing is returned
// (no rotation maps 70 % of the surface to within sigma / 2 of it).
TEST(RotationalSymmetries, ShapesWithNoRotationalSymmetryReturnNothing)
{
  CGAL::Random rng(1708);
  std::vector<std::pair<std::string, Surface_mesh>> shapes;
  for(unsigned seed : {3u, 4u, 5u}) shapes.emplace_back("random hull " + std::to_string(seed), random_hull<Surface_mesh>(seed).mesh);
  shapes.emplace_back("one-plane hull", one_plane_hull<Surface_mesh>().mesh);
  shapes.emplace_back("centrally symmetric hull", centrally_symmetric_hull<Surface_mesh>().mesh);
  for(auto& [name, mesh] : shapes) {
    CGAL::Polygon_mesh_processing::transform(random_motion(rng), mesh);
    const Rotations found = ST::detect_rotational_symmetries(mesh, defaults.verbose(true));
    EXPECT_TRUE(found.empty()) << name << ":\n" << describe(found, center_and_radius(mesh));
  }
}

// ------------------------------------------------------------------------------------------
// max_order
// ------------------------------------------------------------------------------------------

// Orders above max_order are reported at their largest divisor within it: a 6-fold star solid
// is 3-fold with max_order 4 and 5, a 8-fold one 4-fold with max_order 6; 6-fold with max_order 6.
TEST(RotationalSymmetries, MaxOrderCapsTheOrderAtALargestDivisor)
{
  CGAL::Random rng(1709);
  const struct { int k, max_order, expected; } cases[] = {{6, 4, 3}, {6, 5, 3}, {8, 6, 4}, {6, 6, 6}, {5, 4, -1}};
  for(const auto& c : cases) {
    Surface_mesh mesh = star_solid<Surface_mesh>(c.k, 40.);
    CGAL::Polygon_mesh_processing::transform(random_motion(rng), mesh);
    const Rotations found = ST::detect_rotational_symmetries(mesh, defaults.max_order(c.max_order));
    const std::string what = std::to_string(c.k) + "-fold, max_order " + std::to_string(c.max_order);
    if(c.expected < 0) {
      EXPECT_TRUE(found.empty()) << what << ": 5 has no divisor in 2 ... 4\n" << describe(found, center_and_radius(mesh));
      continue;
    }
    ASSERT_EQ(found.size(), 1u) << what << "\n" << describe(found, center_and_radius(mesh));
    EXPECT_EQ(found.front().order, c.expected) << what;
  }
}

// ------------------------------------------------------------------------------------------
// Point sets, mesh types, determinism, the representative of the axis
// ------------------------------------------------------------------------------------------

// 5000 points on twisted star solids (k = 3, 5, 6) under random similarities: the normals are
// estimated from the neighbours and the matches are the nearest points, so the sampling (mean
// spacing about 0.03 R) limits the accuracy: tolerance 0.5 degree and 0.5 % R, the order exact.
TEST(RotationalSymmetries, OfPointsRecoversAxisAndOrderFromSurfaceSamples)
{
  CGAL::Random rng(1710);
  Worst worst;
  for(int k : {3, 5, 6}) {
    Surface_mesh mesh = star_solid<Surface_mesh>(k, 40.);
    const Motion motion = random_motion(rng);
    CGAL::Polygon_mesh_processing::transform(motion, mesh);
    const Line_3 truth = moved(z_axis(), motion);
    const std::vector<Point_3> points = surface_points(mesh, 5000, rng);
    const Center_and_radius frame = center_and_radius(mesh);
    const Rotations found = ST::detect_rotational_symmetries_of_points(points, defaults);
    std::cout << "points on a twisted star solid, k = " << k << ":\n" << describe(found, frame, {truth});
    ASSERT_EQ(found.size(), 1u) << "k = " << k;
    EXPECT_EQ(found.front().order, k);
    const Axis_error e = axis_error(found.front().axis, truth, frame);
    EXPECT_LE(e.degrees, 0.5);
    EXPECT_LE(e.offset, 0.005);
    worst.add(e);
  }
  std::cout << "points on twisted star solids: axis at most " << worst.text() << " from the true one\n";
}

// Equal within `tolerance` (coordinates of the axis's point and direction, symmetry, support).
::testing::AssertionResult same_rotations(const Rotations& a, const Rotations& b, double tolerance)
{
  if(a.size() != b.size()) return ::testing::AssertionFailure() << a.size() << " vs " << b.size() << " axes";
  for(std::size_t i = 0; i < a.size(); ++i) {
    const Point_3 p = a[i].axis.point(), q = b[i].axis.point();
    const Vector_3 u = a[i].axis.to_vector(), v = b[i].axis.to_vector();
    const double d = (std::max)({std::abs(p.x() - q.x()), std::abs(p.y() - q.y()), std::abs(p.z() - q.z()),
                                 std::abs(u.x() - v.x()), std::abs(u.y() - v.y()), std::abs(u.z() - v.z()),
                                 std::abs(a[i].symmetry - b[i].symmetry), std::abs(a[i].support - b[i].support)});
    if(a[i].order != b[i].order || !(d <= tolerance))
      return ::testing::AssertionFailure() << "axis " << i << ": orders " << a[i].order << " and " << b[i].order
                                           << ", difference " << d;
  }
  return ::testing::AssertionSuccess();
}

// The same soup as a Surface_mesh and as a Polyhedron_3 (same triangles in the same order, each
// starting at the same corner): the same axes within 1e-9.
TEST(RotationalSymmetries, SurfaceMeshAndPolyhedronGiveTheSameAxes)
{
  CGAL::Random rng(1711);
  for(const Soup& soup : {star_solid_soup(5, 40.), star_solid_soup(4, 0.)}) {
    const Motion motion = random_motion(rng);
    Surface_mesh sm = soup.mesh<Surface_mesh>();
    Polyhedron poly = soup.mesh<Polyhedron>();
    CGAL::Polygon_mesh_processing::transform(motion, sm);
    CGAL::Polygon_mesh_processing::transform(motion, poly);
    const Rotations a = ST::detect_rotational_symmetries(sm, defaults), b = ST::detect_rotational_symmetries(poly, defaults);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(same_rotations(a, b, 1e-9));
  }
}

// Same seed: bitwise identical axes (with the default number of threads, which splits the work
// the same way each time); another seed (other surface samples): the same axis within 1e-6
// degree and 1e-6 of the radius, and the same order.
TEST(RotationalSymmetries, SameSeedGivesIdenticalAxes)
{
  CGAL::Random rng(1712);
  Surface_mesh mesh = star_solid<Surface_mesh>(6, 40.);
  CGAL::Polygon_mesh_processing::transform(random_motion(rng), mesh);
  const Rotations a = ST::detect_rotational_symmetries(mesh, CGAL::parameters::random_seed(7));
  const Rotations b = ST::detect_rotational_symmetries(mesh, CGAL::parameters::random_seed(7));
  const Rotations c = ST::detect_rotational_symmetries(mesh, CGAL::parameters::random_seed(8));
  ASSERT_EQ(a.size(), 1u);
  EXPECT_TRUE(same_rotations(a, b, 0.));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(a.front().order, c.front().order);
  const Axis_error e = axis_error(a.front().axis, c.front().axis, center_and_radius(mesh));
  EXPECT_LE(e.degrees, 1e-6);
  EXPECT_LE(e.offset, 1e-6);
}

// As documented: the axis passes through its point nearest to the centre of mass, and its
// direction is a unit vector whose largest coordinate is positive; the axes are sorted by
// symmetry measure to three decimals, then by decreasing order.
TEST(RotationalSymmetries, AxisIsTheDocumentedRepresentative)
{
  CGAL::Random rng(1713);
  const Shape<Surface_mesh> s = moved(box<Surface_mesh>(), random_motion(rng));
  const Center_and_radius frame = center_and_radius(s.mesh);
  const Rotations found = ST::detect_rotational_symmetries(s.mesh, defaults);
  ASSERT_EQ(found.size(), 3u);
  for(const Rotation& r : found) {
    EXPECT_LE(std::sqrt(CGAL::squared_distance(r.axis.point(), r.axis.projection(frame.center))), 1e-9 * frame.radius);
    const Vector_3 d = r.axis.to_vector();
    EXPECT_NEAR(d.squared_length(), 1., 1e-12);
    const double largest = (std::max)({std::abs(d.x()), std::abs(d.y()), std::abs(d.z())});
    EXPECT_TRUE(d.x() == largest || d.y() == largest || d.z() == largest) << d;
  }
  for(std::size_t i = 1; i < found.size(); ++i) EXPECT_GE(found[i - 1].symmetry, found[i].symmetry);
  // A 6-fold star solid with its mirror planes: the 6-fold axis only (no flip). A box's three
  // flips measure alike; a hexagonal prism (the star without taper) has a 6-fold axis and six
  // flips measuring alike: the 6-fold one first.
  Soup prism = star_solid_soup(6, 0., 2, 0.5, 1.2, 0.);
  Surface_mesh mesh = prism.mesh<Surface_mesh>();
  CGAL::Polygon_mesh_processing::transform(random_motion(rng), mesh);
  const Rotations axes = ST::detect_rotational_symmetries(mesh, defaults);
  std::cout << "untapered 6-pointed star prism:\n" << describe(axes, center_and_radius(mesh));
  ASSERT_EQ(axes.size(), 7u);
  EXPECT_EQ(axes.front().order, 6);
  for(std::size_t i = 1; i < axes.size(); ++i) {
    EXPECT_EQ(axes[i].order, 2);
    EXPECT_GE(std::lround(1000. * axes[i - 1].symmetry), std::lround(1000. * axes[i].symmetry));
  }
}

// ------------------------------------------------------------------------------------------
// Candidates from planes of symmetry
// ------------------------------------------------------------------------------------------

// Two planes through the z axis at an angle pi k' / k (k' prime to k) meet along the axis of a
// rotation by 2 pi k' / k: candidate of order k. Parallel planes and an angle 4 degrees from
// every such fraction with k <= 12 (86 degrees) give none.
TEST(RotationalSymmetries, PlanePairsMeetingAtPiOverKGiveTheirAxis)
{
  namespace STI = ST::internal;
  auto plane_at = [](double degrees, const Eigen::Vector3d& shift) {
    const double a = degrees * CGAL_PI / 180.;
    const Eigen::Vector3d n(std::cos(a), std::sin(a), 0.);
    return STI::Dplane{n, n.dot(shift)};
  };
  const Eigen::Vector3d point(0.3, -0.2, 0.), center(0.3, -0.2, 5.);
  const struct { double degrees; int order; } cases[] = {{90., 2}, {60., 3}, {45., 4}, {36., 5}, {72., 5}, {30., 6},
                                                         {90. / 3.5, 7}, {22.5, 8}, {67.5, 8}, {15., 12}};
  for(const auto& c : cases) {
    const auto found = STI::plane_pair_candidates({plane_at(10., point), plane_at(10. + c.degrees, point)}, 12, center);
    ASSERT_EQ(found.size(), 1u) << c.degrees << " degrees";
    EXPECT_EQ(found.front().order, c.order) << c.degrees << " degrees";
    EXPECT_NEAR(std::abs(found.front().axis.direction.z()), 1., 1e-12);
    EXPECT_LE((found.front().axis.point - Eigen::Vector3d(0.3, -0.2, 5.)).norm(), 1e-12) << "the point nearest to the centre";
  }
  EXPECT_TRUE(STI::plane_pair_candidates({plane_at(10., point), plane_at(10.5, point)}, 12, center).empty());
  EXPECT_TRUE(STI::plane_pair_candidates({plane_at(10., point), plane_at(96., point)}, 12, center).empty());
  EXPECT_TRUE(STI::plane_pair_candidates({plane_at(10., point), plane_at(40., point)}, 5, center).empty())
    << "order 6 is above max_order 5";
}

// With the three planes of a box given, the same three axes as without.
TEST(RotationalSymmetries, GivenPlanesGiveTheSameAxesOfABox)
{
  CGAL::Random rng(1714);
  const Shape<Surface_mesh> s = moved(box<Surface_mesh>(), random_motion(rng));
  std::vector<ST::Principal_symmetry<K>> planes;
  for(const Plane_3& p : s.planes) planes.push_back({p, 1., 1.});
  const Rotations with = ST::rotational_symmetries(s.mesh, planes, defaults);
  const Rotations without = ST::detect_rotational_symmetries(s.mesh, defaults);
  ASSERT_EQ(with.size(), 3u);
  EXPECT_TRUE(same_rotations(with, without, 1e-9));
}

// ------------------------------------------------------------------------------------------
// symmetry_measure(grid, rotation) and rotation_about_axis()
// ------------------------------------------------------------------------------------------

// On the GEDT of a 5-fold star solid turned at random: the identity measures 1; the rotation by
// 2 pi / 5 about the axis almost 1 (the interpolation error); by pi / 5 (half a step) much less;
// a reflection given as a transformation measures as the same plane given as a plane.
TEST(RotationalSymmetries, SymmetryMeasureOfRotationsHasItsKnownValues)
{
  CGAL::Random rng(1715);
  Surface_mesh mesh = star_solid<Surface_mesh>(5, 0.);
  const Motion motion = random_motion(rng);
  CGAL::Polygon_mesh_processing::transform(motion, mesh);
  const Grid f = ST::gaussian_distance_transform(mesh, CGAL::parameters::grid_resolution(48));
  const Line_3 axis = moved(z_axis(), motion);
  EXPECT_NEAR(ST::symmetry_measure(f, K::Aff_transformation_3(CGAL::IDENTITY)), 1., 1e-12);
  const double step = ST::symmetry_measure(f, ST::rotation_about_axis(axis, 2. * CGAL_PI / 5.));
  const double half = ST::symmetry_measure(f, ST::rotation_about_axis(axis, CGAL_PI / 5.));
  std::cout << "5-fold star: SM of the rotation by 72 degrees " << step << ", by 36 degrees " << half << "\n";
  EXPECT_GE(step, 0.99);
  EXPECT_LE(half, 0.8);
  const Plane_3 plane = moved(Plane_3(0.3, -0.5, 0.8, 0.1), motion);
  const Vector_3 n = unit(plane.orthogonal_vector());
  const double d = plane.d() / std::sqrt(plane.orthogonal_vector().squared_length());
  const K::Aff_transformation_3 reflection(1 - 2 * n.x() * n.x(), -2 * n.x() * n.y(), -2 * n.x() * n.z(), -2 * d * n.x(),
                                           -2 * n.y() * n.x(), 1 - 2 * n.y() * n.y(), -2 * n.y() * n.z(), -2 * d * n.y(),
                                           -2 * n.z() * n.x(), -2 * n.z() * n.y(), 1 - 2 * n.z() * n.z(), -2 * d * n.z());
  EXPECT_NEAR(ST::symmetry_measure(f, reflection), ST::symmetry_measure(f, plane), 1e-12);
}

// The rotation fixes the axis, turns a vector u normal to it into cos(a) u + sin(a) d x u (d the
// unit direction: counterclockwise seen from its tip), and its k-th power by 2 pi / k is the
// identity.
TEST(RotationalSymmetries, RotationAboutAxisIsThatRotation)
{
  const Line_3 axis(Point_3(1., -2., 0.5), Vector_3(1., 2., 2.));
  const Vector_3 d = unit(axis.to_vector()), u = unit(CGAL::cross_product(d, Vector_3(0., 0., 1.)));
  const double a = 0.7;
  const K::Aff_transformation_3 r = ST::rotation_about_axis(axis, a);
  for(double s : {-3., 0., 2.5}) {
    const Point_3 p = axis.point() + s * d;
    EXPECT_LE(std::sqrt(CGAL::squared_distance(r.transform(p), p)), 1e-12);
  }
  const Vector_3 image = r.transform(u), expected = std::cos(a) * u + std::sin(a) * CGAL::cross_product(d, u);
  EXPECT_LE(std::sqrt((image - expected).squared_length()), 1e-12);
  for(int k = 2; k <= 8; ++k) {
    const K::Aff_transformation_3 step = ST::rotation_about_axis(axis, 2. * CGAL_PI / k);
    K::Aff_transformation_3 power(CGAL::IDENTITY);
    for(int j = 0; j < k; ++j) power = step * power;
    const Point_3 q(0.3, 4., -1.);
    EXPECT_LE(std::sqrt(CGAL::squared_distance(power.transform(q), q)), 1e-12) << "k = " << k;
  }
}

// ------------------------------------------------------------------------------------------
// Bad input
// ------------------------------------------------------------------------------------------

// ------------------------------------------------------------------------------------------
// Point groups
// ------------------------------------------------------------------------------------------

// The exact symmetries of a shape whose group is known, as the detections return them.
ST::Point_group group_of_known(const Group_shape& shape)
{
  std::vector<ST::Principal_symmetry<K>> planes;
  for(const Plane_3& p : shape.planes) planes.push_back({p, 1., 1.});
  Rotations axes;
  for(const Known_axis& a : shape.axes) axes.push_back({a.axis, a.order, 1., 1.});
  return ST::point_group(planes, axes);
}

TEST(PointGroup, NamesTheGroupsOfTheKnownShapes)
{
  for(int n = 3; n <= 12; ++n) {
    EXPECT_EQ(group_of_known(regular_prism(n)).name, "D" + std::to_string(n) + "h");
    EXPECT_EQ(group_of_known(regular_prism(n)).order, std::size_t(4 * n));
    EXPECT_EQ(group_of_known(regular_antiprism(n)).name, "D" + std::to_string(n) + "d");
  }
  const std::vector<Group_shape> solids = platonic_solids();
  const char* names[] = {"Td", "Oh", "Oh", "Ih", "Ih"};
  const std::size_t orders[] = {24, 48, 48, 120, 120};
  for(std::size_t i = 0; i < solids.size(); ++i) {
    EXPECT_EQ(group_of_known(solids[i]).name, names[i]);
    EXPECT_EQ(group_of_known(solids[i]).order, orders[i]);
  }
  EXPECT_EQ(group_of_known(box_shape(1., 1., 1.6)).name, "D4h");
  EXPECT_EQ(group_of_known(box_shape(1., 0.7, 0.45)).name, "D2h");
  EXPECT_EQ(group_of_known(flat_polygon(5)).name, "D5h");
  EXPECT_EQ(group_of_known(flat_rectangle()).name, "D2h");
}

// Groups of few elements and continuous ones, from symmetries written out; approximate
// symmetries (support below min_support) do not count.
TEST(PointGroup, NamesCyclicAndContinuousGroupsAndLeavesApproximateSymmetriesOut)
{
  typedef std::vector<ST::Principal_symmetry<K>> Planes;
  const Line_3 z(CGAL::ORIGIN, Vector_3(0, 0, 1)), x(CGAL::ORIGIN, Vector_3(1, 0, 0));
  const Plane_3 xy(0, 0, 1, 0), yz(1, 0, 0, 0), xz(0, 1, 0, 0);
  EXPECT_EQ(ST::point_group(Planes{}, Rotations{}).name, "C1");
  EXPECT_EQ(ST::point_group(Planes{{yz, 1., 1.}}, Rotations{}).name, "Cs");
  EXPECT_EQ(ST::point_group(Planes{{yz, 1., 0.7}}, Rotations{}).name, "C1");
  EXPECT_EQ(ST::point_group(Planes{}, Rotations{{z, 5, 1., 1.}}).name, "C5");
  EXPECT_EQ(ST::point_group(Planes{{yz, 1., 1.}, {xz, 1., 1.}}, Rotations{{z, 2, 1., 1.}}).name, "C2v");
  EXPECT_EQ(ST::point_group(Planes{{xy, 1., 1.}}, Rotations{{z, 4, 1., 1.}}).name, "C4h");
  EXPECT_EQ(ST::point_group(Planes{}, Rotations{{z, 2, 1., 1.}, {x, 2, 1., 1.}}).name, "D2");
  // D2d (a tetragonal disphenoid): of its three two-fold axes, the one with planes along it is the principal one.
  const Line_3 y(CGAL::ORIGIN, Vector_3(0, 1, 0));
  const Plane_3 diagonal(1, 1, 0, 0), other_diagonal(1, -1, 0, 0);
  EXPECT_EQ(ST::point_group(Planes{{diagonal, 1., 1.}, {other_diagonal, 1., 1.}},
                            Rotations{{x, 2, 1., 1.}, {y, 2, 1., 1.}, {z, 2, 1., 1.}}).name,
            "D2d");
  EXPECT_EQ(ST::point_group(Planes{{yz, 1., 1.}}, Rotations{{z, 0, 1., 1.}}).name, "Cinfv");
  EXPECT_EQ(ST::point_group(Planes{{yz, 1., 1.}, {xy, 1., 1.}}, Rotations{{z, 0, 1., 1.}}).name, "Dinfh");
  EXPECT_EQ(ST::point_group(Planes{}, Rotations{{z, 0, 1., 1.}, {x, 0, 1., 1.}}).name, "Kh");
  EXPECT_EQ(ST::point_group(Planes{}, Rotations{{z, 0, 1., 1.}}).order, 0u);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::point_group(Planes{}, Rotations{}, 1.5); }, "min_support"));
}

// The group of what the detections find, with their defaults, on shapes under random similarities.
TEST(PointGroup, DetectedSymmetriesNameTheGroup)
{
  CGAL::Random rng(31);
  const std::vector<Group_shape> solids = platonic_solids();
  const std::vector<std::pair<Group_shape, std::string>> cases = {
    {regular_prism(6), "D6h"}, {regular_antiprism(5), "D5d"}, {solids[0], "Td"}, {solids[1], "Oh"},
    {solids[4], "Ih"},         {box_shape(1., 0.7, 0.45), "D2h"}};
  for(const auto& [shape, name] : cases) {
    Surface_mesh mesh = shape.mesh;
    CGAL::Polygon_mesh_processing::transform(random_motion(rng), mesh);
    EXPECT_EQ(ST::point_group(ST::detect_principal_symmetries(mesh, defaults), ST::detect_rotational_symmetries(mesh, defaults)).name,
              name)
      << shape.name;
  }
  Surface_mesh star = star_solid<Surface_mesh>(5, 0.), twisted = star_solid<Surface_mesh>(4, 30.);
  EXPECT_EQ(ST::point_group(ST::detect_principal_symmetries(star, defaults), ST::detect_rotational_symmetries(star, defaults)).name,
            "C5v");
  EXPECT_EQ(ST::point_group(ST::detect_principal_symmetries(twisted, defaults),
                            ST::detect_rotational_symmetries(twisted, defaults)).name,
            "C4");
}

// Every rotation axis of `shape` under a random similarity found once, with its order, to 1e-3
// degree and 1e-5 of the radius; any other axis found weaker than the weakest of them, but for the
// flip that stands for those about a continuous axis across which the shape has a mirror (a
// cylinder's); the point group named `group`.
void expect_whole_rotation_group(const Group_shape& shape, const std::string& group, unsigned seed)
{
  SCOPED_TRACE(shape.name);
  CGAL::Random rng(seed);
  const Motion m = random_motion(rng);
  Surface_mesh mesh = shape.mesh;
  CGAL::Polygon_mesh_processing::transform(m, mesh);
  const Center_and_radius frame = center_and_radius(mesh);
  const Rotations found = ST::detect_rotational_symmetries(mesh, defaults);
  double weakest = 2.;
  std::vector<bool> is_true(found.size(), false);
  for(const Known_axis& a : shape.axes) {
    const Line_3 truth = moved(a.axis, m);
    std::size_t matches = 0;
    for(std::size_t i = 0; i < found.size(); ++i) {
      const Axis_error e = axis_error(found[i].axis, truth, frame);
      if(e.degrees > 1e-3 || e.offset > 1e-5) continue;
      ++matches;
      is_true[i] = true;
      weakest = (std::min)(weakest, found[i].symmetry);
      EXPECT_EQ(found[i].order, a.order) << describe(found, frame);
    }
    EXPECT_EQ(matches, 1u) << describe(found, frame, {truth});
  }
  for(std::size_t i = 0; i < found.size(); ++i) {
    const bool flip = found[i].order == 2 && shape.axes.size() == 1 && shape.axes.front().order == 0 && !shape.planes.empty();
    if(!is_true[i] && !flip) {
      EXPECT_LT(found[i].symmetry, weakest) << describe(found, frame);
    }
  }
  EXPECT_EQ(ST::point_group(ST::detect_principal_symmetries(mesh, defaults), found).name, group);
}

// Flat polygons: the supports of their area hold for any turn (a pentagon keeps 0.89 of it
// turned by a tenth of a turn); their orders are those of their borders, their flips exact.
TEST(RotationGroups, FlatPolygonsGetTheirAxesWithTheirOrders)
{
  for(int n : {3, 4, 5, 6, 8}) expect_whole_rotation_group(flat_polygon(n), "D" + std::to_string(n) + "h", unsigned(700 + n));
  expect_whole_rotation_group(flat_rectangle(), "D2h", 710);
}

// Two cubes 1e4 apart, blobs on the grid: the four-fold axis through both and the four flips
// between them, exact (no continuous axis), the group D4h.
TEST(RotationGroups, TwoCubesFarApartGetTheirFiveAxes)
{
  expect_whole_rotation_group(cubes_apart(1e4), "D4h", 720);
}

// A cylinder and a cone: the continuous axis, and the cylinder's flips stood for by one.
TEST(RotationGroups, CylinderAndConeGetTheirContinuousAxis)
{
  expect_whole_rotation_group(cylinder(), "Dinfh", 730);
  expect_whole_rotation_group(cone(), "Cinfv", 731);
}

TEST(RotationalSymmetriesBadInput, EmptyNonTriangleAndNonFiniteMeshesAreRejected)
{
  const Surface_mesh empty;
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::detect_rotational_symmetries(empty); }, "no face"));
  Surface_mesh quads;
  CGAL::make_hexahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0), Point_3(0, 1, 1),
                        Point_3(0, 0, 1), Point_3(1, 0, 1), Point_3(1, 1, 1), quads);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::detect_rotational_symmetries(quads); }, "not a triangle"));
  Surface_mesh nan = box<Surface_mesh>().mesh;
  nan.point(*vertices(nan).begin()) = Point_3(std::nan(""), 0, 0);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::detect_rotational_symmetries(nan); }, "NaN"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::detect_rotational_symmetries_of_points(std::vector<Point_3>()); }, "empty"));
}

TEST(RotationalSymmetriesBadInput, BadParametersPlanesAxesAndTransformationsAreRejected)
{
  const Surface_mesh mesh = box<Surface_mesh>().mesh;
  for(int k : {1, 0, -3})
    EXPECT_TRUE(throws_with_message<std::invalid_argument>(
      [&] { ST::detect_rotational_symmetries(mesh, CGAL::parameters::max_order(k)); }, "max_order"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::detect_rotational_symmetries_of_points(std::vector<Point_3>{Point_3(0, 0, 0)}, CGAL::parameters::max_order(1)); },
    "max_order"));
  const std::vector<ST::Principal_symmetry<K>> degenerate{{Plane_3(0, 0, 0, 1), 1., 1.}};
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::rotational_symmetries(mesh, degenerate); },
                                                         "degenerate plane"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::rotation_about_axis(Line_3(Point_3(nan, 0, 0), Vector_3(0, 0, 1)), 1.); }, "degenerate axis"));
  const Grid f = ST::gaussian_distance_transform(mesh, CGAL::parameters::grid_resolution(24));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetry_measure(f, K::Aff_transformation_3(CGAL::SCALING, 1.001)); }, "not a rigid motion"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetry_measure(f, K::Aff_transformation_3(CGAL::TRANSLATION, Vector_3(nan, 0, 0))); }, "NaN"));
}

} // namespace
