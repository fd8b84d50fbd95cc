// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The precompiled core, compiled once per build tree by the CMake target
// CGAL::Symmetry_transform_precompiled: the templates of internal/detection/precompiled_core.h,
// and the definitions of every header that uses internal/common/core_definitions.h (all listed
// here; the test core_definitions_listed checks it).

#define CGAL_SYMMETRY_TRANSFORM_COMPILING_CORE
#include <CGAL/Symmetry_transform/internal/detection/precompiled_core.h>

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_cells.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_tree.h>
#include <CGAL/Symmetry_transform/internal/common/worker_pool.h>
#include <CGAL/Symmetry_transform/internal/detection/border_curve.h>
#include <CGAL/Symmetry_transform/internal/detection/face_support.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>
#include <CGAL/Symmetry_transform/internal/detection/mirror_families.h>
#include <CGAL/Symmetry_transform/internal/detection/parts_apart.h>
#include <CGAL/Symmetry_transform/internal/remeshing/anchor_positions.h>
#include <CGAL/Symmetry_transform/internal/remeshing/anchors_and_chords.h>
#include <CGAL/Symmetry_transform/internal/remeshing/hole_filling.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mesh_extraction.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirror_boundaries.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirrors.h>
#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>
#include <CGAL/Symmetry_transform/internal/remeshing/patch_triangulation.h>
#include <CGAL/Symmetry_transform/internal/remeshing/proxy_generation.h>
#include <CGAL/Symmetry_transform/internal/remeshing/seeding.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>
#include <CGAL/Symmetry_transform/internal/rotation/rigid_motion.h>
#include <CGAL/Symmetry_transform/internal/segmentation/dual_graph.h>
#include <CGAL/Symmetry_transform/internal/segmentation/face_feature.h>
#include <CGAL/Symmetry_transform/internal/segmentation/fuzzy_clustering.h>
#include <CGAL/Symmetry_transform/internal/segmentation/split.h>
