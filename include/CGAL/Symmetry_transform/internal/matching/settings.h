// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_SETTINGS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_SETTINGS_H

// The named parameters of a descriptor: those of the transforms, with its own default resolution.

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>

namespace CGAL::Symmetry_transform::internal {

// The named parameters with grid_resolution set: the one given, defaults::descriptor_grid_resolution by default.
template <typename NamedParameters>
auto descriptor_parameters(const NamedParameters& np)
{
  const int n = int(parameters::choose_parameter(parameters::get_parameter(np, internal_np::st_grid_resolution),
                                                 defaults::descriptor_grid_resolution));
  return np.grid_resolution(n);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_SETTINGS_H
