// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The Gaussian Euclidean Distance Transform: its placement, normalisation and values, for
// meshes and point sets, and the bad inputs of DESIGN.md.

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>
#include <CGAL/Symmetry_transform/internal/grid/gaussian_distance_transform.h>

#include "Symmetry_transform_test_shapes.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace {

using namespace st_test;
namespace ST = CGAL::Symmetry_transform;
namespace PMP = CGAL::Polygon_mesh_processing;

const auto small_grid = CGAL::parameters::grid_resolution(32);

// The grid `f` should hold exp(-d^2 / 2 sigma^2), with d = distance(point), cut to zero beyond
// 3 sigma and normalised to unit sum of squares: returns the largest deviation from it.
template <typename Distance>
double deviation_from_gaussian_of(const Grid& f, double width_in_voxels, const Distance& distance)
{
  const double sigma = width_in_voxels * f.voxel_size();
  const std::size_t n = f.resolution();
  std::vector<double> expected(f.values().size(), 0.);
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        const double d = distance(f.point(i, j, k));
        if(d <= 3. * sigma) expected[f.index(i, j, k)] = std::exp(-d * d / (2. * sigma * sigma));
      }
  const double scale = 1. / std::sqrt(sum_of_squares(expected));
  for(double& x : expected) x *= scale;
  return max_abs_difference(f.values(), expected);
}

template <typename Mesh>
Point_3 area_weighted_centroid(const Mesh& mesh)
{
  double area = 0.;
  Vector_3 sum(0, 0, 0);
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const double a = PMP::face_area(f, mesh);
    sum = sum + a * (CGAL::centroid(get(CGAL::vertex_point, mesh, source(h, mesh)),
                                    get(CGAL::vertex_point, mesh, target(h, mesh)),
                                    get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh))) -
                     CGAL::ORIGIN);
    area += a;
  }
  return CGAL::ORIGIN + sum / area;
}

template <typename Mesh>
double farthest_vertex_distance(const Mesh& mesh, const Point_3& c)
{
  double r2 = 0.;
  for(auto v : vertices(mesh)) r2 = std::max(r2, CGAL::squared_distance(c, get(CGAL::vertex_point, mesh, v)));
  return std::sqrt(r2);
}

// ------------------------------------------------------------------------------------------
// Valid inputs
// ------------------------------------------------------------------------------------------

TEST(GaussianDistanceTransform, SurfaceMeshAndPolyhedronOfTheSameShapeGiveTheSameGrid)
{
  const Grid a = ST::gaussian_distance_transform(one_plane_hull<Surface_mesh>().mesh, small_grid);
  const Grid b = ST::gaussian_distance_transform(one_plane_hull<Polyhedron>().mesh, small_grid);
  EXPECT_LT(CGAL::squared_distance(a.center(), b.center()), 1e-24);
  EXPECT_NEAR(a.radius(), b.radius(), 1e-12);
  EXPECT_EQ(a.side_length(), b.side_length());
  EXPECT_LT(max_abs_difference(a.values(), b.values()), 1e-12);
}

// The band as its definition states it, voxel by voxel: the centres within `cutoff` of the
// plane of a triangle and in its bounding box grown by `cutoff`.
std::vector<char> band_by_definition(const Grid& grid, const std::vector<CGAL::Symmetry_transform::internal::Dtriangle>& triangles,
                                     double cutoff)
{
  namespace STI = CGAL::Symmetry_transform::internal;
  std::vector<char> band(grid.values().size(), 0);
  for(const STI::Dtriangle& t : triangles) {
    const CGAL::Bbox_3 box = t.bbox();
    STI::Dvector normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    normal = normal / std::sqrt(normal.squared_length());
    STI::for_each_voxel_in_box(grid, {box.xmin() - cutoff, box.ymin() - cutoff, box.zmin() - cutoff},
                               {box.xmax() + cutoff, box.ymax() + cutoff, box.zmax() + cutoff},
                               [&](std::size_t v, double x, double y, double z) {
                                 const STI::Dvector d(x - t[0].x(), y - t[0].y(), z - t[0].z());
                                 if(std::abs(d * normal) <= cutoff) band[v] = 1;
                               });
  }
  return band;
}

