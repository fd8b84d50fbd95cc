// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Principal symmetries: on shapes symmetric by construction, under random similarities, the
// refined planes are the true ones to 0.1 degree and 0.1 % of the radius, and stay close under
// vertex noise and with a fifth of the surface cut away; shapes with several planes return all
// of them first, composite shapes the planes of each part; refine_symmetry_plane converges from
// a rough plane; Surface_mesh and Polyhedron_3 agree; runs are deterministic; point sets work;
// symmetry_support is a fraction per face; an asymmetric shape gets honest values; bad input is
// rejected.
//
// Angles are between normals, up to orientation; offsets are the difference of the planes'
// signed distances to the centre (area-weighted centroid), as a fraction of the radius R
// (largest distance from the centre to a vertex); both computed here, independently of the
// package (Symmetry_transform_test_shapes.h).

#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_cells.h>

#include "Symmetry_group_test_shapes.h"
#include "Symmetry_transform_test_shapes.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Symmetry_transform/internal/common/cgal_aabb.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Principal_symmetry<K> Symmetry;
typedef std::vector<Symmetry> Symmetries;

// 32^3 and 1e5 Monte Carlo pairs (a twentieth of the default) find the planes of the simple
// shapes below with the same accuracy as the defaults: ISP, not the transform, sets the accuracy,
// and the transform only has to put a candidate in the basin of each plane. Measured
// (2026-11-22): the tests of accuracy, noise, cuts, several planes, mesh types, points, support
// and asymmetry all passed with random seeds 1-6 at 2e4, 5e4, 1e5 and 2e5 pairs, 1e5 being the
// fastest (fewer pairs leave more noise maxima, each refined by ISP), until stays_near_bin
// started to compare offsets from the origin (see FindsAllPlanesOfBoxFarFromTheOrigin): since,
// some seeds drop true planes of the moved shapes. 64^3 (the default) where the Gaussian of 32^3
// (sigma about 0.1 R) is too wide for the property tested.
const auto grid_32 = CGAL::parameters::grid_resolution(32).number_of_samples(100000).random_seed(1);
const auto grid_64 = CGAL::parameters::grid_resolution(64).number_of_samples(100000).random_seed(1);

// The nearest true plane to a found one, and how far it is.
struct Deviation
{
  double degrees = 1e9;
  double offset = 1e9; // fraction of the radius
  std::size_t index = std::size_t(-1);
};

// Nearest in the sense degrees + 100 * offset (1 degree weighs as 1 % of the radius).
Deviation deviation(const Plane_3& found, const std::vector<Plane_3>& truth, const Center_and_radius& frame)
{
  Deviation best;
  for(std::size_t i = 0; i < truth.size(); ++i) {
    const double degrees = angle_between(found, truth[i]);
    const double offset = offset_between(found, truth[i], frame.center) / frame.radius;
    if(degrees + 100. * offset < best.degrees + 100. * best.offset) best = {degrees, offset, i};
  }
  return best;
}

std::string describe(const Plane_3& plane)
{
  const Plane_3 p = unit_plane(plane);
  std::ostringstream out;
  out << "(" << p.a() << ", " << p.b() << ", " << p.c() << ", " << p.d() << ")";
  return out.str();
}

// The found planes, each with its distance to the nearest true plane.
std::string describe(const Symmetries& found, const std::vector<Plane_3>& truth, const Center_and_radius& frame)
{
  std::ostringstream out;
  for(std::size_t i = 0; i < found.size(); ++i) {
    out << "  #" << i << " SM " << found[i].symmetry << " support " << found[i].support;
    if(!truth.empty()) {
      const Deviation d = deviation(found[i].plane, truth, frame);
      out << "  true plane " << d.index << " at " << d.degrees << " deg, " << 100. * d.offset << " % R";
    }
    out << "\n";
  }
  return out.str();
}

::testing::AssertionResult is_near(const Plane_3& found, const Plane_3& truth, const Center_and_radius& frame,
                                   double max_degrees, double max_offset)
{
  const double degrees = angle_between(found, truth);
  const double offset = offset_between(found, truth, frame.center) / frame.radius;
  if(degrees <= max_degrees && offset <= max_offset) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << describe(found) << " is " << degrees << " deg and " << 100. * offset
                                       << " % R from the true plane " << describe(truth) << " (tolerance "
                                       << max_degrees << " deg, " << 100. * max_offset << " % R)";
}

// Success if `found` is within the tolerance of one of `truth`.
::testing::AssertionResult is_near_one_of(const Plane_3& found, const std::vector<Plane_3>& truth,
                                          const Center_and_radius& frame, double max_degrees, double max_offset)
{
  const Deviation d = deviation(found, truth, frame);
  if(d.index == std::size_t(-1)) return ::testing::AssertionFailure() << "no true plane";
  return is_near(found, truth[d.index], frame, max_degrees, max_offset);
}

