// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SETTINGS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SETTINGS_H

// The settings of symmetric remeshing, read once from the named parameters: those of the
// partition into proxies (Remeshing_settings) and those of the mesh extraction
// (Meshing_settings), with the checks of the bad-input contract.

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The planes a vertex lies on, and those a face has a mirror through, are bits of a std::uint64_t.
constexpr std::size_t max_number_of_mirror_planes = 64;

// CGAL::Surface_mesh_approximation::Seeding_method by its values (RANDOM, INCREMENTAL,
// HIERARCHICAL): its header, Variational_shape_approximation.h, would cost every program that
// remeshes the compilation of CGAL's whole VSA (Boost graph, least-squares fitting).
enum class Seeding : int { random = 0, incremental = 1, hierarchical = 2 };

struct Remeshing_settings
{
  std::vector<Dplane> planes;
  double position_weight = 0.; // alpha of the metric
  bool strongest_plane_only = false;
  std::size_t max_number_of_proxies = 0; // 0: not given
  double min_error_drop = 0.;            // 0: not given
  std::size_t number_of_iterations = defaults::remeshing_iterations;
  std::size_t number_of_relaxations = defaults::remeshing_relaxations;
  Seeding seeding = Seeding::hierarchical;
  unsigned random_seed = defaults::random_seed;
  unsigned threads = 1;
  bool verbose = false;
};

struct Meshing_settings
{
  double subdivision_ratio = defaults::subdivision_ratio;
  bool relative_to_chord = false, with_dihedral_angle = false, optimize_anchor_location = true;
};

// Throws std::invalid_argument on a degenerate plane, more than 64 planes, or a numeric named
// parameter out of its range (parameter_checks.h).
template <typename PlaneRange, typename NamedParameters>
Remeshing_settings remeshing_settings(const PlaneRange& planes, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace r = parameter_ranges;
  check_named_parameters(np);
  Remeshing_settings s;
  for(const auto& plane : planes) s.planes.push_back(to_dplane(plane));
  if(s.planes.size() > max_number_of_mirror_planes)
    throw std::invalid_argument("Symmetry_transform: at most 64 planes of symmetry");
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::max_number_of_proxies_t>::value)
    s.max_number_of_proxies = read_count(np, internal_np::max_number_of_proxies, 0, r::max_number_of_proxies);
  s.min_error_drop = read_real(np, internal_np::min_error_drop, 0., r::min_error_drop);
  s.number_of_iterations = read_count(np, internal_np::number_of_iterations, defaults::remeshing_iterations, r::number_of_iterations);
  s.number_of_relaxations =
    read_count(np, internal_np::number_of_relaxations, defaults::remeshing_relaxations, r::number_of_relaxations);
  s.seeding = Seeding(static_cast<int>(choose_parameter(get_parameter(np, internal_np::seeding_method), int(Seeding::hierarchical))));
  s.position_weight = read_real(np, internal_np::st_position_weight, defaults::position_weight, r::position_weight);
  s.strongest_plane_only = choose_parameter(get_parameter(np, internal_np::st_strongest_plane_only), false);
  s.random_seed = read_random_seed(np, defaults::random_seed);
  s.threads = read_number_of_threads(np);
  s.verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);
  return s;
}

template <typename NamedParameters>
Meshing_settings meshing_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Meshing_settings s;
  s.subdivision_ratio = read_real(np, internal_np::subdivision_ratio, defaults::subdivision_ratio, parameter_ranges::subdivision_ratio);
  s.relative_to_chord = choose_parameter(get_parameter(np, internal_np::relative_to_chord), false);
  s.with_dihedral_angle = choose_parameter(get_parameter(np, internal_np::with_dihedral_angle), false);
  s.optimize_anchor_location = choose_parameter(get_parameter(np, internal_np::optimize_anchor_location), true);
  return s;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_SETTINGS_H
