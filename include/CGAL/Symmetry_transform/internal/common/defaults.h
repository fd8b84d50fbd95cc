// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_DEFAULTS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_DEFAULTS_H

// The default of every named parameter of the package, in one place; the reference manual
// quotes these values. Where a capability has its own default for a shared name, the reason
// is given beside it.

#include <cstddef>

namespace CGAL::Symmetry_transform::internal {
namespace defaults {

// Grid and transforms (gaussian_distance_transform(), point_symmetry_transform(),
// reflective_symmetry_transform(), detect_principal_symmetries()).
constexpr long grid_resolution = 64;          // the thesis's 64^3
constexpr double gaussian_width = 1.5;        // sigma in voxels (DESIGN.md: 1.5 to 2)
// grid_margin has no constant default: unless it is given, the side of the grid leaves room for
// the Gaussian tail around the bounding sphere (internal/grid/settings.h); never read.
constexpr double grid_margin = 1.;
constexpr std::size_t monte_carlo_pairs = 2000000; // the thesis's 2e6 pairs at 64^3
constexpr unsigned random_seed = 0;

// Principal symmetries.
// The maxima of a detection's PRST need only be located to a bin or two, ISP doing the rest:
// a quarter of the transform's own Monte Carlo pairs.
constexpr std::size_t detection_monte_carlo_pairs = 500000;
constexpr std::size_t refinement_samples = 10000;  // DESIGN.md: ~1e4 surface samples for ISP
constexpr unsigned isp_iterations = 20;            // per stage of a refinement
constexpr std::size_t max_number_of_planes = 10;
constexpr double symmetry_threshold = 0.1;         // DESIGN.md: t = 1/10 of the strongest maximum
constexpr double laplacian_threshold = 0.1;        // DESIGN.md: l = 1/10 of the strongest maximum

// Alignment: the thesis's rule of the frame unless the data are said to be partial (a scan).
constexpr bool partial_data = false;

// Matching: a descriptor is compared with many others and stored; 32^3 keeps it at 256 KiB.
constexpr long descriptor_grid_resolution = 32;

// Viewpoint selection: directions of the Fibonacci sphere searched exhaustively.
constexpr std::size_t viewpoint_directions = 4000;

// Rotational symmetries: orders 2 to 12 cover the rotational parts of most manufactured objects
// (gears and turbines with more teeth or blades are reported at the largest divisor of their
// order within the range).
constexpr int max_order = 12;

// Symmetric remeshing (VSA's own defaults where the names are VSA's).
constexpr std::size_t remeshing_iterations = 20;
constexpr std::size_t remeshing_relaxations = 5;
constexpr double position_weight = 0.002;          // the thesis's alpha
constexpr double subdivision_ratio = 5.;
// As CGAL's VSA: without a usable max_number_of_proxies, at most a proxy per 3 faces, and the
// seeding stops when the error drops by less than this fraction.
constexpr std::size_t faces_per_proxy = 3;
constexpr double min_error_drop = 0.1;
constexpr std::size_t metric_samples = 20000;     // remeshing metrics: samples on each surface

// Segmentation: each segment gets its own detection, cheaper than the whole shape's: a coarser
// grid, fewer Monte Carlo pairs and ISP samples, and fewer planes (the features of the clustering).
constexpr std::size_t max_segmentation_depth = 3;
constexpr double smoothing_lambda = 1.;            // as CGAL's SDF segmentation
constexpr long segmentation_grid_resolution = 32;
constexpr std::size_t segmentation_monte_carlo_pairs = 100000;
constexpr std::size_t segmentation_refinement_samples = 5000;
constexpr std::size_t segmentation_max_number_of_planes = 6;
// A segment is split only if one of its planes reflects between this fraction of its area and
// its complement onto it (the thesis's stopping rule, section 5.2.2: 10 % and 90 %).
constexpr double partial_symmetry_fraction = 0.1;
// Parts of a split smaller than this fraction of the segment are merged into a neighbour: thin
// strips along a boundary, left by the graph cut, are no parts.
constexpr double smallest_part_fraction = 0.05;

} // namespace defaults
} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_DEFAULTS_H