// Success if one of the first `count` planes of `found` is within the tolerance of `truth`.
::testing::AssertionResult is_among(const Plane_3& truth, const Symmetries& found, std::size_t count,
                                    const Center_and_radius& frame, double max_degrees, double max_offset)
{
  for(std::size_t i = 0; i < (std::min)(count, found.size()); ++i)
    if(is_near(found[i].plane, truth, frame, max_degrees, max_offset)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "the true plane " << describe(truth) << " is not among the first "
                                       << count << " planes (tolerance " << max_degrees << " deg, "
                                       << 100. * max_offset << " % R)";
}

// Detection with the largest deviations of the strongest plane printed and checked.
template <typename Mesh, typename NamedParameters>
Deviation expect_strongest_plane_near_truth(const std::string& what, const Shape<Mesh>& s, const NamedParameters& np,
                                            double max_degrees, double max_offset)
{
  const Center_and_radius frame = center_and_radius(s.mesh);
  const Symmetries found = ST::detect_principal_symmetries(s.mesh, np);
  std::cout << what << ":\n" << describe(found, s.planes, frame);
  if(found.empty()) {
    ADD_FAILURE() << what << ": no plane found";
    return {};
  }
  EXPECT_TRUE(is_near_one_of(found.front().plane, s.planes, frame, max_degrees, max_offset))
    << what << "\n" << describe(found, s.planes, frame);
  return deviation(found.front().plane, s.planes, frame);
}

struct Worst
{
  double degrees = 0., offset = 0.;
  void add(const Deviation& d)
  {
    degrees = (std::max)(degrees, d.degrees);
    offset = (std::max)(offset, d.offset);
  }
};

std::vector<std::pair<std::string, Shape<Surface_mesh>>> symmetric_shapes()
{
  return {{"box", box<Surface_mesh>()}, {"ellipsoid", ellipsoid<Surface_mesh>()}, {"one-plane hull", one_plane_hull<Surface_mesh>()}};
}

// ------------------------------------------------------------------------------------------
// Accuracy on shapes symmetric by construction
// ------------------------------------------------------------------------------------------

// The accuracy promised: 0.1 degree and 0.1 % of the radius, under three random similarities per
// shape. Measured: see the printed worst case (a few thousandths of a degree).
void expect_strongest_plane_exact(const std::string& name, const Shape<Surface_mesh>& shape, unsigned seed)
{
  CGAL::Random rng(seed);
  Worst worst;
  for(int trial = 0; trial < 3; ++trial) {
    const Shape<Surface_mesh> s = moved(shape, random_motion(rng));
    const Symmetries found = ST::detect_principal_symmetries(s.mesh, grid_32);
    const Center_and_radius frame = center_and_radius(s.mesh);
    const std::string what = name + ", motion " + std::to_string(trial);
    ASSERT_FALSE(found.empty()) << what;
    EXPECT_TRUE(is_near_one_of(found.front().plane, s.planes, frame, 0.1, 0.001)) << what << "\n"
                                                                                 << describe(found, s.planes, frame);
    // A perfect symmetry is fully supported and measured as such on the GEDT.
    EXPECT_GE(found.front().symmetry, 0.99) << what;
    EXPECT_GE(found.front().support, 0.99) << what;
    worst.add(deviation(found.front().plane, s.planes, frame));
  }
  std::cout << name << ": strongest plane at most " << worst.degrees << " deg and " << 100. * worst.offset
            << " % R from a true plane\n";
}

TEST(PrincipalSymmetries, StrongestPlaneOfBoxIsTrueUnderRandomMotions)
{
  expect_strongest_plane_exact("box", box<Surface_mesh>(), 201);
}

TEST(PrincipalSymmetries, StrongestPlaneOfEllipsoidIsTrueUnderRandomMotions)
{
  expect_strongest_plane_exact("ellipsoid", ellipsoid<Surface_mesh>(), 202);
}

TEST(PrincipalSymmetries, StrongestPlaneOfOnePlaneHullIsTrueUnderRandomMotions)
{
  expect_strongest_plane_exact("one-plane hull", one_plane_hull<Surface_mesh>(), 203);
}

// Gaussian noise of standard deviation 0.2 % of the radius on every vertex coordinate: within
// 1 degree and 1 % of the radius (the accuracy promised), two random similarities per shape.
TEST(PrincipalSymmetries, StrongestPlaneSurvivesGaussianVertexNoise)
{
  CGAL::Random rng(204);
  for(const auto& [name, shape] : symmetric_shapes()) {
    Worst worst;
    for(int trial = 0; trial < 2; ++trial) {
      Shape<Surface_mesh> s = moved(shape, random_motion(rng));
      add_vertex_noise(s.mesh, 0.002 * center_and_radius(s.mesh).radius, rng);
      worst.add(expect_strongest_plane_near_truth(name + " with noise, motion " + std::to_string(trial), s, grid_32, 1.,
                                                  0.01));
    }
    std::cout << name << " with 0.2 % noise: strongest plane at most " << worst.degrees << " deg and "
              << 100. * worst.offset << " % R from a true plane\n";
  }
}

// A fifth of the area cut away by one plane (the faces split along it, the cut left open), before
// a random similarity. The cut must break the symmetry, not remove a symmetric slab: its normal,
// (1, 1.43, 2.2) in the shapes' own frame, is oblique to every true plane, so it takes a corner
// off the box and the ellipsoid (the +x+y+z one) and, from the one-plane hull (plane x = 0), the
// top of the +x half near its thin end: an end of one half. The mirror image of the removed
// part stays, unsupported, and every true plane loses 12-16 % of its support (the test checks
// that each keeps less than 0.9; measured 0.845-0.876), while none of the near-symmetries
// gains. Cuts parallel to a true plane leave the other planes of the box and the ellipsoid
// perfect (too easy); cuts of the hull along x alone, across its thick end or along y let its
// near-symmetry (normal close to (0, 0.27, 0.96), SM 0.88 uncut) overtake the true plane, which
// then is no longer the main symmetry. At 32^3 the Gaussian (sigma about 0.1 R) blurs the thin
// hull so much that its near-symmetry wins even with this cut, and the ellipsoid's planes move by
// about 1 degree: 64^3. Target: within 2 degrees and 2 % of the radius.
TEST(PrincipalSymmetries, StrongestPlaneSurvivesAFifthOfTheSurfaceCutAway)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  CGAL::Random rng(205);
  for(const auto& [name, shape] : symmetric_shapes()) {
    Shape<Surface_mesh> cut = shape;
    cut.mesh = cut_away(shape.mesh, Vector_3(1., 1.43, 2.2), 0.2);
    const double removed = 1. - PMP::area(cut.mesh) / PMP::area(shape.mesh);
    EXPECT_NEAR(removed, 0.2, 0.005) << name;
    Worst worst;
    double most_supported = 0.;
    for(int trial = 0; trial < 2; ++trial) {
      const Shape<Surface_mesh> s = moved(cut, random_motion(rng));
      std::vector<double> face_support(num_faces(s.mesh)); // Surface_mesh face indices run from 0
      for(const Plane_3& p : s.planes) {
        const double supported = ST::symmetry_support(s.mesh, p, CGAL::make_property_map(face_support), grid_64);
        EXPECT_LT(supported, 0.9) << name << ": the cut should break the true plane " << describe(p);
        most_supported = (std::max)(most_supported, supported);
      }
      worst.add(expect_strongest_plane_near_truth(name + " cut, motion " + std::to_string(trial), s, grid_64, 2., 0.02));
    }
    std::cout << name << " with " << 100. * removed << " % of its area cut away (true planes supported at most "
              << most_supported << "): strongest plane at most " << worst.degrees << " deg and "
              << 100. * worst.offset << " % R from a true plane\n";
  }
}

// ------------------------------------------------------------------------------------------
// Several planes
// ------------------------------------------------------------------------------------------

// A box of three different sides and an ellipsoid of three different axes have exactly three
// planes each: the first three planes returned are those, each within 0.1 degree and 0.1 % R.
void expect_three_planes_first(const std::string& name, const Shape<Surface_mesh>& shape, unsigned seed)
{
  CGAL::Random rng(seed);
  for(int trial = 0; trial < 2; ++trial) {
    const Shape<Surface_mesh> s = moved(shape, random_motion(rng));
    const Symmetries found = ST::detect_principal_symmetries(s.mesh, grid_32);
    const Center_and_radius frame = center_and_radius(s.mesh);
    const std::string what = name + ", motion " + std::to_string(trial);
    std::cout << what << ":\n" << describe(found, s.planes, frame);
    ASSERT_GE(found.size(), 3u) << what;
    for(const Plane_3& p : s.planes) EXPECT_TRUE(is_among(p, found, 3, frame, 0.1, 0.001)) << what;
    // The three are distinct planes, so each true plane is matched by a different one.
  }
}

TEST(PrincipalSymmetries, ReturnsTheThreePlanesOfBoxFirst)
{
  expect_three_planes_first("box", box<Surface_mesh>(), 206);
}

TEST(PrincipalSymmetries, ReturnsTheThreePlanesOfEllipsoidFirst)
{
  expect_three_planes_first("ellipsoid", ellipsoid<Surface_mesh>(), 207);
}

// The box as built, without motion: the normal of its plane z = 0 is the pole of the (theta,
// phi) parameter space, where phi is undefined. All three planes must be found, at 32^3 and at
// 64^3, whatever the seed (1-4 here). Measured (2026-11-22): the plane z = 0 is missing for some
// seeds (seed 4 at 32^3 and 64^3 with 1e5 pairs; seed 1 with 2e5 pairs and seed 3 with the
// default 2e6 at 64^3). With `verbose`, its candidates, bins (0, j, 31) for several j, are all
// refined to (0, 0, 1) and "dropped: left its bin": stays_near_bin compares bin indices, and the
// phi of a normal at the pole, undefined, lands more than 3 bins away from j.
TEST(PrincipalSymmetries, FindsAllPlanesOfAxisAlignedBoxIncludingThePolarOne)
{
  const Shape<Surface_mesh> s = box<Surface_mesh>();
  const Center_and_radius frame = center_and_radius(s.mesh);
  for(const int resolution : {32, 64})
    for(const unsigned seed : {1u, 2u, 3u, 4u}) {
      const Symmetries found =
        ST::detect_principal_symmetries(s.mesh, grid_32.grid_resolution(resolution).random_seed(seed));
      const std::string what = "axis-aligned box at " + std::to_string(resolution) + "^3, seed " + std::to_string(seed);
      bool all = true;
      for(const Plane_3& p : s.planes) {
        const ::testing::AssertionResult among = is_among(p, found, 3, frame, 0.1, 0.001);
        EXPECT_TRUE(among) << what;
        all = all && among;
      }
      if(!all) std::cout << what << ":\n" << describe(found, s.planes, frame);
    }
}

