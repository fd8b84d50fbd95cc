// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// Named parameters added by the Symmetry_transform package, in the format of CGAL's list.
// Included several times (see parameters_override/), hence no include guard.

CGAL_add_named_parameter(st_grid_resolution_t, st_grid_resolution, grid_resolution)
CGAL_add_named_parameter(st_gaussian_width_t, st_gaussian_width, gaussian_width)
CGAL_add_named_parameter(st_grid_margin_t, st_grid_margin, grid_margin)
CGAL_add_named_parameter(st_prst_method_t, st_prst_method, prst_method)
CGAL_add_named_parameter(st_monte_carlo_estimator_t, st_monte_carlo_estimator, monte_carlo_estimator)
CGAL_add_named_parameter(st_number_of_threads_t, st_number_of_threads, number_of_threads)
