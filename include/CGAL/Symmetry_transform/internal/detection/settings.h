// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_SETTINGS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_SETTINGS_H

// The options of a detection of principal symmetries, read once from the named parameters at
// the entry points (detection_of_mesh(), detection_of_points(), the public functions), then
// handed to the stages: the grid (GEDT), the samples and the iterations of ISP, and the choice of
// candidates. The transform reads its own options (reflective_symmetry_transform()).

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>

#include <cstddef>

namespace CGAL::Symmetry_transform::internal {

// Which candidates of the transform are refined, and how many planes are kept.
struct Candidate_settings
{
  std::size_t max_planes;
  bool max_planes_given;      // a cap the user chose cuts groups; the default one does not
  double symmetry_threshold;  // t, as a fraction of the strongest maximum's symmetry measure
  double laplacian_threshold; // l, as a fraction of the strongest maximum's negative Laplacian
  bool verbose;               // print each candidate and its refinement on std::cerr
  int max_order;              // of the rotations whose exact planes complete their group (plane_group.h)
};

struct Detection_settings
{
  Grid_options grid;          // of the GEDT, whose width also sets the weights of ISP
  Refinement_sampling sampling;
  unsigned isp_iterations;    // at most this many re-fits per stage of ISP
  Candidate_settings candidates;
};

template <typename NamedParameters>
Candidate_settings candidate_settings(const NamedParameters& np)
{
  namespace r = parameter_ranges;
  return {read_count(np, internal_np::st_max_number_of_planes, defaults::max_number_of_planes, r::max_number_of_planes),
          !parameters::is_default_parameter<NamedParameters, internal_np::st_max_number_of_planes_t>::value,
          read_real(np, internal_np::st_symmetry_threshold, defaults::symmetry_threshold, r::symmetry_threshold),
          read_real(np, internal_np::st_laplacian_threshold, defaults::laplacian_threshold, r::laplacian_threshold),
          parameters::choose_parameter(parameters::get_parameter(np, internal_np::verbose), false),
          int(read_count(np, internal_np::st_max_order, defaults::max_order, r::max_order))};
}

template <typename NamedParameters>
unsigned isp_iterations(const NamedParameters& np)
{
  return unsigned(read_count(np, internal_np::number_of_iterations, defaults::isp_iterations,
                             parameter_ranges::number_of_iterations));
}

template <typename NamedParameters>
Detection_settings detection_settings(const NamedParameters& np)
{
  const Grid_options grid = grid_options(np); // first: it checks all the numeric parameters
  return {grid, refinement_sampling(np), isp_iterations(np), candidate_settings(np)};
}

// The settings of ISP on a shape whose GEDT `gedt` was made with `grid`; they refer to `gedt`
// (the band test), which must outlive them.
template <typename GT>
Isp_settings isp_settings(const Grid_settings& grid, unsigned max_iterations, const Voxel_grid<GT>& gedt)
{
  Isp_settings settings;
  settings.sigma = grid.sigma();
  settings.radius = gedt.radius();
  settings.max_iterations = max_iterations;
  settings.threads = grid.threads;
  settings.beyond_band = beyond_band_of(gedt);
  settings.center = to_eigen(to_dpoint(gedt.center()));
  return settings;
}
template <typename GT>
Isp_settings isp_settings(const Grid_settings&, unsigned, const Voxel_grid<GT>&&) = delete;

// The same from the named parameters, for a GEDT made with them.
template <typename GT, typename NamedParameters>
Isp_settings isp_settings(const NamedParameters& np, const Voxel_grid<GT>& gedt)
{
  return isp_settings(grid_settings(np, gedt.radius()), isp_iterations(np), gedt);
}
template <typename GT, typename NamedParameters>
Isp_settings isp_settings(const NamedParameters&, const Voxel_grid<GT>&&) = delete;

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_SETTINGS_H
