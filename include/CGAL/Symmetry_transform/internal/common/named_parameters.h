// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NAMED_PARAMETERS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#ifndef CGAL_SYMMETRY_TRANSFORM_NAMED_PARAMETERS_APPENDED
#error "CGAL's named parameters were compiled without those of Symmetry_transform: CGAL's headers \
were found before the folder include/CGAL/Symmetry_transform/internal/common/parameters_override. \
Put that folder first on the include path (-I), or give CGAL's folder as a system folder (-isystem); \
the CMake target CGAL::Symmetry_transform does it, in any link order, with CMake 3.23 or later."
#endif

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_NAMED_PARAMETERS_H