// Translation invariance: the box turned at random and moved 20 times its radius away from the
// origin, by (20, -14, 8). All three planes must be found, within 0.1 degree and 0.1 % R from
// the mesh (and within 0.5 degree and 0.5 % R from 5000 points on it, as in
// OfPointsRecoversPlaneOfBoxFromSurfaceSamples). It guards the comparison of planes in
// stays_near_bin and same_plane, which must measure offsets from the centre of the transform:
// from the origin, tilting a plane by a bin moves its offset by about the distance to the origin
// times the angle, and far from the origin every candidate was "dropped: left its bin" (no
// plane at all from the mesh, at most one from the points, in an earlier version).
TEST(PrincipalSymmetries, FindsAllPlanesOfBoxFarFromTheOrigin)
{
  CGAL::Random rng(215);
  for(int trial = 0; trial < 3; ++trial) {
    const Shape<Surface_mesh> s = moved(moved(box<Surface_mesh>(), random_motion(rng, true, false, false)),
                                        Motion(CGAL::TRANSLATION, Vector_3(20., -14., 8.)));
    const Center_and_radius frame = center_and_radius(s.mesh);
    const std::string what = "box far from the origin, rotation " + std::to_string(trial);
    const Symmetries found = ST::detect_principal_symmetries(s.mesh, grid_32);
    const Symmetries from_points = ST::detect_principal_symmetries_of_points(surface_points(s.mesh, 5000, rng), grid_32);
    bool all = true;
    for(const Plane_3& p : s.planes) {
      const ::testing::AssertionResult mesh_ok = is_among(p, found, 3, frame, 0.1, 0.001),
                                       points_ok = is_among(p, from_points, 3, frame, 0.5, 0.005);
      EXPECT_TRUE(mesh_ok) << what << ", mesh";
      EXPECT_TRUE(points_ok) << what << ", points";
      all = all && mesh_ok && points_ok;
    }
    if(!all)
      std::cout << what << ", mesh:\n"
                << describe(found, s.planes, frame) << what << ", points:\n"
                << describe(from_points, s.planes, frame);
  }
}

// A box (half-sides 1, 0.7, 0.45) and an ellipsoid (half-axes 1.4, 0.9, 0.6) side by side,
// disjoint, in one mesh: the ellipsoid turned 10 degrees about x then 60 degrees about z and
// centred at (3.4, 1.8, 1.2), so that no plane of one part is a plane of the other and none
// cuts the other part (each misses it by 0.5 or more, 2.6 Gaussian widths at 64^3). All six
// planes are local, each reflecting one part onto itself: half of the area each. True planes
// 0-2 are the box's, 3-5 the ellipsoid's.
Shape<Surface_mesh> box_beside_ellipsoid()
{
  const auto rotation = [](double degrees, int axis) {
    const double c = std::cos(degrees * CGAL_PI / 180.), s = std::sin(degrees * CGAL_PI / 180.);
    return axis == 0 ? Motion(1, 0, 0, 0, c, -s, 0, s, c) : Motion(c, -s, 0, s, c, 0, 0, 0, 1);
  };
  const Shape<Surface_mesh> part = moved(moved(ellipsoid<Surface_mesh>(1.4, 0.9, 0.6), rotation(60., 2) * rotation(10., 0)),
                                         Motion(CGAL::TRANSLATION, Vector_3(3.4, 1.8, 1.2)));
  return merged(box<Surface_mesh>(), part);
}

// Each of the six local planes must be among the returned planes, within 0.1 degree and 0.1 % of
// the composite's radius, at 64^3 with detection's default number of pairs, as built and under a
// random similarity. Planes through both parts that map large pieces of each onto themselves
// (the box's top and bottom faces, for one) come first, with more support than the local ones.
TEST(PrincipalSymmetries, ReturnsTheLocalPlanesOfBothPartsOfBoxBesideEllipsoid)
{
  const Shape<Surface_mesh> composite = box_beside_ellipsoid();
  CGAL::Random rng(208);
  for(int trial = 0; trial < 2; ++trial) {
    const Shape<Surface_mesh> s = trial == 0 ? composite : moved(composite, random_motion(rng));
    const Center_and_radius frame = center_and_radius(s.mesh);
    const Symmetries found = ST::detect_principal_symmetries(s.mesh, CGAL::parameters::grid_resolution(64).random_seed(1));
    const std::string what = trial == 0 ? std::string("composite") : "composite, motion " + std::to_string(trial);
    std::cout << what << " (R = " << frame.radius << "; true planes 0-2: box, 3-5: ellipsoid):\n"
              << describe(found, s.planes, frame);
    for(std::size_t i = 0; i < s.planes.size(); ++i)
      EXPECT_TRUE(is_among(s.planes[i], found, found.size(), frame, 0.1, 0.001))
        << what << ": " << (i < 3 ? "box" : "ellipsoid") << " plane " << i;
  }
}

// ------------------------------------------------------------------------------------------
// Closest points: the fast closest point of a triangle and the closest-triangle field of ISP
// ------------------------------------------------------------------------------------------

namespace STI = CGAL::Symmetry_transform::internal;

// The closest point of a triangle by its Voronoi regions, against the kernel's projection, for
// points all around triangles of every shape (slivers, needles, obtuse, tiny and huge).
TEST(ClosestPoints, ClosestPointOnTriangleAgreesWithKernelProjection)
{
  CGAL::Random rng(17);
  auto random_point = [&](double scale) {
    return Eigen::Vector3d(rng.get_double(-scale, scale), rng.get_double(-scale, scale), rng.get_double(-scale, scale));
  };
  double worst = 0.;
  for(int t = 0; t < 2000; ++t) {
    const double scale = std::pow(10., rng.get_double(-3., 3.));
    const Eigen::Vector3d a = random_point(scale), b = random_point(scale);
    // Every fourth triangle is a sliver: c almost on the line ab.
    const Eigen::Vector3d c = t % 4 == 0 ? a + rng.get_double(-2., 3.) * (b - a) + random_point(1e-6 * scale) : random_point(scale);
    const STI::Dtriangle triangle(STI::Dpoint(a.x(), a.y(), a.z()), STI::Dpoint(b.x(), b.y(), b.z()), STI::Dpoint(c.x(), c.y(), c.z()));
    for(int q = 0; q < 50; ++q) {
      const Eigen::Vector3d p = random_point(3. * scale);
      const STI::Dpoint expected =
        STI::Dkernel().construct_projected_point_3_object()(triangle, STI::Dpoint(p.x(), p.y(), p.z()));
      const Eigen::Vector3d found = STI::closest_point_on_triangle(p, a, b, c);
      // Both are closest points: their distances to p agree (the points themselves may differ
      // by rounding on a sliver, whose closest point is ill-conditioned along it).
      const double difference = std::abs((found - p).norm() - (STI::to_eigen(expected) - p).norm()) / scale;
      worst = (std::max)(worst, difference);
      ASSERT_LT(difference, 1e-9) << "triangle " << t << ", point " << q;
    }
  }
  std::cout << "closest point on a triangle vs the kernel's projection: distances agree within " << worst
            << " of the triangle's size\n";
}

