// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_CELLS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_CELLS_H

// The triangles that cross each cell of a regular grid over a soup, for exact closest-point
// searches near a query where an AABB tree cannot narrow them. When large triangles cross the
// inside of a soup (a web mesh with stray faces), a point lies in the bounding boxes of hundreds
// of them, and a tree search tests them all even when the closest point is a hair away. A cell
// lists only the triangles whose plane crosses it inside their outline: a search with a bound
// (the distance to a known point of the soup, as the hint of an ISP match gives) tests the
// triangles of the few cells within that bound.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_tree.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// On the triangles of a surface, boxes are small and thin: a point of the soup's box lies, on
// average, in at most 12 of them (every libcgal-demo mesh); the tree narrows well there. Above
// this depth the cells serve the searches that have a bound.
constexpr double deepest_box_overlap_for_tree = 32.;
// On up to this many triangles, the cells serve the searches that have a bound whatever the
// overlap: a surface crosses some 10^4 of the 64^3 cells, each then listing a few triangles, and
// a search tests those of a cell or two, against a walk down the tree whose boxes, on the large
// triangles of web meshes, hold the query by dozens (detection 10-25 % faster on such meshes,
// the same on finely tessellated ones).
constexpr std::size_t most_triangles_for_cells = std::size_t(1) << 16;
// Cells along the longest side of the soup's box.
constexpr std::size_t triangle_cells_per_side = 64;
// A search whose bound spans more cells than this is left to the tree (a poor bound).
constexpr std::size_t max_cells_per_search = 64;
// The cells list at most this many members in all (256 MB): on a soup of very many large
// triangles they are not built, and the tree answers every search (slow, in bounded memory).
constexpr std::size_t max_cell_members = std::size_t(1) << 26;
// Cells and bounds are widened by this fraction of a cell, so that rounding cannot leave out
// a triangle that touches a cell.
constexpr double cell_margin = 1e-6;

// The mean number of triangles' bounding boxes that contain a point of the soup's box: 0 on a
// flat soup (box of no volume), where boxes are flat too.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double mean_box_overlap(const std::vector<Dtriangle>& triangles);

class Triangle_cells
{
public:
  struct Nearest
  {
    Eigen::Vector3d point;
    std::size_t triangle; // its index in the soup
  };

  // `triangles` must outlive the cells; if they would list more than `max_members`, none are built.
  explicit Triangle_cells(const std::vector<Dtriangle>& triangles, std::size_t max_members = max_cell_members);

  bool built() const { return !starts_.empty(); }

  // The point of the soup closest to p and its triangle, if the soup has a point within `bound`
  // of p and the cells within `bound` are at most max_cells_per_search; nullopt otherwise (and
  // always if the cells were not built).
  std::optional<Nearest> closest(const Eigen::Vector3d& p, double bound) const;

private:
  // Clamped to the grid (compared as doubles: a far or infinite x converts to no long).
  long cell_of(int axis, double x) const;

  std::size_t index_of(long i, long j, long k) const { return std::size_t((k * dims_[1] + j) * dims_[0] + i); }

  // The cells at the ends of an axis reach to infinity: cell_of() clamps points beyond them there.
  double squared_distance_to_cell(const Eigen::Vector3d& p, const std::array<long, 3>& cell) const;

  // Two passes over the triangles, one to count the members of each cell, one to list them; the
  // count stops as soon as it exceeds `max_members`, and nothing is built.
  void fill(std::size_t max_members);

