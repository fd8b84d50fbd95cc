// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_FRAME_RULES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_FRAME_RULES_H

// The rules of the frames of symmetry_alignment.h (thesis, section 4.1): the axes of the
// principal planes, or of inertia; the planes missing among the principal ones, searched in the
// transform; the orientation of the axes towards more mass. In doubles; the public frame is
// built at the end by to_symmetry_frame().

#include <CGAL/Symmetry_transform/Symmetry_frame.h>
#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/internal/alignment/mass_distribution.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Below this normalised moment (|mean of s |s|| / R^2), the mass is taken as balanced along an axis.
constexpr double balanced_moment = 1e-3;
// The second plane: its normal within this angle of perpendicular to the first axis.
constexpr double second_plane_tolerance_degrees = 10.;
// The plane of the centre: its normal within this angle of the third axis; otherwise it is
// searched in the transform, with the third axis as normal (the thesis's rule).
constexpr double center_plane_tolerance_degrees = 10.;
// The offsets searched for a plane of given normal span this fraction of the transform's range
// [-R, R]: the margin keeps rounding from putting a plane beyond R, where the transform throws.
constexpr double offset_search_extent = 0.98;
// Offsets searched per bin of the transform: every quarter bin, finer than its interpolation.
constexpr std::size_t offsets_per_bin = 4;
// Normals searched perpendicular to the first axis, over half a turn: every half degree.
constexpr int perpendicular_normal_steps = 360;

// A frame in doubles: its origin and its axes (unit, orthogonal, right-handed).
struct Eigen_frame
{
  Eigen::Vector3d center;
  std::array<Eigen::Vector3d, 3> axes;
};

// The eigenvectors of a symmetric matrix, largest eigenvalue first.
inline std::array<Eigen::Vector3d, 3> principal_axes(const Eigen::Matrix3d& covariance)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Matrix3d& vectors = solver.eigenvectors(); // eigenvalues in increasing order
  return {Eigen::Vector3d(vectors.col(2)), Eigen::Vector3d(vectors.col(1)), Eigen::Vector3d(vectors.col(0))};
}

// Orients the axes (unit, orthogonal) towards more mass about `origin` and makes them
// right-handed: each axis a gets the sign that makes the mean of s |s|, s = (x - origin) . a,
// positive; an axis along which the mass is balanced (|mean| <= balanced_moment R^2) gets the
// sign that makes its largest coordinate (in absolute value, the first of equals) positive. If
// the result is left-handed, the axis with the smallest |mean| (the last of equals) is turned
// round: the axes along which the mass is the most lopsided keep their orientation.
inline std::array<Eigen::Vector3d, 3> oriented_axes(std::array<Eigen::Vector3d, 3> axes, const Eigen::Vector3d& origin,
                                                    const Mass_distribution& mass)
{
  double strength[3];
  for(int i = 0; i < 3; ++i) {
    const double moment = mass.signed_square_moment(origin, axes[i]);
    strength[i] = std::abs(moment);
    bool flip = moment < 0.;
    if(strength[i] <= balanced_moment) {
      Eigen::Index largest = 0;
      axes[i].cwiseAbs().maxCoeff(&largest);
      flip = axes[i][largest] < 0.;
      strength[i] = 0.;
    }
    if(flip) axes[i] = -axes[i];
  }
  if(axes[0].cross(axes[1]).dot(axes[2]) < 0.) {
    int weakest = 2;
    for(int i = 1; i >= 0; --i)
      if(strength[i] < strength[weakest]) weakest = i;
    axes[weakest] = -axes[weakest];
  }
  return axes;
}

inline Eigen_frame pca_frame(const Mass_distribution& mass)
{
  return {mass.center(), oriented_axes(principal_axes(mass.covariance()), mass.center(), mass)};
}

