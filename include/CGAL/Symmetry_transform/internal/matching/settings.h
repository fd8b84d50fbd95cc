// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_SETTINGS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_SETTINGS_H

// The named parameters of a descriptor: those of the transforms, with its own default resolution.

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>

namespace CGAL::Symmetry_transform::internal {

// The named parameters with grid_resolution set: the one given, defaults::descriptor_grid_resolution by default.
template <typename NamedParameters>
auto descriptor_parameters(const NamedParameters& np)
{
  check_named_parameters(np);
  return np.grid_resolution(int(read_grid_resolution(np, defaults::descriptor_grid_resolution)));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_SETTINGS_H
