// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_GEOMETRY_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_GEOMETRY_H

// The numerical layer's geometry: plain double points (CGAL's Simple_cartesian<double>) and
// Eigen vectors, its one plane type, and the conversions to and from the user's kernel, which
// all go through CGAL::Cartesian_converter. Whatever the user's kernel (Epick, Epeck, ...), the
// transforms and refinements compute in double precision; its traits name the result types.

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

typedef CGAL::Simple_cartesian<double> Dkernel;
typedef Dkernel::Point_3 Dpoint;
typedef Dkernel::Vector_3 Dvector;
typedef Dkernel::Triangle_3 Dtriangle;

inline Eigen::Vector3d to_eigen(const Dpoint& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }
inline Dpoint to_dpoint(const Eigen::Vector3d& p) { return Dpoint(p.x(), p.y(), p.z()); }

// The plane {x : normal . x = offset}, normal of unit length: the one plane type inside the
// package (CGAL's Plane_3 a x + b y + c z + d = 0 has normal (a, b, c) / |(a, b, c)| and
// offset -d / |(a, b, c)|).
struct Dplane
{
  Eigen::Vector3d normal;
  double offset;

  Eigen::Vector3d reflect(const Eigen::Vector3d& p) const { return p - 2. * (normal.dot(p) - offset) * normal; }
  double signed_distance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
};

// The bounding box of points (at least one).
struct Bounding_box
{
  Eigen::Vector3d low, high;

  explicit Bounding_box(const Eigen::Vector3d& p) : low(p), high(p) {}
  explicit Bounding_box(const std::vector<Eigen::Vector3d>& points) : Bounding_box(points.front())
  {
    for(const Eigen::Vector3d& p : points) add(p);
  }
  void add(const Eigen::Vector3d& p)
  {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  Eigen::Vector3d center() const { return 0.5 * (low + high); }
};

// Coordinates relative to `center`, the centre of a shape, for the computations that form sums,
// products and differences of positions: far from the origin, the input's coordinates keep few
// digits of the shape's size, while the local ones keep them all (DESIGN.md, invariance by design).
struct Local_coordinates
{
  Eigen::Vector3d center = Eigen::Vector3d::Zero();

  Eigen::Vector3d to_local(const Eigen::Vector3d& p) const { return p - center; }
  Eigen::Vector3d to_input(const Eigen::Vector3d& p) const { return p + center; }
  Dpoint to_local(const Dpoint& p) const { return to_dpoint(to_local(to_eigen(p))); }
  Dpoint to_input(const Dpoint& p) const { return to_dpoint(to_input(to_eigen(p))); }
  Dtriangle to_local(const Dtriangle& t) const { return {to_local(t[0]), to_local(t[1]), to_local(t[2])}; }
  Dplane to_local(const Dplane& p) const { return {p.normal, p.offset - p.normal.dot(center)}; }
  Dplane to_input(const Dplane& p) const { return {p.normal, p.offset + p.normal.dot(center)}; }
};

// A point of any kernel in double precision; throws on a NaN or infinite coordinate.
template <typename Point>
Dpoint to_dpoint(const Point& p)
{
  const Dpoint q = CGAL::Cartesian_converter<typename CGAL::Kernel_traits<Point>::Kernel, Dkernel>()(p);
  if(!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()))
    throw std::invalid_argument("Symmetry_transform: the input has a NaN or infinite coordinate");
  return q;
}

// A plane of any kernel as a Dplane; throws if it is degenerate (zero or non-finite normal or offset).
template <typename Plane>
Dplane to_dplane(const Plane& plane)
{
  const Dkernel::Plane_3 p = CGAL::Cartesian_converter<typename CGAL::Kernel_traits<Plane>::Kernel, Dkernel>()(plane);
  const Eigen::Vector3d n(p.a(), p.b(), p.c());
  const double length = n.norm();
  if(!(length > 0.) || !std::isfinite(length) || !std::isfinite(p.d()))
    throw std::invalid_argument("Symmetry_transform: degenerate plane (zero or non-finite normal or offset)");
  return {n / length, -p.d() / length};
}

// The results in the user's kernel GT.
template <typename GT>
typename GT::Plane_3 to_plane(const Dplane& p)
{
  return CGAL::Cartesian_converter<Dkernel, GT>()(Dkernel::Plane_3(p.normal[0], p.normal[1], p.normal[2], -p.offset));
}

template <typename GT>
typename GT::Point_3 to_point(const Eigen::Vector3d& p)
{
  return CGAL::Cartesian_converter<Dkernel, GT>()(to_dpoint(p));
}

template <typename GT>
typename GT::Point_3 to_point(const Dpoint& p)
{
  return CGAL::Cartesian_converter<Dkernel, GT>()(p);
}

template <typename GT>
typename GT::Vector_3 to_vector(const Eigen::Vector3d& v)
{
  return CGAL::Cartesian_converter<Dkernel, GT>()(Dvector(v.x(), v.y(), v.z()));
}

// The smallest n <= max_n such that x in [0, 1/2] lies within `tolerance` of a fraction m / n
// (then in lowest terms), or 0 if there is none: the order of a rotation by 2 pi x, or of the
// one that two planes meeting at pi x generate.
inline int fraction_denominator(double x, int max_n, double tolerance)
{
  for(int n = 1; n <= max_n; ++n)
    for(int m = 0; 2 * m <= n; ++m)
      if(std::abs(x - double(m) / double(n)) < tolerance) return n;
  return 0;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_GEOMETRY_H
