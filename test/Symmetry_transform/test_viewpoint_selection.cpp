// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Viewpoint selection: S(v) = sum |v.u| M(u) over principal planes. For three orthogonal planes
// of measures M1, M2, M3 the best view is (M1, M2, M3)/|M| in their frame (off every normal; a
// diagonal for equal measures) and the worst is the normal of the weakest plane; both rotate with
// the planes; S is even and ignores the length of v; the exported sphere is an icosphere with
// scores in [0, sum M]; no plane gives no best view; bad input is rejected. On a box with three
// different sides, the planes found by detect_principal_symmetries give a best view off every
// normal.

#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include "Symmetry_transform_test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Principal_symmetry<K> Symmetry;
typedef std::vector<Symmetry> Symmetries;
typedef ST::Viewpoint<K> View;

Symmetries three_planes(double m1, double m2, double m3)
{
  return {Symmetry{Plane_3(1, 0, 0, 0), m1, 1.}, Symmetry{Plane_3(0, 1, 0, 0), m2, 1.},
          Symmetry{Plane_3(0, 0, 1, 0), m3, 1.}};
}

// Angle in degrees between two views (v and -v are one view).
double view_angle(const Vector_3& a, const Vector_3& b)
{
  const double c = std::abs(a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::min(1., c)) * 180. / CGAL_PI;
}

std::vector<View> best(const Symmetries& s)
{
  std::vector<View> views;
  ST::best_viewpoints(s, std::back_inserter(views));
  return views;
}

TEST(ViewpointSelection, BestViewOfThreeOrthogonalPlanesIsOffEveryNormal)
{
  const Symmetries s = three_planes(0.9, 0.6, 0.3);
  const std::vector<View> views = best(s);
  ASSERT_FALSE(views.empty());
  for(const Symmetry& p : s) EXPECT_GT(view_angle(views[0].direction, p.plane.orthogonal_vector()), 20.);
  // the exact maximum (+-M1, +-M2, +-M3)/|M|, of score |M| (the 4 views tie)
  const Vector_3& d = views[0].direction;
  EXPECT_LT(view_angle(Vector_3(std::abs(d.x()), std::abs(d.y()), std::abs(d.z())), Vector_3(0.9, 0.6, 0.3)), 1e-6);
  EXPECT_NEAR(views[0].score, std::sqrt(0.81 + 0.36 + 0.09), 1e-12);
  // the 4 sign patterns, as views, are the 4 maxima; best first, one per view, on z >= 0
  EXPECT_EQ(views.size(), 4u);
  for(std::size_t i = 0; i < views.size(); ++i) {
    EXPECT_NEAR(views[i].score, views[0].score, 1e-12);
    EXPECT_GE(views[i].direction.z(), 0.);
    EXPECT_NEAR(views[i].direction.squared_length(), 1., 1e-12);
    for(std::size_t j = 0; j < i; ++j) EXPECT_GT(view_angle(views[i].direction, views[j].direction), 1.);
  }
}

TEST(ViewpointSelection, BestViewsOfEqualPlanesAreTheDiagonals)
{
  const std::vector<View> views = best(three_planes(0.5, 0.5, 0.5));
  ASSERT_EQ(views.size(), 4u);
  for(const View& v : views) {
    double nearest = 180.;
    for(double sy : {-1., 1.})
      for(double sx : {-1., 1.}) nearest = std::min(nearest, view_angle(v.direction, Vector_3(sx, sy, 1.)));
    EXPECT_LT(nearest, 1e-6);
    EXPECT_NEAR(v.score, 0.5 * std::sqrt(3.), 1e-12);
  }
}

TEST(ViewpointSelection, WorstViewOfThreeOrthogonalPlanesIsTheNormalOfTheWeakest)
{
  const View worst = ST::worst_viewpoint(three_planes(0.6, 0.3, 0.9));
  EXPECT_LT(view_angle(worst.direction, Vector_3(0, 1, 0)), 1.);
  EXPECT_NEAR(worst.score, 0.3, 1e-12);
  EXPECT_GT(worst.direction.y(), 0.); // the documented hemisphere
}

