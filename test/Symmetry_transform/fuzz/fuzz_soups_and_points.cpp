// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// libFuzzer target over the public entry points on triangle soups and point sets, on grids of 8
// and 16: the bytes choose the function, its parameters among small valid values (and a few
// invalid Gaussian widths), up to 64 points (raw doubles, so NaN, infinities, huge and denormal
// values, or small integers scaled and offset, so equal, coplanar and far-away points), their
// normals, a plane and up to 64 triangles whose indices may lie past the points (fuzz_input.h).
// A bad input must end in std::invalid_argument, the documented refusal; anything else (another
// exception, a crash, a sanitizer report, a leak, a timeout) is a finding.

#include <CGAL/Symmetry_transform/point_symmetry_transform.h>
#include <CGAL/Symmetry_transform/principal_symmetries.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include "fuzz_input.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace {

namespace ST = CGAL::Symmetry_transform;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef K::Plane_3 Plane_3;
typedef std::pair<Point_3, Vector_3> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

ST::Monte_carlo_estimator estimator_of(int i)
{
  static const ST::Monte_carlo_estimator estimators[4] = {
    ST::Monte_carlo_estimator::PAIR_JACOBIAN, ST::Monte_carlo_estimator::BOUNDED_WEIGHT,
    ST::Monte_carlo_estimator::STRATIFIED_LINES, ST::Monte_carlo_estimator::STRATIFIED_LINES};
  return estimators[i & 3];
}

// The named parameters of every entry point; each function reads those it takes.
auto parameters_of(const st_fuzz::Input& in)
{
  return CGAL::parameters::grid_resolution(in.grid_resolution)
    .gaussian_width(in.gaussian_width)
    .number_of_threads(in.number_of_threads)
    .prst_method(in.exact_prst ? ST::Reflective_symmetry_method::EXACT : ST::Reflective_symmetry_method::MONTE_CARLO)
    .monte_carlo_estimator(estimator_of(in.estimator))
    .number_of_samples(in.number_of_samples)
    .number_of_refinement_samples(in.number_of_refinement_samples)
    .number_of_iterations(in.number_of_iterations)
    .max_number_of_planes(in.max_number_of_planes)
    .max_order(in.max_order)
    .number_of_points_on_faces(in.number_of_points_on_faces)
    .random_seed(in.random_seed);
}

// Calls the chosen function; its result is dropped (the sanitizers watch how it is computed).
template <typename NamedParameters>
void call(const st_fuzz::Input& in, const NamedParameters& np)
{
  std::vector<Point_3> points;
  std::vector<Point_with_normal> with_normals;
  for(std::size_t i = 0; i < in.points.size(); ++i) {
    const st_fuzz::Triple& p = in.points[i];
    const st_fuzz::Triple& n = in.normals[i];
    points.emplace_back(p[0], p[1], p[2]);
    with_normals.emplace_back(points.back(), Vector_3(n[0], n[1], n[2]));
  }
  const auto& triangles = in.triangles;
  const auto np_normals = np.point_map(Point_map()).normal_map(Normal_map());
  const Plane_3 plane(in.plane[0], in.plane[1], in.plane[2], in.plane[3]);
  switch(in.entry) {
  case st_fuzz::PRINCIPAL_SYMMETRIES_OF_TRIANGLE_SOUP:
    ST::detect_principal_symmetries_of_triangle_soup(points, triangles, np); break;
  case st_fuzz::PRINCIPAL_SYMMETRIES_OF_POINTS: ST::detect_principal_symmetries_of_points(points, np); break;
  case st_fuzz::PRINCIPAL_SYMMETRIES_OF_POINTS_WITH_NORMALS:
    ST::detect_principal_symmetries_of_points(with_normals, np_normals); break;
  case st_fuzz::ROTATIONAL_SYMMETRIES_OF_POINTS: ST::detect_rotational_symmetries_of_points(points, np); break;
  case st_fuzz::REFLECTIVE_SYMMETRY_TRANSFORM_OF_POINTS: ST::reflective_symmetry_transform_of_points(points, np); break;
  case st_fuzz::REFLECTIVE_SYMMETRY_TRANSFORM_OF_TRIANGLE_SOUP:
    ST::reflective_symmetry_transform_of_triangle_soup(points, triangles, np); break;
  case st_fuzz::POINT_SYMMETRY_TRANSFORM_OF_POINTS: ST::point_symmetry_transform_of_points(points, np); break;
  case st_fuzz::POINT_SYMMETRY_TRANSFORM_OF_TRIANGLE_SOUP:
    ST::point_symmetry_transform_of_triangle_soup(points, triangles, np); break;
  case st_fuzz::SYMMETRY_FRAME_OF_POINTS: ST::symmetry_frame_of_points(points, np); break;
  case st_fuzz::SYMMETRY_FRAME_OF_POINTS_WITH_NORMALS: ST::symmetry_frame_of_points(with_normals, np_normals); break;
  case st_fuzz::SYMMETRY_FRAME_OF_TRIANGLE_SOUP: ST::symmetry_frame_of_triangle_soup(points, triangles, np); break;
  case st_fuzz::SYMMETRY_DISTANCE_ERROR_OF_TRIANGLE_SOUP:
    ST::symmetry_distance_error_of_triangle_soup(points, triangles, plane, np); break;
  case st_fuzz::SYMMETRY_DISTANCE_ERROR_OF_POINTS: ST::symmetry_distance_error_of_points(points, plane, np); break;
  default: break;
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const st_fuzz::Input in = st_fuzz::decode(data, size);
  // Cancels on its cancel_after-th call when the input asks for it; else never called.
  int calls = 0;
  const std::function<bool(double)> cancel = [&](double) { return ++calls < in.cancel_after; };
  try {
    if(in.cancel)
      call(in, parameters_of(in).callback(cancel));
    else
      call(in, parameters_of(in));
  } catch(const std::invalid_argument&) {
    // The documented refusal of a bad input or parameter.
  }
  return 0;
}