// The field is an approximation that ISP walks with (exact searches end the walk): within the
// band of the transform its distance is never below the exact one (it is the distance to some
// triangle) and rarely much above it: exact on shapes whose triangles are larger than the voxels
// (box, hull, ellipsoid); on a curved one with triangles smaller than the voxels (20480, about
// bull.off's size), the closest triangle is sometimes not among those of the eight voxels (then
// one of its neighbours is taken): measured 4e-4 sigma (median), 0.12 sigma (99th percentile).
TEST(ClosestPoints, ClosestTriangleFieldIsNearTheExactSearchInTheBand)
{
  CGAL::Random rng(23);
  const auto np = CGAL::parameters::grid_resolution(64);
  std::vector<std::pair<std::string, Shape<Surface_mesh>>> shapes = symmetric_shapes();
  shapes.emplace_back("fine ellipsoid", ellipsoid<Surface_mesh>(1., 0.6, 0.35, 5));
  for(const auto& [name, shape] : shapes) {
    const Shape<Surface_mesh> s = moved(shape, random_motion(rng));
    const STI::Triangle_surface<K> surface(STI::triangles_of_mesh(s.mesh, CGAL::parameters::default_values()), np);
    const auto& [triangles, exact, field] = std::tie(surface.triangles, surface.matcher, surface.field);
    const double sigma = STI::isp_settings(np, surface.gedt).sigma;
    std::vector<double> excess;
    for(const Eigen::Vector3d& sample : STI::surface_samples(triangles, np.number_of_refinement_samples(5000))) {
      const Eigen::Vector3d p = sample + sigma * Eigen::Vector3d(gaussian(rng), gaussian(rng), gaussian(rng));
      STI::Triangle_matcher::Hint exact_hint;
      STI::Closest_triangle_field::Hint field_hint;
      const double d = (p - exact.closest(p, exact_hint).first).norm();
      const double approximate = (p - field.closest(p, field_hint).first).norm();
      ASSERT_GE(approximate, d - 1e-12 * sigma) << name;
      excess.push_back((approximate - d) / sigma);
    }
    std::sort(excess.begin(), excess.end());
    const double median = excess[excess.size() / 2], p99 = excess[excess.size() * 99 / 100];
    std::cout << name << ": field distance above the exact one by " << median << " sigma (median), " << p99
              << " sigma (99th percentile)\n";
    EXPECT_LT(median, 1e-3) << name;
    EXPECT_LT(p99, 0.2) << name;
  }
}

// An ellipsoid with 400 large triangles whose corners are drawn in its box (a web soup with stray
// faces across the inside), and the point of it closest to p by testing every triangle.
struct Soup_with_interior_triangles
{
  std::vector<STI::Dtriangle> triangles;
  CGAL::Bbox_3 box;

  explicit Soup_with_interior_triangles(CGAL::Random& rng)
    : triangles(STI::triangles_of_mesh(ellipsoid<Surface_mesh>().mesh, CGAL::parameters::default_values()))
  {
    for(const STI::Dtriangle& t : triangles) box += t.bbox();
    for(int t = 0; t < 400; ++t)
      triangles.emplace_back(random_point(rng), random_point(rng), random_point(rng));
  }

  STI::Dpoint random_point(CGAL::Random& rng) const
  {
    return STI::Dpoint(rng.get_double(box.xmin(), box.xmax()), rng.get_double(box.ymin(), box.ymax()),
                       rng.get_double(box.zmin(), box.zmax()));
  }

  Eigen::Vector3d closest_by_every_triangle(const Eigen::Vector3d& p) const
  {
    Eigen::Vector3d best = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    for(const STI::Dtriangle& t : triangles) {
      const Eigen::Vector3d q = STI::closest_point_on_triangle(p, STI::to_eigen(t[0]), STI::to_eigen(t[1]), STI::to_eigen(t[2]));
      if((p - q).squaredNorm() < (p - best).squaredNorm()) best = q;
    }
    return best;
  }
};

// Large triangles across the inside make the boxes overlap far deeper than on any surface (the
// matcher then searches the cells near a query): the cells find the closest point that testing
// every triangle finds, whenever the soup has a point within the bound, and nothing when it has
// none; through the matcher, searches with hints (as ISP's) are exact too. Cells that would list
// more members than allowed are not built, and answer nothing.
TEST(ClosestPoints, CellsOfASoupWithLargeInteriorTrianglesFindTheClosestPoint)
{
  CGAL::Random rng(31);
  const Soup_with_interior_triangles soup(rng);
  const std::vector<STI::Dtriangle> surface(soup.triangles.begin(), soup.triangles.end() - 400);
  EXPECT_LT(STI::mean_box_overlap(surface), STI::deepest_box_overlap_for_tree);
  ASSERT_GT(STI::mean_box_overlap(soup.triangles), STI::deepest_box_overlap_for_tree);
  const STI::Triangle_cells cells(soup.triangles), too_many(soup.triangles, 1000);
  ASSERT_TRUE(cells.built());
  EXPECT_FALSE(too_many.built());
  const STI::Triangle_matcher matcher(soup.triangles);
  const double size = soup.box.xmax() - soup.box.xmin();
  std::size_t answered = 0, none_within = 0;
  STI::Triangle_matcher::Hint previous; // the match of the previous query: mostly far, the tree answers
  for(int q = 0; q < 3000; ++q) {
    const Eigen::Vector3d p = STI::to_eigen(soup.random_point(rng)), truth = soup.closest_by_every_triangle(p);
    const double d = (p - truth).norm();
    // A point of the soup within 1 % of the size farther than the closest, as a hint gives.
    const Eigen::Vector3d known = soup.closest_by_every_triangle(p + 0.005 * size * Eigen::Vector3d::UnitX());
    const std::optional<STI::Triangle_cells::Nearest> nearest = cells.closest(p, (p - known).norm());
    if(nearest) {
      ++answered;
      ASSERT_NEAR((p - nearest->point).norm(), d, 1e-12 * size) << "query " << q;
    }
    if(d > 0. && !cells.closest(p, 0.5 * d)) ++none_within;
    EXPECT_FALSE(too_many.closest(p, (p - known).norm()));
    ASSERT_NEAR((p - matcher.closest(p, previous).first).norm(), d, 1e-12 * size) << "query " << q;
    // A hint as close as `known` (as ISP's walk gives): the matcher searches the cells.
    STI::Triangle_matcher::Hint near;
    matcher.closest(p + 0.005 * size * Eigen::Vector3d::UnitX(), near);
    ASSERT_NEAR((p - matcher.closest(p, near).first).norm(), d, 1e-12 * size) << "query " << q;
  }
  EXPECT_GT(answered, 2500u); // the others' bounds span more than max_cells_per_search cells
  EXPECT_EQ(none_within, 3000u);
}

// ------------------------------------------------------------------------------------------
// refine_symmetry_plane
// ------------------------------------------------------------------------------------------

