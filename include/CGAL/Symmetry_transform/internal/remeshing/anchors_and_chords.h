// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_ANCHORS_AND_CHORDS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_ANCHORS_AND_CHORDS_H

// The anchors of the output mesh on the patch boundaries (thesis, Section 5.1.2, "Point
// Correspondences"), in the steps of CGAL's VSA (find_anchors, find_edges, subdivide_chord):
// - anchors where three or more patch boundaries meet, plus the vertices on a plane of symmetry
//   where a patch boundary crosses the plane (the split vertices of the thesis);
// - boundary chords between anchors, subdivided at their farthest vertex while it lies farther
//   than `subdivision_ratio` (times the mean edge length, or the chord length) from the chord;
// - a boundary cycle with fewer than three anchors completed by the vertices farthest from its
//   anchors;
// - the anchors of corresponding boundaries completed by each other's mirror images (the mesh
//   vertex nearest the reflected anchor, if it lies on a boundary of the same proxies and not
//   next to another anchor).

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirrors.h>
#include <CGAL/Symmetry_transform/internal/remeshing/partition.h>
#include <CGAL/Symmetry_transform/internal/remeshing/settings.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// A walk around a vertex to the next boundary halfedge ends after at most its number of faces;
// this bound stops it around a vertex where the walk would never reach a boundary (a
// non-manifold vertex of the input).
constexpr std::size_t max_boundary_walk = 1000000;

// A junction: a vertex with at least three boundary edges (each counted twice, see
// Patch_boundaries::boundary_count()).
constexpr std::size_t junction_boundary_count = 6;

// CGAL's rule: a chord between two different anchors with fewer edges is not subdivided.
constexpr std::size_t min_subdivided_chord_edges = 4;

// The mirror image of an anchor becomes an anchor if the mesh vertex nearest to it lies within
// this many mean edge lengths (a vertex of the mirror boundary on a nearly symmetric mesh).
constexpr double mirror_anchor_distance = 1.;

// The anchors of the output mesh, as they are found: working-mesh vertices.
struct Anchor_set
{
  static constexpr std::size_t none = Remeshing_mesh::none;

  std::vector<std::size_t> of_vertex; // per working-mesh vertex: its anchor, or `none`
  std::vector<std::size_t> vertices;  // per anchor: its working-mesh vertex

  explicit Anchor_set(std::size_t number_of_vertices) : of_vertex(number_of_vertices, none) {}

  bool contains(std::size_t v) const { return of_vertex[v] != none; }

  void attach(std::size_t v)
  {
    if(of_vertex[v] != none) return;
    of_vertex[v] = vertices.size();
    vertices.push_back(v);
  }
};

// The boundaries between the patches of a partition, walked on the working mesh.
class Patch_boundaries
{
public:
  static constexpr std::size_t none = Remeshing_mesh::none;

  explicit Patch_boundaries(const Symmetric_partition& partition)
    : mesh_(partition.mesh()), partition_(partition), label_(partition.labels())
  {}

  const Remeshing_mesh& mesh() const { return mesh_; }
  const Symmetric_partition& partition() const { return partition_; }
  // The patch of the face of halfedge h.
  std::size_t label(std::size_t h) const { return label_[h / 3]; }

  // Whether halfedge h separates its patch from another patch or the outside.
  bool is_boundary(std::size_t h) const;

  // The boundary halfedge of the same patch that follows h (a boundary halfedge) on its cycle.
  std::size_t next_boundary(std::size_t h) const;

  // The boundary halfedges from h (excluded) to the next anchor; h is moved there.
  std::vector<std::size_t> walk_chord(std::size_t& h, const Anchor_set& anchors) const;

  // Twice the number of boundary edges at v (a border edge is seen from one face, a patch
  // boundary from two), and the proxies around it, sorted.
  std::size_t boundary_count(std::size_t v, std::vector<std::size_t>* proxies = nullptr) const;

private:
  const Remeshing_mesh& mesh_;
  const Symmetric_partition& partition_;
  const std::vector<std::size_t>& label_;
};

