// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The numeric named parameters: every public function refuses a negative value, a zero where
// it means nothing, and a size that cannot fit in memory or time, with a std::invalid_argument
// naming the parameter and its range, within a second (before any large allocation or long
// loop); on meshes, point sets and triangle soups. Values in range, given in any arithmetic type,
// give the results of the same values given as the documented type.

#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/remeshing_metrics.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>
#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include "Symmetry_transform_test_shapes.h"

#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace ST = CGAL::Symmetry_transform;
namespace params = CGAL::parameters;
using st_test::K;
using st_test::Point_3;
using st_test::Plane_3;
using st_test::Surface_mesh;

// A box as a mesh, as a soup and as points on its surface.
struct Inputs
{
  Surface_mesh mesh = st_test::box<Surface_mesh>().mesh;
  std::vector<Point_3> soup_points;
  std::vector<std::array<std::size_t, 3>> soup_triangles;
  std::vector<Point_3> points;

  Inputs()
  {
    CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, soup_points, soup_triangles);
    CGAL::Random rng(7);
    points = st_test::surface_points(mesh, 2000, rng);
  }
};

const Inputs& inputs()
{
  static const Inputs in;
  return in;
}

const Plane_3 x_plane(1, 0, 0, 0);

// A small grid, so that a value accepted by mistake shows as a wrong result, not a long run.
auto small()
{
  return params::grid_resolution(24).number_of_threads(1).random_seed(1);
}

// `f` throws a std::invalid_argument naming `name` and its range ("NAME must be ...") within a second.
::testing::AssertionResult refused(const std::function<void()>& f, const std::string& name)
{
  const auto start = std::chrono::steady_clock::now();
  ::testing::AssertionResult r = st_test::throws_with_message<std::invalid_argument>(f, name + " must be");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(r && seconds >= 1.) return ::testing::AssertionFailure() << name << " refused after " << seconds << " s";
  return r;
}

// The functions that build a grid from a shape, with the named parameters `np`.
template <typename NP>
std::vector<std::pair<std::string, std::function<void()>>> grid_functions(const NP& np)
{
  const Inputs& in = inputs();
  return {
    {"gaussian_distance_transform", [&in, np] { ST::gaussian_distance_transform(in.mesh, np); }},
    {"gaussian_distance_transform_of_points", [&in, np] { ST::gaussian_distance_transform_of_points(in.points, np); }},
    {"gaussian_distance_transform_of_triangle_soup",
     [&in, np] { ST::gaussian_distance_transform_of_triangle_soup(in.soup_points, in.soup_triangles, np); }},
    {"point_symmetry_transform", [&in, np] { ST::point_symmetry_transform(in.mesh, np); }},
    {"point_symmetry_transform_of_points", [&in, np] { ST::point_symmetry_transform_of_points(in.points, np); }},
    {"point_symmetry_transform_of_triangle_soup",
     [&in, np] { ST::point_symmetry_transform_of_triangle_soup(in.soup_points, in.soup_triangles, np); }},
    {"reflective_symmetry_transform", [&in, np] { ST::reflective_symmetry_transform(in.mesh, np); }},
    {"reflective_symmetry_transform_of_points", [&in, np] { ST::reflective_symmetry_transform_of_points(in.points, np); }},
    {"reflective_symmetry_transform_of_triangle_soup",
     [&in, np] { ST::reflective_symmetry_transform_of_triangle_soup(in.soup_points, in.soup_triangles, np); }},
    {"symmetry_descriptor", [&in, np] { ST::symmetry_descriptor(in.mesh, np); }},
    {"symmetry_descriptor_of_points", [&in, np] { ST::symmetry_descriptor_of_points(in.points, np); }},
  };
}