// From planes turned 8 degrees about 4 axes of each true plane and moved 5 % of the radius along
// their normal either way (8 starts per plane, 56 in all), with the default resolution (64^3,
// which sets the Gaussian width of ISP): back to the truth within 0.1 degree and 0.1 % R.
TEST(RefineSymmetryPlane, ConvergesFromEightDegreesAndFivePercentAway)
{
  CGAL::Random rng(209);
  const auto np = CGAL::parameters::random_seed(1);
  Worst worst;
  for(const auto& [name, shape] : symmetric_shapes()) {
    const Shape<Surface_mesh> s = moved(shape, random_motion(rng));
    const Center_and_radius frame = center_and_radius(s.mesh);
    for(const Plane_3& truth : s.planes) {
      const Point_3 foot = unit_plane(truth).projection(frame.center);
      const std::array<Vector_3, 2> axes = in_plane_axes(truth);
      for(int a = 0; a < 4; ++a) {
        const double angle = a * CGAL_PI / 4.;
        const Plane_3 tilted = rotated_plane(truth, foot, std::cos(angle) * axes[0] + std::sin(angle) * axes[1], 8.);
        for(const double side : {-1., 1.}) {
          const Plane_3 start(foot + side * 0.05 * frame.radius * unit_normal(tilted), unit_normal(tilted));
          ASSERT_NEAR(angle_between(start, truth), 8., 1e-9);
          ASSERT_NEAR(offset_between(start, truth, frame.center) / frame.radius, 0.05, 1e-9);
          const Plane_3 refined = ST::refine_symmetry_plane(s.mesh, start, np);
          EXPECT_TRUE(is_near(refined, truth, frame, 0.1, 0.001)) << name << ", axis " << a << ", side " << side;
          worst.add({angle_between(refined, truth), offset_between(refined, truth, frame.center) / frame.radius, 0});
          const Vector_3 n = refined.orthogonal_vector();
          EXPECT_NEAR(n.squared_length(), 1., 1e-12) << "the refined plane has a unit normal";
        }
      }
    }
  }
  std::cout << "refine_symmetry_plane from 8 deg and 5 % R: at most " << worst.degrees << " deg and "
            << 100. * worst.offset << " % R from the truth\n";
}

// ISP started exactly on a local plane of the composite above stays there: a local symmetry must
// be a fixed point of the refinement, or the detection cannot return it.
TEST(RefineSymmetryPlane, KeepsTheExactLocalPlanesOfBoxBesideEllipsoid)
{
  const Shape<Surface_mesh> s = box_beside_ellipsoid();
  const Center_and_radius frame = center_and_radius(s.mesh);
  for(std::size_t i = 0; i < s.planes.size(); ++i) {
    const Plane_3 refined = ST::refine_symmetry_plane(s.mesh, s.planes[i], CGAL::parameters::random_seed(1));
    std::cout << "composite, refined from its true plane " << i << ": " << angle_between(refined, s.planes[i])
              << " deg, " << 100. * offset_between(refined, s.planes[i], frame.center) / frame.radius << " % R away\n";
    EXPECT_TRUE(is_near(refined, s.planes[i], frame, 0.01, 0.0001)) << (i < 3 ? "box" : "ellipsoid") << " plane " << i;
  }
}

// ------------------------------------------------------------------------------------------
// Mesh types, determinism, point sets
// ------------------------------------------------------------------------------------------

template <typename Mesh>
std::vector<std::array<Point_3, 3>> triangle_list(const Mesh& mesh)
{
  std::vector<std::array<Point_3, 3>> result;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    result.push_back({get(CGAL::vertex_point, mesh, source(h, mesh)), get(CGAL::vertex_point, mesh, target(h, mesh)),
                      get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh))});
  }
  return result;
}

::testing::AssertionResult same_planes(const Symmetries& a, const Symmetries& b, double tolerance)
{
  if(a.size() != b.size()) return ::testing::AssertionFailure() << a.size() << " planes vs " << b.size();
  for(std::size_t i = 0; i < a.size(); ++i) {
    const Plane_3 p = a[i].plane, q = b[i].plane;
    const double d = (std::max)({std::abs(p.a() - q.a()), std::abs(p.b() - q.b()), std::abs(p.c() - q.c()),
                                 std::abs(p.d() - q.d()), std::abs(a[i].symmetry - b[i].symmetry),
                                 std::abs(a[i].support - b[i].support)});
    if(!(d <= tolerance))
      return ::testing::AssertionFailure() << "plane " << i << ": " << describe(p) << " SM " << a[i].symmetry
                                           << " support " << a[i].support << " vs " << describe(q) << " SM "
                                           << b[i].symmetry << " support " << b[i].support << " (difference " << d
                                           << ")";
  }
  return ::testing::AssertionSuccess();
}

// `result` becomes the Polyhedron_3 with the vertices and faces of `mesh` in the same order, each
// face starting at the same vertex: the surface samples, drawn triangle by triangle from the
// first vertex of each, are then the same. (Built in place: a copy of a Polyhedron_3 may start
// its faces at other halfedges, and so may copy_face_graph.)
void make_polyhedron_of(const Surface_mesh& mesh, Polyhedron& result)
{
  std::vector<Point_3> points(mesh.points().begin(), mesh.points().end());
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    triangles.push_back({std::size_t(source(h, mesh)), std::size_t(target(h, mesh)), std::size_t(target(next(h, mesh), mesh))});
  }
  mesh_from_triangle_soup(points, triangles, result);
}

// The same shape as a Surface_mesh and as a Polyhedron_3 (the test checks that the two list the
// same triangles in the same order): planes, symmetries and supports agree within 1e-9, and so
// do refine_symmetry_plane and symmetry_support.
TEST(PrincipalSymmetries, SurfaceMeshAndPolyhedronGiveTheSamePlanes)
{
  CGAL::Random rng(210);
  const Shape<Surface_mesh> shapes[] = {moved(box<Surface_mesh>(), random_motion(rng)),
                                        moved(one_plane_hull<Surface_mesh>(), random_motion(rng))};
  for(int i = 0; i < 2; ++i) {
    const Surface_mesh& sm = shapes[i].mesh;
    Polyhedron poly;
    make_polyhedron_of(sm, poly);
    ASSERT_TRUE(triangle_list(sm) == triangle_list(poly)) << "shape " << i << ": the two meshes differ";
    const Symmetries a = ST::detect_principal_symmetries(sm, grid_32), b = ST::detect_principal_symmetries(poly, grid_32);
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(same_planes(a, b, 1e-9)) << "shape " << i;

    const Plane_3 start = rotated_plane(shapes[i].planes[0], unit_plane(shapes[i].planes[0]).point(),
                                        in_plane_axes(shapes[i].planes[0])[0], 5.);
    const Plane_3 p = ST::refine_symmetry_plane(sm, start, grid_32), q = ST::refine_symmetry_plane(poly, start, grid_32);
    EXPECT_NEAR(p.a(), q.a(), 1e-9);
    EXPECT_NEAR(p.b(), q.b(), 1e-9);
    EXPECT_NEAR(p.c(), q.c(), 1e-9);
    EXPECT_NEAR(p.d(), q.d(), 1e-9);

    std::vector<double> sm_support(num_faces(sm));
    std::map<boost::graph_traits<Polyhedron>::face_descriptor, double> poly_support;
    const double fa = ST::symmetry_support(sm, start, CGAL::make_property_map(sm_support), grid_32);
    const double fb = ST::symmetry_support(poly, start, boost::make_assoc_property_map(poly_support), grid_32);
    EXPECT_NEAR(fa, fb, 1e-9);
    std::size_t f = 0;
    for(auto face : faces(poly)) EXPECT_NEAR(sm_support[f++], poly_support[face], 1e-9);
  }
}

