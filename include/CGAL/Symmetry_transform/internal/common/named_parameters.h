// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NAMED_PARAMETERS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#ifndef CGAL_SYMMETRY_TRANSFORM_NAMED_PARAMETERS_APPENDED
#error "CGAL's named parameters were compiled without those of Symmetry_transform: put \
include/CGAL/Symmetry_transform/internal/common/parameters_override first on the include path \
(linking the CMake target CGAL::Symmetry_transform does it)."
#endif

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NAMED_PARAMETERS_H
