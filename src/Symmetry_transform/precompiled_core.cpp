// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The precompiled core (internal/detection/precompiled_core.h), compiled once per build tree by the
// CMake target CGAL::Symmetry_transform_precompiled.

#define CGAL_SYMMETRY_TRANSFORM_COMPILING_CORE
#include <CGAL/Symmetry_transform/internal/detection/precompiled_core.h>
