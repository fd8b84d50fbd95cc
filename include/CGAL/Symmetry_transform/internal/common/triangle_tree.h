// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_TREE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_TREE_H

// The AABB tree of the triangles of a shape, for the closest-point searches of the distance
// transform and of Iterative Symmetric Points.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <CGAL/Symmetry_transform/internal/common/cgal_aabb.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The point of triangle abc closest to p, by the Voronoi region of the triangle that p projects
// into (vertex, edge or face): a few dot products, no plane constructed, hence about four
// times cheaper than the kernel's projection, which constructs the plane of the triangle (most
// of the cost of a closest-point search).
inline Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                 const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if(d1 <= 0. && d2 <= 0.) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if(d3 >= 0. && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0. && d1 >= 0. && d3 <= 0.) return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if(d6 >= 0. && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0. && d2 >= 0. && d6 <= 0.) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = va + vb + vc;
  if(!(denominator > 0.)) return a; // no area (triangles_of_mesh leaves such triangles out)
  return a + (vb / denominator) * ab + (vc / denominator) * ac;
}

typedef AABB_triangle_primitive_3<Dkernel, std::vector<Dtriangle>::const_iterator> Triangle_primitive;

// CGAL's AABB traits of triangles, with the closest point of a triangle by
// closest_point_on_triangle().
class Triangle_tree_traits : public AABB_traits_3<Dkernel, Triangle_primitive>
{
public:
  struct Closest_point
  {
    // The closest point of the triangle if it is closer to p than `bound`, else `bound`.
    Dpoint operator()(const Dpoint& p, const Triangle_primitive& primitive, const Dpoint& bound) const
    {
      const Dtriangle& t = primitive.datum();
      const Eigen::Vector3d c = closest_point_on_triangle(to_eigen(p), to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2]));
      const Dpoint closest(c.x(), c.y(), c.z());
      return CGAL::squared_distance(p, closest) > CGAL::squared_distance(p, bound) ? bound : closest;
    }
  };

  Closest_point closest_point_object() const { return Closest_point(); }
};

typedef CGAL::AABB_tree<Triangle_tree_traits> Triangle_tree;

// Triangles whose distances to a point differ by less than this fraction of a voxel are at the
// same distance: the closest point of a voxel's centre or of a query is often on an edge or a
// corner that several triangles share, and which of them the rounding of the coordinates favours
// changes when the shape is moved. The one of lowest index is taken instead, whatever the
// rounding (a millionth of a voxel is far above the rounding of coordinates a million radii
// from the origin, and far below anything the distances are used for).
constexpr double equal_distance_fraction_of_voxel = 1e-6;

// Index of the triangle nearest to `p` among `count` candidates (indices `triangle[i]`, squared
// distances `d2[i]`), the lowest index among those within `tie` of the nearest distance.
inline std::size_t nearest_of_tied(const std::int32_t* triangle, const double* d2, std::size_t count, double tie)
{
  const double least = *std::min_element(d2, d2 + count);
  const double reach = (std::sqrt(least) + tie) * (std::sqrt(least) + tie);
  std::size_t best = count;
  for(std::size_t i = 0; i < count; ++i)
    if(d2[i] <= reach && (best == count || triangle[i] < triangle[best])) best = i;
  return best;
}

// The triangle closest to `p` (`closest`, found in `tree`), or, among the triangles at the same
// distance within `tie` (those through the closest point), the one of lowest index.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::int32_t lowest_closest_triangle(const Triangle_tree& tree, const std::vector<Dtriangle>& triangles,
                                                                         const Dpoint& p, const Triangle_tree::Point_and_primitive_id& closest,
                                                                         double tie);

// The hints that start the tree's closest-point searches come from CGAL's Kd-tree of one point per
// triangle (its first corner), here of at most this many triangles, every k-th beyond: a search is
// exact wherever it starts, and from a hint a little farther it only visits a few more nodes. At a
// million triangles the Kd-tree of them all takes 140 MB and 0.3 s, more than the AABB tree.
constexpr std::size_t most_distance_hints = std::size_t(1) << 17;

// tree.accelerate_distance_queries() on at most most_distance_hints of `triangles`, those of the
// tree; with fewer triangles, CGAL's own (the same hints, in the tree's order).
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void accelerate_distance_queries(Triangle_tree& tree, const std::vector<Dtriangle>& triangles);

// The progress is polled before each split of at least this many triangles (the top splits,
// which partially sort up to all of them), and every tree_splits_per_poll smaller splits.
constexpr std::ptrdiff_t tree_large_split = 4096;
constexpr std::size_t tree_splits_per_poll = 64;

// tree.build(), the same splits, with calls to the progress callback while it builds (progress.h):
// a tree of a million triangles takes a second. The search structure of its distance queries
// (accelerate_distance_queries()) has no such hook.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void build_triangle_tree(Triangle_tree& tree);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::int32_t lowest_closest_triangle(const Triangle_tree& tree, const std::vector<Dtriangle>& triangles,
                                                                         const Dpoint& p, const Triangle_tree::Point_and_primitive_id& closest,
                                                                         double tie)
{
  const Dpoint& c = closest.first;
  std::vector<Triangle_tree::Primitive_id> through;
  tree.all_intersected_primitives(CGAL::Bbox_3(c.x() - tie, c.y() - tie, c.z() - tie, c.x() + tie, c.y() + tie, c.z() + tie),
                                  std::back_inserter(through));
  std::vector<std::int32_t> index{std::int32_t(closest.second - triangles.begin())};
  std::vector<double> d2{CGAL::squared_distance(p, c)};
  const Eigen::Vector3d q = to_eigen(p);
  for(const auto& id : through) {
    const Dtriangle& t = *id;
    index.push_back(std::int32_t(id - triangles.begin()));
    d2.push_back((q - closest_point_on_triangle(q, to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2]))).squaredNorm());
  }
  return index[nearest_of_tied(index.data(), d2.data(), index.size(), tie)];
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void accelerate_distance_queries(Triangle_tree& tree, const std::vector<Dtriangle>& triangles)
{
  const std::size_t stride = (triangles.size() + most_distance_hints - 1) / most_distance_hints;
  if(stride <= 1) {
    tree.accelerate_distance_queries();
    return;
  }
  std::vector<Triangle_tree::Point_and_primitive_id> hints;
  hints.reserve(triangles.size() / stride + 1);
  for(std::size_t i = 0; i < triangles.size(); i += stride)
    hints.emplace_back(triangles[i][0], triangles.begin() + std::ptrdiff_t(i));
  tree.accelerate_distance_queries(hints.begin(), hints.end());
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void build_triangle_tree(Triangle_tree& tree)
{
  if(active_progress == nullptr) {
    tree.build();
    return;
  }
  const auto split = tree.traits().split_primitives_object();
  std::size_t splits = 0;
  tree.custom_build(tree.traits().compute_bbox_object(),
                    [&](auto first, auto beyond, const typename Triangle_tree_traits::Bounding_box& box) {
                      if(beyond - first >= tree_large_split || ++splits % tree_splits_per_poll == 0) poll_progress();
                      split(first, beyond, box);
                    });
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_TREE_H
