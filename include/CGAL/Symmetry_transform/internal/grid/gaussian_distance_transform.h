// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_GRID_GAUSSIAN_DISTANCE_TRANSFORM_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_GRID_GAUSSIAN_DISTANCE_TRANSFORM_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_tree.h>


#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

template <typename GT>
Voxel_grid<GT> empty_grid(const Shape_frame& frame, const Grid_settings& settings)
{
  return Voxel_grid<GT>(settings.resolution, to_point<GT>(frame.center), frame.radius, settings.side_length);
}

// Voxel index range [first, last] whose centres lie within [lo, hi] along one axis.
inline std::pair<long, long> voxel_range(double lo, double hi, double origin, double h, long n)
{
  const long first = (std::max)(0L, long(std::ceil((lo - origin) / h - 0.5)));
  const long last = (std::min)(n - 1, long(std::floor((hi - origin) / h - 0.5)));
  return {first, last};
}

// Calls visit(index of the voxel, x, y, z of its centre) for each voxel whose centre lies in the
// box [lo, hi].
template <typename GT, typename Visit>
void for_each_voxel_in_box(const Voxel_grid<GT>& grid, const std::array<double, 3>& lo,
                           const std::array<double, 3>& hi, const Visit& visit)
{
  const double h = grid.voxel_size();
  const long n = long(grid.resolution());
  const auto& o = grid.origin();
  std::array<std::pair<long, long>, 3> range;
  for(int a = 0; a < 3; ++a) range[a] = voxel_range(lo[a], hi[a], o[a], h, n);
  for(long k = range[2].first; k <= range[2].second; ++k)
    for(long j = range[1].first; j <= range[1].second; ++j)
      for(long i = range[0].first; i <= range[0].second; ++i)
        visit(grid.index(std::size_t(i), std::size_t(j), std::size_t(k)), o[0] + (double(i) + 0.5) * h,
              o[1] + (double(j) + 0.5) * h, o[2] + (double(k) + 0.5) * h);
}

// The indices i of [range.first, range.second] with |at + slope i| <= bound (empty: first > second).
inline std::pair<long, long> index_interval(double at, double slope, double bound, const std::pair<long, long>& range)
{
  if(bound < 0.) return {range.first, range.first - 1};
  if(slope == 0.)
    return std::abs(at) <= bound ? range : std::pair<long, long>(range.first, range.first - 1);
  double a = (-bound - at) / slope, b = (bound - at) / slope;
  if(a > b) std::swap(a, b);
  const double first = (std::max)(double(range.first), std::ceil(a)), last = (std::min)(double(range.second), std::floor(b));
  if(first > last) return {range.first, range.first - 1};
  return {long(first), long(last)};
}

// Rounding slack of the band test below, relative to the magnitude of the coordinates: the test's
// own rounding is a few units in the last place (2e-16), far below it.
constexpr double band_test_slack = 1e-12;

// Marks the voxels whose centre lies within `cutoff` of the plane of a triangle and inside
// its bounding box grown by `cutoff`, in the layers [first_layer, last_layer]: a superset of the
// band where the GEDT is non-zero. Along a row of voxels the distance to the plane is affine in
// the index: the voxels surely inside (by band_test_slack) are marked at once, and only those
// near the two ends of the interval are tested one by one, with the test that defines the band.
template <typename GT>
void mark_band_of_triangle(const Voxel_grid<GT>& grid, const Dtriangle& t, double cutoff, std::vector<char>& in_band,
                           long first_layer = 0, long last_layer = std::numeric_limits<long>::max())
{
  const Bbox_3 box = t.bbox();
  Dvector normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
  normal = normal / std::sqrt(normal.squared_length());
  const double h = grid.voxel_size();
  const long n = long(grid.resolution());
  const auto& o = grid.origin();
  const std::array<double, 3> lo = {box.xmin() - cutoff, box.ymin() - cutoff, box.zmin() - cutoff},
                              hi = {box.xmax() + cutoff, box.ymax() + cutoff, box.zmax() + cutoff};
  std::array<std::pair<long, long>, 3> range;
  for(int a = 0; a < 3; ++a) range[a] = voxel_range(lo[a], hi[a], o[a], h, n);
  auto within = [&](long i, double y, double z) { // the definition of the band
    const Dvector d(o[0] + (double(i) + 0.5) * h - t[0].x(), y - t[0].y(), z - t[0].z());
    return std::abs(d * normal) <= cutoff;
  };
  const double magnitude = std::abs(o[0]) + std::abs(o[1]) + std::abs(o[2]) + 3. * double(n + 1) * h +
                           std::abs(t[0].x()) + std::abs(t[0].y()) + std::abs(t[0].z()) + cutoff;
  const double slack = band_test_slack * magnitude, slope = h * normal.x();
  for(long k = (std::max)(range[2].first, first_layer); k <= (std::min)(range[2].second, last_layer); ++k)
    for(long j = range[1].first; j <= range[1].second; ++j) {
      const double y = o[1] + (double(j) + 0.5) * h, z = o[2] + (double(k) + 0.5) * h;
      // Distance to the plane of voxel i, about at + slope * i.
      const double at = (o[0] + 0.5 * h - t[0].x()) * normal.x() + (y - t[0].y()) * normal.y() + (z - t[0].z()) * normal.z();
      const std::pair<long, long> sure = index_interval(at, slope, cutoff - slack, range[0]),
                                  maybe = index_interval(at, slope, cutoff + slack, range[0]);
      char* row = in_band.data() + grid.index(0, std::size_t(j), std::size_t(k));
      for(long i = maybe.first; i <= maybe.second; ++i) {
        if(i == sure.first && sure.first <= sure.second) {
          std::fill(row + sure.first, row + sure.second + 1, char(1));
          i = sure.second;
        } else if(within(i, y, z)) {
          row[i] = 1;
        }
      }
    }
}

