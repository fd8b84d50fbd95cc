// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PATCH_TRIANGULATION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PATCH_TRIANGULATION_H

// The triangles of the output mesh (thesis, Section 5.1.2, "Triangulation"), as CGAL's VSA
// (pseudo_cdt): each patch flooded by multi-source Dijkstra from its anchors, each vertex taking
// the tag of its nearest anchor, and each chord vertex that of the nearer chord end; a face whose
// three vertices have three tags gives a triangle. Of triangles with the same directed edge
// (folded onto each other), the largest is kept.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/remeshing/anchors_and_chords.h>

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

class Patch_triangulation
{
  static constexpr std::size_t none = Remeshing_mesh::none;

public:
  typedef std::array<std::size_t, 3> Triangle;

  Patch_triangulation(const Patch_boundaries& boundaries, const Anchor_set& anchors)
    : boundaries_(boundaries), mesh_(boundaries.mesh()), label_(boundaries.partition().labels()), anchors_(anchors)
  {}

  // The triangles, as indices of anchors; `cycles` has a halfedge of each boundary cycle,
  // ending at an anchor (Boundary_anchors::find()).
  std::vector<Triangle> triangles(const std::vector<std::size_t>& cycles);

private:
  typedef std::pair<double, std::size_t> Entry;

  // Each vertex of each patch, the tag of the anchor nearest along the patch's edges.
  void tag_by_nearest_anchor();

  // The vertex v of patch l at the start of its flooding: at distance 0 if it is an anchor.
  void start_at(std::size_t v, std::size_t l);

  // Dijkstra over the edges of the faces of patch l.
  void flood_patch(std::size_t l);

  // Chord vertices: the tag of the nearer chord end along the chord.
  void tag_chord_vertices(const std::vector<std::size_t>& cycles);

  // A triangle per face whose vertices have three tags, each set of three tags once.
  std::vector<Triangle> triangles_of_tags() const;

  // Two triangles with the same directed edge overlap (one folds onto the other) and make the
  // edge and its ends non-manifold: of each such set, only the largest triangle (area between the
  // anchors' mesh vertices) is kept. The folds are slivers; removing the smaller ones keeps the
  // surface covered best.
  void remove_folded_triangles(std::vector<Triangle>& t) const;