// The functions that detect planes or axes, with the named parameters `np`.
template <typename NP>
std::vector<std::pair<std::string, std::function<void()>>> detection_functions(const NP& np)
{
  const Inputs& in = inputs();
  return {
    {"detect_principal_symmetries", [&in, np] { ST::detect_principal_symmetries(in.mesh, np); }},
    {"detect_principal_symmetries_of_points", [&in, np] { ST::detect_principal_symmetries_of_points(in.points, np); }},
    {"detect_principal_symmetries_of_triangle_soup",
     [&in, np] { ST::detect_principal_symmetries_of_triangle_soup(in.soup_points, in.soup_triangles, np); }},
    {"refine_symmetry_plane", [&in, np] { ST::refine_symmetry_plane(in.mesh, x_plane, np); }},
    {"symmetry_frame", [&in, np] { ST::symmetry_frame(in.mesh, np); }},
    {"symmetry_frame_of_points", [&in, np] { ST::symmetry_frame_of_points(in.points, np); }},
    {"symmetry_frame_of_triangle_soup",
     [&in, np] { ST::symmetry_frame_of_triangle_soup(in.soup_points, in.soup_triangles, np); }},
    {"detect_rotational_symmetries", [&in, np] { ST::detect_rotational_symmetries(in.mesh, np); }},
    {"detect_rotational_symmetries_of_points", [&in, np] { ST::detect_rotational_symmetries_of_points(in.points, np); }},
    {"rotational_symmetries", [&in, np] { ST::rotational_symmetries(in.mesh, std::vector<ST::Principal_symmetry<K>>(), np); }},
    {"symmetry_support", [&in, np] {
       Surface_mesh mesh = in.mesh;
       auto support = mesh.add_property_map<Surface_mesh::Face_index, double>("f:support", 0.).first;
       ST::symmetry_support(mesh, x_plane, support, np);
     }},
    {"segment_by_symmetry", [&in, np] {
       Surface_mesh mesh = in.mesh;
       auto segment = mesh.add_property_map<Surface_mesh::Face_index, std::size_t>("f:segment", 0).first;
       ST::segment_by_symmetry(mesh, segment, np.max_segmentation_depth(1));
     }},
  };
}

// The functions that sample the surface with `number_of_points_on_faces`.
template <typename NP>
std::vector<std::pair<std::string, std::function<void()>>> metric_functions(const NP& np)
{
  const Inputs& in = inputs();
  return {
    {"symmetry_distance_error", [&in, np] { ST::symmetry_distance_error(in.mesh, x_plane, np); }},
    {"symmetry_distance_error_of_points", [&in, np] { ST::symmetry_distance_error_of_points(in.points, x_plane, np); }},
    {"symmetry_distance_error_of_triangle_soup",
     [&in, np] { ST::symmetry_distance_error_of_triangle_soup(in.soup_points, in.soup_triangles, x_plane, np); }},
    {"symmetry_error", [&in, np] { ST::symmetry_error(in.mesh, x_plane, np); }},
    {"approximation_error", [&in, np] { ST::approximation_error(in.mesh, in.mesh, np); }},
    {"symmetry_error with a reference", [&in, np] { ST::symmetry_error(in.mesh, x_plane, in.mesh, 0.1, np); }},
  };
}

template <typename Functions>
void expect_all_refuse(const Functions& functions, const std::string& name)
{
  for(const auto& [function, call] : functions) EXPECT_TRUE(refused(call, name)) << function;
}

TEST(ParameterValidation, NegativeNumberOfSamplesIsRefusedAtOnceEverywhere)
{
  expect_all_refuse(grid_functions(small().number_of_samples(-1)), "number_of_samples");
  expect_all_refuse(detection_functions(small().number_of_samples(-1)), "number_of_samples");
  expect_all_refuse(grid_functions(small().number_of_samples(0)), "number_of_samples");
  const st_test::Grid grid = ST::gaussian_distance_transform(inputs().mesh, small());
  EXPECT_TRUE(refused([&] { ST::reflective_symmetry_transform(grid, params::number_of_samples(-1)); }, "number_of_samples"));
  EXPECT_TRUE(refused([&] { ST::reflective_symmetry_transform(grid, params::number_of_samples(1e11)); }, "number_of_samples"));
}

TEST(ParameterValidation, ZeroSamplesAreAcceptedByTheExactTransformOnly)
{
  const st_test::Grid grid = ST::gaussian_distance_transform(inputs().mesh, small());
  const auto exact = ST::reflective_symmetry_transform(
    grid, params::number_of_samples(0).prst_method(ST::Reflective_symmetry_method::EXACT).number_of_threads(1));
  EXPECT_GT(st_test::sum_of_squares(exact.values()), 0.);
  EXPECT_TRUE(refused([&] {
    ST::reflective_symmetry_transform(grid, params::number_of_samples(0).prst_method(ST::Reflective_symmetry_method::MONTE_CARLO));
  }, "number_of_samples"));
}

