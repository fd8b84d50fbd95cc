// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_MIRROR_FAMILIES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_MIRROR_FAMILIES_H

// Continuous families of mirror planes. The reflections in two planes meeting at an angle that is
// no pi m / n generate rotations about their common line by a dense set of angles: a closed shape
// that has both mirrors has every rotation about that line, and every plane through it is a mirror
// (a pencil of planes: a cylinder, a cone, any surface of revolution). Pencils about two lines: a
// sphere, whose mirrors are every plane through its centre. Each family is returned once, by its
// strongest member found, marked with its line or point; so are the turned copies of the other
// planes about a pencil's line.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The line common to the planes of a pencil, through its point nearest to the shape's centre.
struct Plane_pencil
{
  Eigen::Vector3d point, direction; // direction: unit

  // Whether `plane` contains the line, to within `angle` (radian) and `distance`.
  bool contains(const Dplane& plane, double angle, double distance) const
  {
    return std::abs(plane.normal.dot(direction)) < std::sin(angle) && std::abs(plane.normal.dot(point) - plane.offset) < distance;
  }
};

// The common line of two planes that are not parallel.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Plane_pencil common_line(const Dplane& a, const Dplane& b, const Eigen::Vector3d& center);

// A pencil is taken as such only if a member between those found is a mirror too: two planes
// found a little off a rational angle (those of a point set, to a tenth of a degree) are no
// family. The member tried is the first plane turned about the line by this angle (radian, the
// golden angle: far from any pi m / n of a small n).
constexpr double pencil_test_angle = 2.399963229728653;

// `plane` turned about the line of `pencil` by `angle`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Dplane turned_about(const Plane_pencil& pencil, const Dplane& plane, double angle);

// The point nearest to the lines of two pencils (their common point, for a sphere's).
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::Vector3d nearest_point(const Plane_pencil& p, const Plane_pencil& q);

// A shape with every rotation about the line of `pencil` maps each plane onto its turned copies
// equally well: the planes of `result` that are turned copies of a stronger one (the same angle to
// the line, which they cross at the same point) are dropped, as arbitrary members of one family.
template <typename GT>
void drop_turned_copies(std::vector<Principal_symmetry<GT>>& result, const Plane_pencil& pencil, double angle,
                        double distance)
{
  std::stable_sort(result.begin(), result.end(), [](const auto& a, const auto& b) { return a.symmetry > b.symmetry; });
  auto invariants = [&](const Principal_symmetry<GT>& s) {
    Dplane p = to_dplane(s.plane);
    if(p.normal.dot(pencil.direction) < 0.) p = {-p.normal, -p.offset};
    return std::array<double, 2>{p.normal.dot(pencil.direction), p.normal.dot(pencil.point) - p.offset};
  };
  std::vector<Principal_symmetry<GT>> kept;
  for(const Principal_symmetry<GT>& s : result) {
    const std::array<double, 2> a = invariants(s);
    if(std::none_of(kept.begin(), kept.end(), [&](const Principal_symmetry<GT>& k) {
         const std::array<double, 2> b = invariants(k);
         return std::abs(a[0] - b[0]) < std::sin(angle) && std::abs(a[1] - b[1]) < distance;
       }))
      kept.push_back(s);
  }
  result = std::move(kept);
}

// Whether `plane` belongs to the family of mirrors of `pencils` (one: every plane through its
// line; two: every plane through the lines' common point), to within `angle` and `distance`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool in_mirror_family(const std::vector<Plane_pencil>& pencils, const Dplane& plane, double angle, double distance);

// The planes of `result` that belong to the family of `pencils` (one: every plane through its line;
// more: every plane through the lines' common point) replaced by the strongest of them, marked.
// Members within `angle` and `distance` (the reach of a merge of candidates).
template <typename GT>
void report_mirror_families(std::vector<Principal_symmetry<GT>>& result, const std::vector<Plane_pencil>& pencils,
                            double angle, double distance)
{
  if(pencils.empty()) return;
  const bool sphere = pencils.size() > 1;
  const Eigen::Vector3d center = sphere ? nearest_point(pencils[0], pencils[1]) : pencils[0].point;
  auto member = [&](const Principal_symmetry<GT>& s) {
    return in_mirror_family(pencils, to_dplane(s.plane), angle, distance);
  };
  const auto strongest = std::max_element(result.begin(), result.end(), [&](const auto& a, const auto& b) {
    return (member(a) ? a.symmetry : -1.) < (member(b) ? b.symmetry : -1.);
  });
  if(strongest == result.end() || !member(*strongest)) return;
  Principal_symmetry<GT> family = *strongest;
  family.family = sphere ? Mirror_family::EVERY_PLANE_THROUGH_POINT : Mirror_family::EVERY_PLANE_THROUGH_AXIS;
  const Dplane plane = to_dplane(family.plane);
  const Eigen::Vector3d in_plane = center - (plane.normal.dot(center) - plane.offset) * plane.normal;
  const Eigen::Vector3d direction = sphere ? plane.normal.unitOrthogonal() : pencils[0].direction;
  family.axis = typename GT::Line_3(to_point<GT>(in_plane), to_vector<GT>(direction));
  result.erase(std::remove_if(result.begin(), result.end(), member), result.end());
  if(!sphere) drop_turned_copies(result, pencils[0], angle, distance);
  result.push_back(family);
}

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Plane_pencil common_line(const Dplane& a, const Dplane& b, const Eigen::Vector3d& center)
{
  const Eigen::Vector3d d = a.normal.cross(b.normal);
  const Eigen::Vector3d on_both = (a.offset * b.normal.cross(d) + b.offset * d.cross(a.normal)) / d.squaredNorm();
  const Eigen::Vector3d u = d.normalized();
  return {on_both + (center - on_both).dot(u) * u, u};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Dplane turned_about(const Plane_pencil& pencil, const Dplane& plane, double angle)
{
  const Eigen::Vector3d normal = Eigen::AngleAxisd(angle, pencil.direction) * plane.normal;
  return {normal, normal.dot(pencil.point)};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::Vector3d nearest_point(const Plane_pencil& p, const Plane_pencil& q)
{
  const Eigen::Vector3d w = p.point - q.point;
  const double b = p.direction.dot(q.direction), d = p.direction.dot(w), e = q.direction.dot(w), det = 1. - b * b;
  if(det < 1e-12) return p.point; // parallel lines: a pencil found twice
  const double s = (b * e - d) / det, t = (e - b * d) / det;
  return 0.5 * (p.point + s * p.direction + q.point + t * q.direction);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool in_mirror_family(const std::vector<Plane_pencil>& pencils, const Dplane& plane, double angle, double distance)
{
  if(pencils.size() > 1) return std::abs(plane.normal.dot(nearest_point(pencils[0], pencils[1])) - plane.offset) < distance;
  return !pencils.empty() && pencils[0].contains(plane, angle, distance);
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_MIRROR_FAMILIES_H
