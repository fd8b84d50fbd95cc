// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_BORDER_STITCHING_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_BORDER_STITCHING_H

// The borders of an indexed triangle mesh made of parts (the input, then the images that the
// completion adds under each motion), and the edges along which a part can be stitched to an
// earlier one: where a border edge runs between two vertices that lie, each, within the snapping
// distance of the two ends of a border edge of an earlier part (the vertices of a model cut at its
// mirror plane are their own images). Only stitches that leave every vertex manifold are kept: a
// vertex joined on one side of its fan and open on another would bound two holes. A stitched
// vertex of a later part is not made: its faces use the vertex it is joined to.

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/nearby_surface.h>
#include <CGAL/Symmetry_transform/internal/symmetrization/vertex_orbits.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

typedef std::vector<std::array<std::size_t, 3>> Face_array;

// For each face, whether each of its sides (corner k to corner k + 1) bounds no other face.
inline std::vector<std::array<bool, 3>> face_border_sides(const Face_array& faces)
{
  std::vector<std::tuple<std::size_t, std::size_t, std::size_t>> sides; // (smaller end, larger end, 3 f + k)
  sides.reserve(3 * faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k) {
      const auto [a, b] = std::minmax(faces[f][k], faces[f][(k + 1) % 3]);
      sides.emplace_back(a, b, 3 * f + k);
    }
  std::sort(sides.begin(), sides.end());
  std::vector<std::array<bool, 3>> border(faces.size(), {false, false, false});
  for(std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while(j < sides.size() && std::get<0>(sides[j]) == std::get<0>(sides[i]) && std::get<1>(sides[j]) == std::get<1>(sides[i])) ++j;
    if(j == i + 1) border[std::get<2>(sides[i]) / 3][std::get<2>(sides[i]) % 3] = true;
    i = j;
  }
  return border;
}

// The vertices on a border side of a face.
inline std::vector<char> border_vertices(const Face_array& faces, const std::vector<std::array<bool, 3>>& border,
                                         std::size_t number_of_vertices)
{
  std::vector<char> on_border(number_of_vertices, 0);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k)
      if(border[f][k]) on_border[faces[f][k]] = on_border[faces[f][(k + 1) % 3]] = 1;
  return on_border;
}

// A stitch: the border side u -> v of a face and the border side a -> b of a face of a later
// part, with a joined to v and b to u (the faces on either side of the joined edge oriented alike).
struct Stitch
{
  std::array<std::size_t, 2> kept_side, removed_side;
};

// A mesh as arrays with its borders: positions, faces, border sides, vertices on a border.
struct Bordered_mesh
{
  const std::vector<Eigen::Vector3d>& points;
  const Face_array& faces;
  std::vector<std::array<bool, 3>> border;
  std::vector<char> on_border;

  Bordered_mesh(const std::vector<Eigen::Vector3d>& p, const Face_array& f)
    : points(p), faces(f), border(face_border_sides(f)), on_border(border_vertices(f, border, p.size()))
  {}
};

// The nearest of the neighbours that snapping considers, among the border vertices.
constexpr std::size_t snap_candidates = 8;

// For each border vertex, the border vertex of an earlier part (`part` of each vertex: 0 for the
// input, g for the images under the g-th motion) that it is joined to: the nearest within
// `snap_distance`, itself joined to its own (no_vertex: none).
inline std::vector<std::size_t> snapped_vertices(const Bordered_mesh& mesh, const std::vector<std::size_t>& part,
                                                 double snap_distance)
{
  std::vector<std::size_t> border_list, snap(mesh.points.size(), no_vertex);
  std::vector<Eigen::Vector3d> positions;
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(mesh.on_border[v]) {
      border_list.push_back(v);
      positions.push_back(mesh.points[v]);
    }
  if(border_list.empty()) return snap;
  const Nearest_point nearest(positions);
  for(std::size_t i = 0; i < border_list.size(); ++i) {
    const std::size_t v = border_list[i];
    for(std::size_t j : nearest.nearest_others(i, snap_candidates)) {
      const std::size_t u = border_list[j];
      if((mesh.points[u] - mesh.points[v]).norm() > snap_distance) break;
      if(part[u] < part[v]) {
        snap[v] = snap[u] == no_vertex ? u : snap[u];
        break;
      }
    }
  }
  return snap;
}

// The border sides whose two ends are joined to the two ends of a border side of an earlier part.
inline std::vector<Stitch> candidate_stitches(const Bordered_mesh& mesh, const std::vector<std::size_t>& part,
                                              const std::vector<std::size_t>& snap)
{
  const auto joined = [&](std::size_t v) { return snap[v] == no_vertex ? v : snap[v]; };
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::array<std::size_t, 2>>> sides; // by joined ends
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k)
      if(mesh.border[f][k]) {
        const std::size_t u = mesh.faces[f][k], v = mesh.faces[f][(k + 1) % 3];
        sides[{joined(u), joined(v)}].push_back({u, v});
      }
  std::vector<Stitch> stitches;
  for(const auto& [ends, here] : sides) {
    const auto there = sides.find({ends.second, ends.first});
    // One side each way, the later one removed: a side meeting two others is left open.
    if(here.size() != 1 || there == sides.end() || there->second.size() != 1) continue;
    const std::array<std::size_t, 2>& other = there->second[0];
    if(part[here[0][0]] < part[other[0]]) stitches.push_back({here[0], other});
  }
  return stitches;
}