TEST(ParameterValidation, NegativeOrZeroRefinementSamplesAreRefusedEverywhere)
{
  expect_all_refuse(detection_functions(small().number_of_refinement_samples(-1)), "number_of_refinement_samples");
  expect_all_refuse(detection_functions(small().number_of_refinement_samples(0)), "number_of_refinement_samples");
  // More samples than memory holds: refused by their count, before any is drawn.
  expect_all_refuse(detection_functions(small().number_of_refinement_samples(std::size_t(1) << 40)),
                    "number_of_refinement_samples");
}

TEST(ParameterValidation, PointsOnFacesAreRefusedUnderTheirOwnName)
{
  expect_all_refuse(metric_functions(params::number_of_points_on_faces(-1)), "number_of_points_on_faces");
  expect_all_refuse(metric_functions(params::number_of_points_on_faces(0)), "number_of_points_on_faces");
  expect_all_refuse(metric_functions(params::number_of_points_on_faces(1e12)), "number_of_points_on_faces");
  for(const auto& [function, call] : metric_functions(params::number_of_points_on_faces(0)))
    EXPECT_FALSE(st_test::throws_with_message<std::invalid_argument>(call, "number_of_refinement_samples")) << function;
}

TEST(ParameterValidation, GridResolutionBeyondMemoryOrBelowEightIsRefused)
{
  for(long n : {-1L, 0L, 4L, 1000L, 100000L, 1L << 40}) {
    SCOPED_TRACE(n);
    expect_all_refuse(grid_functions(small().grid_resolution(n)), "grid_resolution");
    expect_all_refuse(detection_functions(small().grid_resolution(n)), "grid_resolution");
  }
  // Just beyond the memory bound, whatever the thread count (the work is split in fixed pieces).
  for(unsigned threads : {1u, 1024u})
    EXPECT_TRUE(refused([&] { ST::gaussian_distance_transform(inputs().mesh, small().number_of_threads(threads).grid_resolution(
                                    ST::internal::max_grid_resolution() + 1)); }, "grid_resolution"));
}

TEST(ParameterValidation, NegativeOrHugeThreadCountsAreRefusedAndZeroMeansTheDefault)
{
  expect_all_refuse(grid_functions(small().number_of_threads(-1)), "number_of_threads");
  expect_all_refuse(detection_functions(small().number_of_threads(-1)), "number_of_threads");
  expect_all_refuse(metric_functions(params::number_of_threads(-1)), "number_of_threads");
  EXPECT_TRUE(refused([] {
    Surface_mesh mesh = inputs().mesh;
    auto error = mesh.add_property_map<Surface_mesh::Face_index, double>("f:error", 0.).first;
    ST::face_symmetry_errors(mesh, x_plane, error, params::number_of_threads(-1));
  }, "number_of_threads"));
  expect_all_refuse(grid_functions(small().number_of_threads(100000)), "number_of_threads");
  // The number of threads changes the speed only: 0 (the default), 1 and 3 give the same grid.
  const st_test::Grid one = ST::gaussian_distance_transform(inputs().mesh, small().number_of_threads(1));
  for(int threads : {0, 3}) {
    const st_test::Grid other = ST::gaussian_distance_transform(inputs().mesh, small().number_of_threads(threads));
    EXPECT_EQ(other.values(), one.values()) << threads << " threads";
  }
}

TEST(ParameterValidation, SeedsOutsideThirtyTwoBitsAreRefused)
{
  expect_all_refuse(grid_functions(small().random_seed(-1)), "random_seed");
  expect_all_refuse(metric_functions(params::random_seed(-1)), "random_seed");
  expect_all_refuse(detection_functions(small().random_seed(std::uint64_t(1) << 33)), "random_seed");
}

TEST(ParameterValidation, DetectionCountsAndThresholdsOutOfRangeAreRefused)
{
  expect_all_refuse(detection_functions(small().number_of_iterations(-1)), "number_of_iterations");
  expect_all_refuse(detection_functions(small().max_number_of_planes(0)), "max_number_of_planes");
  expect_all_refuse(detection_functions(small().max_number_of_planes(-2)), "max_number_of_planes");
  expect_all_refuse(detection_functions(small().symmetry_threshold(-0.1)), "symmetry_threshold");
  expect_all_refuse(detection_functions(small().laplacian_threshold(2.)), "laplacian_threshold");
  expect_all_refuse(detection_functions(small().gaussian_width(std::nan(""))), "gaussian_width");
  expect_all_refuse(grid_functions(small().gaussian_width(-1.)), "gaussian_width");
  expect_all_refuse(grid_functions(small().grid_margin(0.5)), "grid_margin");
  expect_all_refuse(detection_functions(small().max_order(-1)), "max_order");
  expect_all_refuse(detection_functions(small().max_order(1000000)), "max_order");
}