  // Calls f(cell) for each cell that the triangle may cross (a few more, never fewer): seen along
  // the axis of its normal's largest coordinate, each column of cells that its outline may meet,
  // and in that column the cells that its plane crosses; every cell of its box if it has no area.
  template <typename F>
  void for_each_cell_crossed(const Dtriangle& t, F f) const
  {
    const std::array<Eigen::Vector3d, 3> v{to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2])};
    const Eigen::Vector3d n = (v[1] - v[0]).cross(v[2] - v[0]);
    int d = 0;
    for(int a = 1; a < 3; ++a)
      if(std::abs(n[a]) > std::abs(n[d])) d = a;
    const int u = (d + 1) % 3, w = (d + 2) % 3;
    const CGAL::Bbox_3 box = t.bbox();
    if(n[d] == 0.) {
      for(long k = cell_of(2, box.zmin()); k <= cell_of(2, box.zmax()); ++k)
        for(long j = cell_of(1, box.ymin()); j <= cell_of(1, box.ymax()); ++j)
          for(long i = cell_of(0, box.xmin()); i <= cell_of(0, box.xmax()); ++i) f(index_of(i, j, k));
      return;
    }
    const double half = 0.5 * cell_size_ * (1. + 2. * cell_margin);
    // The outward normals of the outline's edges in the (u, w) plane, and their margins.
    std::array<Eigen::Vector2d, 3> edge_normals;
    std::array<double, 3> edge_offsets;
    for(int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& a = v[e], & b = v[(e + 1) % 3], & c = v[(e + 2) % 3];
      Eigen::Vector2d m(b[w] - a[w], a[u] - b[u]);
      if(m.dot(Eigen::Vector2d(c[u] - a[u], c[w] - a[w])) > 0.) m = -m;
      edge_normals[e] = m;
      edge_offsets[e] = m.dot(Eigen::Vector2d(a[u], a[w])) + half * (std::abs(m[0]) + std::abs(m[1]));
    }
    for(long i = cell_of(u, box.min(u)); i <= cell_of(u, box.max(u)); ++i)
      for(long j = cell_of(w, box.min(w)); j <= cell_of(w, box.max(w)); ++j) {
        const Eigen::Vector2d centre(origin_[u] + (double(i) + 0.5) * cell_size_, origin_[w] + (double(j) + 0.5) * cell_size_);
        bool outside = false;
        for(int e = 0; e < 3 && !outside; ++e) outside = edge_normals[e].dot(centre) > edge_offsets[e];
        if(outside) continue;
        // The plane n.x = n.v0 over the column's square: its height along d at the centre, and the spread.
        const double height = (n.dot(v[0]) - n[u] * centre[0] - n[w] * centre[1]) / n[d],
                     spread = half * (std::abs(n[u]) + std::abs(n[w])) / std::abs(n[d]);
        const long k_lo = (std::max)(cell_of(d, height - spread), cell_of(d, box.min(d))),
                   k_hi = (std::min)(cell_of(d, height + spread), cell_of(d, box.max(d)));
        std::array<long, 3> cell;
        cell[u] = i;
        cell[w] = j;
        for(long k = k_lo; k <= k_hi; ++k) {
          cell[d] = k;
          f(index_of(cell[0], cell[1], cell[2]));
        }
      }
  }

  const std::vector<Dtriangle>& triangles_;
  std::array<double, 3> origin_;
  std::array<long, 3> dims_;
  double cell_size_;
  std::vector<std::uint32_t> starts_;  // of each cell's members in members_, and the end
  std::vector<std::uint32_t> members_; // the triangles of each cell, in turn
};

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double mean_box_overlap(const std::vector<Dtriangle>& triangles)
{
  auto volume = [](const CGAL::Bbox_3& b) {
    return (b.xmax() - b.xmin()) * (b.ymax() - b.ymin()) * (b.zmax() - b.zmin());
  };
  CGAL::Bbox_3 all;
  double sum = 0.;
  for(const Dtriangle& t : triangles) {
    const CGAL::Bbox_3 box = t.bbox();
    sum += volume(box);
    all += box;
  }
  return volume(all) > 0. ? sum / volume(all) : 0.;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Triangle_cells::Triangle_cells(const std::vector<Dtriangle>& triangles, std::size_t max_members)
  : triangles_(triangles)
{
  CGAL::Bbox_3 box;
  for(const Dtriangle& t : triangles) box += t.bbox();
  double longest = 0.;
  for(int a = 0; a < 3; ++a) longest = (std::max)(longest, box.max(a) - box.min(a));
  cell_size_ = longest > 0. ? longest / double(triangle_cells_per_side) : 1.; // 1: a soup that is one point
  for(int a = 0; a < 3; ++a) {
    origin_[a] = box.min(a);
    dims_[a] = long((std::min)(triangle_cells_per_side, (std::max)(std::size_t(1),
                    std::size_t(std::ceil((box.max(a) - box.min(a)) / cell_size_)))));
  }
  fill(max_members);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::optional<Triangle_cells::Nearest> Triangle_cells::closest(const Eigen::Vector3d& p, double bound) const
{
  if(!built()) return std::nullopt;
  const double reach = bound * (1. + cell_margin) + cell_margin * cell_size_;
  std::array<long, 3> lo, hi;
  std::size_t count = 1;
  for(int a = 0; a < 3; ++a) {
    lo[a] = cell_of(a, p[a] - reach);
    hi[a] = cell_of(a, p[a] + reach);
    count *= std::size_t(hi[a] - lo[a] + 1);
  }
  if(count > max_cells_per_search) return std::nullopt;
  double best = reach * reach;
  std::optional<Nearest> nearest;
  auto search = [&](long i, long j, long k) {
    if(squared_distance_to_cell(p, {i, j, k}) > best) return;
    const std::size_t cell = index_of(i, j, k);
    for(std::uint32_t e = starts_[cell]; e < starts_[cell + 1]; ++e) {
      const Dtriangle& t = triangles_[members_[e]];
      const Eigen::Vector3d q = closest_point_on_triangle(p, to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2]));
      const double d2 = (p - q).squaredNorm();
      if(d2 < best || (d2 == best && !nearest)) {
        best = d2;
        nearest = Nearest{q, members_[e]};
      }
    }
  };
  // The cell of p first: its triangles shrink the bound, and most other cells are then skipped.
  const std::array<long, 3> own{cell_of(0, p[0]), cell_of(1, p[1]), cell_of(2, p[2])};
  search(own[0], own[1], own[2]);
  for(long k = lo[2]; k <= hi[2]; ++k)
    for(long j = lo[1]; j <= hi[1]; ++j)
      for(long i = lo[0]; i <= hi[0]; ++i)
        if(std::array<long, 3>{i, j, k} != own) search(i, j, k);
  return nearest;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE long Triangle_cells::cell_of(int axis, double x) const
{
  const double c = std::floor((x - origin_[axis]) / cell_size_);
  return !(c > 0.) ? 0L : c >= double(dims_[axis] - 1) ? dims_[axis] - 1 : long(c);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double Triangle_cells::squared_distance_to_cell(const Eigen::Vector3d& p, const std::array<long, 3>& cell) const
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  double d2 = 0.;
  for(int a = 0; a < 3; ++a) {
    const double low = cell[a] == 0 ? -infinity : origin_[a] + double(cell[a]) * cell_size_,
                 high = cell[a] == dims_[a] - 1 ? infinity : origin_[a] + double(cell[a] + 1) * cell_size_;
    const double gap = (std::max)({low - p[a], p[a] - high, 0.});
    d2 += gap * gap;
  }
  return d2;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Triangle_cells::fill(std::size_t max_members)
{
  starts_.assign(std::size_t(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
  std::size_t members = 0;
  for(const Dtriangle& t : triangles_) {
    for_each_cell_crossed(t, [&](std::size_t cell) {
      ++starts_[cell + 1];
      ++members;
    });
    if(members > max_members) {
      starts_ = std::vector<std::uint32_t>();
      return;
    }
  }
  for(std::size_t c = 1; c < starts_.size(); ++c) starts_[c] += starts_[c - 1];
  members_.resize(starts_.back());
  std::vector<std::uint32_t> next(starts_.begin(), starts_.end() - 1);
  for(std::size_t t = 0; t < triangles_.size(); ++t)
    for_each_cell_crossed(triangles_[t], [&](std::size_t cell) { members_[next[cell]++] = std::uint32_t(t); });
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_TRIANGLE_CELLS_H
