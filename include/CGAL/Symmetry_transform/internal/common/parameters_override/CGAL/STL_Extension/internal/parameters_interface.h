// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// CGAL 5.5 keeps its list of named parameters closed: this file stands in front of CGAL's
// own list on the include path, includes it, and appends the parameters of this package, so
// that they chain with CGAL's (`CGAL::parameters::random_seed(3).grid_resolution(64)`).
// Like CGAL's list, it is included several times and therefore has no include guard.

#include_next <CGAL/STL_Extension/internal/parameters_interface.h>
#include <CGAL/Symmetry_transform/internal/common/parameters_interface.h>

#ifndef CGAL_SYMMETRY_TRANSFORM_NAMED_PARAMETERS_APPENDED
#define CGAL_SYMMETRY_TRANSFORM_NAMED_PARAMETERS_APPENDED
#endif
