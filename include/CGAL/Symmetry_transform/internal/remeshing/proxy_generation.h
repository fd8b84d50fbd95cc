// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PROXY_GENERATION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PROXY_GENERATION_H

// Symmetric proxy generation (thesis, Section 5.1.2), in its order: seeding (seeding.h), Lloyd
// iterations of flooding and fitting with proxy teleportation (partition.h), then the patch
// boundaries of the two sides of each plane put in step (mirror_boundaries.h).

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirror_boundaries.h>
#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>
#include <CGAL/Symmetry_transform/internal/remeshing/seeding.h>

#include <algorithm>
#include <iostream>

namespace CGAL::Symmetry_transform::internal {

// Seeding, then `number_of_iterations` iterations with a teleportation attempt after each
// `number_of_relaxations` of them, then the boundaries in step.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void generate_proxies(Symmetric_partition& partition);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void generate_proxies(Symmetric_partition& partition)
{
  const Remeshing_settings& settings = partition.settings();
  Progress_stage stage(0., progress_shares::remeshing_seeding);
  seed_proxies(partition);
  stage.move_to(progress_shares::remeshing_seeding, 1.);
  if(settings.verbose)
    std::cerr << "  seeding: " << partition.proxies().size() << " proxies, error " << partition.total_error() << "\n";
  const std::size_t relaxations = (std::max<std::size_t>)(1, settings.number_of_relaxations);
  for(std::size_t i = 0; i < settings.number_of_iterations; ++i) {
    report_progress(i, settings.number_of_iterations);
    if(i > 0 && i % relaxations == 0) partition.teleport();
    partition.iterate();
  }
  if(settings.verbose)
    std::cerr << "  " << settings.number_of_iterations << " iterations: error " << partition.total_error() << "\n";
  if(partition.plane_count() > 0 && mirror_boundaries(partition) > 0) {
    reconnect_patches(partition);
    partition.fit();
  }
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PROXY_GENERATION_H
