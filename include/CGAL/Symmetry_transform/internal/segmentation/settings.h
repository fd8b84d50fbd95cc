// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SETTINGS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SETTINGS_H

// The settings of segment_by_symmetry(), read once from the named parameters: those of the tree
// and those of the detection on each segment, whose defaults are fitted to segmentation and
// whose sample counts and grid are scaled to the segment; and the tuned constants of the split
// and of the hierarchy.

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace CGAL::Symmetry_transform::internal {

// The tuned constants of the segmentation (those of the clustering and of the dual graph aside).
// The value of max_number_of_segments that sets no limit (Symmetry_segment::none).
constexpr std::size_t no_segment_limit = (std::numeric_limits<std::size_t>::max)();
// Segments covering less than this fraction of the mesh's area are not examined (TOO_SMALL):
// a detection on them costs as much as on a large one, for a part too small to matter.
constexpr double least_examined_area_fraction = 0.02;
// Nor are segments of fewer faces than a tetrahedron: too few to be split into parts.
constexpr std::size_t least_examined_faces = 4;
// The Gaussian width of the feature vectors, relative to the detection's (see face_supports()).
constexpr double feature_width_factor = 0.5;
// Refinement samples and Monte Carlo samples of a segment covering a fraction of the mesh's
// area: the density of the whole mesh's, at least these many.
constexpr std::size_t least_refinement_samples = 1000;
constexpr std::size_t least_monte_carlo_samples = 20000;
// The smallest grid of a segment below the root, if the root's is larger.
constexpr long least_segment_resolution = 24;

struct Segmentation_settings
{
  // The tree.
  std::size_t max_depth;
  std::size_t max_segments;
  double lambda; // the weight of the boundary in the graph cut
  double partial_symmetry_fraction; // split only if a plane reflects between it and 1 - it
  double smallest_part_fraction;    // of the segment: smaller parts of a split are merged
  bool verbose;
  // The detection on a segment: that of detect_principal_symmetries(), with defaults fitted to
  // segmentation.
  long grid_resolution;
  double gaussian_width;
  std::size_t number_of_samples;
  std::size_t number_of_refinement_samples;
  unsigned number_of_iterations;
  std::size_t max_number_of_planes;
  double symmetry_threshold;
  double laplacian_threshold;
  Reflective_symmetry_method method;
  Monte_carlo_estimator estimator;
  unsigned seed;
  unsigned threads;
};

// The settings of the detection on a segment, read from the named parameters.
template <typename NamedParameters>
void read_detection_settings(const NamedParameters& np, Segmentation_settings& s)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace r = parameter_ranges;
  s.threads = read_number_of_threads(np);
  s.grid_resolution = read_grid_resolution(np, defaults::segmentation_grid_resolution);
  s.gaussian_width = read_real(np, internal_np::st_gaussian_width, defaults::gaussian_width, r::gaussian_width);
  s.method = choose_parameter(get_parameter(np, internal_np::st_prst_method), Reflective_symmetry_method::MONTE_CARLO);
  s.number_of_samples = read_count(np, internal_np::number_of_samples, defaults::segmentation_monte_carlo_pairs,
                                   s.method == Reflective_symmetry_method::EXACT ? r::number_of_samples_or_zero
                                                                                 : r::number_of_samples);
  s.number_of_refinement_samples = read_sample_count(np, internal_np::st_number_of_refinement_samples,
                                                     defaults::segmentation_refinement_samples, r::number_of_refinement_samples);
  s.number_of_iterations = unsigned(read_count(np, internal_np::number_of_iterations, defaults::isp_iterations, r::number_of_iterations));
  s.max_number_of_planes =
    read_count(np, internal_np::st_max_number_of_planes, defaults::segmentation_max_number_of_planes, r::max_number_of_planes);
  s.symmetry_threshold = read_real(np, internal_np::st_symmetry_threshold, defaults::symmetry_threshold, r::symmetry_threshold);
  s.laplacian_threshold = read_real(np, internal_np::st_laplacian_threshold, defaults::laplacian_threshold, r::laplacian_threshold);
  s.estimator =
    choose_parameter(get_parameter(np, internal_np::st_monte_carlo_estimator), Monte_carlo_estimator::STRATIFIED_LINES);
  s.seed = read_random_seed(np, defaults::random_seed);
}

// All the settings of segment_by_symmetry(), checked.
template <typename NamedParameters>
Segmentation_settings segmentation_settings(const NamedParameters& np)
{
  namespace r = parameter_ranges;
  check_named_parameters(np);
  Segmentation_settings s;
  s.max_depth = read_count(np, internal_np::st_max_segmentation_depth, defaults::max_segmentation_depth, r::max_segmentation_depth);
  s.max_segments = read_count(np, internal_np::st_max_number_of_segments, no_segment_limit, r::max_number_of_segments);
  s.lambda = read_real(np, internal_np::st_smoothing_lambda, defaults::smoothing_lambda, r::smoothing_lambda);
  s.verbose = parameters::choose_parameter(parameters::get_parameter(np, internal_np::verbose), false);
  s.partial_symmetry_fraction = read_real(np, internal_np::st_partial_symmetry_fraction, defaults::partial_symmetry_fraction,
                                          r::partial_symmetry_fraction);
  s.smallest_part_fraction =
    read_real(np, internal_np::st_smallest_part_fraction, defaults::smallest_part_fraction, r::smallest_part_fraction);
  read_detection_settings(np, s);
  return s;
}

// `count` scaled by `fraction`, at least `least` (or `count` if smaller).
inline std::size_t samples_of_fraction(std::size_t count, double fraction, std::size_t least)
{
  return (std::max)((std::min)(least, count), std::size_t(std::lround(fraction * double(count))));
}

// The grid resolution of a segment of radius `radius` in a mesh whose largest component has the
// radius `root_radius`: the voxels keep their size, down to least_segment_resolution (or 12
// Gaussian widths, the smallest grid allowed), an even number.
inline long segment_resolution(const Segmentation_settings& s, double radius, double root_radius)
{
  // even, as the transform requires
  const long least = (std::min)(s.grid_resolution, (std::max)(least_segment_resolution, 2 * (long(6. * s.gaussian_width) + 1)));
  const long scaled = 2 * long(std::lround(0.5 * double(s.grid_resolution) * radius / root_radius));
  return (std::max)(least, (std::min)(s.grid_resolution, scaled));
}

// The named parameters of the detection on a segment's triangles.
inline auto detection_parameters(const Segmentation_settings& s, double fraction, long resolution, unsigned threads)
{
  return CGAL::parameters::grid_resolution(resolution)
    .gaussian_width(s.gaussian_width)
    .number_of_samples(samples_of_fraction(s.number_of_samples, fraction, least_monte_carlo_samples))
    .number_of_refinement_samples(samples_of_fraction(s.number_of_refinement_samples, fraction, least_refinement_samples))
    .number_of_iterations(s.number_of_iterations)
    .max_number_of_planes(s.max_number_of_planes)
    .symmetry_threshold(s.symmetry_threshold)
    .laplacian_threshold(s.laplacian_threshold)
    .prst_method(s.method)
    .monte_carlo_estimator(s.estimator)
    .random_seed(s.seed)
    .number_of_threads(threads);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_SETTINGS_H