  const Patch_boundaries& boundaries_;
  const Remeshing_mesh& mesh_;
  const std::vector<std::size_t>& label_;
  const Anchor_set& anchors_;
  std::vector<std::size_t> tag_;   // per vertex: the anchor whose region it is in
  std::vector<double> distance_;   // per vertex: to its anchor, in the flooding of its patch
  std::vector<std::size_t> stamp_; // per vertex: the last patch whose flooding reached it
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
};

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Patch_triangulation::Triangle> Patch_triangulation::triangles(const std::vector<std::size_t>& cycles)
{
  tag_.assign(mesh_.points.size(), none);
  for(std::size_t a = 0; a < anchors_.vertices.size(); ++a) tag_[anchors_.vertices[a]] = a;
  tag_by_nearest_anchor();
  tag_chord_vertices(cycles);
  std::vector<Triangle> result = triangles_of_tags();
  remove_folded_triangles(result);
  return result;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Patch_triangulation::tag_by_nearest_anchor()
{
  const std::size_t nf = mesh_.number_of_faces();
  // Faces of each patch.
  std::vector<std::size_t> begin(label_.empty() ? 1 : *std::max_element(label_.begin(), label_.end()) + 2, 0);
  for(std::size_t f = 0; f < nf; ++f) ++begin[label_[f] + 1];
  for(std::size_t l = 0; l + 1 < begin.size(); ++l) begin[l + 1] += begin[l];
  std::vector<std::size_t> faces_of(nf), fill(begin.begin(), begin.end() - 1);
  for(std::size_t f = 0; f < nf; ++f) faces_of[fill[label_[f]]++] = f;
  distance_.assign(mesh_.points.size(), 0.);
  stamp_.assign(mesh_.points.size(), none);
  for(std::size_t l = 0; l + 1 < begin.size(); ++l) {
    if(begin[l] == begin[l + 1]) continue;
    for(std::size_t i = begin[l]; i < begin[l + 1]; ++i)
      for(std::size_t v : mesh_.faces[faces_of[i]]) start_at(v, l);
    flood_patch(l);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Patch_triangulation::start_at(std::size_t v, std::size_t l)
{
  if(stamp_[v] == l) return;
  stamp_[v] = l;
  distance_[v] = std::numeric_limits<double>::infinity();
  if(anchors_.contains(v)) {
    distance_[v] = 0.;
    tag_[v] = anchors_.of_vertex[v];
    queue_.push({0., v});
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Patch_triangulation::flood_patch(std::size_t l)
{
  while(!queue_.empty()) {
    const auto [d, v] = queue_.top();
    queue_.pop();
    if(d > distance_[v]) continue;
    for(std::size_t i = mesh_.vertex_face_begin[v]; i < mesh_.vertex_face_begin[v + 1]; ++i) {
      const std::size_t f = mesh_.vertex_face[i];
      if(label_[f] != l) continue;
      for(std::size_t w : mesh_.faces[f]) {
        if(w == v) continue;
        const double dw = d + (mesh_.points[w] - mesh_.points[v]).norm();
        if(dw < distance_[w]) {
          distance_[w] = dw;
          tag_[w] = tag_[v];
          queue_.push({dw, w});
        }
      }
    }
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Patch_triangulation::tag_chord_vertices(const std::vector<std::size_t>& cycles)
{
  for(std::size_t head : cycles) {
    std::size_t h = head;
    do {
      const std::vector<std::size_t> chord = boundaries_.walk_chord(h, anchors_);
      std::vector<double> along(1, 0.);
      for(std::size_t c : chord)
        along.push_back(along.back() + (mesh_.points[mesh_.target(c)] - mesh_.points[mesh_.source(c)]).norm());
      const std::size_t left = anchors_.of_vertex[mesh_.source(chord.front())],
                        right = anchors_.of_vertex[mesh_.target(chord.back())];
      for(std::size_t i = 0; i + 1 < chord.size(); ++i)
        tag_[mesh_.target(chord[i])] = along[i + 1] < along.back() / 2. ? left : right;
    } while(h != head);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Patch_triangulation::Triangle> Patch_triangulation::triangles_of_tags() const
{
  std::vector<Triangle> result;
  std::set<Triangle> seen;
  for(std::size_t f = 0; f < mesh_.number_of_faces(); ++f) {
    const std::size_t i = tag_[mesh_.faces[f][0]], j = tag_[mesh_.faces[f][1]], k = tag_[mesh_.faces[f][2]];
    if(i == none || j == none || k == none || i == j || j == k || i == k) continue;
    Triangle key = {i, j, k};
    std::sort(key.begin(), key.end());
    if(seen.insert(key).second) result.push_back({i, j, k});
  }
  return result;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Patch_triangulation::remove_folded_triangles(std::vector<Triangle>& t) const
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  std::map<Edge, std::vector<std::size_t>> directed;
  for(std::size_t i = 0; i < t.size(); ++i)
    for(int c = 0; c < 3; ++c) directed[Edge(t[i][c], t[i][(c + 1) % 3])].push_back(i);
  auto area = [&](std::size_t i) {
    const Eigen::Vector3d &a = mesh_.points[anchors_.vertices[t[i][0]]], &b = mesh_.points[anchors_.vertices[t[i][1]]],
                          &c = mesh_.points[anchors_.vertices[t[i][2]]];
    return (b - a).cross(c - a).norm();
  };
  std::vector<char> removed(t.size(), 0);
  for(const auto& entry : directed) {
    std::size_t largest = none;
    for(std::size_t i : entry.second)
      if(!removed[i] && (largest == none || area(i) > area(largest))) largest = i;
    for(std::size_t i : entry.second)
      if(i != largest) removed[i] = 1;
  }
  std::vector<Triangle> kept;
  for(std::size_t i = 0; i < t.size(); ++i)
    if(!removed[i]) kept.push_back(t[i]);
  t.swap(kept);
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_PATCH_TRIANGULATION_H
