// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_WORKING_MESH_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_WORKING_MESH_H

// The working mesh of symmetric remeshing: an indexed triangle soup in double precision with
// its faces that cross a plane of symmetry split there (thesis, Section 5.1.2, "Proxies Spanning
// Reflection Planes"), its halfedge adjacency, and per-face area, centroid and normal. The
// algorithm works on plain arrays for speed; the public layer converts from and to the user's
// mesh and kernel.

#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// A reflection n.x = offset, |n| = 1 (the Dplane of ISP), with the reflection of a direction.
inline Eigen::Vector3d reflect_vector(const Dplane& p, const Eigen::Vector3d& v)
{
  return v - 2. * p.normal.dot(v) * p.normal;
}

inline double signed_distance(const Dplane& p, const Eigen::Vector3d& x) { return p.normal.dot(x) - p.offset; }

struct Remeshing_mesh
{
  static constexpr std::size_t none = std::size_t(-1);

  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 3>> faces;
  std::vector<std::size_t> origin;   // per face: the index of the input face it comes from
  std::vector<std::size_t> opposite; // per halfedge 3f+i (faces[f][i] -> faces[f][i+1]): `none` on a border
  std::vector<std::size_t> vertex_face_begin, vertex_face; // the faces around each vertex (CSR)
  std::vector<double> area;
  std::vector<Eigen::Vector3d> centroid, normal;
  double average_edge_length = 0., diagonal = 0.;

  std::size_t number_of_faces() const { return faces.size(); }
  static std::size_t face_of(std::size_t h) { return h / 3; }
  static std::size_t next(std::size_t h) { return h - h % 3 + (h % 3 + 1) % 3; }
  static std::size_t prev(std::size_t h) { return h - h % 3 + (h % 3 + 2) % 3; }
  std::size_t source(std::size_t h) const { return faces[h / 3][h % 3]; }
  std::size_t target(std::size_t h) const { return faces[h / 3][(h % 3 + 1) % 3]; }
  // The face across halfedge h, or `none`.
  std::size_t neighbor(std::size_t h) const { return opposite[h] == none ? none : opposite[h] / 3; }

  // Adjacency and face geometry from `points` and `faces`. An edge shared by more than two faces
  // (non-manifold) is treated as a border of each.
  void build()
  {
    const std::size_t nh = 3 * faces.size();
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed(nh);
    auto key = [](std::size_t a, std::size_t b) { return (std::uint64_t(a) << 32) | std::uint64_t(b); };
    for(std::size_t h = 0; h < nh; ++h) keyed[h] = {key(source(h), target(h)), h};
    std::sort(keyed.begin(), keyed.end());
    auto range = [&](std::uint64_t k) {
      return std::equal_range(keyed.begin(), keyed.end(), std::make_pair(k, std::size_t(0)),
                              [](const auto& x, const auto& y) { return x.first < y.first; });
    };
    opposite.assign(nh, none);
    for(std::size_t h = 0; h < nh; ++h) {
      const auto same = range(key(source(h), target(h))), reverse = range(key(target(h), source(h)));
      if(same.second - same.first == 1 && reverse.second - reverse.first == 1) opposite[h] = reverse.first->second;
    }
    vertex_face_begin.assign(points.size() + 1, 0);
    for(const auto& f : faces)
      for(std::size_t v : f) ++vertex_face_begin[v + 1];
    for(std::size_t v = 0; v < points.size(); ++v) vertex_face_begin[v + 1] += vertex_face_begin[v];
    vertex_face.assign(vertex_face_begin.back(), 0);
    std::vector<std::size_t> fill(vertex_face_begin.begin(), vertex_face_begin.end() - 1);
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(std::size_t v : faces[f]) vertex_face[fill[v]++] = f;

    area.resize(faces.size());
    centroid.resize(faces.size());
    normal.resize(faces.size());
    double length = 0.;
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const Eigen::Vector3d &a = points[faces[f][0]], &b = points[faces[f][1]], &c = points[faces[f][2]];
      const Eigen::Vector3d cross = (b - a).cross(c - a);
      area[f] = 0.5 * cross.norm();
      centroid[f] = (a + b + c) / 3.;
      normal[f] = area[f] > 0. ? Eigen::Vector3d(cross / (2. * area[f])) : Eigen::Vector3d::Zero();
      length += (b - a).norm() + (c - b).norm() + (a - c).norm();
    }
    average_edge_length = length / double(3 * faces.size());
  }

  // Splits the faces that cross `plane` (vertices at distance at most `tolerance` count as on
  // it): a crossing edge gets a vertex on the plane, shared by its two faces, and a face with one
  // crossing edge becomes two triangles, one with two crossing edges three (the quadrilateral
  // side cut along its shorter diagonal). Orientation and `origin` are kept.
  void split_along(const Dplane& plane, double tolerance)
  {
    std::vector<double> side(points.size());
    for(std::size_t v = 0; v < points.size(); ++v) {
      const double s = signed_distance(plane, points[v]);
      side[v] = std::abs(s) <= tolerance ? 0. : s;
    }
    std::unordered_map<std::uint64_t, std::size_t> cut; // edge (smaller, larger index) -> its vertex on the plane
    auto cut_vertex = [&](std::size_t a, std::size_t b) {
      if(a > b) std::swap(a, b);
      const std::uint64_t k = (std::uint64_t(a) << 32) | std::uint64_t(b);
      const auto found = cut.find(k);
      if(found != cut.end()) return found->second;
      const double t = side[a] / (side[a] - side[b]);
      Eigen::Vector3d p = points[a] + t * (points[b] - points[a]);
      p -= signed_distance(plane, p) * plane.normal;
      points.push_back(p);
      side.push_back(0.);
      cut.emplace(k, points.size() - 1);
      return points.size() - 1;
    };
    auto crosses = [&](std::size_t a, std::size_t b) { return side[a] * side[b] < 0.; };
    std::vector<std::array<std::size_t, 3>> new_faces;
    std::vector<std::size_t> new_origin;
    new_faces.reserve(faces.size());
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const auto& t = faces[f];
      int count = 0;
      for(int i = 0; i < 3; ++i) count += crosses(t[i], t[(i + 1) % 3]) ? 1 : 0;
      auto emit = [&](std::size_t a, std::size_t b, std::size_t c) {
        new_faces.push_back({a, b, c});
        new_origin.push_back(origin[f]);
      };
      if(count == 0) {
        emit(t[0], t[1], t[2]);
      } else if(count == 1) { // a vertex on the plane, the opposite edge crossing it
        int i = 0;
        while(!crosses(t[(i + 1) % 3], t[(i + 2) % 3])) ++i;
        const std::size_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3], m = cut_vertex(b, c);
        emit(a, b, m);
        emit(a, m, c);
      } else { // vertex a alone on its side
        int i = 0;
        while(!(crosses(t[i], t[(i + 1) % 3]) && crosses(t[i], t[(i + 2) % 3]))) ++i;
        const std::size_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        const std::size_t mb = cut_vertex(a, b), mc = cut_vertex(a, c);
        emit(a, mb, mc);
        if((points[mb] - points[c]).squaredNorm() <= (points[b] - points[mc]).squaredNorm()) {
          emit(mb, b, c);
          emit(mb, c, mc);
        } else {
          emit(mb, b, mc);
          emit(b, c, mc);
        }
      }
    }
    faces.swap(new_faces);
    origin.swap(new_origin);
  }
};

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_WORKING_MESH_H
