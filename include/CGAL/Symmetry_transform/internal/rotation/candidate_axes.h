// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_CANDIDATE_AXES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_CANDIDATE_AXES_H

// Where rotation axes may lie, before any refinement:
// - the axes of inertia: the second-moment tensor of a shape invariant under a rotation by
//   2 pi / k about a (k >= 3) is alpha a a^T + beta (I - a a^T), so a is its distinct
//   eigenvector; a 2-fold axis is one of its eigenvectors. Exact for whole symmetric shapes.
// - the directions searched on the sphere of normals: the local maxima of the correlation of
//   the normals' density with its rotation by 2 pi / k (normal_density.h). They need no axis
//   point, so they hold when the centre of mass is off the axis (a part of the shape missing),
//   and find symmetries with no mirror plane (twisted propellers, screws) as well as others.
// - the lines where two planes of symmetry meet at an angle pi / k (a rotation by 2 pi / k is the
//   product of the reflections through them), when the planes are known.

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/rotation/axis.h>
#include <CGAL/Symmetry_transform/internal/rotation/normal_density.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// A direction (or a whole axis) with the order it was found for and how well the rotation by
// 2 pi / order scored there.
struct Axis_candidate
{
  Daxis axis;
  int order;
  double score;
};

// The directions searched: a Fibonacci hemisphere of this many (half the sphere: a and -a are
// the same axis), about 5 degrees apart, finer than the 6 degrees of the normals' density.
constexpr std::size_t searched_directions = 800;
// Local maxima of each order's correlation kept, strongest first: a k-fold shape has its axis at
// the top for k and its divisors; the others make room for the axes of shapes with several.
constexpr std::size_t maxima_per_order = 3;

// The Fibonacci hemisphere (z > 0) and, for each direction, those within `reach` radians up to sign.
struct Direction_sphere
{
  std::vector<Eigen::Vector3d> directions;
  std::vector<std::vector<std::size_t>> neighbours;

  explicit Direction_sphere(std::size_t count)
  {
    for(const Eigen::Vector3d& d : fibonacci_sphere(2 * count))
      if(d.z() > 0.) directions.push_back(d);
    const double reach = 2.5 * std::sqrt(2. * CGAL_PI / double(directions.size()));
    neighbours.resize(directions.size());
    for(std::size_t i = 0; i < directions.size(); ++i)
      for(std::size_t j = 0; j < directions.size(); ++j)
        if(i != j && std::abs(directions[i].dot(directions[j])) > std::cos(reach)) neighbours[i].push_back(j);
  }
};

// The local maxima of the correlation of the normals' density with its rotations by 2 pi / k
// about the searched directions, `maxima_per_order` per order, as axes through `center`.
inline std::vector<Axis_candidate> normal_density_candidates(const Normal_density& density, int max_order,
                                                             const Eigen::Vector3d& center, unsigned threads)
{
  static const Direction_sphere sphere(searched_directions);
  const std::size_t n = sphere.directions.size();
  std::vector<Axis_candidate> result;
  std::vector<double> score(n);
  for(int k = 2; k <= max_order; ++k) {
    parallel_for(n, threads, [&](unsigned, std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end && parallel_step(); ++i)
        score[i] = density.correlation(rotation_about(Eigen::Vector3d::Zero(), sphere.directions[i], 2. * CGAL_PI / k).linear);
    });
    std::vector<Axis_candidate> maxima;
    for(std::size_t i = 0; i < n; ++i)
      if(std::all_of(sphere.neighbours[i].begin(), sphere.neighbours[i].end(), [&](std::size_t j) {
           return score[j] < score[i] || (score[j] == score[i] && j > i);
         }))
        maxima.push_back({{center, sphere.directions[i]}, k, score[i]});
    std::sort(maxima.begin(), maxima.end(), [](const Axis_candidate& a, const Axis_candidate& b) { return a.score > b.score; });
    if(maxima.size() > maxima_per_order) maxima.resize(maxima_per_order);
    result.insert(result.end(), maxima.begin(), maxima.end());
  }
  return result;
}

// The three axes of inertia through the centre of mass, for every order.
inline std::vector<Axis_candidate> inertia_candidates(const Mass_distribution& mass, int max_order)
{
  std::vector<Axis_candidate> result;
  for(const Eigen::Vector3d& direction : principal_axes(mass.covariance()))
    for(int k = 2; k <= max_order; ++k) result.push_back({{mass.center(), direction.normalized()}, k, 0.});
  return result;
}

// The lines where two of `planes` meet at an angle pi k' / k (k' prime to k, k <= max_order,
// within 1 degree), with order k: the rotation by twice that angle is the product of the two
// reflections. Parallel planes (within 1 degree) do not meet.
inline std::vector<Axis_candidate> plane_pair_candidates(const std::vector<Dplane>& planes, int max_order,
                                                         const Eigen::Vector3d& center)
{
  constexpr double tolerance = CGAL_PI / 180.;
  std::vector<Axis_candidate> result;
  for(std::size_t i = 0; i < planes.size(); ++i)
    for(std::size_t j = i + 1; j < planes.size(); ++j) {
      const Eigen::Vector3d direction = planes[i].normal.cross(planes[j].normal);
      if(direction.norm() < std::sin(tolerance)) continue;
      const double angle = std::acos(std::clamp(std::abs(planes[i].normal.dot(planes[j].normal)), 0., 1.));
      // The smallest k with angle = pi k' / k for some k' (angle in (0, pi/2]).
      const int order = fraction_denominator(angle / CGAL_PI, max_order, tolerance / CGAL_PI);
      if(order < 2) continue;
      // The point of the line nearest to the centre: on both planes, least squares along the line.
      Eigen::Matrix3d m;
      m << planes[i].normal.transpose(), planes[j].normal.transpose(), direction.normalized().transpose();
      const Eigen::Vector3d point = m.inverse() * Eigen::Vector3d(planes[i].offset, planes[j].offset,
                                                                  direction.normalized().dot(center));
      result.push_back({{point, direction.normalized()}, order, 0.});
    }
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_CANDIDATE_AXES_H
