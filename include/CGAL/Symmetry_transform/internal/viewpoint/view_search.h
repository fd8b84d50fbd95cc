// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_VIEW_SEARCH_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_VIEW_SEARCH_H

// The searches of viewpoint_selection.h over the sphere of view directions: the local maxima of
// the viewpoint score over a Fibonacci sphere, each refined exactly, and its global minimum over
// the vertices of the arrangement of the planes' great circles.

#include <CGAL/Symmetry_transform/Viewpoint.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/viewpoint/weighted_normals.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The fewest directions of the Fibonacci sphere: an icosahedron's vertices, the coarsest sampling
// that leaves no direction far from a sample.
constexpr std::size_t least_number_of_directions = 12;
// A sample is a local maximum if no sample within this many spacings sqrt(4 pi / n) scores more:
// the ring of its nearest neighbours on the Fibonacci sphere lies within it.
constexpr double neighbourhood_spacings = 1.6;
// Maxima closer than this angle, as views, are one view: the ascent ends on exact maxima, so two
// ends of one maximum differ by rounding only.
constexpr double merged_views_degrees = 0.5;
// A coordinate of a view direction within this of 0 counts as 0 when choosing between v and -v.
constexpr double zero_coordinate = 1e-12;
// A cross product of two unit normals shorter than this gives no direction (parallel planes).
constexpr double least_cross_product = 1e-9;

// The representative of {v, -v} with z > 0 (then y > 0, then x > 0; |c| <= zero_coordinate counts as 0).
inline Vec3 canonical_view(Vec3 v)
{
  for(int i = 2; i >= 0; --i) {
    if(v[i] > zero_coordinate) return v;
    if(v[i] < -zero_coordinate) return -v;
  }
  return v;
}

// The Fibonacci sphere: n directions, z decreasing from 1 - 1/n to -1 + 1/n.
inline std::vector<Vec3> fibonacci_sphere(std::size_t n)
{
  std::vector<Vec3> points(n);
  const double golden_angle = CGAL_PI * (3. - std::sqrt(5.));
  for(std::size_t i = 0; i < n; ++i) {
    const double z = 1. - (2. * double(i) + 1.) / double(n), r = std::sqrt((std::max)(0., 1. - z * z));
    const double phi = golden_angle * double(i);
    points[i] = {r * std::cos(phi), r * std::sin(phi), z};
  }
  return points;
}

template <typename GT>
Viewpoint<GT> make_viewpoint(const Vec3& v, double score)
{
  return Viewpoint<GT>{to_vector<GT>(canonical_view(v)), score};
}

typedef std::pair<double, Vec3> Scored_view; // score, direction

// The samples of the Fibonacci sphere of n directions that score at least as much as every
// sample within neighbourhood_spacings spacings (ties broken by index), each ascended to its
// exact local maximum; best first.
inline std::vector<Scored_view> local_maxima(const Weighted_normals& planes, std::size_t n)
{
  const std::vector<Vec3> samples = fibonacci_sphere(n);
  std::vector<double> scores(n);
  for(std::size_t i = 0; i < n; ++i) scores[i] = planes.score(samples[i]);

  // Neighbours within the angle r; |z_i - z_j| <= r for them, and z, spaced by 2/n, is monotone in the index.
  const double r = neighbourhood_spacings * std::sqrt(4. * CGAL_PI / double(n)), cos_r = std::cos(r);
  const std::size_t window = std::size_t(std::ceil(r * double(n) / 2.)) + 1;
  std::vector<Scored_view> maxima;
  for(std::size_t i = 0; i < n; ++i) {
    bool is_max = true;
    for(std::size_t j = (i > window ? i - window : 0); is_max && j < (std::min)(n, i + window + 1); ++j) {
      if(j == i || samples[i].dot(samples[j]) < cos_r) continue;
      if(scores[j] > scores[i] || (scores[j] == scores[i] && j < i)) is_max = false;
    }
    if(!is_max) continue;
    const Vec3 v = canonical_view(planes.ascend(samples[i]));
    maxima.emplace_back(planes.score(v), v);
  }
  std::stable_sort(maxima.begin(), maxima.end(),
                   [](const Scored_view& a, const Scored_view& b) { return a.first > b.first; });
  return maxima;
}

// The views of `maxima` (best first), less those within merged_views_degrees of a better one.
inline std::vector<Scored_view> distinct_views(const std::vector<Scored_view>& maxima)
{
  const double merge = std::cos(merged_views_degrees * CGAL_PI / 180.);
  std::vector<Scored_view> kept;
  for(const Scored_view& m : maxima) {
    bool duplicate = false;
    for(const Scored_view& k : kept) duplicate = duplicate || std::abs(k.second.dot(m.second)) > merge;
    if(!duplicate) kept.push_back(m);
  }
  return kept;
}

// The global minimum of S: over the directions u_i x u_j of every pair of planes, and one
// direction in each plane; (0, 0, 1) if no direction scores less.
inline Scored_view worst_view(const Weighted_normals& planes)
{
  Scored_view worst = {planes.score(Vec3(0., 0., 1.)), Vec3(0., 0., 1.)};
  auto consider = [&](const Vec3& c) {
    const double length = c.norm();
    if(!(length > least_cross_product)) return;
    const Vec3 v = c / length;
    const double s = planes.score(v);
    if(s < worst.first) worst = {s, v};
  };
  const std::size_t m = planes.normals.size();
  for(std::size_t i = 0; i < m; ++i) {
    const Vec3& u = planes.normals[i];
    // a direction in plane i: u crossed with the axis it is least aligned with
    Eigen::Index least;
    u.cwiseAbs().minCoeff(&least);
    consider(u.cross(Vec3::Unit(least)));
    for(std::size_t j = i + 1; j < m; ++j) consider(u.cross(planes.normals[j]));
  }
  return worst;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_VIEW_SEARCH_H
