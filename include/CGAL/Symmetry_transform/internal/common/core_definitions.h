// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CORE_DEFINITIONS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CORE_DEFINITIONS_H

// The functions of the package that depend on no user type (plain double geometry), and the
// member functions of its classes that do not, are declared in their headers (free functions with
// CGAL_SYMMETRY_TRANSFORM_CORE_INLINE) and defined at the end of the header, inside
// `#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS`, with CGAL_SYMMETRY_TRANSFORM_CORE_INLINE:
// - header-only (the default): defined `inline` in every translation unit, as before;
// - with CGAL_SYMMETRY_TRANSFORM_PRECOMPILED_CORE (the CMake target
//   CGAL::Symmetry_transform_precompiled): a translation unit sees the declarations only and
//   neither parses nor checks the definitions; src/Symmetry_transform/precompiled_core.cpp compiles
//   them once per build tree (CGAL_SYMMETRY_TRANSFORM_COMPILING_CORE), and must include every
//   header that uses these macros.
// The two forms define the same functions inline and not: all the files of one program must use
// the same target.

#if defined(CGAL_SYMMETRY_TRANSFORM_COMPILING_CORE)
#define CGAL_SYMMETRY_TRANSFORM_CORE_INLINE
#define CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS 1
#elif defined(CGAL_SYMMETRY_TRANSFORM_PRECOMPILED_CORE)
#define CGAL_SYMMETRY_TRANSFORM_CORE_INLINE
#define CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS 0
#else
#define CGAL_SYMMETRY_TRANSFORM_CORE_INLINE inline
#define CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS 1
#endif

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_CORE_DEFINITIONS_H
