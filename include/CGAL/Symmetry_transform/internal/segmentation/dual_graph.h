// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_DUAL_GRAPH_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_DUAL_GRAPH_H

// The faces of a mesh as indices 0..n-1 (those of its face index map), their geometry in double
// precision, and the dual graph of the segmentation: one edge per pair of faces sharing a mesh
// edge, with its length and the Katz-Tal angular distance of the two faces. Connected parts of
// sets of faces, and the triangles of a set of faces (what a segment's detection reads).

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <iterator>
#include <numeric>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Katz and Tal weigh convex creases less than concave ones: a part boundary tends to run along
// a concave crease. Here convex creases do not count at all: the cost of a normalised angular
// distance makes any crease much cheaper than the smooth surface around it, and the convex edges
// of a box would become cheap cuts between its faces.
constexpr double convex_crease_factor = 0.;

struct Dual_edge
{
  std::size_t first, second; // the two faces
  double length;             // of the mesh edge they share
  double angular_distance;   // eta (1 - cos alpha), alpha the angle of the normals, eta 1 if concave, 0 if convex
};

// The dual edges of one triangle: at most one per side, stored in place (a vector per face would
// be a million small allocations on a million-face mesh).
class Face_dual_edges
{
public:
  void push_back(std::size_t e);
  const std::size_t* begin() const { return edges_.data(); }
  const std::size_t* end() const { return edges_.data() + size_; }

private:
  std::array<std::size_t, 3> edges_;
  std::uint8_t size_ = 0;
};

struct Segmentation_mesh
{
  std::vector<std::array<Eigen::Vector3d, 3>> triangles; // every face, degenerate ones included
  std::vector<double> areas;
  std::vector<Dual_edge> edges;
  std::vector<Face_dual_edges> face_edges; // the dual edges of each face
  std::vector<double> face_features; // the user's feature of each face (face_feature.h), or empty

  std::size_t number_of_faces() const { return triangles.size(); }
};

inline Eigen::Vector3d unit_normal_of(const std::array<Eigen::Vector3d, 3>& t)
{
  const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]);
  const double l = n.norm();
  return l > 0. ? Eigen::Vector3d(n / l) : Eigen::Vector3d::Zero();
}

// Adds the dual edges of the mesh, one per pair of faces sharing an edge, in the order of faces(tm)
// and of their halfedges.
template <typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap>
void add_dual_edges(const TriangleMesh& tm, const VertexPointMap& vpm, const FaceIndexMap& face_index,
                    Segmentation_mesh& mesh)
{
  auto point = [&](typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) { return to_eigen(to_dpoint(get(vpm, v))); };
  for(auto f : faces(tm)) {
    const std::size_t i = std::size_t(get(face_index, f));
    if(i % sequential_items_per_report == 0) poll_progress(); // (progress.h)
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
      const std::size_t j = std::size_t(get(face_index, g));
      if(j <= i) continue; // each pair once (j == i cannot happen in a valid halfedge graph)
      const Eigen::Vector3d a = point(source(h, tm)), b = point(target(h, tm));
      const Eigen::Vector3d d = point(target(next(opposite(h, tm), tm), tm));
      const Eigen::Vector3d n1 = unit_normal_of(mesh.triangles[i]), n2 = unit_normal_of(mesh.triangles[j]);
      // Concave when the far vertex of the second face lies above the first face's plane.
      const bool concave = n1.dot(d - a) > 0.;
      const double distance = (concave ? 1. : convex_crease_factor) * (std::max)(0., 1. - n1.dot(n2));
      mesh.face_edges[i].push_back(mesh.edges.size());
      mesh.face_edges[j].push_back(mesh.edges.size());
      mesh.edges.push_back({i, j, (b - a).norm(), distance});
    }
  }
}

inline double area_of(const std::array<Eigen::Vector3d, 3>& t) { return 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm(); }

template <typename TriangleMesh>
std::size_t number_of_faces(const TriangleMesh& tm)
{
  return std::size_t(std::distance(faces(tm).begin(), faces(tm).end()));
}

// Whether `face_index` numbers the faces 0 to n - 1, each once: CGAL's initialized index maps do,
// except on a Surface_mesh with removed faces not yet collected (its indices then have gaps).
template <typename TriangleMesh, typename FaceIndexMap>
bool numbers_the_faces(const TriangleMesh& tm, const FaceIndexMap& face_index)
{
  std::vector<bool> seen(number_of_faces(tm), false);
  for(auto f : faces(tm)) {
    const std::size_t i = std::size_t(get(face_index, f));
    if(i >= seen.size() || seen[i]) return false;
    seen[i] = true;
  }
  return true;
}

// The faces numbered in the order of faces(tm), in a dynamic property map of the mesh.
template <typename TriangleMesh>
auto face_index_in_order(const TriangleMesh& tm)
{
  auto face_index = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  std::size_t i = 0;
  for(auto f : faces(tm)) put(face_index, f, i++);
  return face_index;
}