// Same seed: bitwise identical planes, symmetries and supports (with the default number of
// threads, which splits the work the same way each time).
TEST(PrincipalSymmetries, SameSeedGivesIdenticalPlanes)
{
  CGAL::Random rng(211);
  const Shape<Surface_mesh> s = moved(one_plane_hull<Surface_mesh>(), random_motion(rng));
  const Symmetries a = ST::detect_principal_symmetries(s.mesh, grid_32.random_seed(7));
  const Symmetries b = ST::detect_principal_symmetries(s.mesh, grid_32.random_seed(7));
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(same_planes(a, b, 0.));
  const Plane_3 start = rotated_plane(s.planes[0], unit_plane(s.planes[0]).point(), in_plane_axes(s.planes[0])[1], 6.);
  EXPECT_TRUE(ST::refine_symmetry_plane(s.mesh, start, grid_32.random_seed(7)) ==
              ST::refine_symmetry_plane(s.mesh, start, grid_32.random_seed(7)));
}

// 5000 points sampled uniformly on a box under three random similarities: the strongest plane is
// a true one. ISP on points matches each reflected point to its nearest sample, so the sampling
// (mean spacing about 0.03 R here) limits the accuracy: tolerance 0.5 degree and 0.5 % R
// (measured: see the printed worst case).
TEST(PrincipalSymmetries, OfPointsRecoversPlaneOfBoxFromSurfaceSamples)
{
  CGAL::Random rng(212);
  Worst worst;
  for(int trial = 0; trial < 3; ++trial) {
    const Shape<Surface_mesh> s = moved(box<Surface_mesh>(), random_motion(rng));
    const std::vector<Point_3> points = surface_points(s.mesh, 5000, rng);
    const Center_and_radius frame = center_and_radius(s.mesh);
    const Symmetries found = ST::detect_principal_symmetries_of_points(points, grid_32);
    std::cout << "points on a box, motion " << trial << ":\n" << describe(found, s.planes, frame);
    ASSERT_FALSE(found.empty());
    EXPECT_TRUE(is_near_one_of(found.front().plane, s.planes, frame, 0.5, 0.005)) << "motion " << trial;
    for(const Plane_3& p : s.planes) EXPECT_TRUE(is_among(p, found, 3, frame, 0.5, 0.005)) << "motion " << trial;
    worst.add(deviation(found.front().plane, s.planes, frame));
  }
  std::cout << "points on a box: strongest plane at most " << worst.degrees << " deg and " << 100. * worst.offset
            << " % R from a true plane\n";
}

// ------------------------------------------------------------------------------------------
// symmetry_support
// ------------------------------------------------------------------------------------------

// On the one-plane hull under three random similarities, at 64^3: its plane gives every face a
// support above 0.9 (measured: all 1), and a plane turned 20 degrees about any of 4 axes of
// it gives a supported fraction below 0.8 (measured 0.35-0.71, see the output), far below. Every
// face gets a value, in [0,1], and the fraction is their area-weighted mean.
TEST(SymmetrySupport, TruePlaneSupportsEveryFaceAndATurnedPlaneMuchLess)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  CGAL::Random rng(213);
  double least_true = 1., most_turned = 0., least_turned = 1.;
  for(int trial = 0; trial < 3; ++trial) {
    Shape<Surface_mesh> s = moved(one_plane_hull<Surface_mesh>(), random_motion(rng));
    const Center_and_radius frame = center_and_radius(s.mesh);
    auto support = s.mesh.add_property_map<Surface_mesh::Face_index, double>("f:support", -1.).first;
    const auto check_map = [&](double fraction) {
      double weighted = 0.;
      for(auto f : faces(s.mesh)) {
        EXPECT_GE(support[f], 0.);
        EXPECT_LE(support[f], 1.);
        weighted += support[f] * PMP::face_area(f, s.mesh);
      }
      EXPECT_GE(fraction, 0.);
      EXPECT_LE(fraction, 1.);
      EXPECT_NEAR(fraction, weighted / PMP::area(s.mesh), 1e-9);
    };

    const double fraction = ST::symmetry_support(s.mesh, s.planes[0], support, grid_64);
    check_map(fraction);
    EXPECT_GE(fraction, 0.99);
    for(auto f : faces(s.mesh)) {
      EXPECT_GT(support[f], 0.9) << "face " << f;
      least_true = (std::min)(least_true, support[f]);
    }

    const Point_3 foot = unit_plane(s.planes[0]).projection(frame.center);
    const std::array<Vector_3, 2> axes = in_plane_axes(s.planes[0]);
    for(int a = 0; a < 4; ++a) {
      const double angle = a * CGAL_PI / 4.;
      const Plane_3 turned =
        rotated_plane(s.planes[0], foot, std::cos(angle) * axes[0] + std::sin(angle) * axes[1], 20.);
      const double turned_fraction = ST::symmetry_support(s.mesh, turned, support, grid_64);
      check_map(turned_fraction);
      EXPECT_LT(turned_fraction, 0.8) << "motion " << trial << ", axis " << a;
      most_turned = (std::max)(most_turned, turned_fraction);
      least_turned = (std::min)(least_turned, turned_fraction);
    }
  }
  std::cout << "symmetry_support on the one-plane hull: least face support at the true plane " << least_true
            << "; supported fraction 20 deg away " << least_turned << " to " << most_turned << "\n";
}

// ------------------------------------------------------------------------------------------
// No symmetry
// ------------------------------------------------------------------------------------------

// The supported fraction of the surface for `plane`, computed here from its definition: the mean
// over `count` uniform surface points of exp(-d^2 / 2 sigma^2), d the distance from the reflected
// point to the mesh (CGAL::AABB_tree), sigma the width of the GEDT.
double reference_support(const Surface_mesh& mesh, const Plane_3& plane, double sigma, std::size_t count)
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Surface_mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::Symmetry_transform::internal::AABB_traits_3<K, Primitive>> Tree;
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  CGAL::Random rng(216);
  double sum = 0.;
  for(const Point_3& p : surface_points(mesh, count, rng))
    sum += std::exp(-tree.squared_distance(reflect(p, plane)) / (2. * sigma * sigma));
  return sum / double(count);
}

