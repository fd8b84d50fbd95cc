// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NEAREST_POINT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NEAREST_POINT_H

// The nearest of a set of points to a query, in a CGAL::Kd_tree: the one Kd-tree of the package
// (the GEDT of a point set, ISP on a point set, the mirror faces of the remeshing, the
// symmetrization and the completion).

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Queries are thread-safe once constructed. The tree holds indices into its own copy of the points.
class Nearest_point
{
  typedef CGAL::Pointer_property_map<Dpoint>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Dkernel>> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;

public:
  struct Answer
  {
    std::size_t index;
    double squared_distance;
  };

  explicit Nearest_point(const std::vector<Eigen::Vector3d>& points) : Nearest_point(to_dpoints(points)) {}

  explicit Nearest_point(std::vector<Dpoint> points);

  Answer operator()(const Dpoint& q) const;

  Answer operator()(const Eigen::Vector3d& q) const { return (*this)(to_dpoint(q)); }

  // The k nearest points to point i other than itself, nearest first.
  std::vector<std::size_t> nearest_others(std::size_t i, std::size_t k) const;

  const Dpoint& point(std::size_t i) const { return points_[i]; }

private:
  static std::vector<Dpoint> to_dpoints(const std::vector<Eigen::Vector3d>& points);

  Point_map map() const { return CGAL::make_property_map(points_); }

  std::vector<Dpoint> points_;
  std::unique_ptr<Search::Tree> tree_;
};

// The k nearest other points of each of the first `count` points of `nearest`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> nearest_neighbourhoods(const Nearest_point& nearest, std::size_t count,
                                                                                                 std::size_t k, unsigned threads);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> nearest_neighbourhoods(const Nearest_point& nearest, std::size_t count,
                                                                                                 std::size_t k, unsigned threads)
{
  std::vector<std::vector<std::size_t>> neighbours(count);
  parallel_for(count, threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end && parallel_step(); ++i) neighbours[i] = nearest.nearest_others(i, k);
  });
  throw_if_cancelled();
  return neighbours;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Nearest_point::Nearest_point(std::vector<Dpoint> points) : points_(std::move(points))
{
  std::vector<std::size_t> indices(points_.size());
  for(std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  tree_ = std::make_unique<Search::Tree>(indices.begin(), indices.end(), Search::Tree::Splitter(), Traits(map()));
  tree_->build();
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Nearest_point::Answer Nearest_point::operator()(const Dpoint& q) const
{
  const Search search(*tree_, q, 1, 0., true, Search::Distance(map()));
  return {search.begin()->first, search.begin()->second};
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::size_t> Nearest_point::nearest_others(std::size_t i, std::size_t k) const
{
  const Search search(*tree_, points_[i], unsigned(k + 1), 0., true, Search::Distance(map()));
  std::vector<std::size_t> result;
  for(const auto& found : search)
    if(found.first != i && result.size() < k) result.push_back(found.first);
  return result;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Dpoint> Nearest_point::to_dpoints(const std::vector<Eigen::Vector3d>& points)
{
  std::vector<Dpoint> result;
  result.reserve(points.size());
  for(const Eigen::Vector3d& p : points) result.push_back(to_dpoint(p));
  return result;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NEAREST_POINT_H
