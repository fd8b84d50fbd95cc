// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_POINT_NORMALS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_POINT_NORMALS_H

// Closest points of a point set with a normal: the refinement of an axis fits the distances of
// rotated samples to the tangent planes at their matches, as on a mesh, and the search of
// directions reads the density of the normals. The normals are those of the least-squares
// planes of the nearest neighbours (CGAL::pca_estimate_normals); their signs do not matter.

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>

#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

class Point_normal_matcher
{
  // Neighbours of each least-squares plane: CGAL's examples use 18 (Point_set_processing_3).
  static constexpr unsigned neighbours = 18;

public:
  static constexpr bool has_normals = true;
  static constexpr bool matches_on_triangles = false;
  // Nothing to start from: a Kd-tree search is cheap.
  struct Hint
  {
    bool valid = false;
  };

  explicit Point_normal_matcher(const std::vector<Dpoint>& points) : nearest_(points)
  {
    std::vector<std::pair<Dpoint, Dvector>> oriented;
    for(const Dpoint& p : points) oriented.emplace_back(p, Dvector(0., 0., 0.));
    if(points.size() > neighbours)
      CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
        oriented, neighbours,
        CGAL::parameters::point_map(CGAL::First_of_pair_property_map<std::pair<Dpoint, Dvector>>())
          .normal_map(CGAL::Second_of_pair_property_map<std::pair<Dpoint, Dvector>>()));
    for(const auto& pn : oriented) {
      const Eigen::Vector3d n(pn.second.x(), pn.second.y(), pn.second.z());
      normals_.push_back(n.norm() > 0. ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero());
    }
  }

  Match closest(const Eigen::Vector3d& p, Hint& hint) const
  {
    hint.valid = true;
    const std::size_t i = nearest_(p).index;
    return {to_eigen(nearest_.point(i)), normals_[i]};
  }

private:
  Nearest_point nearest_;
  std::vector<Eigen::Vector3d> normals_;
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_POINT_NORMALS_H
