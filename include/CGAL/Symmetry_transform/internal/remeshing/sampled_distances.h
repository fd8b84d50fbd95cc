// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SAMPLED_DISTANCES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SAMPLED_DISTANCES_H

// The pieces of the remeshing metrics (remeshing_metrics.h): area-uniform seeded samples of a
// surface, and the distances from points, moved by a map (the identity or a reflection), to
// their closest points on a triangle soup (CGAL::AABB_tree, through Triangle_matcher).

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// `number_of_points_on_faces` and `random_seed`, checked (with all the numeric named parameters).
template <typename NamedParameters>
Refinement_sampling metric_sampling(const NamedParameters& np)
{
  check_named_parameters(np);
  return {read_sample_count(np, internal_np::number_of_points_on_faces, defaults::metric_samples,
                            parameter_ranges::number_of_points_on_faces),
          read_random_seed(np, defaults::random_seed)};
}

// `number_of_points_on_faces` samples of the triangles, seeded by `random_seed`.
template <typename NamedParameters>
std::vector<Eigen::Vector3d> metric_samples(const std::vector<Dtriangle>& triangles, const NamedParameters& np)
{
  return surface_samples(triangles, metric_sampling(np));
}

// Distances from the points, moved by `map`, to the triangles.
template <typename Map>
std::vector<double> distances_to(const std::vector<Eigen::Vector3d>& points, const Map& map,
                                 const std::vector<Dtriangle>& triangles, unsigned threads)
{
  const Triangle_matcher matcher(triangles);
  std::vector<double> d(points.size());
  parallel_for(points.size(), threads, [&](unsigned, std::size_t begin, std::size_t end) {
    Triangle_matcher::Hint hint;
    for(std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d q = map(points[i]);
      d[i] = (matcher.closest(q, hint).first - q).norm(); // the hint: the previous point's match
    }
  });
  return d;
}

template <typename NamedParameters>
unsigned metric_threads(const NamedParameters& np)
{
  return read_number_of_threads(np);
}

inline double root_mean_square(const std::vector<double>& d)
{
  double sum = 0.;
  for(double x : d) sum += x * x;
  return d.empty() ? 0. : std::sqrt(sum / double(d.size()));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SAMPLED_DISTANCES_H
