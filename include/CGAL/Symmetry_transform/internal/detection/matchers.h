// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_MATCHERS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_MATCHERS_H

// The closest-point searches of Iterative Symmetric Points ("matchers"): exact on a triangle
// soup (AABB tree), approximate on a triangle soup (the closest triangles recorded with the
// GEDT), and on a point set (Kd-tree). Each offers
//   Match closest(const Eigen::Vector3d& p, Hint& hint) const
// the closest point to p and the unit normal of the surface there (zero on a point set without
// normals); `hint` holds the match of a nearby point if `hint.valid`, a start for the search, and
// receives this one.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_cells.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_tree.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The closest point and the unit normal of the surface there.
typedef std::pair<Eigen::Vector3d, Eigen::Vector3d> Match;

inline Eigen::Vector3d unit_normal(const Dtriangle& t)
{
  return to_eigen(CGAL::ORIGIN + CGAL::cross_product(t[1] - t[0], t[2] - t[0])).normalized();
}

// Exact closest points on a triangle soup, by its AABB tree; on a small soup, or where large
// triangles cross the inside of the soup (their boxes overlap deeper than
// deepest_box_overlap_for_tree), a search with a hint tests the triangles of the cells near the
// query instead (triangle_cells.h).
class Triangle_matcher
{
public:
  static constexpr bool has_normals = true;
  static constexpr bool matches_on_triangles = true;

  // A previous match, on the surface and with its triangle: the search for a nearby query starts there.
  struct Hint
  {
    Triangle_tree::Point_and_primitive_id match;
    bool valid = false;
  };

  explicit Triangle_matcher(const std::vector<Dtriangle>& triangles);
  explicit Triangle_matcher(std::vector<Dtriangle>&&) = delete; // it refers to the triangles

  Match closest(const Eigen::Vector3d& p, Hint& hint) const;

  Match closest(const Eigen::Vector3d& p) const
  {
    Hint none;
    return closest(p, none);
  }

  // Its AABB tree, distance queries accelerated (the GEDT of the same triangles uses it).
  const Triangle_tree& tree() const { return tree_; }

private:
  const std::vector<Dtriangle>& triangles_;
  Triangle_tree tree_;
  std::optional<Triangle_cells> cells_; // for small soups and those whose boxes overlap deeply
};

// Approximate closest points on a triangle soup, about ten times cheaper than the exact search:
// the nearest of the triangles closest to the eight voxel centres around the query, read from
// a grid filled with the Gaussian distance transform. Within the band of the transform the
// distance is close to the true one (on a smooth surface the true closest triangle is a
// neighbour of these) and the normal that of the surface there; outside, the exact matcher
// answers. ISP walks with it and ends with exact searches, which start from its matches.
class Closest_triangle_field
{
public:
  static constexpr bool has_normals = true;
  static constexpr bool matches_on_triangles = true;
  typedef Triangle_matcher::Hint Hint;

  // `closest_triangles`: per voxel (index (k n + j) n + i) the triangle closest to its centre,
  // or -1; `origin`: the corner of the grid, `voxel_size` and `resolution` its geometry.
  Closest_triangle_field(const std::vector<Dtriangle>& triangles, const Triangle_matcher& exact,
                         std::vector<std::int32_t> closest_triangles, const std::array<double, 3>& origin,
                         double voxel_size, std::size_t resolution)
    : triangles_(triangles), exact_(exact), closest_triangles_(std::move(closest_triangles)), origin_(origin),
      voxel_size_(voxel_size), resolution_(long(resolution))
  {}

  Match closest(const Eigen::Vector3d& p, Hint& hint) const;

  // The point nearest to p on the closest triangles of the 8 voxels around p, and its triangle;
  // triangle -1 if none of these voxels lies in the band.
  std::pair<Eigen::Vector3d, std::int32_t> nearest_in_cell(const Eigen::Vector3d& p) const;

private:
  // The lowest of the 8 voxels whose centres surround p, clamped to the grid.
  std::array<long, 3> cell_corner(const Eigen::Vector3d& p) const
  {
    std::array<long, 3> corner;
    for(int a = 0; a < 3; ++a)
      corner[a] = (std::min)((std::max)(long(std::floor((p[a] - origin_[a]) / voxel_size_ - 0.5)), 0L), resolution_ - 2);
    return corner;
  }

  const std::vector<Dtriangle>& triangles_;
  const Triangle_matcher& exact_;
  std::vector<std::int32_t> closest_triangles_;
  std::array<double, 3> origin_;
  double voxel_size_;
  long resolution_;
};