// The band is marked by rows and by layers in parallel, and the detection hands the GEDT its
// matcher's tree: the band is that of the definition, and the grid and the closest
// triangle of each voxel are those of one thread and of a tree of the GEDT's own, to the bit;
// also far from the origin, where the rounding of the coordinates is larger.
TEST(GaussianDistanceTransform, BandGridAndClosestTrianglesDoNotDependOnThreadsOrOnWhoseTreeIsUsed)
{
  namespace STI = CGAL::Symmetry_transform::internal;
  for(const Vector_3& shift : {Vector_3(0, 0, 0), Vector_3(1e4, -3e3, 7e3)}) {
    Surface_mesh mesh = ellipsoid<Surface_mesh>(1., 0.6, 0.35, 4).mesh;
    for(auto v : vertices(mesh)) mesh.point(v) = mesh.point(v) + shift;
    const std::vector<STI::Dtriangle> triangles = STI::triangles_of_mesh(mesh, CGAL::parameters::default_values());
    const STI::Shape_frame frame = STI::frame_of_triangles(triangles);
    std::vector<std::int32_t> closest_alone, closest_shared;
    const STI::Grid_settings alone = STI::grid_settings(STI::grid_options(small_grid.number_of_threads(1)), frame.radius);
    const Grid a = STI::gaussian_distance_transform_of_triangles<K>(triangles, frame, alone, &closest_alone);
    const STI::Triangle_matcher matcher(triangles);
    const STI::Grid_settings shared = STI::grid_settings(STI::grid_options(small_grid.number_of_threads(3)), frame.radius);
    const Grid b = STI::gaussian_distance_transform_of_triangles<K>(triangles, matcher.tree(), frame, shared, &closest_shared);
    EXPECT_EQ(a.values(), b.values());
    EXPECT_EQ(closest_alone, closest_shared);
    const std::vector<char> band = band_by_definition(a, triangles, alone.cutoff());
    std::size_t in_band = 0, differ = 0;
    for(std::size_t v = 0; v < band.size(); ++v) {
      in_band += band[v];
      differ += (band[v] != 0) != (closest_alone[v] >= 0);
    }
    EXPECT_GT(in_band, 1000u);
    EXPECT_EQ(differ, 0u);
  }
}

// Beyond most_distance_hints triangles the searches start from the hints of some triangles only:
// their closest points are still exact (brute force over every triangle) and as far as with
// CGAL's hints of all triangles.
TEST(GaussianDistanceTransform, ClosestPointsOfALargeSoupAreExactWithHintsOfSomeTriangles)
{
  namespace STI = CGAL::Symmetry_transform::internal;
  const int side = 260; // 135,200 triangles of a wavy height field
  auto corner = [&](int i, int j) {
    const double x = double(i) / side, y = double(j) / side;
    return STI::Dpoint(x, y, 0.1 * std::sin(9. * x) * std::cos(7. * y));
  };
  std::vector<STI::Dtriangle> triangles;
  for(int i = 0; i < side; ++i)
    for(int j = 0; j < side; ++j) {
      triangles.emplace_back(corner(i, j), corner(i + 1, j), corner(i + 1, j + 1));
      triangles.emplace_back(corner(i, j), corner(i + 1, j + 1), corner(i, j + 1));
    }
  ASSERT_GT(triangles.size(), STI::most_distance_hints);
  STI::Triangle_tree some(triangles.begin(), triangles.end()), all(triangles.begin(), triangles.end());
  some.build();
  all.build();
  STI::accelerate_distance_queries(some, triangles);
  all.accelerate_distance_queries();
  CGAL::Random random(7);
  for(int q = 0; q < 2000; ++q) {
    const STI::Dpoint p(random.get_double(-0.2, 1.2), random.get_double(-0.2, 1.2), random.get_double(-0.4, 0.4));
    const double d2 = CGAL::squared_distance(p, some.closest_point(p));
    ASSERT_NEAR(d2, CGAL::squared_distance(p, all.closest_point(p)), 1e-15);
    if(q % 40 != 0) continue;
    double least = std::numeric_limits<double>::infinity();
    const Eigen::Vector3d e = STI::to_eigen(p);
    for(const STI::Dtriangle& t : triangles)
      least = (std::min)(least, (e - STI::closest_point_on_triangle(e, STI::to_eigen(t[0]), STI::to_eigen(t[1]),
                                                                      STI::to_eigen(t[2]))).squaredNorm());
    ASSERT_NEAR(d2, least, 1e-15);
  }
}

TEST(GaussianDistanceTransform, SumOfSquaresIsOne)
{
  EXPECT_NEAR(sum_of_squares(ST::gaussian_distance_transform(ellipsoid<Surface_mesh>().mesh, small_grid).values()), 1.,
              1e-12);
  EXPECT_NEAR(sum_of_squares(ST::gaussian_distance_transform(box<Polyhedron>().mesh, small_grid).values()), 1., 1e-12);
  const std::vector<Point_3> points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 2, 1)};
  EXPECT_NEAR(sum_of_squares(ST::gaussian_distance_transform_of_points(points, small_grid).values()), 1., 1e-12);
}

