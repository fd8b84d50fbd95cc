// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_GROUP_CLOSURE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_GROUP_CLOSURE_H

// The rotations of a shape form a group: the image of a rotation axis by another rotation of the
// shape is an axis of the same order, and the product of two rotations is a rotation. From the
// axes found, these give the others of the group: the 2k two-fold axes of a gear with k teeth
// (dihedral group: k axes across the k-fold one, in two classes) from the k-fold axis and one of
// them, the 3-fold axes of a cube from its 4-fold ones. What exact symmetries generate is exact
// (the images of their axes keep their orders, the products' axes need their orders tested);
// what approximate ones generate is a candidate, refined and tested as the others (a product of
// approximate symmetries need not be one).

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/rotation/axis.h>
#include <CGAL/Symmetry_transform/internal/rotation/candidate_axes.h>
#include <CGAL/Symmetry_transform/internal/rotation/rigid_motion.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// A product's angle is taken as 2 pi m / n if within 0.01 radian of it (0.6 degree: found axes of
// approximate symmetries are within a fraction of a degree of their true place); a product that
// also translates along its axis by more than 1 % of the radius (axes that do not meet) is a
// screw motion, no rotation.
constexpr double closure_angle_tolerance = 0.01;
constexpr double closure_screw_tolerance = 0.01;

// The axis of a rotation, through its point nearest to `center`, with the order n <= max_order
// of its angle 2 pi m / n (m, n coprime), or 0 for an angle that is no such fraction (the powers
// of that rotation are dense: of symmetries, a continuous axis, such as two flips of a cylinder
// give); none for the identity or a screw motion.
inline std::optional<Axis_candidate> axis_of(const Rigid_motion& r, int max_order, const Eigen::Vector3d& center,
                                             double radius)
{
  const Eigen::Matrix3d& l = r.linear;
  const double angle = std::acos(std::clamp((l.trace() - 1.) / 2., -1., 1.));
  Eigen::Vector3d direction(l(2, 1) - l(1, 2), l(0, 2) - l(2, 0), l(1, 0) - l(0, 1));
  if(direction.norm() < 1e-6) { // angle 0 or pi: (L + I) / 2 = a a^T for a half turn
    const Eigen::Matrix3d half_turn = (l + Eigen::Matrix3d::Identity()) / 2.;
    Eigen::Index column = 0;
    half_turn.diagonal().maxCoeff(&column);
    direction = half_turn.col(column);
  }
  if(angle < closure_angle_tolerance || !(direction.norm() > 0.)) return std::nullopt;
  direction.normalize();
  if(std::abs(r.translation.dot(direction)) > closure_screw_tolerance * radius) return std::nullopt;
  const int n = fraction_denominator(angle / (2. * CGAL_PI), max_order, closure_angle_tolerance / (2. * CGAL_PI));
  const int order = n >= 2 ? n : 0;
  // The axis point p solves (I - L) p = t; the least-squares solution of least norm from the
  // centre is the axis's point nearest to it.
  const Eigen::Matrix3d fixed = Eigen::Matrix3d::Identity() - l;
  const Eigen::Vector3d shift = fixed.jacobiSvd(Eigen::ComputeFullU | Eigen::ComputeFullV)
                                  .solve(r.translation - fixed * center);
  return Axis_candidate{{center + shift, direction}, order, 0.};
}

// The axes a set of found ones generates: the images of found axes by the rotations about
// others (an image of a k-fold axis of a shape by one of its symmetries is a k-fold axis of it),
// and the axes of products of two rotations (whose order may be a multiple of the product's).
// Each candidate's score is the least of the scores of the two found axes it comes from.
struct Generated_axes
{
  std::vector<Axis_candidate> images;
  std::vector<Axis_candidate> products;
};

// The axes the found ones generate and that are not among them (`same` tells two axes apart):
// the images of each discrete axis by the rotations about each other, and the axes of the
// products of their generators. `found`: discrete axes with their orders (continuous ones are
// left out: their images are infinitely many).
inline Generated_axes group_closure(const std::vector<Axis_candidate>& found, int max_order, const Eigen::Vector3d& center,
                                    double radius, const std::function<bool(const Daxis&, const Daxis&)>& same)
{
  Generated_axes result;
  auto add = [&](std::vector<Axis_candidate>& to, const Axis_candidate& c) {
    auto is_c = [&](const Axis_candidate& other) { return same(other.axis, c.axis); };
    if(std::none_of(found.begin(), found.end(), is_c) && std::none_of(result.images.begin(), result.images.end(), is_c) &&
       std::none_of(result.products.begin(), result.products.end(), is_c))
      to.push_back(c);
  };
  for(const Axis_candidate& a : found)
    for(const Axis_candidate& b : found) {
      if(&a == &b || a.order < 2 || b.order < 2) continue;
      const double score = (std::min)(a.score, b.score);
      const Rigid_motion rb = b.axis.rotation(2. * CGAL_PI / double(b.order));
      Rigid_motion power = rb;
      for(int j = 1; j < b.order; ++j, power = compose(rb, power))
        add(result.images, {{power(a.axis.point), (power.linear * a.axis.direction).normalized()}, a.order, score});
      if(std::optional<Axis_candidate> product =
           axis_of(compose(a.axis.rotation(2. * CGAL_PI / double(a.order)), rb), max_order, center, radius)) {
        product->score = score;
        add(result.products, *product);
      }
    }
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_GROUP_CLOSURE_H