// The convex hull of 30 random points in a cube has no symmetry: its planes are weak maxima with
// honest values. At 64^3 (where the symmetric shapes measure SM 0.999 and support 1): every
// returned plane has SM below 0.9 and support below 0.8 (measured on this hull: at most 0.84 and
// 0.76; over the hulls of seeds 3-6, up to 0.87 and 0.80), each SM is the measure of the plane on
// the GEDT, and each support is the supported fraction computed here from 20000 surface points
// within 0.02 (measured: within 0.009). Sorted strongest first, unit normals. symmetry_support
// estimates the same fraction with 4 points per face (its centroid and 3 points around it, none
// near the face's edges): on this hull of large faces it reads up to 0.05 higher (printed).
TEST(PrincipalSymmetries, AsymmetricShapeReturnsWeakMaximaWithHonestValues)
{
  Shape<Surface_mesh> s = random_hull<Surface_mesh>(3);
  const Symmetries found = ST::detect_principal_symmetries(s.mesh, grid_64);
  const Grid gedt = ST::gaussian_distance_transform(s.mesh, grid_64);
  const double sigma = 1.5 * gedt.voxel_size(); // the default gaussian_width, in voxels
  std::cout << "random hull:\n" << describe(found, {}, center_and_radius(s.mesh));
  ASSERT_FALSE(found.empty()) << "weak maxima are still maxima";
  std::vector<double> face_support(num_faces(s.mesh));
  for(std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_LT(found[i].symmetry, 0.9) << "plane " << i;
    EXPECT_LT(found[i].support, 0.8) << "plane " << i;
    EXPECT_NEAR(found[i].symmetry, ST::symmetry_measure(gedt, found[i].plane), 1e-12) << "plane " << i;
    const double reference = reference_support(s.mesh, found[i].plane, sigma, 20000);
    EXPECT_NEAR(found[i].support, reference, 0.02) << "plane " << i;
    const double by_faces = ST::symmetry_support(s.mesh, found[i].plane, CGAL::make_property_map(face_support), grid_64);
    std::cout << "  #" << i << " support " << found[i].support << ", from 20000 points " << reference
              << ", symmetry_support " << by_faces << "\n";
    EXPECT_NEAR(found[i].plane.orthogonal_vector().squared_length(), 1., 1e-12);
    if(i > 0) {
      EXPECT_GE(found[i - 1].symmetry, found[i].symmetry);
    }
  }
}

// principal_symmetries on a transform computed beforehand gives what detect_principal_symmetries
// gives; max_number_of_planes caps the list.
TEST(PrincipalSymmetries, GivenTransformAndPlaneLimitAreHonoured)
{
  CGAL::Random rng(214);
  const Shape<Surface_mesh> s = moved(ellipsoid<Surface_mesh>(), random_motion(rng));
  // The number of Monte Carlo samples given: detection's default differs from the transform's.
  const auto np = grid_32.number_of_samples(300000);
  const Symmetries detected = ST::detect_principal_symmetries(s.mesh, np);
  const ST::Reflective_symmetry_transform<K> prst = ST::reflective_symmetry_transform(s.mesh, np);
  EXPECT_TRUE(same_planes(ST::principal_symmetries(s.mesh, prst, np), detected, 0.));
  // The refinement stops at the second plane accepted: both are among those of the full run.
  const Symmetries two = ST::detect_principal_symmetries(s.mesh, np.max_number_of_planes(2));
  ASSERT_EQ(two.size(), 2u);
  for(const auto& p : two)
    EXPECT_TRUE(std::any_of(detected.begin(), detected.end(),
                            [&](const auto& q) { return same_planes({p}, {q}, 0.); }))
      << describe(p.plane);
}

// ------------------------------------------------------------------------------------------
// Whole groups: the planes that exact ones generate
// ------------------------------------------------------------------------------------------

// A shape under the random similarity of `seed`, with its true planes moved alike.
struct Moved_group
{
  Surface_mesh mesh;
  std::vector<Plane_3> truth;
  Center_and_radius frame;
};

Moved_group moved_group(const Group_shape& shape, unsigned seed)
{
  CGAL::Random rng(seed);
  const Motion m = random_motion(rng);
  Moved_group g{shape.mesh, {}, {}};
  CGAL::Polygon_mesh_processing::transform(m, g.mesh);
  for(const Plane_3& p : shape.planes) g.truth.push_back(moved(p, m));
  g.frame = center_and_radius(g.mesh);
  return g;
}

// Every mirror plane of `shape` under a random similarity, found once, to 1e-3 degree and 1e-5 of
// the radius (the accuracy of the exact planes); every other plane found weaker than the weakest
// of them. With the defaults (64^3), which cap the planes at 10 but do not cut a group.
void expect_whole_group(const Group_shape& shape, unsigned seed)
{
  SCOPED_TRACE(shape.name);
  const Moved_group g = moved_group(shape, seed);
  const Symmetries found = ST::detect_principal_symmetries(g.mesh, CGAL::parameters::random_seed(1));
  double weakest = 2.;
  std::vector<bool> is_true(found.size(), false);
  for(const Plane_3& t : g.truth) {
    std::size_t matches = 0;
    for(std::size_t i = 0; i < found.size(); ++i)
      if(is_near(found[i].plane, t, g.frame, 1e-3, 1e-5)) {
        ++matches;
        is_true[i] = true;
        weakest = (std::min)(weakest, found[i].symmetry);
      }
    EXPECT_EQ(matches, 1u) << describe(t) << "\n" << describe(found, g.truth, g.frame);
  }
  for(std::size_t i = 0; i < found.size(); ++i)
    if(!is_true[i]) {
      EXPECT_LT(found[i].symmetry, weakest) << describe(found, g.truth, g.frame);
    }
}

TEST(PlaneGroups, PrismsGetAllTheirMirrorPlanes)
{
  for(int n = 3; n <= 12; ++n) expect_whole_group(regular_prism(n), unsigned(n));
}

TEST(PlaneGroups, AntiprismsGetAllTheirMirrorPlanes)
{
  for(int n = 3; n <= 12; ++n) expect_whole_group(regular_antiprism(n), unsigned(100 + n));
}

TEST(PlaneGroups, PlatonicSolidsAndBoxesGetAllTheirMirrorPlanes)
{
  unsigned seed = 200;
  for(const Group_shape& shape : platonic_solids()) expect_whole_group(shape, ++seed);
  expect_whole_group(box_shape(1., 1., 1.6), ++seed);
  expect_whole_group(box_shape(1., 0.7, 0.45), ++seed);
}

// The shapes' groups as computed from their vertices, which the tests above rely on.
TEST(PlaneGroups, KnownGroupsHaveTheirTextbookSizes)
{
  const std::vector<Group_shape> solids = platonic_solids();
  const std::size_t planes[] = {6, 9, 9, 15, 15}, axes[] = {7, 13, 13, 31, 31};
  for(std::size_t i = 0; i < solids.size(); ++i) {
    EXPECT_EQ(solids[i].planes.size(), planes[i]) << solids[i].name;
    EXPECT_EQ(solids[i].axes.size(), axes[i]) << solids[i].name;
  }
  for(int n = 3; n <= 12; ++n) {
    EXPECT_EQ(regular_prism(n).planes.size(), std::size_t(n + 1));
    EXPECT_EQ(regular_antiprism(n).planes.size(), std::size_t(n));
    EXPECT_EQ(regular_prism(n).axes.size(), std::size_t(n + 1)); // the n-fold axis and n flips
  }
}

// A cap the user chooses cuts the group: the icosahedron's 15 planes by default, 10 with
// max_number_of_planes(10), each of them one of the 15.
TEST(PlaneGroups, AChosenCapCutsTheGroup)
{
  const Group_shape icosahedron = platonic_solids()[4];
  const Center_and_radius frame = center_and_radius(icosahedron.mesh);
  EXPECT_EQ(ST::detect_principal_symmetries(icosahedron.mesh).size(), 15u);
  const Symmetries ten = ST::detect_principal_symmetries(icosahedron.mesh, CGAL::parameters::max_number_of_planes(10));
  ASSERT_EQ(ten.size(), 10u);
  for(const Symmetry& s : ten) EXPECT_TRUE(is_near_one_of(s.plane, icosahedron.planes, frame, 1e-3, 1e-5));
}

// ------------------------------------------------------------------------------------------
// Flat shapes and parts far apart
// ------------------------------------------------------------------------------------------