TEST(ViewpointSelection, WorstViewIsBelowEverySample)
{
  // three planes in general position, and a fourth
  const Symmetries s = {Symmetry{Plane_3(1, 0.2, 0, 0), 0.8, 1.}, Symmetry{Plane_3(0.1, 1, 0.3, 0), 0.5, 1.},
                        Symmetry{Plane_3(0, 0.4, 1, 0), 0.7, 1.}, Symmetry{Plane_3(1, 1, 1, 2), 0.2, 1.}};
  const View worst = ST::worst_viewpoint(s);
  for(const auto& v : ST::internal::fibonacci_sphere(20000))
    EXPECT_LE(worst.score, ST::viewpoint_score(s, Vector_3(v[0], v[1], v[2])) + 1e-12);
  const std::vector<View> views = best(s);
  ASSERT_FALSE(views.empty());
  for(const auto& v : ST::internal::fibonacci_sphere(20000))
    EXPECT_GE(views[0].score, ST::viewpoint_score(s, Vector_3(v[0], v[1], v[2])) - 1e-12);
}

TEST(ViewpointSelection, ViewsRotateWithThePlanes)
{
  const Symmetries s = three_planes(0.9, 0.6, 0.3);
  CGAL::Random rng(7);
  for(int trial = 0; trial < 3; ++trial) {
    const Motion m = random_motion(rng, true, false, false);
    Symmetries r = s;
    for(Symmetry& p : r) p.plane = moved(p.plane, m);
    const std::vector<View> views = best(s), rotated = best(r);
    ASSERT_EQ(views.size(), rotated.size());
    for(const View& v : views) {
      double nearest = 180.;
      for(const View& w : rotated) nearest = std::min(nearest, view_angle(m.transform(v.direction), w.direction));
      EXPECT_LT(nearest, 1e-6);
    }
    EXPECT_NEAR(views[0].score, rotated[0].score, 1e-12);
    const View worst = ST::worst_viewpoint(s), worst_rotated = ST::worst_viewpoint(r);
    EXPECT_LT(view_angle(m.transform(worst.direction), worst_rotated.direction), 1e-6);
    EXPECT_NEAR(worst.score, worst_rotated.score, 1e-12);
  }
}

TEST(ViewpointSelection, CoarseSamplingFindsTheSameExactViews)
{
  const Symmetries s = three_planes(0.9, 0.6, 0.3);
  std::vector<View> coarse;
  ST::best_viewpoints(s, std::back_inserter(coarse), CGAL::parameters::number_of_directions(1000));
  const std::vector<View> fine = best(s);
  ASSERT_EQ(coarse.size(), fine.size());
  for(std::size_t i = 0; i < fine.size(); ++i) {
    double nearest = 180.;
    for(const View& c : coarse) nearest = std::min(nearest, view_angle(c.direction, fine[i].direction));
    EXPECT_LT(nearest, 1e-6);
  }
  // deterministic
  const std::vector<View> again = best(s);
  for(std::size_t i = 0; i < fine.size(); ++i) EXPECT_EQ(again[i].direction, fine[i].direction);
}

