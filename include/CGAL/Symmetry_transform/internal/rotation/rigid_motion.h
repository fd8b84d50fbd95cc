// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_RIGID_MOTION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_RIGID_MOTION_H

// A rigid motion x -> L x + t in double precision, from and to the user's
// Aff_transformation_3: what symmetry_measure(grid, rotation) applies to the grid, and what the
// rotational symmetries are made of. Kept free of the rest of the package (symmetry_measure.h
// includes it).

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>

namespace CGAL::Symmetry_transform::internal {

// How far from orthogonal the linear part of a user's transformation may be (max |L^T L - I|):
// rotation matrices typed with 7 or more significant digits pass, a scaling of 1e-5 does not.
constexpr double orthogonality_tolerance = 1e-6;

struct Rigid_motion
{
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return linear * x + translation; }

  // In place, on the coordinates of a point (the form the grid measures take).
  void move(double* x) const
  {
    const Eigen::Vector3d y = (*this)(Eigen::Vector3d(x[0], x[1], x[2]));
    x[0] = y[0];
    x[1] = y[1];
    x[2] = y[2];
  }
};

// a after b
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Rigid_motion compose(const Rigid_motion& a, const Rigid_motion& b);

// of an isometry
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Rigid_motion inverse(const Rigid_motion& a);

// The rotation by `angle` (radians, counterclockwise seen from the tip of `direction`) about the
// line through `point` along the unit vector `direction` (Rodrigues' formula).
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Rigid_motion rotation_about(const Eigen::Vector3d& point, const Eigen::Vector3d& direction, double angle);

// The motion of an Aff_transformation_3 of any kernel; throws unless it is an isometry (its
// linear part orthogonal) with finite coefficients.
template <typename Transformation>
Rigid_motion rigid_motion(const Transformation& t)
{
  Rigid_motion r;
  for(int i = 0; i < 3; ++i) {
    for(int j = 0; j < 3; ++j) r.linear(i, j) = CGAL::to_double(t.m(i, j));
    r.translation[i] = CGAL::to_double(t.m(i, 3));
  }
  if(!r.linear.allFinite() || !r.translation.allFinite())
    throw std::invalid_argument("Symmetry_transform: the transformation has a NaN or infinite coefficient");
  if(!((r.linear.transpose() * r.linear - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= orthogonality_tolerance))
    throw std::invalid_argument("Symmetry_transform: the transformation is not a rigid motion (its linear part is "
                                "not orthogonal)");
  return r;
}

// The motion as an Aff_transformation_3 of the kernel GT.
template <typename GT>
typename GT::Aff_transformation_3 to_transformation(const Rigid_motion& r)
{
  const Eigen::Matrix3d& l = r.linear;
  const Eigen::Vector3d& t = r.translation;
  return typename GT::Aff_transformation_3(l(0, 0), l(0, 1), l(0, 2), t[0], l(1, 0), l(1, 1), l(1, 2), t[1],
                                           l(2, 0), l(2, 1), l(2, 2), t[2]);
}

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Rigid_motion compose(const Rigid_motion& a, const Rigid_motion& b)
{
  Rigid_motion r;
  r.linear = a.linear * b.linear;
  r.translation = a.linear * b.translation + a.translation;
  return r;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Rigid_motion inverse(const Rigid_motion& a)
{
  Rigid_motion r;
  r.linear = a.linear.transpose();
  r.translation = -(r.linear * a.translation);
  return r;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Rigid_motion rotation_about(const Eigen::Vector3d& point, const Eigen::Vector3d& direction, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d cross;
  cross << 0., -direction.z(), direction.y(), direction.z(), 0., -direction.x(), -direction.y(), direction.x(), 0.;
  Rigid_motion r;
  r.linear = c * Eigen::Matrix3d::Identity() + s * cross + (1. - c) * direction * direction.transpose();
  r.translation = point - r.linear * point;
  return r;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_RIGID_MOTION_H
