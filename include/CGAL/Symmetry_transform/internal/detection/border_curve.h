// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_BORDER_CURVE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_BORDER_CURVE_H

// The border of a flat surface (zero thickness: every triangle in one plane), as points along its
// border edges with the normals of the border in that plane. On such a surface only the border
// says where an in-plane symmetry lies:
// - turned about the axis across its plane by any angle, the surface keeps most of its area on
//   itself (a regular pentagon 0.89 of it at a tenth of a turn, an octagon 0.96 at a sixteenth), so
//   the supports of its area cannot tell a k-fold symmetry from a continuous one nor from a 2k-fold
//   one; its border, turned by anything but a symmetry, leaves itself but for a few crossings. The
//   order of a rotation of a flat surface is tested on its border, and its axis placed there
//   (turn_center_on_border());
// - a mirror across it maps the inside onto the inside wherever it lies nearly: only the samples
//   mapped beyond the border pull it, from one side at a time. Fitted to the border mapped onto
//   the border, from both sides, it is exact (mirror_refined_on_border()).

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/small_matrices.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// A surface is flat when every triangle's normal is within this angle (radian) of the first's and
// every vertex within this fraction of the radius of its plane: the rounding of a plane moved by a
// similarity, far below any real thickness.
constexpr double flat_surface_tolerance = 1e-7;
// Points along the border: the order test's probes are border_probes of them; the spacing of the
// others is this fraction of the test's narrowest width, sigma / 4 (their distance to the curve
// then errs by a hundredth of the width at most).
constexpr std::size_t border_probes = 2000;
constexpr double border_spacing_in_sigmas = 0.025;
// The fit of a mirror to the border: Gauss-Newton steps at the widths (in sigmas) of ISP's fine
// phase, until a step moves the line by less than this fraction of the radius.
constexpr std::array<double, 3> border_fit_widths{{1., 0.5, 0.25}};
constexpr unsigned border_fit_iterations = 20;
constexpr double border_fit_settled_step = 1e-12;
// Planes within this angle (radian) of the perpendicular to a flat surface are its in-plane mirrors.
constexpr double in_plane_mirror_tolerance = 1e-3;

struct Border_curve
{
  Dplane plane;                        // of the flat surface
  std::vector<Eigen::Vector3d> points; // along the border
  std::vector<Eigen::Vector3d> probes; // border_probes of them, spread along the border
  Oriented_point_matcher matcher;      // closest points among the points, with the border's normal in the plane
};

// The plane of `triangles` if they all lie in one.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::optional<Dplane> plane_of_flat_surface(const std::vector<Dtriangle>& triangles, double radius);

// The edges that bound one triangle only, as pairs of end points.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> border_edges(const std::vector<Dtriangle>& triangles);

// The border of `triangles` if they form a flat surface with a border, sampled every
// border_spacing_in_sigmas `sigma`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::optional<Border_curve> border_curve(const std::vector<Dtriangle>& triangles, double radius, double sigma);

// The sums of one Gauss-Newton step of the fit of the mirror {x : m.x = offset} (m in the plane of
// the border) to the border: the border points reflected, matched to the border, each residual
// along the border's normal at the match, weighted at `width`; unknowns (turn of m about the
// plane's normal, offset).
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::pair<Eigen::Matrix2d, Eigen::Vector2d> border_fit_sums(const Border_curve& border, const Eigen::Vector3d& m,
                                                                                              double offset, double width);

// Gauss-Newton steps of a fit to the border at each of border_fit_widths (in sigmas): `sums(width)`
// gives the normal equations at the current unknowns, `apply(step)` moves them and says by how
// much (a fraction of the radius); until a step moves them by less than border_fit_settled_step.
// False if a step cannot be solved.
template <typename Sums, typename Apply>
bool fit_to_border(double sigma, Sums sums, Apply apply)
{
  for(double width : border_fit_widths)
    for(unsigned i = 0; i < border_fit_iterations; ++i) {
      const auto [jtj, jtr] = sums(width * sigma);
      const Eigen::Vector2d step = solve_symmetric<2>(jtj, -jtr);
      if(!step.allFinite() || !(jtj(0, 0) * jtj(1, 1) - jtj(0, 1) * jtj(1, 0) > 0.)) return false;
      if(apply(step) < border_fit_settled_step) break;
    }
  return true;
}

