// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_GRID_SETTINGS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_GRID_SETTINGS_H

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL::Symmetry_transform::internal {

// Beyond this many standard deviations the Gaussian is set to zero: exp(-4.5) = 1.1%, and
// the energy lost, erfc(3) ~ 2e-5 of the total, is far below the discretisation error.
constexpr double gaussian_cutoff_in_sigmas = 3.;

// The grid's named parameters, each checked by grid_options() (with all the other numeric named
// parameters of the call: it is the first reader of most functions); their relation is checked
// by grid_settings().
struct Grid_options
{
  long resolution;
  double sigma_in_voxels;
  bool default_margin; // then the side leaves room for the Gaussian tail (see grid_settings())
  double margin;
  unsigned threads;
};

template <typename NamedParameters>
Grid_options grid_options(const NamedParameters& np)
{
  namespace r = parameter_ranges;
  check_named_parameters(np);
  const unsigned threads = read_number_of_threads(np);
  return {read_grid_resolution(np, defaults::grid_resolution),
          read_real(np, internal_np::st_gaussian_width, defaults::gaussian_width, r::gaussian_width),
          parameters::is_default_parameter<NamedParameters, internal_np::st_grid_margin_t>::value,
          read_real(np, internal_np::st_grid_margin, defaults::grid_margin, r::grid_margin), threads};
}

// Grid resolution n, Gaussian width sigma (in voxels) and cube side of a shape of the given radius.
// The default side leaves room for the Gaussian tail around the bounding sphere:
// side/2 = R + cutoff * sigma * side / n.
struct Grid_settings
{
  std::size_t resolution;
  double sigma_in_voxels;
  double side_length;
  unsigned threads;

  double voxel_size() const { return side_length / double(resolution); }
  double sigma() const { return sigma_in_voxels * voxel_size(); }
  double cutoff() const { return gaussian_cutoff_in_sigmas * sigma(); }
};

// Throws std::invalid_argument on invalid options or a grid that would not fit in memory.
inline Grid_settings grid_settings(const Grid_options& options, double radius)
{
  const long n = options.resolution;
  const double sigma = options.sigma_in_voxels;
  if(!(sigma > 0.))
    throw std::invalid_argument("Symmetry_transform: gaussian_width must be positive");
  const double tail = 2. * gaussian_cutoff_in_sigmas * sigma;
  if(n < min_grid_resolution || double(n) <= 2. * tail)
    throw std::invalid_argument("Symmetry_transform: grid_resolution " + std::to_string(n) +
                                " is too small: it must be at least " + std::to_string(min_grid_resolution) +
                                " and more than 12 Gaussian widths (" +
                                std::to_string(int(std::floor(2. * tail))) + ")");
  check_memory(double(n) * double(n) * double(n) * grid_bytes_per_voxel, "a grid of this resolution");
  if(!(options.margin >= 1.)) throw std::invalid_argument("Symmetry_transform: grid_margin must be at least 1");
  const double factor = options.default_margin ? 1. / (1. - tail / double(n)) : options.margin;
  return {std::size_t(n), sigma, 2. * radius * factor, (std::max)(1u, options.threads)};
}

template <typename NamedParameters>
Grid_settings grid_settings(const NamedParameters& np, double radius)
{
  return grid_settings(grid_options(np), radius);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_GRID_SETTINGS_H
