// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SURFACE_SAMPLES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SURFACE_SAMPLES_H

// The samples that Iterative Symmetric Points reflects (and that the remeshing metrics measure
// distances from): area-uniform on a mesh, a random subset of a point set, from the seed alone.

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Random.h>
#include <CGAL/hilbert_sort.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// ISP's coarse phase uses the first samples of isp_order(): every coarse_sample_stride-th, spread
// over the shape, an eighth of the cost of a fine iteration.
constexpr std::size_t coarse_sample_stride = 8;

// Samples in the order ISP visits them: every coarse_sample_stride-th first (those of the coarse
// phase), then the others, each part along a Hilbert curve, so that consecutive samples are close
// and the match of one is a good start for the search of the next.
inline std::vector<Eigen::Vector3d> isp_order(std::vector<Dpoint> points)
{
  CGAL::hilbert_sort(points.begin(), points.end(), Dkernel(), CGAL::Hilbert_sort_median_policy());
  std::vector<Eigen::Vector3d> ordered;
  ordered.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); i += coarse_sample_stride) ordered.push_back(to_eigen(points[i]));
  for(std::size_t i = 0; i < points.size(); ++i)
    if(i % coarse_sample_stride != 0) ordered.push_back(to_eigen(points[i]));
  return ordered;
}

// How many samples ISP reflects, and their seed.
struct Refinement_sampling
{
  std::size_t count;
  unsigned seed;
};

template <typename NamedParameters>
Refinement_sampling refinement_sampling(const NamedParameters& np)
{
  return {read_sample_count(np, internal_np::st_number_of_refinement_samples, defaults::refinement_samples,
                            parameter_ranges::number_of_refinement_samples),
          read_random_seed(np, defaults::random_seed)};
}

// The count of a sampling made in code (the readers check the user's).
inline void check_refinement_samples(const Refinement_sampling& sampling)
{
  if(sampling.count == 0) throw std::invalid_argument("Symmetry_transform: no sample to draw");
}

// Area-uniform random samples of the triangles, from the seed alone. (CGAL 5.5's
// Random_points_in_triangles_3 picks the triangle with the given generator, but the point in
// it with CGAL::get_default_random(): runs would differ.)
inline std::vector<Eigen::Vector3d> surface_samples(const std::vector<Dtriangle>& triangles,
                                                    const Refinement_sampling& sampling)
{
  check_refinement_samples(sampling);
  CGAL::Random random(sampling.seed);
  std::vector<double> cumulative_area;
  cumulative_area.reserve(triangles.size());
  double total = 0.;
  for(const Dtriangle& t : triangles) cumulative_area.push_back(total += std::sqrt(t.squared_area()));
  std::vector<Dpoint> samples;
  samples.reserve(sampling.count);
  for(std::size_t i = sampling.count; i > 0; --i) {
    const std::size_t f = std::size_t(std::upper_bound(cumulative_area.begin(), cumulative_area.end() - 1,
                                                       random.get_double(0., total)) - cumulative_area.begin());
    double u = random.get_double(), v = random.get_double();
    if(u + v > 1.) { u = 1. - u; v = 1. - v; } // fold the parallelogram onto the triangle
    const Dtriangle& t = triangles[f];
    samples.push_back(t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]));
  }
  return isp_order(std::move(samples));
}

template <typename NamedParameters>
std::vector<Eigen::Vector3d> surface_samples(const std::vector<Dtriangle>& triangles, const NamedParameters& np)
{
  return surface_samples(triangles, refinement_sampling(np));
}

// A seeded random subset of the points.
inline std::vector<Eigen::Vector3d> point_samples(const std::vector<Dpoint>& points, const Refinement_sampling& sampling)
{
  check_refinement_samples(sampling);
  std::vector<Dpoint> chosen = points;
  CGAL::Random random(sampling.seed);
  const std::size_t count = (std::min)(points.size(), sampling.count);
  for(std::size_t i = 0; i < count; ++i) std::swap(chosen[i], chosen[i + std::size_t(random.get_int(0, int(chosen.size() - i)))]);
  chosen.resize(count);
  return isp_order(std::move(chosen));
}

template <typename NamedParameters>
std::vector<Eigen::Vector3d> point_samples(const std::vector<Dpoint>& points, const NamedParameters& np)
{
  return point_samples(points, refinement_sampling(np));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SURFACE_SAMPLES_H