TEST(GaussianDistanceTransform, GridIsCentredOnAreaWeightedCentroidWithRadiusOfFarthestVertex)
{
  const Surface_mesh mesh = one_plane_hull<Surface_mesh>().mesh;
  const Grid f = ST::gaussian_distance_transform(mesh, small_grid);
  const Point_3 c = area_weighted_centroid(mesh);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(f.center(), c)), 1e-12);
  Vector_3 sum(0, 0, 0);
  for(auto v : vertices(mesh)) sum = sum + (mesh.point(v) - CGAL::ORIGIN);
  const Point_3 vertex_mean = CGAL::ORIGIN + sum / double(num_vertices(mesh));
  EXPECT_GT(std::sqrt(CGAL::squared_distance(f.center(), vertex_mean)), 1e-3) << "the test tells the centroids apart";
  EXPECT_NEAR(f.radius(), farthest_vertex_distance(mesh, c), 1e-12);
  // Default cube side: the bounding sphere plus 3 Gaussian widths of 1.5 voxels on each side.
  EXPECT_NEAR(f.side_length(), 2. * f.radius() / (1. - 6. * 1.5 / 32.), 1e-12);
  EXPECT_NEAR(ST::gaussian_distance_transform(mesh, small_grid.grid_margin(1.5)).side_length(), 3. * f.radius(), 1e-12);
}

TEST(GaussianDistanceTransform, ValuesAreGaussianOfAnalyticDistanceToBox)
{
  const double h[3] = {1., 0.7, 0.45};
  const Grid f = ST::gaussian_distance_transform(box<Surface_mesh>(h[0], h[1], h[2]).mesh,
                                                 CGAL::parameters::grid_resolution(40).gaussian_width(2.0));
  const double deviation = deviation_from_gaussian_of(f, 2.0, [&](const Point_3& p) {
    const double q[3] = {std::abs(p.x()) - h[0], std::abs(p.y()) - h[1], std::abs(p.z()) - h[2]};
    double outside = 0.;
    for(double x : q) outside += CGAL::square(std::max(x, 0.));
    return std::sqrt(outside) + std::abs(std::min(std::max({q[0], q[1], q[2]}), 0.));
  });
  EXPECT_LT(deviation, 1e-12);
}

TEST(GaussianDistanceTransform, PointSetValuesAreGaussianOfDistanceToNearestPoint)
{
  CGAL::Random rng(7);
  std::vector<std::pair<Point_3, int>> points;
  for(int i = 0; i < 30; ++i)
    points.emplace_back(Point_3(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-0.5, 0.5)), i);
  const Grid f = ST::gaussian_distance_transform_of_points(
    points,
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<Point_3, int>>()).grid_resolution(24));

  Vector_3 sum(0, 0, 0);
  for(const auto& p : points) sum = sum + (p.first - CGAL::ORIGIN);
  const Point_3 mean = CGAL::ORIGIN + sum / double(points.size());
  double r2 = 0.;
  for(const auto& p : points) r2 = std::max(r2, CGAL::squared_distance(mean, p.first));
  EXPECT_LT(std::sqrt(CGAL::squared_distance(f.center(), mean)), 1e-12);
  EXPECT_NEAR(f.radius(), std::sqrt(r2), 1e-12);
  EXPECT_NEAR(sum_of_squares(f.values()), 1., 1e-12);
  EXPECT_LT(deviation_from_gaussian_of(f, 1.5,
                                       [&](const Point_3& x) {
                                         double d2 = std::numeric_limits<double>::infinity();
                                         for(const auto& p : points)
                                           d2 = std::min(d2, CGAL::squared_distance(x, p.first));
                                         return std::sqrt(d2);
                                       }),
            1e-12);
}

TEST(GaussianDistanceTransform, PlacementIsInvariantUnderRotation)
{
  CGAL::Random rng(11);
  const Shape<Surface_mesh> shape = one_plane_hull<Surface_mesh>();
  const Grid f = ST::gaussian_distance_transform(shape.mesh, small_grid);
  for(int trial = 0; trial < 3; ++trial) {
    const Motion rotation = random_motion(rng, true, false, false);
    const Grid g = ST::gaussian_distance_transform(moved(shape, rotation).mesh, small_grid);
    EXPECT_NEAR(g.radius(), f.radius(), 1e-12);
    EXPECT_NEAR(g.side_length(), f.side_length(), 1e-12);
    EXPECT_LT(std::sqrt(CGAL::squared_distance(g.center(), rotation.transform(f.center()))), 1e-12);
  }
}

