// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CGAL_AABB_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CGAL_AABB_H

// CGAL's AABB traits and triangle primitive under the names of the CGAL version compiled against:
// CGAL 6.0 renamed them with a _3 suffix and deprecated the old headers, which then warn.

#include <CGAL/version.h>

#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_triangle_primitive_3.h>
#else
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#endif
#include <CGAL/AABB_tree.h>

namespace CGAL::Symmetry_transform::internal {

#if CGAL_VERSION_NR >= 1060000000
template <typename GeomTraits, typename Primitive>
using AABB_traits_3 = CGAL::AABB_traits_3<GeomTraits, Primitive>;
template <typename GeomTraits, typename Iterator>
using AABB_triangle_primitive_3 = CGAL::AABB_triangle_primitive_3<GeomTraits, Iterator>;
#else
template <typename GeomTraits, typename Primitive>
using AABB_traits_3 = CGAL::AABB_traits<GeomTraits, Primitive>;
template <typename GeomTraits, typename Iterator>
using AABB_triangle_primitive_3 = CGAL::AABB_triangle_primitive<GeomTraits, Iterator>;
#endif

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CGAL_AABB_H
