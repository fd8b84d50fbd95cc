// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PROGRESS_SHARES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PROGRESS_SHARES_H

// The shares of their stages in the progress that the long functions report (progress.h), so
// that the values passed to the callback grow roughly in proportion to the time spent. Measured
// with the defaults (grid 64, 2 threads) on the meshes of test_progress_callback and on
// libcgal-demo meshes of 10K to 1M faces (benchmark/Symmetry_transform/RESULTS.md, "Progress and
// cancellation"); the proportions vary with the mesh, a bar needs no more.

#include <algorithm>
#include <cstddef>

namespace CGAL::Symmetry_transform::internal {
namespace progress_shares {

// The GEDT of triangles: its AABB tree until gedt_tree (unless the caller gives it one), then
// the voxels of the band marked until gedt_band of the rest, then the Gaussian of the distances
// in the band. The GEDT of points: the band until gedt_band_of_points, then the distances (a
// Kd-tree, then a search per voxel). The surface of a detection (Triangle_surface): the AABB
// tree, which the GEDT and ISP share, until surface_tree, then the GEDT.
constexpr double gedt_tree = 0.2, gedt_band = 0.3, gedt_band_of_points = 0.2, surface_tree = 0.2;

// A detection: the surface (GEDT, trees) or the GEDT of points, then the transform, then the
// refinements of the candidates. The surface costs in proportion to the faces, the rest does
// not: its share is F / (F + detection_faces_at_half_share) for F faces (or points), at least
// min_detection_surface (the grid: 0.1 on bull.off, 12K faces; 0.67 on 1.2M faces).
constexpr double detection_faces_at_half_share = 250000., min_detection_surface = 0.1;
inline double detection_surface_share(std::size_t faces)
{
  return (std::max)(min_detection_surface, double(faces) / (double(faces) + detection_faces_at_half_share));
}
// Of what follows the surface: the transform (500K Monte Carlo pairs), the rest refinements. A
// transform computed from a mesh: the GEDT, then the transform itself (2M pairs by default).
constexpr double detection_transform = 0.25, transform_gedt = 0.3;

// Symmetric remeshing: the working mesh split along the planes and the mirror faces until
// remeshing_preparation, then the partition (the seeding, which runs iterations of its own, for
// remeshing_seeding of it, then the iterations), then the extraction of the mesh from
// remeshing_extraction.
constexpr double remeshing_preparation = 0.35, remeshing_extraction = 0.97, remeshing_seeding = 0.3;

// Segmentation: the dual graph and the connected components, then the levels of splits. Each
// level has segmentation_level_share of what the level above leaves (the rest goes to the deeper
// levels): deeper segments are smaller and their grids coarser.
constexpr double segmentation_preparation = 0.05, segmentation_level_share = 0.5;

} // namespace progress_shares
} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PROGRESS_SHARES_H
