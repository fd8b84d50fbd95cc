// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PLANE_GROUP_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PLANE_GROUP_H

// The mirror planes of a shape form (with its rotations) a group: the image of a mirror plane by
// the reflection in another is a mirror plane. The exact planes found therefore generate the
// others of their group (the 15 planes of an icosahedron from the ten strongest, the 13 of a
// 12-gonal prism from three), which the transform's candidates, capped and ranked by a noisy
// estimate, may miss. Each image is refined and tested on the shape as a candidate is: images of
// approximate planes need not be planes of symmetry.

#include <CGAL/Symmetry_transform/internal/common/geometry.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The planes that generate others: those a refinement maps onto the shape almost wholly (exact
// symmetries of a mesh reach 0.99; partial ones, which generate nothing, rarely 0.9).
constexpr double group_generator_support = 0.95;
// An image is kept if its refined support is within this of its generators' lower one.
constexpr double group_support_tolerance = 0.05;
// Two exact planes meet at pi m / n to about 1e-5 radian; 1e-3 keeps irrational angles (a
// continuous family, whose images would never end) out.
constexpr double group_angle_tolerance = 1e-3;

inline bool parallel_planes(const Dplane& a, const Dplane& b)
{
  return a.normal.cross(b.normal).norm() < group_angle_tolerance;
}

// The order n <= max_order of the rotation that two planes meeting at `angle` generate (angle =
// pi m / n, m prime to n), or 0 if there is none: parallel planes or an angle no such fraction.
inline int generated_order(const Dplane& a, const Dplane& b, int max_order)
{
  if(parallel_planes(a, b)) return 0;
  const double angle = std::acos(std::clamp(std::abs(a.normal.dot(b.normal)), 0., 1.)); // in [0, pi/2]
  const int n = fraction_denominator(angle / CGAL_PI, max_order, group_angle_tolerance / CGAL_PI);
  return n >= 2 ? n : 0;
}

// The image of `plane` by the reflection in `mirror`.
inline Dplane reflected(const Dplane& plane, const Dplane& mirror)
{
  const Eigen::Vector3d normal = (plane.normal - 2. * plane.normal.dot(mirror.normal) * mirror.normal).normalized();
  const Eigen::Vector3d point = mirror.reflect(plane.offset * plane.normal);
  return {normal, normal.dot(point)};
}

// The most planes a finite group has whose rotations have orders up to max_order: the n + 1 of a
// prism's group D_nh, or the 15 of the icosahedron's.
inline std::size_t largest_plane_group(int max_order)
{
  return (std::max)(std::size_t(max_order) + 1, std::size_t(15));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PLANE_GROUP_H