// Whether `plane` is across the plane of the flat surface of `border` (an in-plane mirror).
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool is_in_plane_mirror(const Border_curve& border, const Dplane& plane);

// An in-plane mirror of the flat surface of `border`, refined on its border: its line in the
// surface's plane fitted so that the border maps onto the border; it stays across the plane.
// `plane` itself if it is no in-plane mirror or the fit fails.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Dplane mirror_refined_on_border(const Border_curve& border, const Dplane& plane, double sigma, double radius);

// The sums of one Gauss-Newton step of the fit of the centre `center` of `turn` (a rotation about
// the normal of the border's plane) to the border: the border points turned about the centre,
// matched to the border, each residual along the border's normal at the match, weighted at
// `width`; unknowns: the centre's move along `u` and `v`, a basis of the plane.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::pair<Eigen::Matrix2d, Eigen::Vector2d> turn_fit_sums(const Border_curve& border, const Eigen::Matrix3d& turn,
                                                                                            const Eigen::Vector3d& center, const Eigen::Vector3d& u,
                                                                                            const Eigen::Vector3d& v, double width);

// Where the axis across the flat surface of `border` of its `order`-fold rotations (order >= 2)
// meets its plane, refined on its border from near `point`: the centre fitted so that the border
// turned by a 1 / order turn maps onto the border. The normals of a flat surface are all alike:
// only its border places the axis. `point` moved onto the plane if the fit fails.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::Vector3d turn_center_on_border(const Border_curve& border, const Eigen::Vector3d& point, int order,
                                                                          double sigma, double radius);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::optional<Dplane> plane_of_flat_surface(const std::vector<Dtriangle>& triangles, double radius)
{
  auto vertex = [](const Dtriangle& t, int i) { return to_eigen(t[i]); };
  std::optional<Eigen::Vector3d> normal;
  std::optional<Eigen::Vector3d> origin;
  for(const Dtriangle& t : triangles) {
    const Eigen::Vector3d n = (vertex(t, 1) - vertex(t, 0)).cross(vertex(t, 2) - vertex(t, 0));
    if(!(n.norm() > 0.)) continue;
    if(!normal) normal = n.normalized(), origin = vertex(t, 0);
    if(n.normalized().cross(*normal).norm() > flat_surface_tolerance) return std::nullopt;
    for(int i = 0; i < 3; ++i)
      if(std::abs((vertex(t, i) - *origin).dot(*normal)) > flat_surface_tolerance * radius) return std::nullopt;
  }
  if(!normal) return std::nullopt;
  return Dplane{*normal, normal->dot(*origin)};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> border_edges(const std::vector<Dtriangle>& triangles)
{
  typedef std::array<double, 3> Key;
  auto key = [](const Dpoint& p) { return Key{p.x(), p.y(), p.z()}; };
  std::map<std::pair<Key, Key>, int> count;
  for(const Dtriangle& t : triangles)
    for(int i = 0; i < 3; ++i) {
      const Key a = key(t[i]), b = key(t[(i + 1) % 3]);
      ++count[std::minmax(a, b)];
    }
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> edges;
  for(const auto& [edge, n] : count)
    if(n == 1)
      edges.emplace_back(Eigen::Vector3d(edge.first[0], edge.first[1], edge.first[2]),
                         Eigen::Vector3d(edge.second[0], edge.second[1], edge.second[2]));
  return edges;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::optional<Border_curve> border_curve(const std::vector<Dtriangle>& triangles, double radius, double sigma)
{
  const std::optional<Dplane> plane = plane_of_flat_surface(triangles, radius);
  if(!plane) return std::nullopt;
  const double spacing = border_spacing_in_sigmas * sigma;
  std::vector<Eigen::Vector3d> points, normals;
  for(const auto& [a, b] : border_edges(triangles)) {
    const std::size_t steps = (std::max)(std::size_t(1), std::size_t(std::ceil((b - a).norm() / spacing)));
    const Eigen::Vector3d normal = plane->normal.cross(b - a).normalized();
    for(std::size_t i = 0; i < steps; ++i) {
      points.push_back(a + (b - a) * (double(i) / double(steps)));
      normals.push_back(normal);
    }
  }
  if(points.empty()) return std::nullopt;
  std::vector<Eigen::Vector3d> probes;
  const double stride = (std::max)(1., double(points.size()) / double(border_probes));
  for(double i = 0.; std::size_t(i) < points.size(); i += stride) probes.push_back(points[std::size_t(i)]);
  std::vector<Dpoint> dpoints;
  for(const Eigen::Vector3d& p : points) dpoints.push_back(to_dpoint(p));
  return Border_curve{*plane, std::move(points), std::move(probes), Oriented_point_matcher(dpoints, std::move(normals))};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::pair<Eigen::Matrix2d, Eigen::Vector2d> border_fit_sums(const Border_curve& border, const Eigen::Vector3d& m,
                                                                                              double offset, double width)
{
  const Eigen::Vector3d t = border.plane.normal.cross(m);
  Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero();
  Eigen::Vector2d jtr = Eigen::Vector2d::Zero();
  for(const Eigen::Vector3d& x : border.points) {
    const double side = m.dot(x) - offset;
    const Eigen::Vector3d image = x - 2. * side * m;
    Oriented_point_matcher::Hint hint;
    const Match match = border.matcher.closest(image, hint);
    const double w = std::exp(-(image - match.first).squaredNorm() / (2. * width * width));
    const Eigen::Vector2d j(match.second.dot(-2. * (t.dot(x) * m + side * t)), match.second.dot(2. * m));
    jtj += w * j * j.transpose();
    jtr += w * match.second.dot(image - match.first) * j;
  }
  return {jtj, jtr};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool is_in_plane_mirror(const Border_curve& border, const Dplane& plane)
{
  return std::abs(plane.normal.dot(border.plane.normal)) <= std::sin(in_plane_mirror_tolerance);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Dplane mirror_refined_on_border(const Border_curve& border, const Dplane& plane, double sigma, double radius)
{
  if(!is_in_plane_mirror(border, plane)) return plane;
  Eigen::Vector3d m = (plane.normal - plane.normal.dot(border.plane.normal) * border.plane.normal).normalized();
  // The line where `plane` meets the surface's plane: m.x there.
  double offset = (plane.offset - border.plane.offset * plane.normal.dot(border.plane.normal)) / plane.normal.dot(m);
  const bool fitted = fit_to_border(
    sigma, [&](double width) { return border_fit_sums(border, m, offset, width); },
    [&](const Eigen::Vector2d& step) {
      m = (m + step[0] * border.plane.normal.cross(m)).normalized();
      offset += step[1];
      return std::abs(step[0]) + std::abs(step[1]) / radius;
    });
  return fitted ? Dplane{m, offset} : plane;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::pair<Eigen::Matrix2d, Eigen::Vector2d> turn_fit_sums(const Border_curve& border, const Eigen::Matrix3d& turn,
                                                                                            const Eigen::Vector3d& center, const Eigen::Vector3d& u,
                                                                                            const Eigen::Vector3d& v, double width)
{
  const Eigen::Matrix3d fixed_minus_turn = Eigen::Matrix3d::Identity() - turn;
  Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero();
  Eigen::Vector2d jtr = Eigen::Vector2d::Zero();
  for(const Eigen::Vector3d& x : border.points) {
    const Eigen::Vector3d image = center + turn * (x - center);
    Oriented_point_matcher::Hint hint;
    const Match match = border.matcher.closest(image, hint);
    const double w = std::exp(-(image - match.first).squaredNorm() / (2. * width * width));
    const Eigen::Vector2d j(match.second.dot(fixed_minus_turn * u), match.second.dot(fixed_minus_turn * v));
    jtj += w * j * j.transpose();
    jtr += w * match.second.dot(image - match.first) * j;
  }
  return {jtj, jtr};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Eigen::Vector3d turn_center_on_border(const Border_curve& border, const Eigen::Vector3d& point, int order,
                                                                          double sigma, double radius)
{
  const Eigen::Vector3d normal = border.plane.normal;
  const Eigen::Vector3d start = point - (normal.dot(point) - border.plane.offset) * normal;
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(2. * CGAL_PI / order, normal).toRotationMatrix();
  Eigen::Vector3d center = start;
  const bool fitted = fit_to_border(
    sigma, [&](double width) { return turn_fit_sums(border, turn, center, u, v, width); },
    [&](const Eigen::Vector2d& step) {
      center += step[0] * u + step[1] * v;
      return step.norm() / radius;
    });
  return fitted ? center : start;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_BORDER_CURVE_H
