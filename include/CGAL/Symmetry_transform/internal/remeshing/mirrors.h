// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H

// Mirror images in the working mesh of symmetric remeshing: the face that mirrors each face
// through each plane (for the flooding), and the nearest mesh vertex to a point (for the mirror
// images of anchors), both by Kd-tree queries.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// A face has a mirror face through a plane if a face centroid lies within this fraction of the
// bounding-box diagonal of the mirror image of its centroid: twice the symmetry error of the
// least symmetric meshes of the comparison (bull, elephant: about 1e-2 where they are
// symmetric), so that an approximate symmetry still pairs faces, while the parts the plane
// does not map (a turned head) find none.
constexpr double mirror_face_distance = 0.02;

// Per face and plane, the face whose centroid lies nearest to the mirror image of its centroid
// (a Kd-tree query made once), or `none` if that is farther than `mirror_face_distance` (no
// symmetric counterpart) or the face itself. With `strongest_only`, a face keeps only the plane
// whose image lies closest.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::size_t> mirror_faces(const Remeshing_mesh& m, const std::vector<Dplane>& planes,
                                                                          bool strongest_only, unsigned threads);

// The working-mesh vertex nearest to a point (for the mirror images of anchors), or `none`
// where there is no plane (the Kd-tree is only built where mirror images are looked for).
class Nearest_vertex
{
public:
  Nearest_vertex(const Remeshing_mesh& m, const std::vector<Dplane>& planes);

  std::size_t operator()(const Eigen::Vector3d& p) const { return tree_ ? (*tree_)(p).index : Remeshing_mesh::none; }

private:
  std::optional<Nearest_point> tree_;
};

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::size_t> mirror_faces(const Remeshing_mesh& m, const std::vector<Dplane>& planes,
                                                                          bool strongest_only, unsigned threads)
{
  const double tolerance = mirror_face_distance * m.diagonal;
  const std::size_t nf = m.number_of_faces(), k = planes.size();
  std::vector<std::size_t> mirror(nf * k, Remeshing_mesh::none);
  if(k == 0) return mirror;
  const Nearest_point nearest(m.centroid);
  std::vector<double> distance(nf * k, 0.);
  parallel_for(nf, threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end && parallel_step(); ++f)
      for(std::size_t j = 0; j < k; ++j) {
        const auto [g, d2] = nearest(planes[j].reflect(m.centroid[f]));
        const double d = std::sqrt(d2);
        distance[f * k + j] = d;
        if(d <= tolerance && g != f) mirror[f * k + j] = g;
      }
  });
  if(strongest_only && k > 1)
    for(std::size_t f = 0; f < nf; ++f) {
      std::size_t best = Remeshing_mesh::none;
      for(std::size_t j = 0; j < k; ++j)
        if(mirror[f * k + j] != Remeshing_mesh::none && (best == Remeshing_mesh::none || distance[f * k + j] < distance[f * k + best]))
          best = j;
      for(std::size_t j = 0; j < k; ++j)
        if(j != best) mirror[f * k + j] = Remeshing_mesh::none;
    }
  return mirror;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Nearest_vertex::Nearest_vertex(const Remeshing_mesh& m, const std::vector<Dplane>& planes)
{
  if(!planes.empty()) tree_.emplace(m.points);
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H
