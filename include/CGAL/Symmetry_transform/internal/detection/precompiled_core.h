// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PRECOMPILED_CORE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PRECOMPILED_CORE_H

// The precompiled core: the detection's heavy templates for the two kernels that nearly every
// program uses (CGAL's Epick, and the package's own double kernel, which the segmentation uses).
// With CGAL_SYMMETRY_TRANSFORM_PRECOMPILED_CORE (set by the CMake target
// CGAL::Symmetry_transform_precompiled) they are declared `extern template`: a translation unit
// does not compile them, src/Symmetry_transform/precompiled_core.cpp compiles them once per
// build tree. Without it, nothing changes: the package is header-only.
// What is listed here depends on neither the user's mesh nor the named parameters.
// The package's double-only functions are the core's too (internal/common/core_definitions.h).

#if defined(CGAL_SYMMETRY_TRANSFORM_PRECOMPILED_CORE) || defined(CGAL_SYMMETRY_TRANSFORM_COMPILING_CORE)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>

#ifdef CGAL_SYMMETRY_TRANSFORM_COMPILING_CORE
#define CGAL_SYMMETRY_TRANSFORM_INSTANTIATION template
#else
#define CGAL_SYMMETRY_TRANSFORM_INSTANTIATION extern template
#endif

#define CGAL_SYMMETRY_TRANSFORM_INSTANTIATE_DETECTION_CORE(K)                                                          \
  CGAL_SYMMETRY_TRANSFORM_INSTANTIATION class Triangle_surface<K>;                                                     \
  CGAL_SYMMETRY_TRANSFORM_INSTANTIATION void fill_reflective_symmetry<K>(                                              \
    const Voxel_grid<K>&, Reflective_symmetry_method, Monte_carlo_estimator, std::size_t, unsigned, unsigned,           \
    Reflective_symmetry_transform<K>&);                                                                                \
  CGAL_SYMMETRY_TRANSFORM_INSTANTIATION std::vector<Principal_symmetry<K>> principal_symmetries_of_surface<K>(         \
    const Triangle_surface<K>&, const Reflective_symmetry_transform<K>&, const Detection_settings&);                   \
  CGAL_SYMMETRY_TRANSFORM_INSTANTIATION std::vector<Shape_part> parts_of<K>(const std::vector<Dtriangle>&,             \
                                                                            const Voxel_grid<K>&, const Grid_settings&); \
  CGAL_SYMMETRY_TRANSFORM_INSTANTIATION std::vector<Principal_symmetry<K>> refined_at_part_scale<K, Triangle_matcher>( \
    const std::vector<Dplane>&, const Eigen::Vector3d&, const Voxel_grid<K>&, const std::vector<Eigen::Vector3d>&,     \
    const Triangle_matcher&, Isp_settings);

namespace CGAL::Symmetry_transform::internal {
CGAL_SYMMETRY_TRANSFORM_INSTANTIATE_DETECTION_CORE(CGAL::Exact_predicates_inexact_constructions_kernel)
CGAL_SYMMETRY_TRANSFORM_INSTANTIATE_DETECTION_CORE(Dkernel)
} // namespace CGAL::Symmetry_transform::internal

#undef CGAL_SYMMETRY_TRANSFORM_INSTANTIATE_DETECTION_CORE
#undef CGAL_SYMMETRY_TRANSFORM_INSTANTIATION

#endif

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PRECOMPILED_CORE_H