// Finds the anchors of the patch boundaries (see the top of the file).
class Boundary_anchors
{
  static constexpr std::size_t none = Remeshing_mesh::none;

public:
  Boundary_anchors(const Patch_boundaries& boundaries, const std::vector<Dplane>& planes, Anchor_set& anchors)
    : boundaries_(boundaries), mesh_(boundaries.mesh()), planes_(planes), anchors_(anchors)
  {}

  // Adds the anchors; returns a halfedge of each boundary cycle, ending at an anchor.
  std::vector<std::size_t> find(const Meshing_settings& settings, const Nearest_vertex& nearest_vertex);

private:
  void find_junctions_and_plane_crossings();

  // Whether the vertex v, on plane j, has boundary edges to both sides of the plane: the middle
  // of a chord symmetric about the plane lies there, and its tag (the nearer end of the chord)
  // would otherwise be a tie.
  bool boundary_crosses_plane(std::size_t v, std::size_t j) const;

  void find_chords(const Meshing_settings& settings);

  // Subdivides chord[begin, end) at its farthest vertex while the criterion holds (CGAL's rule).
  void subdivide(const std::vector<std::size_t>& chord, std::size_t begin, std::size_t end, const Meshing_settings& s);

  // The distance of the farthest vertex from the chord, relative to the mean edge length or the
  // chord length, weighted by the sine of the angle between the two patches if asked.
  double chord_criterion(std::size_t first_halfedge, double largest, double length, const Meshing_settings& s) const;

  // A boundary cycle needs three anchors: each one added is the vertex whose distance to the
  // nearest anchor of the cycle is largest. The rule depends on the anchors, not on where the
  // walk around the cycle starts: mirror cycles get mirror anchors.
  void add_anchors_to_short_cycles();

  // The boundary halfedge of the cycle of `head` whose target lies farthest from the cycle's
  // centroid: the first anchor of a cycle that has none, chosen so that mirror cycles get mirror
  // anchors (the first halfedge in index order would not).
  std::size_t farthest_from_centroid(std::size_t head) const;

  // Each anchor's mirror images through the planes become anchors too, where the mesh vertex
  // nearest the image lies within `mirror_anchor_distance` and on a boundary of the same proxies.
  void complete_with_mirrors(const Nearest_vertex& nearest_vertex);

  // Whether a vertex shares an edge with an anchor (anchors that close make slivers and
  // non-manifold fans).
  bool next_to_anchor(std::size_t v) const;

