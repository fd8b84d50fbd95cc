// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_FACE_SUPPORT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_FACE_SUPPORT_H

// The support of a reflection on each face of a mesh (thesis, Figure 3.7): the mean Gaussian
// weight exp(-d^2 / 2 sigma^2) of the distances d from the reflected points of the face to the
// surface, at the points face_support_points() places on the face.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The points at which the support of a reflection on triangle abc is measured: its centroid and
// three interior points, each a third of the way from the centroid to a corner (symmetry_support(),
// and the segmentation's features).
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::array<Eigen::Vector3d, 4> face_support_points(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                                                       const Eigen::Vector3d& c);

// The support of the reflection through `mirror` and the area of `count` triangles, those of
// triangle f being corners(f) (three Eigen::Vector3d), from the exact closest points of
// `matcher`, computed in parallel (symmetry_support() of a mesh or of a soup).
template <typename Corners>
void triangle_supports(std::size_t count, const Corners& corners, const Triangle_matcher& matcher, const Dplane& mirror,
                       double sigma, unsigned threads, std::vector<double>& support, std::vector<double>& area)
{
  support.resize(count);
  area.resize(count);
  parallel_for(count, threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f) {
      const std::array<Eigen::Vector3d, 3> v = corners(f);
      const Eigen::Vector3d &a = v[0], &b = v[1], &c = v[2];
      area[f] = 0.5 * (b - a).cross(c - a).norm();
      const std::array<Eigen::Vector3d, 4> points = face_support_points(a, b, c);
      double sum = 0.;
      for(const Eigen::Vector3d& p : points) {
        const Eigen::Vector3d image = mirror.reflect(p);
        sum += std::exp(-(image - matcher.closest(image).first).squaredNorm() / (2. * sigma * sigma));
      }
      support[f] = sum / double(points.size());
      if(!parallel_step()) return;
    }
  });
}

// The same for each face of a mesh.
template <typename TriangleMesh>
struct Face_supports
{
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> faces;
  std::vector<double> support, area;
};

template <typename TriangleMesh, typename VertexPointMap>
Face_supports<TriangleMesh> face_supports(const TriangleMesh& tm, const VertexPointMap& vpm,
                                                          const Triangle_matcher& matcher, const Dplane& mirror,
                                                          double sigma, unsigned threads)
{
  Face_supports<TriangleMesh> result;
  result.faces.assign(faces(tm).begin(), faces(tm).end());
  auto corners = [&](std::size_t f) {
    const auto h = halfedge(result.faces[f], tm);
    return std::array<Eigen::Vector3d, 3>{to_eigen(to_dpoint(get(vpm, source(h, tm)))),
                                          to_eigen(to_dpoint(get(vpm, target(h, tm)))),
                                          to_eigen(to_dpoint(get(vpm, target(next(h, tm), tm))))};
  };
  triangle_supports(result.faces.size(), corners, matcher, mirror, sigma, threads, result.support, result.area);
  return result;
}

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::array<Eigen::Vector3d, 4> face_support_points(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                                                       const Eigen::Vector3d& c)
{
  return {Eigen::Vector3d((a + b + c) / 3.), Eigen::Vector3d((4. * a + b + c) / 6.),
          Eigen::Vector3d((a + 4. * b + c) / 6.), Eigen::Vector3d((a + b + 4. * c) / 6.)};
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_FACE_SUPPORT_H
