// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H

// Mirror images in the working mesh of symmetric remeshing: the face that mirrors each face
// through each plane (for the flooding), and the nearest mesh vertex to a point (for the mirror
// images of anchors), both by Kd-tree queries.

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>


#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// Per face and plane, the face whose centroid lies nearest to the mirror image of its centroid
// (a Kd-tree query made once), or `none` if that is farther than `tolerance` (no symmetric
// counterpart) or the face itself. With `strongest_only`, a face keeps only the plane whose
// image lies closest.
inline std::vector<std::size_t> mirror_faces(const Remeshing_mesh& m, const std::vector<Dplane>& planes,
                                             double tolerance, bool strongest_only, unsigned threads)
{
  const std::size_t nf = m.number_of_faces(), k = planes.size();
  std::vector<std::size_t> mirror(nf * k, Remeshing_mesh::none);
  if(k == 0) return mirror;
  const Nearest_point nearest(m.centroid);
  std::vector<double> distance(nf * k, 0.);
  parallel_for(nf, threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
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

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_MIRRORS_H
