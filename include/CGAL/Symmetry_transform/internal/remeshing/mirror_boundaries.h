// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRROR_BOUNDARIES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRROR_BOUNDARIES_H

// Mirror-consistent patch boundaries, after the last Lloyd iteration: the flooding order decides
// where a boundary runs on each side of a plane, so on a nearly symmetric mesh the two sides'
// boundaries, and the junctions where the output's anchors go, still differ by a face here and
// there. A face on the negative side of a plane then takes the mirror of its mirror face's
// patch, if it lies next to that patch and fits it about as well as its own (the flooding's
// rule); a patch cut in pieces by this keeps its largest piece and gives the others to
// neighbouring patches.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>

#include <cstdint>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The faces are relabelled in sweeps over the mesh until none changes, at most this many per
// plane: a change can enable another next to it, hence the repeated sweeps; the bound stops
// faces that would keep changing patches.
constexpr std::size_t max_boundary_sweeps = 10;

// Faces of the negative side of each plane relabelled after their mirror faces; returns how
// many changed. A face does not join a patch across the plane, as in the flooding.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t mirror_boundaries(Symmetric_partition& partition);

// Each patch connected: the faces of all but its largest piece join neighbouring patches.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void reconnect_patches(Symmetric_partition& partition);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t mirror_boundaries(Symmetric_partition& partition)
{
  const Remeshing_mesh& mesh = partition.mesh();
  const std::vector<std::size_t>& label = partition.labels();
  const std::size_t transforms = partition.transforms();
  std::size_t changed = 0;
  for(std::size_t j = 0; j < partition.plane_count(); ++j)
    for(std::size_t sweep = 0, before = ~std::size_t(0); sweep < max_boundary_sweeps && changed != before; ++sweep) {
      before = changed;
      for(std::size_t f = 0; f < mesh.number_of_faces(); ++f) {
        const std::size_t mf = partition.mirror_face(f, j);
        if(mf == Symmetric_partition::none || partition.settings().planes[j].signed_distance(mesh.centroid[f]) >= 0.)
          continue;
        const std::size_t ml = label[mf], i = ml % transforms;
        if(i != 0 && i != j + 1) continue;
        const std::size_t target = ml - i + (i == 0 ? j + 1 : 0);
        if(label[f] == target || partition.is_closed(target) || !partition.next_to(f, target, std::uint64_t(1) << j) ||
           !partition.fits_about_as_well(f, partition.error(f, target), partition.error(f, label[f])))
          continue;
        partition.relabel(f, target);
        ++changed;
      }
    }
  return changed;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void reconnect_patches(Symmetric_partition& partition)
{
  const Remeshing_mesh& mesh = partition.mesh();
  const std::vector<std::size_t>& label = partition.labels();
  std::vector<double> piece_area;
  const std::vector<std::size_t> piece = mesh.connected_pieces(
    [&label](std::size_t f, std::size_t g) { return label[g] == label[f]; },
    [&](std::size_t f, std::size_t p) {
      if(p == piece_area.size()) piece_area.push_back(0.);
      piece_area[p] += mesh.area[f];
    });
  std::vector<std::size_t> largest(partition.proxies().size() * partition.transforms(), Symmetric_partition::none);
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f) {
    std::size_t& l = largest[label[f]];
    if(l == Symmetric_partition::none || piece_area[piece[f]] > piece_area[l]) l = piece[f];
  }
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
    if(piece[f] != largest[label[f]]) partition.relabel(f, Symmetric_partition::none);
  partition.join_neighbouring_patches();
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRROR_BOUNDARIES_H
