// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_MASS_DISTRIBUTION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_MASS_DISTRIBUTION_H

// The mass of a shape for the frames of symmetry_alignment.h: its surface (area measure) for a
// mesh, its points (counting measure) for a point set, and the moments the frame rules read.
// Plain doubles and Eigen (the numerical layer).

#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The moments are exact on the triangles: the integral of a polynomial of degree k of a linear
// function s over a triangle T of area A is 2A k!/(k+2)! h_k(s_0, s_1, s_2), h_k the complete
// homogeneous symmetric polynomial of the values at the corners.
class Mass_distribution
{
public:
  explicit Mass_distribution(std::vector<Dtriangle> triangles)
    : triangles_(std::move(triangles))
  {
    const Shape_frame frame = frame_of_triangles(triangles_);
    center_ = to_eigen(frame.center);
    radius_ = frame.radius;
    for(const Dtriangle& t : triangles_) mass_ += std::sqrt(t.squared_area());
  }

  explicit Mass_distribution(std::vector<Dpoint> points)
    : points_(std::move(points))
  {
    const Shape_frame frame = frame_of_points(points_);
    center_ = to_eigen(frame.center);
    radius_ = frame.radius;
    mass_ = double(points_.size());
  }

  const Eigen::Vector3d& center() const { return center_; }
  double radius() const { return radius_; }

  // The covariance about the centre of mass, per unit mass: for a triangle with corners v_i
  // relative to the centre, A/12 (sum_i v_i v_i^T + (sum_i v_i)(sum_i v_i)^T).
  Eigen::Matrix3d covariance() const
  {
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const Dtriangle& t : triangles_) {
      const Eigen::Vector3d v[3] = {corner(t, 0) - center_, corner(t, 1) - center_, corner(t, 2) - center_};
      const Eigen::Vector3d sum = v[0] + v[1] + v[2];
      covariance += std::sqrt(t.squared_area()) / 12. *
                    (v[0] * v[0].transpose() + v[1] * v[1].transpose() + v[2] * v[2].transpose() + sum * sum.transpose());
    }
    for(const Dpoint& p : points_) {
      const Eigen::Vector3d v = to_eigen(p) - center_;
      covariance += v * v.transpose();
    }
    return covariance / mass_;
  }

  // The mean of s |s|, s = (x - origin) . axis the signed distance to the plane through `origin`
  // normal to `axis`, per unit mass, over R^2: positive when the mass on the positive side,
  // weighted by its squared distance to the plane, exceeds that on the negative side.
  double signed_square_moment(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis) const
  {
    double moment = 0.;
    for(const Dtriangle& t : triangles_) moment += signed_square_moment(t, origin, axis);
    for(const Dpoint& p : points_) {
      const double s = (to_eigen(p) - origin).dot(axis);
      moment += s * std::abs(s);
    }
    return moment / mass_ / (radius_ * radius_);
  }

private:
  static Eigen::Vector3d corner(const Dtriangle& t, int i) { return to_eigen(t[i]); }

  // The integral of s |s| over a triangle. Exact: where s keeps its sign, +-A/6 h_2(s_0, s_1, s_2);
  // otherwise the triangle is split where s = 0 into the corner alone on its side, a triangle of
  // area A t_j t_k (t = s_i / (s_i - s_j)) on which the integral of s^2 is A t_j t_k s_i^2 / 6,
  // and the rest.
  static double signed_square_moment(const Dtriangle& t, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis)
  {
    const double s[3] = {(corner(t, 0) - origin).dot(axis), (corner(t, 1) - origin).dot(axis),
                         (corner(t, 2) - origin).dot(axis)};
    const double area = std::sqrt(t.squared_area());
    const double all = area / 6. * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[0] * s[1] + s[1] * s[2] + s[2] * s[0]);
    const int positive = int(s[0] > 0.) + int(s[1] > 0.) + int(s[2] > 0.),
              negative = int(s[0] < 0.) + int(s[1] < 0.) + int(s[2] < 0.);
    if(negative == 0) return all;
    if(positive == 0) return -all;
    // The corner alone on its side (strictly), the other two on the other side or on the plane.
    int i = 0;
    if(positive == 1) while(!(s[i] > 0.)) ++i;
    else while(!(s[i] < 0.)) ++i;
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double alone = area * (s[i] / (s[i] - s[j])) * (s[i] / (s[i] - s[k])) * s[i] * s[i] / 6.;
    return (s[i] > 0. ? 1. : -1.) * (alone - (all - alone));
  }

  std::vector<Dtriangle> triangles_;
  std::vector<Dpoint> points_;
  Eigen::Vector3d center_;
  double radius_ = 0.;
  double mass_ = 0.;
};

template <typename TriangleMesh, typename NamedParameters>
Mass_distribution mass_of_mesh(const TriangleMesh& tm, const NamedParameters& np)
{
  return Mass_distribution(triangles_of_mesh(tm, np));
}

template <typename PointRange, typename NamedParameters>
Mass_distribution mass_of_points(const PointRange& points, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  return Mass_distribution(points_of_range(points, NP_helper::get_const_point_map(points, np)));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_MASS_DISTRIBUTION_H
