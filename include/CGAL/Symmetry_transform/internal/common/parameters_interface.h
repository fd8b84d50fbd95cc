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
CGAL_add_named_parameter(st_number_of_refinement_samples_t, st_number_of_refinement_samples, number_of_refinement_samples)
CGAL_add_named_parameter(st_max_number_of_planes_t, st_max_number_of_planes, max_number_of_planes)
CGAL_add_named_parameter(st_symmetry_threshold_t, st_symmetry_threshold, symmetry_threshold)
CGAL_add_named_parameter(st_laplacian_threshold_t, st_laplacian_threshold, laplacian_threshold)

// Symmetric remeshing (symmetric_remeshing.h)
CGAL_add_named_parameter(st_position_weight_t, st_position_weight, position_weight)
CGAL_add_named_parameter(st_strongest_plane_only_t, st_strongest_plane_only, strongest_plane_only)
CGAL_add_named_parameter(st_output_mesh_t, st_output_mesh, output_mesh)
// end of symmetric remeshing

// Segmentation (symmetry_segmentation.h)
CGAL_add_named_parameter(st_max_segmentation_depth_t, st_max_segmentation_depth, max_segmentation_depth)
CGAL_add_named_parameter(st_max_number_of_segments_t, st_max_number_of_segments, max_number_of_segments)
CGAL_add_named_parameter(st_smoothing_lambda_t, st_smoothing_lambda, smoothing_lambda)
CGAL_add_named_parameter(st_segmentation_tree_t, st_segmentation_tree, segmentation_tree)
CGAL_add_named_parameter(st_partial_symmetry_fraction_t, st_partial_symmetry_fraction, partial_symmetry_fraction)
CGAL_add_named_parameter(st_smallest_part_fraction_t, st_smallest_part_fraction, smallest_part_fraction)
CGAL_add_named_parameter(st_face_feature_map_t, st_face_feature_map, face_feature_map)
// end of segmentation

// Alignment (symmetry_alignment.h)
CGAL_add_named_parameter(st_partial_data_t, st_partial_data, partial_data)

// Viewpoint selection (viewpoint_selection.h)
CGAL_add_named_parameter(st_number_of_directions_t, st_number_of_directions, number_of_directions)

// Rotational symmetries (rotational_symmetries.h)
CGAL_add_named_parameter(st_max_order_t, st_max_order, max_order)

// Symmetrization (symmetrization.h)
CGAL_add_named_parameter(st_vertex_displacement_map_t, st_vertex_displacement_map, vertex_displacement_map)
CGAL_add_named_parameter(st_whole_mesh_t, st_whole_mesh, whole_mesh)
CGAL_add_named_parameter(st_coverage_distance_t, st_coverage_distance, coverage_distance)
CGAL_add_named_parameter(st_stitch_borders_t, st_stitch_borders, stitch_borders)
