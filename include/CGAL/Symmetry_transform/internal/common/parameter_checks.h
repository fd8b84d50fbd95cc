// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARAMETER_CHECKS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARAMETER_CHECKS_H

// The accepted ranges of the numeric named parameters, and their checks: a value is checked as
// the user gave it (a negative int is refused before any cast to an unsigned type), against
// bounds that keep the memory and the time of a call finite. A bad value throws
// std::invalid_argument naming the parameter and its range, before any large allocation.

#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace CGAL::Symmetry_transform::internal {

// A computation may take at most this fraction of the physical memory: the rest for the system.
constexpr double max_memory_fraction = 0.75;
// The memory assumed where the system cannot tell (64 GiB).
constexpr double assumed_memory_bytes = 64. * 1024. * 1024. * 1024.;

inline double memory_budget_bytes()
{
  double available = assumed_memory_bytes;
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
  available = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
#endif
  return max_memory_fraction * available;
}

inline void check_memory(double bytes, const std::string& what, const std::string& parameter = "grid_resolution")
{
  if(bytes > memory_budget_bytes())
    throw std::invalid_argument("Symmetry_transform: " + what + " needs " +
                                std::to_string(bytes / (1024. * 1024. * 1024.)) +
                                " GiB, more than this machine's memory: lower " + parameter);
}

// Below 8 samples per axis a grid cannot hold a shape and its band.
constexpr long min_grid_resolution = 8;

// The most memory any function of the package takes per voxel of its grid, at its peak, whatever
// the number of threads: the point symmetry transform's padded FFT grids, (2n)^3 doubles and their
// spectrum (128 bytes per voxel), with the GEDT and the result (16); or a detection's GEDT (8),
// band (1) and closest triangles (4), transform bins (8), the transform's sharpened (8) and
// single-precision (4) copies of the GEDT, its Monte Carlo tables of the voxels in the band (at
// most 48), and the voting estimators' eight vote arrays (64, prst/monte_carlo.h).
constexpr double grid_bytes_per_voxel = 145.;

// The largest grid_resolution whose computation fits in memory.
inline long max_grid_resolution()
{
  return long(std::cbrt(memory_budget_bytes() / grid_bytes_per_voxel));
}

// The range of an integer parameter, [least, most].
struct Count_range
{
  const char* name;
  std::uintmax_t least, most;
};

// The range of a real parameter: from `least` to `most`, each bound included or not.
struct Real_range
{
  const char* name;
  double least, most;
  bool least_included, most_included;
};

namespace parameter_ranges {

constexpr std::uintmax_t unbounded = (std::numeric_limits<std::uintmax_t>::max)();

// Samples and iterations: bounds far above any useful value (the defaults are 5000 to 2e6
// samples and 20 iterations), that keep a mistaken one (a negative number cast to an unsigned
// type) from running for days or exhausting the memory.
constexpr Count_range number_of_samples{"number_of_samples", 1, 10000000000ull};
// With the exact method, which draws no sample, 0 is accepted.
constexpr Count_range number_of_samples_or_zero{"number_of_samples", 0, 10000000000ull};
constexpr Count_range number_of_refinement_samples{"number_of_refinement_samples", 1, 100000000};
constexpr Count_range number_of_points_on_faces{"number_of_points_on_faces", 1, 100000000};
constexpr Count_range number_of_iterations{"number_of_iterations", 0, 1000000};
constexpr Count_range number_of_relaxations{"number_of_relaxations", 0, 1000000};
// 0: the default, std::thread::hardware_concurrency().
constexpr Count_range number_of_threads{"number_of_threads", 0, 1024};
constexpr Count_range random_seed{"random_seed", 0, (std::numeric_limits<std::uint32_t>::max)()};
constexpr Count_range max_number_of_planes{"max_number_of_planes", 1, unbounded};
constexpr Count_range max_number_of_proxies{"max_number_of_proxies", 1, unbounded};
constexpr Count_range max_segmentation_depth{"max_segmentation_depth", 0, unbounded};
constexpr Count_range max_number_of_segments{"max_number_of_segments", 1, unbounded};
constexpr Count_range number_of_directions{"number_of_directions", 12, 10000000};
constexpr Count_range max_order{"max_order", 2, 1000};

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr Real_range gaussian_width{"gaussian_width", 0., infinity, false, false};
constexpr Real_range grid_margin{"grid_margin", 1., infinity, true, false};
constexpr Real_range symmetry_threshold{"symmetry_threshold", 0., 1., true, true};
constexpr Real_range laplacian_threshold{"laplacian_threshold", 0., 1., true, true};
constexpr Real_range smoothing_lambda{"smoothing_lambda", 0., infinity, true, false};
constexpr Real_range partial_symmetry_fraction{"partial_symmetry_fraction", 0., 0.5, true, true};
constexpr Real_range smallest_part_fraction{"smallest_part_fraction", 0., 1., true, false};
constexpr Real_range position_weight{"position_weight", 0., 1., true, true};
constexpr Real_range min_error_drop{"min_error_drop", 0., 1., true, true};
constexpr Real_range subdivision_ratio{"subdivision_ratio", 0., infinity, false, false};
constexpr Real_range coverage_distance{"coverage_distance", 0., infinity, false, false};

} // namespace parameter_ranges