// The id of each vertex once the stitches are made: the smallest of the vertices joined to it.
inline std::vector<std::size_t> joined_ids(std::size_t count, const std::vector<Stitch>& stitches)
{
  std::vector<std::size_t> id(count);
  for(std::size_t v = 0; v < count; ++v) id[v] = v;
  const auto root = [&](std::size_t v) {
    while(id[v] != v) v = id[v] = id[id[v]];
    return v;
  };
  const auto join = [&](std::size_t a, std::size_t b) {
    const std::size_t ra = root(a), rb = root(b);
    id[(std::max)(ra, rb)] = (std::min)(ra, rb);
  };
  for(const Stitch& s : stitches) {
    join(s.removed_side[0], s.kept_side[1]);
    join(s.removed_side[1], s.kept_side[0]);
  }
  for(std::size_t v = 0; v < count; ++v) id[v] = root(v);
  return id;
}

// Whether the faces around the vertices joined into `members` form one fan once joined: no side
// twice, and each face linked to the next through a shared side, in one chain or one ring.
inline bool is_manifold_once_joined(const Face_array& faces, const Faces_around_vertices& rings,
                                    const std::vector<std::size_t>& members, const std::vector<std::size_t>& id)
{
  std::vector<std::size_t> out, in; // of each face around: the other ends of its sides leaving the vertex and entering it
  for(std::size_t v : members)
    for(std::size_t i = rings.first[v]; i < rings.first[v + 1]; ++i) {
      const std::array<std::size_t, 3>& f = faces[rings.around[i]];
      const std::size_t k = std::size_t(std::find(f.begin(), f.end(), v) - f.begin());
      out.push_back(id[f[(k + 1) % 3]]);
      in.push_back(id[f[(k + 2) % 3]]);
    }
  std::vector<std::size_t> sorted_out = out, sorted_in = in;
  std::sort(sorted_out.begin(), sorted_out.end());
  std::sort(sorted_in.begin(), sorted_in.end());
  if(std::adjacent_find(sorted_out.begin(), sorted_out.end()) != sorted_out.end() ||
     std::adjacent_find(sorted_in.begin(), sorted_in.end()) != sorted_in.end())
    return false;
  // The face after face i turning about the vertex enters it from where face i leaves it.
  const auto after = [&](std::size_t i) { return std::size_t(std::find(in.begin(), in.end(), out[i]) - in.begin()); };
  std::size_t first = 0; // the start of the chain: a face that no face comes before (any, for a ring)
  for(std::size_t i = 0; i < out.size(); ++i)
    if(std::find(out.begin(), out.end(), in[i]) == out.end()) first = i;
  std::size_t visited = 1;
  for(std::size_t i = after(first); i < out.size() && i != first; i = after(i)) ++visited;
  return visited == out.size();
}

// The stitches that leave every joined vertex manifold: those at a vertex that would not be are
// dropped, until none is.
inline std::vector<Stitch> manifold_stitches(const Bordered_mesh& mesh, std::vector<Stitch> stitches)
{
  const Faces_around_vertices rings(mesh.faces, mesh.points.size());
  for(bool dropped = true; dropped;) {
    const std::vector<std::size_t> id = joined_ids(mesh.points.size(), stitches);
    std::map<std::size_t, std::vector<std::size_t>> members; // of each vertex joined to others
    for(std::size_t v = 0; v < id.size(); ++v)
      if(id[v] != v) members[id[v]].push_back(v);
    std::set<std::size_t> bad;
    for(auto& [kept, joined] : members) {
      joined.push_back(kept);
      if(!is_manifold_once_joined(mesh.faces, rings, joined, id)) bad.insert(kept);
    }
    const std::size_t before = stitches.size();
    stitches.erase(std::remove_if(stitches.begin(), stitches.end(),
                                  [&](const Stitch& s) { return bad.count(id[s.kept_side[0]]) || bad.count(id[s.kept_side[1]]); }),
                   stitches.end());
    dropped = stitches.size() < before;
  }
  return stitches;
}

// The stitches between the parts of `points` and `faces` (see the head of this file).
inline std::vector<Stitch> border_stitches(const std::vector<Eigen::Vector3d>& points, const Face_array& faces,
                                           const std::vector<std::size_t>& part, double snap_distance)
{
  const Bordered_mesh mesh(points, faces);
  return manifold_stitches(mesh, candidate_stitches(mesh, part, snapped_vertices(mesh, part, snap_distance)));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_SYMMETRIZATION_BORDER_STITCHING_H