// The band of all triangles. A union, whatever the order: each thread marks the voxels of its
// own layers (a fixed slab of the grid) for every triangle. On a fine mesh, each triangle's box
// spans about (2 cutoff / h)^3 = 10^3 voxels, the main cost of its GEDT.
template <typename GT>
std::vector<char> band_of_triangles(const Voxel_grid<GT>& grid, const std::vector<Dtriangle>& triangles, double cutoff,
                                    unsigned threads)
{
  std::vector<char> in_band(grid.values().size(), 0);
  const std::size_t layers = grid.resolution();
  parallel_for(layers, threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      // Under a callback, a cancel is seen within a few thousand triangles (a million take a second).
      if(i % sequential_items_per_report == 0 && !parallel_poll()) return;
      mark_band_of_triangle(grid, triangles[i], cutoff, in_band, long(begin), long(end) - 1);
    }
  });
  return in_band;
}

// Marks the voxels within `cutoff` of a point.
template <typename GT>
void mark_band_of_point(const Voxel_grid<GT>& grid, const Dpoint& p, double cutoff,
                        std::vector<char>& in_band)
{
  for_each_voxel_in_box(grid, {p.x() - cutoff, p.y() - cutoff, p.z() - cutoff},
                        {p.x() + cutoff, p.y() + cutoff, p.z() + cutoff},
                        [&](std::size_t v, double x, double y, double z) {
                          const double dx = x - p.x(), dy = y - p.y(), dz = z - p.z();
                          if(dx * dx + dy * dy + dz * dz <= cutoff * cutoff) in_band[v] = 1;
                        });
}

// Sets each voxel v of the band to exp(-d^2 / 2 sigma^2), d^2 = squared_distance(point, v)
// computed in parallel, then normalises the grid to unit sum of squares.
template <typename GT, typename SquaredDistance>
void fill_gaussian_of_band(Voxel_grid<GT>& grid, const std::vector<char>& in_band,
                           const Grid_settings& settings, const SquaredDistance& squared_distance)
{
  std::vector<std::size_t> band;
  for(std::size_t v = 0; v < in_band.size(); ++v)
    if(in_band[v]) band.push_back(v);
  const std::size_t n = grid.resolution();
  const double h = grid.voxel_size(), sigma = settings.sigma(), cutoff2 = settings.cutoff() * settings.cutoff();
  const auto& o = grid.origin();
  std::vector<double>& f = grid.values();
  parallel_for(band.size(), settings.threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t b = begin; b < end; ++b) {
      const std::size_t v = band[b];
      const Dpoint p(o[0] + (double(v % n) + 0.5) * h, o[1] + (double(v / n % n) + 0.5) * h,
                     o[2] + (double(v / (n * n)) + 0.5) * h);
      const double d2 = squared_distance(p, v);
      f[v] = d2 <= cutoff2 ? std::exp(-d2 / (2. * sigma * sigma)) : 0.;
      if(!parallel_step()) return;
    }
  });
  double sum_of_squares = 0.;
  for(double x : f) sum_of_squares += x * x;
  const double scale = 1. / std::sqrt(sum_of_squares);
  for(double& x : f) x *= scale;
}

