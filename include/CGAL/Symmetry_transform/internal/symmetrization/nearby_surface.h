// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_NEARBY_SURFACE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_NEARBY_SURFACE_H

// The closest point of a mesh to a query near it, without a search tree of its triangles: among
// the faces around the vertex nearest to the query in the input (a Kd-tree built once), at the
// current positions of the vertices, which move a little at each step of the symmetrization.
// Exact when the closest point lies on those faces, as it does for the images of the points of a
// nearly symmetric surface; a tree of the moved triangles, rebuilt at every step, would cost
// several times the plane detection on a million faces.

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_tree.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The faces around each vertex: around[first[v] .. first[v + 1]).
struct Faces_around_vertices
{
  std::vector<std::size_t> first, around;

  Faces_around_vertices(const std::vector<std::array<std::size_t, 3>>& faces, std::size_t number_of_vertices)
    : first(number_of_vertices + 1, 0)
  {
    for(const auto& f : faces)
      for(std::size_t v : f) ++first[v + 1];
    for(std::size_t v = 0; v < number_of_vertices; ++v) first[v + 1] += first[v];
    around.resize(first.back());
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(std::size_t v : faces[f]) around[next[v]++] = f;
  }
};

class Nearby_surface
{
public:
  // `nearest` and `faces` must outlive the object.
  Nearby_surface(const Nearest_point& nearest, const std::vector<std::array<std::size_t, 3>>& faces,
                 std::size_t number_of_vertices)
    : nearest_(nearest), faces_(faces), rings_(faces, number_of_vertices)
  {}

  const Faces_around_vertices& rings() const { return rings_; }

  struct Closest
  {
    Eigen::Vector3d point;
    double squared_distance;
    std::size_t face; // the number of faces when the closest point is the vertex alone (no face around it)
  };

  // The closest point to q of the faces around the vertex nearest to q, at `points`, found from
  // `vertex`, the answer of a query nearby (the same point's image at the previous step): a walk
  // to ever nearer neighbours instead of a search in the Kd-tree (`unknown`: a search). `vertex`
  // becomes the vertex reached.
  Eigen::Vector3d closest(const Eigen::Vector3d& q, const std::vector<Eigen::Vector3d>& points,
                          std::size_t& vertex) const
  {
    vertex = vertex == unknown ? nearest_(q).index : nearer_neighbour(q, points, vertex);
    return closest_around(q, points, vertex).point;
  }

  // The closest point to q, and its face, searched from the vertex nearest to q.
  Closest closest_on_face(const Eigen::Vector3d& q, const std::vector<Eigen::Vector3d>& points) const
  {
    return closest_around(q, points, nearest_(q).index);
  }

  static constexpr std::size_t unknown = std::size_t(-1);

private:
  // From `vertex`, the neighbour nearest to q while it is nearer than the vertex itself.
  std::size_t nearer_neighbour(const Eigen::Vector3d& q, const std::vector<Eigen::Vector3d>& points,
                               std::size_t vertex) const
  {
    for(std::size_t best = vertex;; vertex = best) {
      for(std::size_t k = rings_.first[vertex]; k < rings_.first[vertex + 1]; ++k)
        for(std::size_t c : faces_[rings_.around[k]])
          if((q - points[c]).squaredNorm() < (q - points[best]).squaredNorm()) best = c;
      if(best == vertex) return vertex;
    }
  }

  // The closest point to q of the faces around `vertex`, then of those around the corners of the
  // face where it lies: a closest point on an edge of the first ring may lie across it.
  Closest closest_around(const Eigen::Vector3d& q, const std::vector<Eigen::Vector3d>& points, std::size_t vertex) const
  {
    Closest best{points[vertex], (q - points[vertex]).squaredNorm(), faces_.size()};
    improve_around(q, points, vertex, best);
    if(best.face == faces_.size()) return best;
    const std::array<std::size_t, 3> corners = faces_[best.face];
    for(std::size_t c : corners)
      if(c != vertex) improve_around(q, points, c, best);
    return best;
  }

  void improve_around(const Eigen::Vector3d& q, const std::vector<Eigen::Vector3d>& points, std::size_t vertex,
                      Closest& best) const
  {
    for(std::size_t k = rings_.first[vertex]; k < rings_.first[vertex + 1]; ++k) {
      const std::array<std::size_t, 3>& f = faces_[rings_.around[k]];
      const Eigen::Vector3d c = closest_point_on_triangle(q, points[f[0]], points[f[1]], points[f[2]]);
      const double d = (q - c).squaredNorm();
      if(d < best.squared_distance) best = {c, d, rings_.around[k]};
    }
  }

  const Nearest_point& nearest_;
  const std::vector<std::array<std::size_t, 3>>& faces_;
  Faces_around_vertices rings_;
};

// The neighbours of a point of a point set: for the smoothing of its displacement, and for the
// growth of the regions that the completion adds.
constexpr std::size_t point_neighbours = 8;

// Nearby_surface for a point set: the surface near a query is the tangent plane of the point
// nearest to it (the point itself where it has no normal).
class Nearby_points
{
public:
  // `nearest` and `normals` (unit, or empty, or zero where a point has none) must outlive the object.
  Nearby_points(const Nearest_point& nearest, const std::vector<Eigen::Vector3d>& normals)
    : nearest_(nearest), normals_(normals)
  {}

  // The projection of q onto the tangent plane of the point nearest to it (found among the points
  // where they were at the start: `points` are where they are now); `point` becomes that point.
  Eigen::Vector3d closest(const Eigen::Vector3d& q, const std::vector<Eigen::Vector3d>& points, std::size_t& point) const
  {
    point = nearest_(q).index;
    if(normals_.empty()) return points[point];
    const Eigen::Vector3d& n = normals_[point];
    return q - (q - points[point]).dot(n) * n;
  }

  static constexpr std::size_t unknown = std::size_t(-1);

private:
  const Nearest_point& nearest_;
  const std::vector<Eigen::Vector3d>& normals_;
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_NEARBY_SURFACE_H