// Reads the mesh, its faces numbered 0 to n - 1 by `face_index` (the checks of
// triangles_of_mesh() having been done by the caller).
template <typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap>
Segmentation_mesh segmentation_mesh(const TriangleMesh& tm, const VertexPointMap& vpm, const FaceIndexMap& face_index)
{
  Segmentation_mesh mesh;
  const std::size_t n = number_of_faces(tm);
  mesh.triangles.resize(n);
  mesh.areas.resize(n);
  mesh.face_edges.resize(n);
  for(auto f : faces(tm)) {
    const std::size_t i = std::size_t(get(face_index, f));
    const Dtriangle t = triangle_of_face(halfedge(f, tm), tm, vpm);
    mesh.triangles[i] = {to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2])};
    mesh.areas[i] = area_of(mesh.triangles[i]);
    if(i % sequential_items_per_report == 0) poll_progress(); // a million faces take half a second
  }
  poll_progress();
  add_dual_edges(tm, vpm, face_index, mesh);
  poll_progress();
  return mesh;
}

inline std::size_t other_face(const Dual_edge& e, std::size_t f) { return e.first == f ? e.second : e.first; }

// The connected parts of the faces whose `region` value is the same (regions given for the faces
// of `faces` only, through `local`, the position of a face in `faces` or -1): each part as a list
// of faces, in increasing order of their first face in `faces`.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> connected_parts(const Segmentation_mesh& mesh,
                                                                                          const std::vector<std::size_t>& faces,
                                                                                          const std::vector<std::size_t>& local,
                                                                                          const std::vector<std::size_t>& region);

// Merges each part smaller than `min_area`, smallest first, into the neighbouring part with which
// it shares the longest boundary; a part with no neighbour (a component of the mesh of its own)
// stays. The result is in the order of the parts' first faces.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> merge_small_parts(const Segmentation_mesh& mesh,
                                                                                            std::vector<std::vector<std::size_t>> parts,
                                                                                            double min_area);

// The triangles of the faces, degenerate faces left out: a subset of a mesh's faces can meet at a
// vertex in ways a halfedge mesh rejects, and the detection only reads triangles.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Dtriangle> triangles_of_faces(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces);

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> connected_parts(const Segmentation_mesh& mesh,
                                                                                          const std::vector<std::size_t>& faces,
                                                                                          const std::vector<std::size_t>& local,
                                                                                          const std::vector<std::size_t>& region)
{
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> part(faces.size(), none);
  std::vector<std::vector<std::size_t>> parts;
  std::vector<std::size_t> stack;
  for(std::size_t start = 0; start < faces.size(); ++start) {
    if(part[start] != none) continue;
    parts.emplace_back();
    part[start] = parts.size() - 1;
    stack.push_back(start);
    while(!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      parts.back().push_back(faces[i]);
      for(std::size_t e : mesh.face_edges[faces[i]]) {
        const std::size_t j = local[other_face(mesh.edges[e], faces[i])];
        if(j == none || part[j] != none || region[j] != region[i]) continue;
        part[j] = parts.size() - 1;
        stack.push_back(j);
      }
    }
  }
  for(auto& p : parts) std::sort(p.begin(), p.end());
  return parts;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::vector<std::size_t>> merge_small_parts(const Segmentation_mesh& mesh,
                                                                                            std::vector<std::vector<std::size_t>> parts,
                                                                                            double min_area)
{
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> part_of(mesh.number_of_faces(), none);
  std::vector<double> area(parts.size(), 0.);
  for(std::size_t p = 0; p < parts.size(); ++p)
    for(std::size_t f : parts[p]) {
      part_of[f] = p;
      area[p] += mesh.areas[f];
    }
  std::vector<std::size_t> order(parts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return area[a] < area[b]; });
  for(std::size_t p : order) {
    if(!(area[p] < min_area)) continue;
    std::map<std::size_t, double> shared; // neighbouring part -> length of the common boundary
    for(std::size_t f : parts[p])
      for(std::size_t e : mesh.face_edges[f]) {
        const std::size_t q = part_of[other_face(mesh.edges[e], f)];
        if(q != none && q != p) shared[q] += mesh.edges[e].length;
      }
    if(shared.empty()) continue;
    const std::size_t target =
      std::max_element(shared.begin(), shared.end(), [](const auto& x, const auto& y) { return x.second < y.second; })->first;
    for(std::size_t f : parts[p]) part_of[f] = target;
    parts[target].insert(parts[target].end(), parts[p].begin(), parts[p].end());
    area[target] += area[p];
    parts[p].clear();
  }
  parts.erase(std::remove_if(parts.begin(), parts.end(), [](const auto& x) { return x.empty(); }), parts.end());
  for(auto& x : parts) std::sort(x.begin(), x.end());
  std::sort(parts.begin(), parts.end(), [](const auto& x, const auto& y) { return x.front() < y.front(); });
  return parts;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Dtriangle> triangles_of_faces(const Segmentation_mesh& mesh, const std::vector<std::size_t>& faces)
{
  std::vector<Dtriangle> triangles;
  triangles.reserve(faces.size());
  auto point = [](const Eigen::Vector3d& p) { return Dpoint(p.x(), p.y(), p.z()); };
  for(std::size_t f : faces) {
    const auto& t = mesh.triangles[f];
    if(mesh.areas[f] > 0.) triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  }
  return triangles;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Face_dual_edges::push_back(std::size_t e)
{
  CGAL_assertion(size_ < 3); // each entry is one of the triangle's halfedges
  edges_[size_++] = e;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SEGMENTATION_DUAL_GRAPH_H