// If `closest_triangles` is given, it receives the index of the triangle closest to the centre
// of each voxel of the band (-1 elsewhere), the lowest of those at the same distance: a
// Closest_triangle_field for ISP.
// `tree`: the AABB tree of `triangles`, distance queries accelerated (Triangle_matcher's).
template <typename GT>
void fill_gaussian_distance_transform_of_triangles(Voxel_grid<GT>& grid, const std::vector<Dtriangle>& triangles,
                                                   const Triangle_tree& tree, const Grid_settings& settings,
                                                   std::vector<std::int32_t>* closest_triangles = nullptr)
{
  Progress_stage stage(0., progress_shares::gedt_band);
  const std::vector<char> in_band = band_of_triangles(grid, triangles, settings.cutoff(), settings.threads);
  stage.move_to(progress_shares::gedt_band, 1.);
  if(closest_triangles != nullptr) closest_triangles->assign(grid.values().size(), -1);
  const double tie = equal_distance_fraction_of_voxel * grid.voxel_size();
  fill_gaussian_of_band(grid, in_band, settings, [&](const Dpoint& p, std::size_t v) {
    const auto closest = tree.closest_point_and_primitive(p);
    if(closest_triangles != nullptr) (*closest_triangles)[v] = lowest_closest_triangle(tree, triangles, p, closest, tie);
    return CGAL::squared_distance(p, closest.first);
  });
}

template <typename GT>
void fill_gaussian_distance_transform_of_triangles(Voxel_grid<GT>& grid,
                                                   const std::vector<Dtriangle>& triangles,
                                                   const Grid_settings& settings,
                                                   std::vector<std::int32_t>* closest_triangles = nullptr)
{
  Progress_stage stage(0., progress_shares::gedt_tree);
  Triangle_tree tree(triangles.begin(), triangles.end());
  build_triangle_tree(tree);
  accelerate_distance_queries(tree, triangles);
  tree.squared_distance(CGAL::ORIGIN); // builds the search structure before threads share the tree
  stage.move_to(progress_shares::gedt_tree, 1.);
  fill_gaussian_distance_transform_of_triangles(grid, triangles, tree, settings, closest_triangles);
}

// The GEDT of a triangle soup of the given frame, on the grid `settings` describe.
template <typename GT>
Voxel_grid<GT> gaussian_distance_transform_of_triangles(const std::vector<Dtriangle>& triangles, const Shape_frame& frame,
                                                       const Grid_settings& settings,
                                                       std::vector<std::int32_t>* closest_triangles = nullptr)
{
  Voxel_grid<GT> grid = empty_grid<GT>(frame, settings);
  fill_gaussian_distance_transform_of_triangles(grid, triangles, settings, closest_triangles);
  return grid;
}

// The same with the AABB tree of `triangles` (distance queries accelerated): the detection
// shares its matcher's, one tree instead of two (on a million faces, about a second).
template <typename GT>
Voxel_grid<GT> gaussian_distance_transform_of_triangles(const std::vector<Dtriangle>& triangles, const Triangle_tree& tree,
                                                       const Shape_frame& frame, const Grid_settings& settings,
                                                       std::vector<std::int32_t>* closest_triangles = nullptr)
{
  Voxel_grid<GT> grid = empty_grid<GT>(frame, settings);
  fill_gaussian_distance_transform_of_triangles(grid, triangles, tree, settings, closest_triangles);
  return grid;
}

// The GEDT of a triangle soup, on the grid the named parameters describe.
template <typename GT, typename NamedParameters>
Voxel_grid<GT> gaussian_distance_transform_of_triangles(const std::vector<Dtriangle>& triangles, const NamedParameters& np,
                                                       std::vector<std::int32_t>* closest_triangles = nullptr)
{
  const Shape_frame frame = frame_of_triangles(triangles);
  return gaussian_distance_transform_of_triangles<GT>(triangles, frame, grid_settings(np, frame.radius), closest_triangles);
}

template <typename GT>
void fill_gaussian_distance_transform_of_points(Voxel_grid<GT>& grid, const std::vector<Dpoint>& points,
                                                const Grid_settings& settings)
{
  std::vector<char> in_band(grid.values().size(), 0);
  Progress_stage stage(0., progress_shares::gedt_band_of_points);
  for(std::size_t i = 0; i < points.size(); ++i) {
    sequential_step(i, points.size());
    mark_band_of_point(grid, points[i], settings.cutoff(), in_band);
  }
  stage.move_to(progress_shares::gedt_band_of_points, 1.);
  const Nearest_point nearest(points);
  fill_gaussian_of_band(grid, in_band, settings, [&](const Dpoint& p, std::size_t) { return nearest(p).squared_distance; });
}

// The GEDT of a point set of the given frame, on the grid `settings` describe.
template <typename GT>
Voxel_grid<GT> gaussian_distance_transform_of_points(const std::vector<Dpoint>& points, const Shape_frame& frame,
                                                     const Grid_settings& settings)
{
  Voxel_grid<GT> grid = empty_grid<GT>(frame, settings);
  fill_gaussian_distance_transform_of_points(grid, points, settings);
  return grid;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_GRID_GAUSSIAN_DISTANCE_TRANSFORM_H