// The strongest plane of the transform with unit normal `normal` (the thesis's search for the
// plane that fixes the centre of symmetry), among offsets every 1/offsets_per_bin bin within
// offset_search_extent R of the centre; returns the plane and its value.
template <typename GT>
std::pair<Dplane, double> strongest_plane_of_normal(const Reflective_symmetry_transform<GT>& prst,
                                                    const Eigen::Vector3d& normal)
{
  const Plane_bins& bins = prst.bins();
  const double normal_dot_center = normal.dot(Eigen::Vector3d(bins.center[0], bins.center[1], bins.center[2]));
  const std::size_t steps = offsets_per_bin * bins.n;
  std::pair<Dplane, double> best{{normal, 0.}, -std::numeric_limits<double>::infinity()};
  for(std::size_t i = 0; i < steps; ++i) {
    const double r = offset_search_extent * bins.radius * (2. * (double(i) + 0.5) / double(steps) - 1.);
    const double value =
      prst.value(typename GT::Plane_3(normal.x(), normal.y(), normal.z(), -(normal_dot_center + r)));
    if(value > best.second) best = {{normal, normal_dot_center + r}, value};
  }
  return best;
}

// The strongest plane of the transform with unit normal `normal`, its offset moved to the
// vertex of the parabola through the values at the nearest bin centre and the two beside it:
// the values are samples at the bin centres and their interpolation peaks there, up to half a
// bin (R / n) off a plane that lies between two centres.
template <typename GT>
Dplane peak_plane_of_normal(const Reflective_symmetry_transform<GT>& prst, const Eigen::Vector3d& normal)
{
  const Dplane strongest = strongest_plane_of_normal(prst, normal).first;
  const Plane_bins& bins = prst.bins();
  const double width = bins.offset_step(),
               normal_dot_center = normal.dot(Eigen::Vector3d(bins.center[0], bins.center[1], bins.center[2]));
  const double r = bins.offset(std::size_t(std::clamp(std::round((strongest.offset - normal_dot_center + bins.radius) / width - 0.5),
                                                      0., double(bins.n - 1))));
  if(std::abs(r) + width > offset_search_extent * bins.radius) return strongest;
  const auto value_at = [&](double offset) {
    return prst.value(typename GT::Plane_3(normal.x(), normal.y(), normal.z(), -(normal_dot_center + offset)));
  };
  const double below = value_at(r - width), at = value_at(r), above = value_at(r + width);
  const double curvature = 2. * at - below - above;
  if(curvature <= 0.) return strongest;
  const double shift = std::clamp((above - below) / (2. * curvature), -0.5, 0.5);
  return {normal, normal_dot_center + r + shift * width};
}

// The strongest plane of the transform among those perpendicular to the unit vector `axis`
// (the thesis's search for the second axis): perpendicular_normal_steps normals over half a turn.
template <typename GT>
Dplane strongest_plane_perpendicular_to(const Reflective_symmetry_transform<GT>& prst, const Eigen::Vector3d& axis)
{
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  std::pair<Dplane, double> best{{e1, 0.}, -std::numeric_limits<double>::infinity()};
  for(int step = 0; step < perpendicular_normal_steps; ++step) {
    const double angle = step * CGAL_PI / double(perpendicular_normal_steps);
    const std::pair<Dplane, double> candidate =
      strongest_plane_of_normal(prst, std::cos(angle) * e1 + std::sin(angle) * e2);
    if(candidate.second > best.second) best = candidate;
  }
  return best.first;
}

// The planes of the principal symmetries, strongest first. A family of mirrors stands for its
// planes: after its own, the members across it that the frame needs, through its axis (one for a
// pencil, two for a sphere's), so that the frame's centre lies on the axis.
template <typename GT>
std::vector<Dplane> planes_of(const std::vector<Principal_symmetry<GT>>& symmetries)
{
  std::vector<Dplane> planes;
  for(const Principal_symmetry<GT>& symmetry : symmetries) {
    const Dplane plane = to_dplane(symmetry.plane);
    planes.push_back(plane);
    if(symmetry.family == Mirror_family::ONE_PLANE) continue;
    const Eigen::Vector3d point = to_eigen(to_dpoint(symmetry.axis.point()));
    const Eigen::Vector3d along = to_eigen(to_dpoint(symmetry.axis.point() + symmetry.axis.to_vector())) - point;
    const Eigen::Vector3d across = plane.normal.cross(along).normalized();
    planes.push_back({across, across.dot(point)});
    if(symmetry.family == Mirror_family::EVERY_PLANE_THROUGH_POINT) {
      const Eigen::Vector3d third = plane.normal.cross(across);
      planes.push_back({third, third.dot(point)});
    }
  }
  return planes;
}