inline std::string range_text(const Count_range& range)
{
  if(range.most == parameter_ranges::unbounded) return "an integer at least " + std::to_string(range.least);
  return "an integer in [" + std::to_string(range.least) + ", " + std::to_string(range.most) + "]";
}

inline std::string range_text(const Real_range& range)
{
  std::ostringstream text;
  text << "a number in " << (range.least_included ? '[' : '(') << range.least << ", " << range.most
       << (range.most_included ? ']' : ')');
  return text.str();
}

template <typename T, typename Range>
[[noreturn]] void throw_out_of_range(const T& value, const Range& range)
{
  std::ostringstream given;
  given << +value; // a char-sized integer as a number
  throw std::invalid_argument(std::string("Symmetry_transform: ") + range.name + " must be " + range_text(range) +
                              ", not " + given.str());
}

// `value` as given by the user, checked against `range`, then as a std::size_t.
template <typename T>
std::size_t checked_count(const T& value, const Count_range& range)
{
  static_assert(std::is_arithmetic_v<T>, "a count parameter must be a number");
  bool in_range;
  if constexpr(std::is_floating_point_v<T>)
    in_range = value >= double(range.least) && value <= double(range.most) && value == std::floor(value);
  else if constexpr(std::is_signed_v<T>)
    in_range = value >= 0 && std::uintmax_t(value) >= range.least && std::uintmax_t(value) <= range.most;
  else
    in_range = std::uintmax_t(value) >= range.least && std::uintmax_t(value) <= range.most;
  if(!in_range || std::uintmax_t(value) > (std::numeric_limits<std::size_t>::max)()) throw_out_of_range(value, range);
  return std::size_t(value);
}

template <typename T>
double checked_real(const T& value, const Real_range& range)
{
  static_assert(std::is_arithmetic_v<T>, "a real parameter must be a number");
  const double x = double(value);
  const bool above = range.least_included ? x >= range.least : x > range.least;
  const bool below = range.most_included ? x <= range.most : x < range.most;
  if(!(above && below && std::isfinite(x))) throw_out_of_range(value, range);
  return x;
}

// The value of the parameter `tag` of `np` (`fallback` if not given), checked.
template <typename NamedParameters, typename Tag, typename Default>
std::size_t read_count(const NamedParameters& np, Tag tag, const Default& fallback, const Count_range& range)
{
  return checked_count(parameters::choose_parameter(parameters::get_parameter(np, tag), fallback), range);
}

template <typename NamedParameters, typename Tag, typename Default>
double read_real(const NamedParameters& np, Tag tag, const Default& fallback, const Real_range& range)
{
  return checked_real(parameters::choose_parameter(parameters::get_parameter(np, tag), fallback), range);
}

// `number_of_threads`, 0 (the default) standing for the number of cores.
template <typename NamedParameters>
unsigned read_number_of_threads(const NamedParameters& np)
{
  const std::size_t threads = read_count(np, internal_np::st_number_of_threads, 0u, parameter_ranges::number_of_threads);
  return threads != 0 ? unsigned(threads) : (std::max)(1u, std::thread::hardware_concurrency());
}

template <typename NamedParameters>
unsigned read_random_seed(const NamedParameters& np, unsigned fallback)
{
  return unsigned(read_count(np, internal_np::random_seed, fallback, parameter_ranges::random_seed));
}