TEST(GaussianDistanceTransform, ExtraDegenerateFaceLeavesGridUnchanged)
{
  Surface_mesh mesh = box<Surface_mesh>().mesh;
  const Grid f = ST::gaussian_distance_transform(mesh, small_grid);
  // A zero-area triangle inside the box: were it kept, the GEDT would be non-zero around it.
  CGAL::make_triangle(Point_3(0, 0, 0), Point_3(0.15, 0, 0), Point_3(0.3, 0, 0), mesh);
  const Grid g = ST::gaussian_distance_transform(mesh, small_grid);
  EXPECT_EQ(g.radius(), f.radius());
  EXPECT_LT(CGAL::squared_distance(g.center(), f.center()), 1e-24);
  EXPECT_LT(max_abs_difference(g.values(), f.values()), 1e-14);
}

TEST(GaussianDistanceTransform, FlatMeshIsValidAndSymmetricAboutItsOwnPlane)
{
  CGAL::Random rng(5);
  const Motion motion = random_motion(rng);
  Surface_mesh mesh;
  CGAL::make_quad(Point_3(-1, -0.6, 0), Point_3(1, -0.6, 0), Point_3(1, 0.6, 0), Point_3(-1, 0.6, 0), mesh);
  PMP::triangulate_faces(mesh);
  PMP::transform(motion, mesh);
  const Grid f = ST::gaussian_distance_transform(mesh, small_grid);
  EXPECT_NEAR(sum_of_squares(f.values()), 1., 1e-12);
  const Plane_3 own = moved(Plane_3(0, 0, 1, 0), motion);
  EXPECT_GE(ST::symmetry_measure(f, own), 0.99);
  EXPECT_LT(ST::symmetry_measure(f, rotated_plane(own, f.center(), in_plane_axes(own)[0], 20.)), 0.9);
}

TEST(GaussianDistanceTransform, CollinearPointSetIsValidAndSymmetricAboutItsBisector)
{
  std::vector<Point_3> points;
  for(int i = 0; i <= 20; ++i) points.emplace_back(0.1 * i, 0.05 * i, -0.02 * i);
  const Grid f = ST::gaussian_distance_transform_of_points(points, small_grid);
  EXPECT_NEAR(sum_of_squares(f.values()), 1., 1e-12);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(f.center(), Point_3(1., 0.5, -0.2))), 1e-12);
  const Plane_3 bisector(f.center(), points.back() - points.front());
  EXPECT_GE(ST::symmetry_measure(f, bisector), 0.99);
  EXPECT_LT(ST::symmetry_measure(f, Plane_3(points[5], points.back() - points.front())), 0.9);
}

// ------------------------------------------------------------------------------------------
// Bad inputs: a std::invalid_argument that says what is wrong
// ------------------------------------------------------------------------------------------

template <typename Input, typename NP = CGAL::parameters::Default_named_parameters>
::testing::AssertionResult mesh_is_rejected(const Input& mesh, const std::string& message,
                                            const NP& np = CGAL::parameters::default_values())
{
  return throws_with_message<std::invalid_argument>([&] { ST::gaussian_distance_transform(mesh, np); }, message);
}

template <typename Input, typename NP = CGAL::parameters::Default_named_parameters>
::testing::AssertionResult points_are_rejected(const Input& points, const std::string& message,
                                               const NP& np = CGAL::parameters::default_values())
{
  return throws_with_message<std::invalid_argument>([&] { ST::gaussian_distance_transform_of_points(points, np); },
                                                    message);
}

TEST(GaussianDistanceTransformBadInput, EmptyMeshIsRejected)
{
  EXPECT_TRUE(mesh_is_rejected(Surface_mesh(), "no face"));
  EXPECT_TRUE(mesh_is_rejected(Polyhedron(), "no face"));
}

TEST(GaussianDistanceTransformBadInput, QuadFaceIsRejected)
{
  Polyhedron mesh;
  CGAL::make_hexahedron(Point_3(-1, -1, -1), Point_3(1, -1, -1), Point_3(1, 1, -1), Point_3(-1, 1, -1),
                        Point_3(-1, 1, 1), Point_3(-1, -1, 1), Point_3(1, -1, 1), Point_3(1, 1, 1), mesh);
  EXPECT_TRUE(mesh_is_rejected(mesh, "not a triangle"));
}