  const Patch_boundaries& boundaries_;
  const Remeshing_mesh& mesh_;
  const std::vector<Dplane>& planes_;
  Anchor_set& anchors_;
  std::vector<std::size_t> cycles_;
};

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Patch_boundaries::is_boundary(std::size_t h) const
{
  const std::size_t n = mesh_.neighbor(h);
  return n == none || label_[n] != label_[h / 3];
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t Patch_boundaries::next_boundary(std::size_t h) const
{
  std::size_t g = Remeshing_mesh::next(h);
  for(std::size_t turns = 0; !is_boundary(g) && turns < max_boundary_walk; ++turns) g = Remeshing_mesh::next(mesh_.opposite[g]);
  return g;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::size_t> Patch_boundaries::walk_chord(std::size_t& h, const Anchor_set& anchors) const
{
  std::vector<std::size_t> chord;
  do {
    h = next_boundary(h);
    chord.push_back(h);
  } while(!anchors.contains(mesh_.target(h)));
  return chord;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t Patch_boundaries::boundary_count(std::size_t v, std::vector<std::size_t>* proxies) const
{
  std::size_t count = 0;
  for(std::size_t i = mesh_.vertex_face_begin[v]; i < mesh_.vertex_face_begin[v + 1]; ++i) {
    const std::size_t f = mesh_.vertex_face[i];
    if(proxies) proxies->push_back(partition_.proxy_of(label_[f]));
    for(int c = 0; c < 3; ++c) {
      const std::size_t h = 3 * f + c;
      if(mesh_.source(h) != v && mesh_.target(h) != v) continue;
      if(mesh_.neighbor(h) == none) count += 2;
      else if(is_boundary(h)) count += 1;
    }
  }
  if(proxies) {
    std::sort(proxies->begin(), proxies->end());
    proxies->erase(std::unique(proxies->begin(), proxies->end()), proxies->end());
  }
  return count;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<std::size_t> Boundary_anchors::find(const Meshing_settings& settings, const Nearest_vertex& nearest_vertex)
{
  find_junctions_and_plane_crossings();
  find_chords(settings);
  add_anchors_to_short_cycles();
  complete_with_mirrors(nearest_vertex);
  return cycles_;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Boundary_anchors::find_junctions_and_plane_crossings()
{
  for(std::size_t v = 0; v < mesh_.points.size(); ++v) {
    if(boundaries_.boundary_count(v) >= junction_boundary_count) {
      anchors_.attach(v);
      continue;
    }
    for(std::size_t j = 0; j < planes_.size() && !anchors_.contains(v); ++j)
      if(((mesh_.vertex_planes[v] >> j) & 1u) && boundary_crosses_plane(v, j)) anchors_.attach(v);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Boundary_anchors::boundary_crosses_plane(std::size_t v, std::size_t j) const
{
  bool above = false, below = false;
  for(std::size_t i = mesh_.vertex_face_begin[v]; i < mesh_.vertex_face_begin[v + 1]; ++i)
    for(int c = 0; c < 3; ++c) {
      const std::size_t h = 3 * mesh_.vertex_face[i] + c;
      const std::size_t other = mesh_.source(h) == v ? mesh_.target(h) : mesh_.target(h) == v ? mesh_.source(h) : none;
      if(other == none || !boundaries_.is_boundary(h) || ((mesh_.vertex_planes[other] >> j) & 1u)) continue;
      (planes_[j].signed_distance(mesh_.points[other]) > 0. ? above : below) = true;
    }
  return above && below;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Boundary_anchors::find_chords(const Meshing_settings& settings)
{
  const std::size_t nh = 3 * mesh_.number_of_faces();
  std::vector<char> candidate(nh, 0);
  for(std::size_t h = 0; h < nh; ++h) candidate[h] = boundaries_.is_boundary(h) ? 1 : 0;
  for(std::size_t start = 0; start < nh; ++start) {
    if(!candidate[start]) continue;
    std::size_t head = start;
    while(!anchors_.contains(mesh_.target(head))) {
      head = boundaries_.next_boundary(head);
      if(head == start) break;
    }
    if(!anchors_.contains(mesh_.target(head))) {
      head = farthest_from_centroid(head);
      anchors_.attach(mesh_.target(head));
    }
    cycles_.push_back(head);
    std::size_t h = head;
    do {
      const std::vector<std::size_t> chord = boundaries_.walk_chord(h, anchors_);
      subdivide(chord, 0, chord.size(), settings);
      for(std::size_t c : chord) candidate[c] = 0;
    } while(h != head);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Boundary_anchors::subdivide(const std::vector<std::size_t>& chord, std::size_t begin, std::size_t end, const Meshing_settings& s)
{
  const std::size_t first = mesh_.source(chord[begin]), last = mesh_.target(chord[end - 1]);
  if(first != last && end - begin < min_subdivided_chord_edges) return;
  const Eigen::Vector3d &a = mesh_.points[first], &b = mesh_.points[last];
  std::size_t farthest = begin;
  double largest = 0.;
  const double length = (b - a).norm();
  bool split = false;
  if(first == last) { // a closed chord: split at the vertex farthest from its end
    for(std::size_t i = begin; i + 1 < end; ++i) {
      const double d = (mesh_.points[mesh_.target(chord[i])] - a).norm();
      if(d > largest) { largest = d; farthest = i; }
    }
    split = end - begin > 2;
  } else {
    for(std::size_t i = begin; i + 1 < end; ++i) {
      const Eigen::Vector3d x = mesh_.points[mesh_.target(chord[i])] - a;
      const double d = length > 0. ? (b - a).cross(x).norm() / length : x.norm();
      if(d > largest) { largest = d; farthest = i; }
    }
    split = chord_criterion(chord[begin], largest, length, s) > s.subdivision_ratio;
  }
  if(!split || largest <= 0.) return;
  anchors_.attach(mesh_.target(chord[farthest]));
  subdivide(chord, begin, farthest + 1, s);
  subdivide(chord, farthest + 1, end, s);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double Boundary_anchors::chord_criterion(std::size_t first_halfedge, double largest, double length, const Meshing_settings& s) const
{
  double criterion = largest / (s.relative_to_chord && length > 0. ? length : mesh_.average_edge_length);
  if(s.with_dihedral_angle && mesh_.neighbor(first_halfedge) != none) {
    const Symmetric_partition& partition = boundaries_.partition();
    criterion *= partition.patch_normal(boundaries_.label(first_halfedge))
                   .cross(partition.patch_normal(partition.labels()[mesh_.neighbor(first_halfedge)]))
                   .norm();
  }
  return criterion;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Boundary_anchors::add_anchors_to_short_cycles()
{
  for(std::size_t head : cycles_) {
    std::vector<std::size_t> on_anchors, others;
    std::size_t h = head;
    do {
      h = boundaries_.next_boundary(h);
      (anchors_.contains(mesh_.target(h)) ? on_anchors : others).push_back(mesh_.target(h));
    } while(h != head);
    while(on_anchors.size() < 3 && !others.empty()) {
      std::size_t best = 0;
      double largest = -1.;
      for(std::size_t i = 0; i < others.size(); ++i) {
        double nearest = std::numeric_limits<double>::infinity();
        for(std::size_t a : on_anchors) nearest = (std::min)(nearest, (mesh_.points[others[i]] - mesh_.points[a]).norm());
        if(nearest > largest) { largest = nearest; best = i; }
      }
      anchors_.attach(others[best]);
      on_anchors.push_back(others[best]);
      others.erase(others.begin() + std::ptrdiff_t(best));
    }
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t Boundary_anchors::farthest_from_centroid(std::size_t head) const
{
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::size_t count = 0, h = head;
  do {
    centroid += mesh_.points[mesh_.target(h)];
    ++count;
    h = boundaries_.next_boundary(h);
  } while(h != head);
  centroid /= double(count);
  std::size_t best = head;
  double largest = -1.;
  do {
    const double d = (mesh_.points[mesh_.target(h)] - centroid).squaredNorm();
    if(d > largest) { largest = d; best = h; }
    h = boundaries_.next_boundary(h);
  } while(h != head);
  return best;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Boundary_anchors::complete_with_mirrors(const Nearest_vertex& nearest_vertex)
{
  if(planes_.empty()) return;
  std::vector<std::size_t> proxies, image_proxies;
  for(std::size_t a = 0; a < anchors_.vertices.size(); ++a) { // grows while looping
    const std::size_t v = anchors_.vertices[a];
    proxies.clear();
    boundaries_.boundary_count(v, &proxies);
    for(const Dplane& plane : planes_) {
      const Eigen::Vector3d image = plane.reflect(mesh_.points[v]);
      const std::size_t w = nearest_vertex(image);
      if(w == none || anchors_.contains(w) ||
         (mesh_.points[w] - image).norm() > mirror_anchor_distance * mesh_.average_edge_length)
        continue;
      image_proxies.clear();
      if(boundaries_.boundary_count(w, &image_proxies) >= 2 && image_proxies == proxies && !next_to_anchor(w))
        anchors_.attach(w);
    }
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Boundary_anchors::next_to_anchor(std::size_t v) const
{
  for(std::size_t i = mesh_.vertex_face_begin[v]; i < mesh_.vertex_face_begin[v + 1]; ++i)
    for(std::size_t w : mesh_.faces[mesh_.vertex_face[i]])
      if(w != v && anchors_.contains(w)) return true;
  return false;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_ANCHORS_AND_CHORDS_H