// A plane of a frame and where it comes from: the index of the principal symmetry, or
// searched_plane if it was searched in the transform.
constexpr int searched_plane = -1;
struct Frame_plane
{
  Dplane plane;
  int principal;
};

// The three planes of a frame, in the order of its axes, and the frame.
struct Frame_choice
{
  std::array<Frame_plane, 3> planes;
  Eigen_frame frame;
};

// The point where three planes meet.
inline Eigen::Vector3d intersection(const std::array<Frame_plane, 3>& planes)
{
  Eigen::Matrix3d normals;
  Eigen::Vector3d offsets;
  for(int i = 0; i < 3; ++i) {
    normals.row(i) = planes[std::size_t(i)].plane.normal.transpose();
    offsets[i] = planes[std::size_t(i)].plane.offset;
  }
  return normals.partialPivLu().solve(offsets);
}

// The greedy rule of the thesis on the principal planes (strongest first, at least one): a
// second or third plane missing among them is searched in the transform.
template <typename GT>
Frame_choice greedy_frame_choice(const Mass_distribution& mass, const std::vector<Dplane>& planes,
                                 const Reflective_symmetry_transform<GT>& prst)
{
  const double second_tolerance = std::sin(second_plane_tolerance_degrees * CGAL_PI / 180.),
               center_tolerance = std::cos(center_plane_tolerance_degrees * CGAL_PI / 180.);
  Frame_choice choice;
  choice.planes[0] = {planes.front(), 0};
  std::array<Eigen::Vector3d, 3> axes;
  axes[0] = planes.front().normal;
  const auto second = std::find_if(planes.begin() + 1, planes.end(), [&](const Dplane& p) {
    return std::abs(p.normal.dot(axes[0])) <= second_tolerance;
  });
  choice.planes[1] = second != planes.end() ? Frame_plane{*second, int(second - planes.begin())}
                                            : Frame_plane{strongest_plane_perpendicular_to(prst, axes[0]), searched_plane};
  const Eigen::Vector3d& n1 = choice.planes[1].plane.normal;
  axes[1] = (n1 - n1.dot(axes[0]) * axes[0]).normalized();
  axes[2] = axes[0].cross(axes[1]);
  const auto third = std::find_if(planes.begin() + 1, planes.end(), [&](const Dplane& p) {
    return int(&p - planes.data()) != choice.planes[1].principal && std::abs(p.normal.dot(axes[2])) >= center_tolerance;
  });
  choice.planes[2] = third != planes.end() ? Frame_plane{*third, int(third - planes.begin())}
                                           : Frame_plane{strongest_plane_of_normal(prst, axes[2]).first, searched_plane};
  const Eigen::Vector3d center = intersection(choice.planes);
  choice.frame = {center, oriented_axes(axes, center, mass)};
  return choice;
}

// The frame of the principal symmetries (strongest first), by the rules of symmetry_frame(): a
// second or third plane missing among them is searched in the transform, as the thesis does.
template <typename GT>
Eigen_frame symmetry_frame(const Mass_distribution& mass, const std::vector<Principal_symmetry<GT>>& symmetries,
                           const Reflective_symmetry_transform<GT>& prst)
{
  const std::vector<Dplane> planes = planes_of(symmetries);
  if(planes.empty()) return pca_frame(mass);
  return greedy_frame_choice(mass, planes, prst).frame;
}

template <typename GT>
Symmetry_frame<GT> to_symmetry_frame(const Eigen_frame& frame)
{
  Symmetry_frame<GT> result;
  result.center = to_point<GT>(frame.center);
  for(std::size_t i = 0; i < 3; ++i) result.axes[i] = to_vector<GT>(frame.axes[i]);
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_FRAME_RULES_H