// `grid_resolution` (`fallback` if not given), in [8, max_grid_resolution()].
template <typename NamedParameters>
long read_grid_resolution(const NamedParameters& np, long fallback)
{
  const Count_range range{"grid_resolution", std::uintmax_t(min_grid_resolution),
                          std::uintmax_t(max_grid_resolution())};
  return long(read_count(np, internal_np::st_grid_resolution, fallback, range));
}

// A sample reflected by ISP or measured by the metrics takes at most this many bytes, with its
// copies (the Hilbert sort, the ordered copy, its normal, its match and its distance).
constexpr double bytes_per_sample = 128.;

// A count of samples (`range`), read as read_count() does; the samples must fit in memory too.
template <typename NamedParameters, typename Tag, typename Default>
std::size_t read_sample_count(const NamedParameters& np, Tag tag, const Default& fallback, const Count_range& range)
{
  const std::size_t count = read_count(np, tag, fallback, range);
  check_memory(double(count) * bytes_per_sample, std::to_string(count) + " " + range.name, range.name);
  return count;
}

template <typename NamedParameters, typename Tag, typename Range>
void check_if_given(const NamedParameters& np, Tag tag, const Range& range)
{
  if constexpr(!parameters::is_default_parameter<NamedParameters, Tag>::value) {
    if constexpr(std::is_same_v<Range, Count_range>) read_count(np, tag, 0, range);
    else read_real(np, tag, 0., range);
  }
}

// Checks every numeric named parameter of `np` that is given, whichever function reads it: the
// public functions call it (through the readers of their settings) before any work.
template <typename NamedParameters>
void check_named_parameters(const NamedParameters& np)
{
  namespace r = parameter_ranges;
  read_number_of_threads(np); // its checks
  check_if_given(np, internal_np::random_seed, r::random_seed);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::st_grid_resolution_t>::value)
    read_grid_resolution(np, 0);
  check_if_given(np, internal_np::st_gaussian_width, r::gaussian_width);
  check_if_given(np, internal_np::st_grid_margin, r::grid_margin);
  // 0 with a prst_method given: reflective_symmetry_transform() accepts it with the exact method only.
  if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::st_prst_method_t>::value)
    check_if_given(np, internal_np::number_of_samples, r::number_of_samples);
  else
    check_if_given(np, internal_np::number_of_samples, r::number_of_samples_or_zero);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::st_number_of_refinement_samples_t>::value)
    read_sample_count(np, internal_np::st_number_of_refinement_samples, 0, r::number_of_refinement_samples);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::number_of_points_on_faces_t>::value)
    read_sample_count(np, internal_np::number_of_points_on_faces, 0, r::number_of_points_on_faces);
  check_if_given(np, internal_np::number_of_iterations, r::number_of_iterations);
  check_if_given(np, internal_np::number_of_relaxations, r::number_of_relaxations);
  check_if_given(np, internal_np::st_max_number_of_planes, r::max_number_of_planes);
  check_if_given(np, internal_np::st_symmetry_threshold, r::symmetry_threshold);
  check_if_given(np, internal_np::st_laplacian_threshold, r::laplacian_threshold);
  check_if_given(np, internal_np::max_number_of_proxies, r::max_number_of_proxies);
  check_if_given(np, internal_np::min_error_drop, r::min_error_drop);
  check_if_given(np, internal_np::st_position_weight, r::position_weight);
  check_if_given(np, internal_np::st_coverage_distance, r::coverage_distance);
  check_if_given(np, internal_np::subdivision_ratio, r::subdivision_ratio);
  check_if_given(np, internal_np::st_max_segmentation_depth, r::max_segmentation_depth);
  check_if_given(np, internal_np::st_max_number_of_segments, r::max_number_of_segments);
  check_if_given(np, internal_np::st_smoothing_lambda, r::smoothing_lambda);
  check_if_given(np, internal_np::st_partial_symmetry_fraction, r::partial_symmetry_fraction);
  check_if_given(np, internal_np::st_smallest_part_fraction, r::smallest_part_fraction);
  check_if_given(np, internal_np::st_number_of_directions, r::number_of_directions);
  check_if_given(np, internal_np::st_max_order, r::max_order);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARAMETER_CHECKS_H