TEST(ParameterValidation, SegmentationParametersOutOfRangeAreRefused)
{
  const auto segment = [](const auto& np) {
    return [np] {
      Surface_mesh mesh = inputs().mesh;
      auto ids = mesh.add_property_map<Surface_mesh::Face_index, std::size_t>("f:segment", 0).first;
      ST::segment_by_symmetry(mesh, ids, np);
    };
  };
  EXPECT_TRUE(refused(segment(small().max_segmentation_depth(-1)), "max_segmentation_depth"));
  EXPECT_TRUE(refused(segment(small().max_number_of_segments(0)), "max_number_of_segments"));
  EXPECT_TRUE(refused(segment(small().max_number_of_segments(-3)), "max_number_of_segments"));
  EXPECT_TRUE(refused(segment(small().smoothing_lambda(-1.)), "smoothing_lambda"));
  EXPECT_TRUE(refused(segment(small().partial_symmetry_fraction(0.7)), "partial_symmetry_fraction"));
  EXPECT_TRUE(refused(segment(small().smallest_part_fraction(1.)), "smallest_part_fraction"));
}

TEST(ParameterValidation, RemeshingParametersOutOfRangeAreRefused)
{
  const std::vector<Plane_3> planes = st_test::coordinate_planes();
  const auto remesh = [&planes](const auto& np) {
    return [&planes, np] { ST::symmetric_approximate_triangle_mesh(inputs().mesh, planes, np); };
  };
  EXPECT_TRUE(refused(remesh(params::max_number_of_proxies(-1)), "max_number_of_proxies"));
  EXPECT_TRUE(refused(remesh(params::max_number_of_proxies(0)), "max_number_of_proxies"));
  EXPECT_TRUE(refused(remesh(params::number_of_iterations(-1)), "number_of_iterations"));
  EXPECT_TRUE(refused(remesh(params::number_of_relaxations(-1)), "number_of_relaxations"));
  EXPECT_TRUE(refused(remesh(params::position_weight(2.)), "position_weight"));
  EXPECT_TRUE(refused(remesh(params::min_error_drop(-0.5)), "min_error_drop"));
  EXPECT_TRUE(refused(remesh(params::subdivision_ratio(0.)), "subdivision_ratio"));
  EXPECT_TRUE(refused(remesh(params::number_of_threads(-1)), "number_of_threads"));
  EXPECT_TRUE(refused(remesh(params::random_seed(-1)), "random_seed"));
}

TEST(ParameterValidation, ViewpointDirectionsOutOfRangeAreRefused)
{
  const std::vector<ST::Principal_symmetry<K>> none;
  std::vector<ST::Viewpoint<K>> views;
  for(long directions : {-1L, 0L, 5L, 1000000000L})
    EXPECT_TRUE(refused([&] { ST::best_viewpoints(none, std::back_inserter(views), params::number_of_directions(directions)); },
                        "number_of_directions")) << directions;
}

TEST(ParameterValidation, TheMessageGivesTheRangeAndTheValue)
{
  try {
    ST::detect_principal_symmetries(inputs().mesh, small().number_of_samples(-1));
    FAIL() << "did not throw";
  } catch(const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("number_of_samples must be an integer in [1, 10000000000], not -1"), std::string::npos)
      << e.what();
  }
}

TEST(ParameterValidation, ValuesInRangeGiveTheSameResultInAnyArithmeticType)
{
  const st_test::Grid grid = ST::gaussian_distance_transform(inputs().mesh, small());
  const auto as_size = ST::reflective_symmetry_transform(grid, params::number_of_samples(std::size_t(50000)).number_of_threads(1u));
  const auto as_double = ST::reflective_symmetry_transform(grid, params::number_of_samples(50000.).number_of_threads(1.));
  EXPECT_EQ(as_size.values(), as_double.values());
  EXPECT_GT(st_test::sum_of_squares(as_size.values()), 0.);
  EXPECT_TRUE(refused([&] { ST::reflective_symmetry_transform(grid, params::number_of_samples(50000.5)); }, "number_of_samples"));
  // At most one plane when one is asked for.
  EXPECT_LE(ST::detect_principal_symmetries(inputs().mesh, small().max_number_of_planes(1)).size(), 1u);
}

} // namespace
