// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MESH_EXTRACTION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MESH_EXTRACTION_H

// The output mesh of symmetric remeshing from the patches (thesis, Section 5.1.2, "Point
// Correspondences" and "Triangulation"), in the steps of CGAL's VSA (extract_mesh): anchors and
// chords (anchors_and_chords.h), triangles (patch_triangulation.h), anchor positions snapped to
// mirror positions (anchor_positions.h), then the holes left by removed folds filled
// (hole_filling.h).

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/remeshing/anchor_positions.h>
#include <CGAL/Symmetry_transform/internal/remeshing/anchors_and_chords.h>
#include <CGAL/Symmetry_transform/internal/remeshing/hole_filling.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirrors.h>
#include <CGAL/Symmetry_transform/internal/remeshing/patch_triangulation.h>
#include <CGAL/Symmetry_transform/internal/remeshing/settings.h>

#include <array>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

struct Remeshing_output
{
  std::vector<std::size_t> anchor_vertices; // working-mesh vertex of each anchor (`none` for none)
  std::vector<Eigen::Vector3d> anchors;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::size_t matched_anchors = 0; // anchors moved to an exact mirror position
};

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Remeshing_output extract_mesh(const Symmetric_partition& partition, const Meshing_settings& settings);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Remeshing_output extract_mesh(const Symmetric_partition& partition, const Meshing_settings& settings)
{
  const Remeshing_mesh& mesh = partition.mesh();
  const std::vector<Dplane>& planes = partition.settings().planes;
  const Nearest_vertex nearest_vertex(mesh, planes);
  report_progress(0.2); // the steps take tenths of a second on a million faces (progress.h)
  const Patch_boundaries boundaries(partition);
  Anchor_set anchors(mesh.points.size());
  report_progress(0.3);
  const std::vector<std::size_t> cycles = Boundary_anchors(boundaries, planes, anchors).find(settings, nearest_vertex);
  report_progress(0.5);
  Remeshing_output out;
  out.triangles = Patch_triangulation(boundaries, anchors).triangles(cycles);
  out.anchor_vertices = anchors.vertices;
  report_progress(0.7);
  out.anchors = anchor_positions(partition, out.anchor_vertices, settings.optimize_anchor_location);
  out.matched_anchors = snap_to_mirror_positions(boundaries, planes, out.anchor_vertices, out.anchors);
  report_progress(0.8);
  Hole_filling(mesh, nearest_vertex, out.anchor_vertices, out.anchors, out.triangles).run();
  return out;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MESH_EXTRACTION_H
