// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_ANCHOR_POSITIONS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_ANCHOR_POSITIONS_H

// Where the anchors of the output mesh go: the mean of their projections onto the planes of
// their patches (CGAL's VSA, optimize_anchor_location), then, for symmetry (thesis, Section
// 5.1.2, "Point Correspondences"), anchors matched across each plane (same proxies around,
// mutually nearest mirror images) moved to exact mirror positions, and those matched to
// themselves onto the plane.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/remeshing/anchors_and_chords.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Two anchors are matched across a plane if the mirror image of one lies within this many mean
// edge lengths of the other (and each is the nearest to the image of the other).
constexpr double mirror_match_distance = 2.;

// Rounds of alternating projections onto the mirror constraints of the planes: one is exact for
// a single plane; with anchors matched through several planes the projections converge, and a
// fixed count keeps the result independent of a convergence test.
constexpr int mirror_snapping_rounds = 8;

// The position of each anchor (a working-mesh vertex): the mean of its projections onto the
// planes of the patches around it, weighted by their areas, if `optimize`, else the vertex.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Eigen::Vector3d> anchor_positions(const Symmetric_partition& partition,
                                                                                  const std::vector<std::size_t>& anchor_vertices, bool optimize);

typedef std::vector<std::pair<std::size_t, std::size_t>> Anchor_pairs;

// Per plane, the pairs (a, b), a <= b, of anchors with the same proxies around whose mirror
// images (of their working-mesh vertices) are mutually nearest, within `mirror_match_distance`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Anchor_pairs> mirror_anchor_pairs(const Patch_boundaries& boundaries, const std::vector<Dplane>& planes,
                                                                                  const std::vector<std::size_t>& anchor_vertices);

// Moves the anchors of each pair to exact mirror positions (an anchor paired with itself onto
// the plane) by alternating projections; returns the number of anchors in a pair.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t snap_to_mirror_positions(const Patch_boundaries& boundaries, const std::vector<Dplane>& planes,
                                                                         const std::vector<std::size_t>& anchor_vertices,
                                                                         std::vector<Eigen::Vector3d>& positions);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Eigen::Vector3d> anchor_positions(const Symmetric_partition& partition,
                                                                                  const std::vector<std::size_t>& anchor_vertices, bool optimize)
{
  const Remeshing_mesh& mesh = partition.mesh();
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::size_t> labels;
  for(std::size_t v : anchor_vertices) {
    const Eigen::Vector3d& x = mesh.points[v];
    labels.clear();
    for(std::size_t i = mesh.vertex_face_begin[v]; i < mesh.vertex_face_begin[v + 1]; ++i)
      labels.push_back(partition.labels()[mesh.vertex_face[i]]);
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double weight = 0.;
    for(std::size_t l : labels) {
      const Eigen::Vector3d& n = partition.patch_normal(l);
      const double w = partition.patch_area(l);
      sum += w * (x - n.dot(x - partition.patch_center(l)) * n);
      weight += w;
    }
    positions.push_back(optimize && weight > 0. ? Eigen::Vector3d(sum / weight) : x);
  }
  return positions;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Anchor_pairs> mirror_anchor_pairs(const Patch_boundaries& boundaries, const std::vector<Dplane>& planes,
                                                                                  const std::vector<std::size_t>& anchor_vertices)
{
  const Remeshing_mesh& mesh = boundaries.mesh();
  const std::size_t na = anchor_vertices.size();
  std::map<std::vector<std::size_t>, std::vector<std::size_t>> by_proxies;
  std::vector<std::vector<std::size_t>> proxies(na);
  for(std::size_t a = 0; a < na; ++a) {
    boundaries.boundary_count(anchor_vertices[a], &proxies[a]);
    by_proxies[proxies[a]].push_back(a);
  }
  const double tolerance = mirror_match_distance * mesh.average_edge_length;
  std::vector<Anchor_pairs> pairs(planes.size());
  for(std::size_t j = 0; j < planes.size(); ++j) {
    auto nearest = [&](std::size_t a) {
      const Eigen::Vector3d image = planes[j].reflect(mesh.points[anchor_vertices[a]]);
      std::size_t best = Remeshing_mesh::none;
      double d = tolerance;
      for(std::size_t b : by_proxies[proxies[a]]) {
        const double e = (mesh.points[anchor_vertices[b]] - image).norm();
        if(e <= d) { d = e; best = b; }
      }
      return best;
    };
    for(std::size_t a = 0; a < na; ++a) {
      const std::size_t b = nearest(a);
      if(b != Remeshing_mesh::none && b >= a && nearest(b) == a) pairs[j].push_back({a, b});
    }
  }
  return pairs;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t snap_to_mirror_positions(const Patch_boundaries& boundaries, const std::vector<Dplane>& planes,
                                                                         const std::vector<std::size_t>& anchor_vertices,
                                                                         std::vector<Eigen::Vector3d>& positions)
{
  if(planes.empty() || anchor_vertices.empty()) return 0;
  const std::vector<Anchor_pairs> pairs = mirror_anchor_pairs(boundaries, planes, anchor_vertices);
  for(int round = 0; round < mirror_snapping_rounds; ++round)
    for(std::size_t j = 0; j < planes.size(); ++j)
      for(const auto& [a, b] : pairs[j]) {
        const Dplane& plane = planes[j];
        if(a == b) {
          positions[a] -= plane.signed_distance(positions[a]) * plane.normal;
        } else {
          const Eigen::Vector3d mean = 0.5 * (positions[a] + plane.reflect(positions[b]));
          positions[a] = mean;
          positions[b] = plane.reflect(mean);
        }
      }
  std::vector<char> matched(anchor_vertices.size(), 0);
  for(const Anchor_pairs& plane_pairs : pairs)
    for(const auto& [a, b] : plane_pairs) matched[a] = matched[b] = 1;
  return std::size_t(std::count(matched.begin(), matched.end(), 1));
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_ANCHOR_POSITIONS_H
