// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_HOLE_FILLING_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_HOLE_FILLING_H

// The holes left in the output mesh where folded triangles were removed (patch_triangulation.h):
// flaps (triangles held by their corners only) removed first; then each cycle of output border
// edges (read against the orientation of the triangles, split where it passes a vertex twice)
// whose edges do not all follow a border of the input is filled by the triangulation of least
// total edge length between the final anchor positions or, where the cycle has none that makes
// no edge twice, by a fan from a new vertex at its centroid: choices that only depend on
// lengths, invariant under a reflection, so that the fill of a hole and that of its mirror
// image are mirror images of each other.
//
// The triangulation is a dynamic programming of its own, not
// CGAL::Polygon_mesh_processing::triangulate_hole_polyline(): that function minimises the
// largest dihedral angle, then the area, and cannot exclude the diagonals that are already
// edges of the output, which would then be shared by three triangles or more (non-manifold).
// Tried (5 meshes x 13 settings, 155 holes): 81 of its fills broke the rule (63 reused an
// output edge, 18 repeated an output triangle) and became fans, and 35 of the 65 outputs changed.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/remeshing/mirrors.h>
#include <CGAL/Symmetry_transform/internal/remeshing/working_mesh.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Hole cycles longer than this are left open: the triangulation costs n^3 steps (8e6 here).
constexpr std::size_t max_hole_cycle_length = 200;

// A triangle (a, b, c) is flat if twice its area is at most this fraction of |b - a|^2 (plus
// `flat_triangle_floor`, for sides whose square underflows): the limit of rounding, not of shape.
constexpr double flat_triangle_ratio = 1e-12;
constexpr double flat_triangle_floor = 1e-300;

inline bool is_flat(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  return (b - a).cross(c - a).norm() <= flat_triangle_ratio * (b - a).squaredNorm() + flat_triangle_floor;
}

class Hole_filling
{
  static constexpr std::size_t none = Remeshing_mesh::none;

public:
  typedef std::array<std::size_t, 3> Triangle;
  typedef std::vector<std::size_t> Cycle;

  // The output mesh: per anchor its working-mesh vertex and its position, and the triangles.
  Hole_filling(const Remeshing_mesh& mesh, const Nearest_vertex& nearest_vertex, std::vector<std::size_t>& anchor_vertices,
               std::vector<Eigen::Vector3d>& positions, std::vector<Triangle>& triangles)
    : mesh_(mesh), nearest_vertex_(nearest_vertex), anchor_vertices_(anchor_vertices), positions_(positions),
      triangles_(triangles)
  {}

  void run();

private:
  typedef std::pair<std::size_t, std::size_t> Edge;

  bool anchor_on_border(std::size_t a) const { return anchor_vertices_[a] != none && on_border_[anchor_vertices_[a]]; }

  bool follows_input_border(const Cycle& cycle) const;

  // A triangle none of whose edges is shared (a flap left by the removed folds, held by its
  // corners only) goes, unless it lies on a border of the input.
  void remove_flaps();

  // Records the edges of an output triangle and, with `with_key`, its corners.
  void record(const Triangle& t, bool with_key);

  // The cycles of hole edges, (b, a) for each output edge (a, b) without its reverse.
  std::vector<Cycle> hole_cycles() const;

  // Of the hole edges leaving v, the shortest (a geometric choice), removed from `hole`.
  std::size_t take_shortest(std::multimap<std::size_t, std::size_t>& hole, std::size_t v) const;

  // Whether the triangle (i, k, j) of the cycle, oriented as the cycle, may fill it: not flat,
  // not an output triangle, and no side that is not an edge of the cycle is an output edge.
  bool allowed(const Cycle& cycle, std::size_t i, std::size_t k, std::size_t j) const;

  // The triangulation of the cycle of least total diagonal length among the allowed ones, added
  // to the output; false if there is none.
  bool triangulate_cycle(const Cycle& cycle);

  // A fan from a new vertex at the centroid of the cycle (the mirror image of that of the mirror
  // cycle), unless a triangle of it would be flat.
  void fan_fill(const Cycle& cycle);

