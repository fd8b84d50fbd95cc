// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_AXIS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_AXIS_H

// The one axis type of the numerical layer (a point and a unit direction), its rotations, and
// the conversions from and to the user's Line_3 (through CGAL::Cartesian_converter).

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/rotation/rigid_motion.h>

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>

namespace CGAL::Symmetry_transform::internal {

// The line {point + s direction}, direction of unit length.
struct Daxis
{
  Eigen::Vector3d point;
  Eigen::Vector3d direction;

  Rigid_motion rotation(double angle) const { return rotation_about(point, direction, angle); }

  // The point of the line nearest to c.
  Eigen::Vector3d projection(const Eigen::Vector3d& c) const { return point + (c - point).dot(direction) * direction; }

  double distance(const Eigen::Vector3d& c) const { return (c - projection(c)).norm(); }

  // The same line, through its point nearest to c, its direction with its largest coordinate
  // positive (the first of equals): one representative of the two orientations.
  Daxis canonical(const Eigen::Vector3d& c) const
  {
    Eigen::Index largest = 0;
    direction.cwiseAbs().maxCoeff(&largest);
    return {projection(c), direction[largest] < 0. ? Eigen::Vector3d(-direction) : direction};
  }
};

// Angle in radians between the lines' directions, up to orientation: in [0, pi/2].
inline double angle_between(const Daxis& a, const Daxis& b)
{
  return std::atan2(a.direction.cross(b.direction).norm(), std::abs(a.direction.dot(b.direction)));
}

// Whether two axes are the same line near c: directions within `angle`, and each passing within
// `distance` of the other's point nearest to c.
inline bool same_axis(const Daxis& a, const Daxis& b, const Eigen::Vector3d& c, double angle, double distance)
{
  return angle_between(a, b) < angle && a.distance(b.projection(c)) < distance && b.distance(a.projection(c)) < distance;
}

// Distance between two lines (between their points nearest to each other).
inline double line_distance(const Daxis& a, const Daxis& b)
{
  const Eigen::Vector3d normal = a.direction.cross(b.direction);
  if(normal.norm() < 1e-12) return a.distance(b.point); // parallel
  return std::abs((b.point - a.point).dot(normal.normalized()));
}

// A line of any kernel as a Daxis; throws if it is degenerate (zero or non-finite direction or point).
template <typename Line>
Daxis to_daxis(const Line& line)
{
  const Dkernel::Line_3 l = CGAL::Cartesian_converter<typename CGAL::Kernel_traits<Line>::Kernel, Dkernel>()(line);
  const Eigen::Vector3d point = to_eigen(l.point()),
                        direction(l.to_vector().x(), l.to_vector().y(), l.to_vector().z());
  const double length = direction.norm();
  if(!(length > 0.) || !std::isfinite(length) || !point.allFinite())
    throw std::invalid_argument("Symmetry_transform: degenerate axis (zero or non-finite direction or point)");
  return {point, direction / length};
}

template <typename GT>
typename GT::Line_3 to_line(const Daxis& axis)
{
  const Dkernel::Line_3 l(to_dpoint(axis.point), Dvector(axis.direction.x(), axis.direction.y(), axis.direction.z()));
  return CGAL::Cartesian_converter<Dkernel, GT>()(l);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_AXIS_H