TEST(ViewpointSelection, ScoreIsEvenAndIgnoresTheLength)
{
  const Symmetries s = three_planes(0.9, 0.6, 0.3);
  CGAL::Random rng(3);
  for(int i = 0; i < 50; ++i) {
    const Vector_3 v(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    const double score = ST::viewpoint_score(s, v);
    EXPECT_DOUBLE_EQ(score, ST::viewpoint_score(s, -v));
    EXPECT_NEAR(score, ST::viewpoint_score(s, 3.5 * v), 1e-12);
    EXPECT_GE(score, 0.3 - 1e-12);
    EXPECT_LE(score, std::sqrt(0.81 + 0.36 + 0.09) + 1e-12);
  }
  EXPECT_NEAR(ST::viewpoint_score(s, Vector_3(2, 0, 0)), 0.9, 1e-15);
}

TEST(ViewpointSelection, ScoreSphereIsAnIcosphereWithScoresWithinBounds)
{
  const Symmetries s = three_planes(0.9, 0.6, 0.3);
  for(unsigned int subdivisions : {0u, 3u}) {
    CGAL::Surface_mesh<Point_3> sphere = ST::viewpoint_score_sphere(s, subdivisions);
    EXPECT_EQ(num_vertices(sphere), 10u * (1u << (2 * subdivisions)) + 2u);
    EXPECT_EQ(num_faces(sphere), 20u * (1u << (2 * subdivisions)));
    // add_property_map() returns the existing map, and false, when there is one.
    const auto score = sphere.add_property_map<CGAL::Surface_mesh<Point_3>::Vertex_index, double>("v:score", -1.);
    ASSERT_FALSE(score.second);
    for(auto v : vertices(sphere)) {
      const Vector_3 d = sphere.point(v) - CGAL::ORIGIN;
      EXPECT_NEAR(d.squared_length(), 1., 1e-12);
      EXPECT_GE(score.first[v], 0.);
      EXPECT_LE(score.first[v], 1.8);
      EXPECT_NEAR(score.first[v], ST::viewpoint_score(s, d), 1e-12);
    }
  }
}

TEST(ViewpointSelection, NoPlaneGivesNoBestViewAndScoresZero)
{
  const Symmetries none;
  EXPECT_TRUE(best(none).empty());
  EXPECT_EQ(ST::viewpoint_score(none, Vector_3(1, 2, 3)), 0.);
  const View worst = ST::worst_viewpoint(none);
  EXPECT_EQ(worst.score, 0.);
  EXPECT_EQ(worst.direction, Vector_3(0, 0, 1));
  // planes of measure zero count as none
  EXPECT_TRUE(best(three_planes(0., 0., 0.)).empty());
}

TEST(ViewpointSelection, OnePlaneIsBestSeenAlongItsNormalAndWorstWithin)
{
  const Symmetries s = {Symmetry{Plane_3(1, 1, 0, 0.5), 0.7, 1.}};
  const std::vector<View> views = best(s);
  ASSERT_EQ(views.size(), 1u);
  EXPECT_LT(view_angle(views[0].direction, Vector_3(1, 1, 0)), 1e-6);
  EXPECT_NEAR(views[0].score, 0.7, 1e-12);
  const View worst = ST::worst_viewpoint(s);
  EXPECT_NEAR(worst.direction * Vector_3(1, 1, 0), 0., 1e-12);
  EXPECT_NEAR(worst.score, 0., 1e-12);
}

TEST(ViewpointSelection, RejectsBadInput)
{
  const Symmetries s = three_planes(0.9, 0.6, 0.3);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::viewpoint_score(s, Vector_3(0, 0, 0)); }, "zero"));
  const Symmetries no_normal = {Symmetry{Plane_3(0, 0, 0, 1), 0.5, 1.}};
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { best(no_normal); }, "normal"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::worst_viewpoint(no_normal); }, "normal"));
  const Symmetries negative = three_planes(0.9, -0.6, 0.3);
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { best(negative); }, "negative"));
  std::vector<View> views;
  EXPECT_TRUE(throws_with_message<std::invalid_argument>(
    [&] { ST::best_viewpoints(s, std::back_inserter(views), CGAL::parameters::number_of_directions(5)); },
    "number_of_directions"));
  EXPECT_TRUE(throws_with_message<std::invalid_argument>([&] { ST::viewpoint_score_sphere(s, 9); }, "subdivisions"));
}

TEST(ViewpointSelection, BestViewOfDetectedBoxPlanesIsOffEveryNormal)
{
  // 32^3 and 1e5 Monte Carlo pairs, as grid_32 in test_principal_symmetries.cpp
  const auto np = CGAL::parameters::grid_resolution(32).number_of_samples(100000).random_seed(1);
  const Shape<Surface_mesh> shape = box<Surface_mesh>();
  const Symmetries s = ST::detect_principal_symmetries(shape.mesh, np);
  ASSERT_GE(s.size(), 3u);
  const std::vector<View> views = best(s);
  ASSERT_FALSE(views.empty());
  for(const Plane_3& p : shape.planes) EXPECT_GT(view_angle(views[0].direction, p.orthogonal_vector()), 20.);
  // the worst view is the normal of one of the box's planes (the weakest one, if only they were found)
  const View worst = ST::worst_viewpoint(s);
  double nearest = 180.;
  for(const Plane_3& p : shape.planes) nearest = std::min(nearest, view_angle(worst.direction, p.orthogonal_vector()));
  EXPECT_LT(nearest, 1.);
  for(const Symmetry& p : s)
    std::cout << "plane " << p.plane << " M " << p.symmetry << "\n";
  std::cout << "best " << views[0].direction << " S " << views[0].score << "; worst " << worst.direction << " S "
            << worst.score << "\n";
}

} // namespace