  const Remeshing_mesh& mesh_;
  const Nearest_vertex& nearest_vertex_;
  std::vector<std::size_t>& anchor_vertices_;
  std::vector<Eigen::Vector3d>& positions_;
  std::vector<Triangle>& triangles_;
  std::vector<char> on_border_;          // per working-mesh vertex: on a border of the input
  std::set<Edge> directed_;              // the directed edges of the output
  std::set<Triangle> keys_;              // the output triangles' sorted corners (not the fans')
};

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Hole_filling::run()
{
  if(triangles_.empty()) return;
  on_border_.assign(mesh_.points.size(), 0);
  for(std::size_t h = 0; h < mesh_.opposite.size(); ++h)
    if(mesh_.opposite[h] == none) on_border_[mesh_.source(h)] = on_border_[mesh_.target(h)] = 1;
  remove_flaps();
  for(const Triangle& t : triangles_) record(t, true);
  for(const Cycle& cycle : hole_cycles()) {
    const std::size_t n = cycle.size();
    if(n < 3 || n > max_hole_cycle_length || follows_input_border(cycle)) continue;
    if(!triangulate_cycle(cycle)) fan_fill(cycle);
  }
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Hole_filling::follows_input_border(const Cycle& cycle) const
{
  for(std::size_t i = 0; i < cycle.size(); ++i)
    if(!(anchor_on_border(cycle[i]) && anchor_on_border(cycle[(i + 1) % cycle.size()]))) return false;
  return true;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Hole_filling::remove_flaps()
{
  std::map<Edge, std::size_t> count;
  for(const Triangle& t : triangles_)
    for(int c = 0; c < 3; ++c) ++count[std::minmax(t[c], t[(c + 1) % 3])];
  std::vector<Triangle> kept;
  for(const Triangle& t : triangles_) {
    bool flap = true;
    for(int c = 0; c < 3 && flap; ++c) flap = count[std::minmax(t[c], t[(c + 1) % 3])] == 1;
    if(flap && !(anchor_on_border(t[0]) && anchor_on_border(t[1]) && anchor_on_border(t[2]))) continue;
    kept.push_back(t);
  }
  triangles_.swap(kept);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Hole_filling::record(const Triangle& t, bool with_key)
{
  for(int c = 0; c < 3; ++c) directed_.insert(Edge(t[c], t[(c + 1) % 3]));
  if(!with_key) return;
  Triangle key = t;
  std::sort(key.begin(), key.end());
  keys_.insert(key);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Hole_filling::Cycle> Hole_filling::hole_cycles() const
{
  std::multimap<std::size_t, std::size_t> hole;
  for(const Edge& e : directed_)
    if(!directed_.count(Edge(e.second, e.first))) hole.insert({e.second, e.first});
  std::vector<Cycle> cycles;
  while(!hole.empty()) {
    Cycle path(1, hole.begin()->first);
    std::map<std::size_t, std::size_t> position{{path.front(), 0}};
    while(hole.count(path.back())) {
      const std::size_t w = take_shortest(hole, path.back());
      const auto found = position.find(w);
      if(found == position.end()) {
        position[w] = path.size();
        path.push_back(w);
        continue;
      }
      // A cycle closes at w: cut it off the path.
      cycles.emplace_back(path.begin() + std::ptrdiff_t(found->second), path.end());
      for(std::size_t i = found->second + 1; i < path.size(); ++i) position.erase(path[i]);
      path.resize(found->second + 1);
    }
  }
  return cycles;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::size_t Hole_filling::take_shortest(std::multimap<std::size_t, std::size_t>& hole, std::size_t v) const
{
  const auto& x = positions_;
  auto range = hole.equal_range(v);
  auto best = range.first;
  for(auto it = range.first; it != range.second; ++it)
    if((x[it->second] - x[v]).norm() < (x[best->second] - x[v]).norm()) best = it;
  const std::size_t w = best->second;
  hole.erase(best);
  return w;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Hole_filling::allowed(const Cycle& cycle, std::size_t i, std::size_t k, std::size_t j) const
{
  const std::size_t a = cycle[i], b = cycle[k], c = cycle[j];
  if(a == b || b == c || a == c) return false;
  if(is_flat(positions_[a], positions_[b], positions_[c])) return false;
  Triangle key = {a, b, c};
  std::sort(key.begin(), key.end());
  if(keys_.count(key)) return false;
  const Edge sides[3] = {{i, k}, {k, j}, {j, i}};
  for(const auto& [p, q] : sides) {
    const bool on_cycle = (p + 1) % cycle.size() == q;
    if(!on_cycle && (directed_.count(Edge(cycle[p], cycle[q])) || directed_.count(Edge(cycle[q], cycle[p]))))
      return false;
  }
  return true;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Hole_filling::triangulate_cycle(const Cycle& cycle)
{
  const std::size_t n = cycle.size();
  const double infinity = std::numeric_limits<double>::infinity();
  // cost[i][j]: least total length of the diagonals triangulating the cycle from i to j.
  std::vector<std::vector<double>> cost(n, std::vector<double>(n, infinity));
  std::vector<std::vector<std::size_t>> split(n, std::vector<std::size_t>(n, none));
  for(std::size_t i = 0; i + 1 < n; ++i) cost[i][i + 1] = 0.;
  for(std::size_t gap = 2; gap < n; ++gap)
    for(std::size_t i = 0; i + gap < n; ++i) {
      const std::size_t j = i + gap;
      const double diagonal = (i == 0 && j == n - 1) ? 0. : (positions_[cycle[i]] - positions_[cycle[j]]).norm();
      for(std::size_t k = i + 1; k < j; ++k) {
        if(cost[i][k] == infinity || cost[k][j] == infinity || !allowed(cycle, i, k, j)) continue;
        const double c = cost[i][k] + cost[k][j] + diagonal;
        if(c < cost[i][j]) { cost[i][j] = c; split[i][j] = k; }
      }
    }
  if(cost[0][n - 1] == infinity) return false;
  std::vector<Edge> stack = {{0, n - 1}};
  while(!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if(j < i + 2) continue;
    const std::size_t k = split[i][j];
    const Triangle t = {cycle[i], cycle[k], cycle[j]};
    triangles_.push_back(t);
    record(t, true);
    stack.push_back({i, k});
    stack.push_back({k, j});
  }
  return true;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Hole_filling::fan_fill(const Cycle& cycle)
{
  const std::size_t n = cycle.size();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for(std::size_t v : cycle) centroid += positions_[v];
  centroid /= double(n);
  for(std::size_t i = 0; i < n; ++i)
    if(is_flat(positions_[cycle[i]], positions_[cycle[(i + 1) % n]], centroid)) return;
  const std::size_t c = positions_.size();
  positions_.push_back(centroid);
  anchor_vertices_.push_back(nearest_vertex_(centroid));
  for(std::size_t i = 0; i < n; ++i) {
    const Triangle t = {cycle[i], cycle[(i + 1) % n], c};
    triangles_.push_back(t);
    record(t, false);
  }
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_REMESHING_HOLE_FILLING_H