// Flat regular polygons and a flat rectangle, of zero thickness: their triangles' normals are
// all the same and leave an in-plane mirror's turn and shift to the border of the shape. Every
// mirror plane is found once, as exact as those of solids (1e-3 degree and 1e-5 of the radius),
// nothing else.
TEST(FlatShapes, EveryMirrorIsFoundAsExactlyAsThoseOfSolids)
{
  std::vector<Group_shape> shapes;
  for(int n : {3, 4, 5, 6, 8}) shapes.push_back(flat_polygon(n));
  shapes.push_back(flat_rectangle());
  unsigned seed = 300;
  for(const Group_shape& shape : shapes) {
    expect_whole_group(shape, ++seed);
    const Moved_group g = moved_group(shape, seed);
    for(const Symmetry& s : ST::detect_principal_symmetries(g.mesh, CGAL::parameters::random_seed(1)))
      EXPECT_TRUE(is_near_one_of(s.plane, g.truth, g.frame, 1e-3, 1e-5)) << shape.name;
  }
}

// A cylinder and a cone: their mirrors through the axis are returned once, as the pencil of
// planes through the axis, the line to 1e-3 degree and 1e-5 of the radius, and no other plane
// found contains the axis; the cylinder's cross-section is found, exact.
TEST(RevolutionShapes, PencilOfMirrorsIsReportedOnceWithItsAxis)
{
  unsigned seed = 600;
  for(const Group_shape& shape : {cylinder(), cone()}) {
    SCOPED_TRACE(shape.name);
    CGAL::Random rng(++seed);
    const Motion m = random_motion(rng);
    Surface_mesh mesh = shape.mesh;
    CGAL::Polygon_mesh_processing::transform(m, mesh);
    const Center_and_radius frame = center_and_radius(mesh);
    const Line_3 axis(m.transform(shape.pencils.front().point()), m.transform(shape.pencils.front().to_vector()));
    const Symmetries found = ST::detect_principal_symmetries(mesh, CGAL::parameters::random_seed(1));
    std::size_t pencils = 0;
    for(const Symmetry& s : found) {
      const Vector_3 n = unit_normal(s.plane), d = axis.to_vector() / std::sqrt(axis.to_vector().squared_length());
      const bool contains_axis =
        std::abs(n * d) < 1e-3 && std::sqrt(CGAL::squared_distance(s.plane, axis.point())) < 1e-3 * frame.radius;
      if(s.family != ST::Mirror_family::EVERY_PLANE_THROUGH_AXIS) {
        EXPECT_FALSE(contains_axis) << "a member of the pencil listed alone\n" << describe(found, {}, frame);
        continue;
      }
      ++pencils;
      EXPECT_TRUE(contains_axis);
      const Vector_3 u = s.axis.to_vector() / std::sqrt(s.axis.to_vector().squared_length());
      EXPECT_LT(std::sqrt(CGAL::cross_product(u, d).squared_length()), std::sin(1e-3 * CGAL_PI / 180.));
      EXPECT_LT(std::sqrt(CGAL::squared_distance(axis, s.axis.point())), 1e-5 * frame.radius);
    }
    EXPECT_EQ(pencils, 1u) << describe(found, {}, frame);
    for(const Plane_3& p : shape.planes)
      EXPECT_TRUE(is_among(moved(p, m), found, found.size(), frame, 1e-3, 1e-5)) << describe(found, {}, frame);
  }
}

// Two mirrored copies of an asymmetric hull, farther apart than the grid can see them (each a
// blob of a few voxels): the mirror between them is the strongest plane, exact, at 50 and 500
// radii, under a random similarity.
TEST(PartsApart, MirrorBetweenTwoCopiesIsTheStrongestPlane)
{
  for(double distance : {50., 500.}) {
    SCOPED_TRACE(distance);
    const Shape<Surface_mesh> pair = mirrored_copies(random_hull<Surface_mesh>().mesh, distance);
    const Moved_group g = moved_group({"mirrored copies", pair.mesh, pair.planes, {}, {}}, 400);
    const Symmetries found = ST::detect_principal_symmetries(g.mesh);
    ASSERT_FALSE(found.empty());
    EXPECT_TRUE(is_near(found.front().plane, g.truth.front(), g.frame, 1e-6, 1e-9)) << describe(found, g.truth, g.frame);
  }
}

// Two unit cubes 1e4 apart: their five common mirrors (the bisector and the four planes through
// both centres), each exact and found once, stronger than any other plane.
TEST(PartsApart, TwoCubesFarApartGetTheirFiveMirrors)
{
  expect_whole_group(cubes_apart(1e4), 500);
}

// ------------------------------------------------------------------------------------------
// Bad input
// ------------------------------------------------------------------------------------------

TEST(PrincipalSymmetriesBadInput, EmptyMeshIsRejected)
{
  const Surface_mesh empty;
  std::vector<double> support;
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::detect_principal_symmetries(empty, grid_32); },
                                                         "no face"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::refine_symmetry_plane(empty, Plane_3(1, 0, 0, 0), grid_32); }, "no face"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetry_support(empty, Plane_3(1, 0, 0, 0), CGAL::make_property_map(support), grid_32); },
    "no face"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::detect_principal_symmetries_of_points(std::vector<Point_3>(), grid_32); }, "empty"));
}

TEST(PrincipalSymmetriesBadInput, AllDegenerateMeshIsRejected)
{
  // Two triangles of zero area: three collinear points, and a repeated point.
  Surface_mesh mesh;
  const auto a = mesh.add_vertex(Point_3(0, 0, 0)), b = mesh.add_vertex(Point_3(1, 0, 0)),
             c = mesh.add_vertex(Point_3(2, 0, 0)), d = mesh.add_vertex(Point_3(0, 1, 0)),
             e = mesh.add_vertex(Point_3(0, 1, 0));
  ASSERT_TRUE(mesh.add_face(a, b, c) != Surface_mesh::null_face());
  ASSERT_TRUE(mesh.add_face(a, e, d) != Surface_mesh::null_face());
  std::vector<double> support(num_faces(mesh));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::detect_principal_symmetries(mesh, grid_32); },
                                                         "degenerate"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::refine_symmetry_plane(mesh, Plane_3(1, 0, 0, 0), grid_32); }, "degenerate"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetry_support(mesh, Plane_3(1, 0, 0, 0), CGAL::make_property_map(support), grid_32); },
    "degenerate"));
}

TEST(PrincipalSymmetriesBadInput, DegeneratePlaneIsRejected)
{
  const Shape<Surface_mesh> s = box<Surface_mesh>();
  std::vector<double> support(num_faces(s.mesh));
  const Plane_3 degenerate(0, 0, 0, 1);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::refine_symmetry_plane(s.mesh, degenerate, grid_32); },
                                                         "degenerate plane"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::symmetry_support(s.mesh, degenerate, CGAL::make_property_map(support), grid_32); }, "degenerate plane"));
}

TEST(PrincipalSymmetriesBadInput, ZeroRefinementSamplesAreRejected)
{
  const Shape<Surface_mesh> s = box<Surface_mesh>();
  const auto zero = grid_32.number_of_refinement_samples(0);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::detect_principal_symmetries(s.mesh, zero); },
                                                         "number_of_refinement_samples"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::refine_symmetry_plane(s.mesh, Plane_3(1, 0, 0, 0), zero); }, "number_of_refinement_samples"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] {
      std::vector<Point_3> corners;
      for(auto v : vertices(s.mesh)) corners.push_back(s.mesh.point(v));
      ST::detect_principal_symmetries_of_points(corners, zero);
    },
    "number_of_refinement_samples"));
}

} // namespace