// Closest points of a point set. Without normals (Point_matcher) the normal of a match is zero
// and ISP fits the plane point to point; with the unit normals of the points
// (Oriented_point_matcher: a point set with a normal_map) it is the normal of the closest point,
// whose orientation does not matter, and ISP fits point to plane as on a mesh.
template <bool with_normals>
class Point_set_matcher
{
public:
  static constexpr bool has_normals = with_normals;
  static constexpr bool matches_on_triangles = false;

  // Nothing to start from: a Kd-tree search is cheap.
  struct Hint
  {
    bool valid = false;
  };

  explicit Point_set_matcher(const std::vector<Dpoint>& points) : nearest_(points) {}

  // `unit_normals`: one per point, in the order of `points` (zero where a point has none).
  Point_set_matcher(const std::vector<Dpoint>& points, std::vector<Eigen::Vector3d> unit_normals)
    : nearest_(points), normals_(std::move(unit_normals))
  {}

  Match closest(const Eigen::Vector3d& p, Hint& hint) const
  {
    hint.valid = true;
    const std::size_t i = nearest_(p).index;
    if constexpr(with_normals) return {to_eigen(nearest_.point(i)), normals_[i]};
    else return {to_eigen(nearest_.point(i)), Eigen::Vector3d::Zero()};
  }

private:
  Nearest_point nearest_;
  std::vector<Eigen::Vector3d> normals_;
};

typedef Point_set_matcher<false> Point_matcher;
typedef Point_set_matcher<true> Oriented_point_matcher;


#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Triangle_matcher::Triangle_matcher(const std::vector<Dtriangle>& triangles)
  : triangles_(triangles), tree_(triangles.begin(), triangles.end())
{
  build_triangle_tree(tree_);
  accelerate_distance_queries(tree_, triangles);
  tree_.closest_point(CGAL::ORIGIN); // builds the search structure before threads share the tree
  if(triangles.size() <= most_triangles_for_cells || mean_box_overlap(triangles) > deepest_box_overlap_for_tree) {
    cells_.emplace(triangles);
    if(!cells_->built()) cells_.reset(); // too many members (max_cell_members): the tree alone
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Match Triangle_matcher::closest(const Eigen::Vector3d& p, Hint& hint) const
{
  if(cells_ && hint.valid) {
    // The hint's match is a point of the soup: the closest one is no farther.
    const std::optional<Triangle_cells::Nearest> nearest = cells_->closest(p, (p - to_eigen(hint.match.first)).norm());
    if(nearest) {
      hint.match = {to_dpoint(nearest->point), triangles_.begin() + std::ptrdiff_t(nearest->triangle)};
      return {nearest->point, unit_normal(triangles_[nearest->triangle])};
    }
  }
  const Dpoint query = to_dpoint(p);
  hint.match = hint.valid ? tree_.closest_point_and_primitive(query, hint.match)
                          : tree_.closest_point_and_primitive(query);
  hint.valid = true;
  return {to_eigen(hint.match.first), unit_normal(*hint.match.second)};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Match Closest_triangle_field::closest(const Eigen::Vector3d& p, Hint& hint) const
{
  const auto [on_triangle, t] = nearest_in_cell(p);
  if(t < 0) {
    hint.valid = false; // beyond the band, a match found near another point is no start
    return exact_.closest(p, hint);
  }
  hint = {{to_dpoint(on_triangle), triangles_.begin() + t}, true};
  return {on_triangle, unit_normal(triangles_[std::size_t(t)])};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::pair<Eigen::Vector3d, std::int32_t>
Closest_triangle_field::nearest_in_cell(const Eigen::Vector3d& p) const
{
  const std::array<long, 3> corner = cell_corner(p);
  std::array<std::int32_t, 8> seen;
  std::array<double, 8> d2;
  std::array<Eigen::Vector3d, 8> on_triangle;
  std::size_t count = 0;
  for(long c = 0; c < 8; ++c) {
    const std::int32_t t = closest_triangles_[std::size_t(
      ((corner[2] + (c >> 2)) * resolution_ + corner[1] + ((c >> 1) & 1)) * resolution_ + corner[0] + (c & 1))];
    if(t < 0 || std::find(seen.begin(), seen.begin() + count, t) != seen.begin() + count) continue;
    const Dtriangle& v = triangles_[std::size_t(t)];
    on_triangle[count] = closest_point_on_triangle(p, to_eigen(v[0]), to_eigen(v[1]), to_eigen(v[2]));
    d2[count] = (p - on_triangle[count]).squaredNorm();
    seen[count++] = t;
  }
  if(count == 0) return {Eigen::Vector3d::Zero(), -1};
  const std::size_t nearest = nearest_of_tied(seen.data(), d2.data(), count, equal_distance_fraction_of_voxel * voxel_size_);
  return {on_triangle[nearest], seen[nearest]};
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_MATCHERS_H
