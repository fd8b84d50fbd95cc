// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_COARSE_ALIGNMENT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_COARSE_ALIGNMENT_H

// The coarse stage of the axis search: how well a rotation maps a few hundred surface samples
// onto the shape, read from a coarse GEDT (no closest-point search: one interpolation per
// sample), the best axis point for a direction (a grid search around the centre of mass), and
// a pattern search of the axis. The coarse GEDT's width (about 0.13 R at 32^3) gives the
// stage a wide basin; the refinement on the surface gives the precision.

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/rotation/axis.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The angles a refinement fits at once for order k: 2 pi / k, and the largest multiple of it
// up to pi, which moves the samples farthest and so pins the axis best (one angle for k <= 3).
inline std::vector<double> refinement_angles(int k)
{
  std::vector<double> angles{2. * CGAL_PI / double(k)};
  if(k / 2 > 1) angles.push_back(2. * CGAL_PI * double(k / 2) / double(k));
  return angles;
}

// How well a rotation maps samples of a shape onto it, read from a GEDT f (no closest-point
// search: one interpolation per sample): the mean of f^p at the rotated samples over that at the
// samples themselves. f = C exp(-d^2 / 2 sigma^2), so f^p / C^p is the Gaussian weight of the
// distance d to the surface at the width sigma / sqrt(p): p = 1 gives the support at sigma,
// p = 4 the sharper one at sigma / 2. 1 when the rotation maps the shape onto itself.
//
// The searches maximise it less centre_preference times the distance from the axis to the centre
// of mass over the radius: where it is flat, they settle on the axis nearest to the centre (a
// long uniform bar is mapped onto itself almost as well by its flips about any point along it;
// the rotations of a whole shape fix its centre of mass). The preference, 1e-3 over a distance
// of R, moves a true peak by nothing measurable.
constexpr double centre_preference = 1e-3;

template <typename GT>
class Gedt_overlap
{
public:
  // `sigma`: the Gaussian width of `gedt`, in the units of the points; `center`, `radius`: the
  // shape's centre of mass and radius.
  Gedt_overlap(const Voxel_grid<GT>& gedt, std::vector<Eigen::Vector3d> samples, double sigma,
               const Eigen::Vector3d& center, double radius, int power = 1)
    : gedt_(gedt), samples_(std::move(samples)), sigma_(sigma), center_(center), radius_(radius), power_(power)
  {
    for(const Eigen::Vector3d& x : samples_) self_ += value(x);
  }

  // The overlap less the preference for the centre.
  double operator()(const Daxis& axis, const std::vector<double>& angles) const
  {
    if(!(self_ > 0.)) return 0.;
    double sum = 0.;
    for(double angle : angles) {
      const Rigid_motion r = axis.rotation(angle);
      for(const Eigen::Vector3d& x : samples_) sum += value(r(x));
    }
    return sum / (self_ * double(angles.size())) - centre_preference * axis.distance(center_) / radius_;
  }

  // The width of the weights, in the units of the points.
  double sigma() const { return sigma_ / std::sqrt(double(power_)); }

private:
  double value(const Eigen::Vector3d& x) const
  {
    const double f = gedt_.trilinear_value(x.x(), x.y(), x.z());
    double result = f;
    for(int i = 1; i < power_; ++i) result *= f;
    return result;
  }

  const Voxel_grid<GT>& gedt_;
  std::vector<Eigen::Vector3d> samples_;
  double sigma_;
  Eigen::Vector3d center_;
  double radius_;
  int power_;
  double self_ = 0.;
};

// Tuned for the coarse GEDT's width sigma_c: the axis point is searched in a disc of radius
// 0.3 R around the centre of mass (a fifth of a shape cut away moves its centre of mass by up
// to about 0.25 R off the axis), every sigma_c / 2 (the overlap falls by 12 % at sigma_c / 2
// from its peak: a step that finds every peak).
constexpr double axis_point_search_radius = 0.3;
constexpr double axis_point_search_step = 0.5;

// The axis of direction `direction` through the point of the disc around `center` (normal to
// `direction`) whose rotation by `angles` overlaps best; its overlap in `best`.
template <typename GT>
Daxis best_axis_point(const Gedt_overlap<GT>& overlap, const Eigen::Vector3d& center, double radius,
                      const Eigen::Vector3d& direction, const std::vector<double>& angles, double& best)
{
  const Eigen::Vector3d t1 = direction.unitOrthogonal(), t2 = direction.cross(t1);
  const double step = axis_point_search_step * overlap.sigma(), reach = axis_point_search_radius * radius;
  const long n = long(std::floor(reach / step));
  Daxis result{center, direction};
  best = -1.;
  for(long i = -n; i <= n; ++i)
    for(long j = -n; j <= n; ++j) {
      if(double(i * i + j * j) * step * step > reach * reach) continue;
      const Daxis axis{center + double(i) * step * t1 + double(j) * step * t2, direction};
      const double value = overlap(axis, angles);
      if(value > best) {
        best = value;
        result = axis;
      }
    }
  return result;
}

// The axis moved by d: its direction turned by (d[0], d[1]) radians along a tangent basis, its
// point moved by (d[2], d[3]) times `length` along the same basis.
inline Daxis perturbed(const Daxis& axis, const Eigen::Vector4d& d, double length)
{
  const Eigen::Vector3d t1 = axis.direction.unitOrthogonal(), t2 = axis.direction.cross(t1);
  return {axis.point + length * (d[2] * t1 + d[3] * t2), (axis.direction + d[0] * t1 + d[1] * t2).normalized()};
}

// Pattern search: from steps of `angle_step` radians and half the overlap's width, halved when
// no move along the four coordinates improves the overlap, four times: the coarse stage starts
// at 0.05 rad (3 degrees) and ends at 0.2 degree and sigma_c / 32, within the basin of the
// sharp stage, which starts at 0.01 rad and ends at 0.04 degree and sigma / 64, within the
// basin of the refinement on the surface.
constexpr double coarse_pattern_angle_step = 0.05;
constexpr double sharp_pattern_angle_step = 0.01;
constexpr int pattern_search_halvings = 4;

template <typename GT>
Daxis pattern_search(const Gedt_overlap<GT>& overlap, Daxis axis, const std::vector<double>& angles, double angle_step,
                     double& best)
{
  best = overlap(axis, angles);
  double length = 0.5 * overlap.sigma();
  // Each pass moves (the overlap grows) or halves the steps; the cap only guards against a
  // plateau of rounding-level gains.
  constexpr int max_passes = 100;
  for(int halvings = 0, pass = 0; halvings <= pattern_search_halvings && pass < max_passes; ++pass) {
    bool moved = false;
    for(int i = 0; i < 4 && !moved; ++i)
      for(double sign : {1., -1.}) {
        Eigen::Vector4d d = Eigen::Vector4d::Zero();
        d[i] = sign * (i < 2 ? angle_step : 1.);
        const Daxis trial = perturbed(axis, d, length);
        const double value = overlap(trial, angles);
        if(value > best) {
          best = value;
          axis = trial;
          moved = true;
          break;
        }
      }
    if(!moved) {
      angle_step /= 2.;
      length /= 2.;
      ++halvings;
    }
  }
  return axis;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_COARSE_ALIGNMENT_H
