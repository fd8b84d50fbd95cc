// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The Point Symmetry Transform: its maximum lies at the centre of centrally symmetric shapes
// under random motions, its samples are the direct symmetry measures, it moves with the shape.

#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "Symmetry_transform_test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
typedef ST::Point_symmetry_transform<K> Pst;

// 64^3: at 32^3 the Gaussian (1.5 voxels) is so wide relative to the shapes that even the
// one-plane hull measures 0.92 at its centroid; at 64^3 it measures 0.75.
const auto grid_64 = CGAL::parameters::grid_resolution(64);

double maximum_sample(const Pst& pst)
{
  return *std::max_element(pst.grid().values().begin(), pst.grid().values().end());
}

double distance_in_voxels(const Point_3& a, const Point_3& b, const Grid& f)
{
  return std::sqrt(CGAL::squared_distance(a, b)) / f.voxel_size();
}

// The centrally symmetric shapes, each under three random similarities.
template <typename Test>
void for_centrally_symmetric_shapes_under_random_motions(const Test& test)
{
  CGAL::Random rng(42);
  const std::pair<const char*, Shape<Surface_mesh>> shapes[] = {{"box", box<Surface_mesh>()},
                                                                {"ellipsoid", ellipsoid<Surface_mesh>()},
                                                                {"hull", centrally_symmetric_hull<Surface_mesh>()}};
  for(const auto& [name, shape] : shapes)
    for(int trial = 0; trial < 3; ++trial) {
      SCOPED_TRACE(std::string(name) + ", motion " + std::to_string(trial));
      const Shape<Surface_mesh> s = moved(shape, random_motion(rng));
      const Grid f = ST::gaussian_distance_transform(s.mesh, grid_64);
      test(s, f, ST::point_symmetry_transform(f));
    }
}

TEST(PointSymmetryTransform, MaximumSampleIsACornerOfTheVoxelCellHoldingTheTrueCentre)
{
  for_centrally_symmetric_shapes_under_random_motions([](const Shape<Surface_mesh>& s, const Grid& f, const Pst& pst) {
    const std::vector<double>& v = pst.grid().values();
    const std::size_t best = std::size_t(std::max_element(v.begin(), v.end()) - v.begin()), n = f.resolution();
    const std::size_t ijk[3] = {best % n, best / n % n, best / (n * n)};
    const Vector_3 c = *s.center - f.point(0, 0, 0);
    for(int axis = 0; axis < 3; ++axis) {
      const double u = c[axis] / f.voxel_size(); // sample coordinate of the true centre
      EXPECT_LT(std::abs(double(ijk[axis]) - u), 1.) << "axis " << axis;
    }
    EXPECT_GE(ST::symmetry_measure(f, *s.center), 0.99);
    // The true centre is at most half a voxel from a sample along each axis, so the reflection
    // through that sample is off by at most one voxel: exp(-1 / (4 sigma^2)) = 0.895 across a face.
    EXPECT_GE(maximum_sample(pst), 0.85);
  });
}

TEST(PointSymmetryTransform, CenterOfSymmetryIsWithinHalfAVoxelOfTrueCentre)
{
  for_centrally_symmetric_shapes_under_random_motions([](const Shape<Surface_mesh>& s, const Grid& f, const Pst& pst) {
    const Point_3 c = pst.center_of_symmetry();
    EXPECT_LE(distance_in_voxels(c, *s.center, f), 0.5);
    EXPECT_GE(ST::symmetry_measure(f, c), 0.99);
  });
}

TEST(PointSymmetryTransform, ShapeWithoutCentreOfSymmetryHasClearlyLowerMaximum)
{
  const Pst symmetric =
    ST::point_symmetry_transform(ST::gaussian_distance_transform(box<Surface_mesh>().mesh, grid_64));
  const Grid f = ST::gaussian_distance_transform(one_plane_hull<Surface_mesh>().mesh, grid_64);
  const Pst pst = ST::point_symmetry_transform(f);
  EXPECT_LE(maximum_sample(pst), 0.8);
  EXPECT_LE(ST::symmetry_measure(f, pst.center_of_symmetry()), 0.8);
  EXPECT_LE(maximum_sample(pst), maximum_sample(symmetric) - 0.1);
}

TEST(PointSymmetryTransform, SamplesEqualDirectSymmetryMeasure)
{
  // At a sample p, 2p - x is a sample for every sample x: the direct measure's cubic
  // interpolation is exact there, and the two differ only by the FFT's rounding.
  CGAL::Random rng(3);
  const Grid f = ST::gaussian_distance_transform(moved(one_plane_hull<Surface_mesh>(), random_motion(rng)).mesh,
                                                 CGAL::parameters::grid_resolution(32));
  const Pst pst = ST::point_symmetry_transform(f);
  const std::size_t n = f.resolution();
  double largest = 0.;
  for(int trial = 0; trial < 30; ++trial) {
    const std::size_t i = std::size_t(rng.get_int(n / 4, 3 * n / 4)), j = std::size_t(rng.get_int(n / 4, 3 * n / 4)),
                      k = std::size_t(rng.get_int(n / 4, 3 * n / 4));
    const double direct = ST::symmetry_measure(f, f.point(i, j, k));
    largest = std::max(largest, direct);
    EXPECT_NEAR(pst.grid()(i, j, k), direct, 1e-12);
    EXPECT_NEAR(pst.value(f.point(i, j, k)), direct, 1e-12);
  }
  EXPECT_GT(largest, 0.1) << "the samples compared include non-trivial values";
}

TEST(PointSymmetryTransform, CentreMovesWithTranslatedShape)
{
  CGAL::Random rng(8);
  const Shape<Surface_mesh> s = ellipsoid<Surface_mesh>();
  const Pst pst = ST::point_symmetry_transform(s.mesh, grid_64);
  const Motion translation = random_motion(rng, false, true, false);
  const Pst moved_pst = ST::point_symmetry_transform(moved(s, translation).mesh, grid_64);
  const Point_3 expected = translation.transform(pst.center_of_symmetry());
  EXPECT_LT(std::sqrt(CGAL::squared_distance(moved_pst.center_of_symmetry(), expected)), 1e-9);
  EXPECT_GT(std::sqrt(CGAL::squared_distance(moved_pst.center_of_symmetry(), pst.center_of_symmetry())), 1.);
}

} // namespace