TEST(GaussianDistanceTransformBadInput, MeshOfDegenerateFacesOnlyIsRejected)
{
  Surface_mesh mesh;
  CGAL::make_triangle(Point_3(0, 0, 0), Point_3(1, 1, 1), Point_3(2, 2, 2), mesh);
  CGAL::make_triangle(Point_3(0, 0, 0), Point_3(0, 0, 0), Point_3(0, 1, 0), mesh);
  EXPECT_TRUE(mesh_is_rejected(mesh, "degenerate"));
}

Surface_mesh box_with_corner_at(const Point_3& p)
{
  Surface_mesh mesh = box<Surface_mesh>().mesh;
  mesh.point(*vertices(mesh).begin()) = p;
  return mesh;
}

TEST(GaussianDistanceTransformBadInput, NanCoordinateIsRejected)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(mesh_is_rejected(box_with_corner_at(Point_3(1, nan, 1)), "NaN"));
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>{Point_3(0, 0, 0), Point_3(nan, 0, 0)}, "NaN"));
}

TEST(GaussianDistanceTransformBadInput, InfiniteCoordinateIsRejected)
{
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(mesh_is_rejected(box_with_corner_at(Point_3(1, 1, -inf)), "infinite"));
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>{Point_3(0, 0, 0), Point_3(0, inf, 0)}, "infinite"));
}

TEST(GaussianDistanceTransformBadInput, EmptyPointSetIsRejected)
{
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>(), "empty"));
}

TEST(GaussianDistanceTransformBadInput, SinglePointAndCoincidentPointsAreRejected)
{
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>{Point_3(1, 2, 3)}, "single point"));
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>(5, Point_3(1, 2, 3)), "single point"));
}

// Beyond 1e100 or below 1e-100 the sums of squares leave the range of doubles: a point at -5e303
// among points at the origin made the grid's spacing infinite and its voxel indices NaN.
TEST(GaussianDistanceTransformBadInput, ShapeTooLargeOrTooSmallForDoublesIsRejected)
{
  std::vector<Point_3> huge(45, Point_3(0, 0, 0));
  huge.push_back(Point_3(-5e303, 0, 0));
  EXPECT_TRUE(points_are_rejected(huge, "scale it first"));
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>{Point_3(0, 0, 0), Point_3(1e120, 0, 0)}, "scale it first"));
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>{Point_3(0, 0, 0), Point_3(0, 1e-120, 0)}, "scale it first"));
  EXPECT_TRUE(mesh_is_rejected(box_with_corner_at(Point_3(1e200, 1, 1)), "scale it first"));
  EXPECT_NO_THROW(ST::gaussian_distance_transform_of_points(
    std::vector<Point_3>{Point_3(0, 0, 0), Point_3(1e90, 0, 0), Point_3(0, 1e90, 0)}, CGAL::parameters::grid_resolution(32)));
}

TEST(GaussianDistanceTransformBadInput, GridTooLargeForMemoryIsRejected)
{
  EXPECT_TRUE(mesh_is_rejected(box<Surface_mesh>().mesh, "grid_resolution must be", CGAL::parameters::grid_resolution(100000)));
}

TEST(GaussianDistanceTransformBadInput, GridTooSmallIsRejected)
{
  EXPECT_TRUE(mesh_is_rejected(box<Surface_mesh>().mesh, "grid_resolution must be", CGAL::parameters::grid_resolution(4)));
  // 16 samples cannot hold 4 x 3 widths of 1.5 voxels.
  EXPECT_TRUE(mesh_is_rejected(box<Surface_mesh>().mesh, "too small", CGAL::parameters::grid_resolution(16)));
}

TEST(GaussianDistanceTransformBadInput, NonPositiveGaussianWidthIsRejected)
{
  EXPECT_TRUE(mesh_is_rejected(box<Surface_mesh>().mesh, "gaussian_width", CGAL::parameters::gaussian_width(0.)));
  EXPECT_TRUE(mesh_is_rejected(box<Surface_mesh>().mesh, "gaussian_width", CGAL::parameters::gaussian_width(-1.)));
}

TEST(GaussianDistanceTransformBadInput, GridMarginBelowOneIsRejected)
{
  EXPECT_TRUE(mesh_is_rejected(box<Surface_mesh>().mesh, "grid_margin", CGAL::parameters::grid_margin(0.5)));
  EXPECT_TRUE(mesh_is_rejected(box<Surface_mesh>().mesh, "grid_margin", CGAL::parameters::grid_margin(0.)));
  EXPECT_TRUE(points_are_rejected(std::vector<Point_3>{Point_3(0, 0, 0), Point_3(1, 0, 0)}, "grid_margin",
                                  CGAL::parameters::grid_margin(0.99)));
}

} // namespace
