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

// Marks the voxels whose centre lies within `cutoff` of the plane of a triangle and inside
// its bounding box grown by `cutoff`: a superset of the band where the GEDT is non-zero.
template <typename GT>
void mark_band_of_triangle(const Voxel_grid<GT>& grid, const Dtriangle& t, double cutoff,
                           std::vector<char>& in_band)
{
  const Bbox_3 box = t.bbox();
  Dvector normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
  normal = normal / std::sqrt(normal.squared_length());
  for_each_voxel_in_box(grid, {box.xmin() - cutoff, box.ymin() - cutoff, box.zmin() - cutoff},
                        {box.xmax() + cutoff, box.ymax() + cutoff, box.zmax() + cutoff},
                        [&](std::size_t v, double x, double y, double z) {
                          const Dvector d(x - t[0].x(), y - t[0].y(), z - t[0].z());
                          if(std::abs(d * normal) <= cutoff) in_band[v] = 1;
                        });
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
// of each voxel of the band (-1 elsewhere): a Closest_triangle_field for ISP, at no extra cost.
template <typename GT>
void fill_gaussian_distance_transform_of_triangles(Voxel_grid<GT>& grid,
                                                   const std::vector<Dtriangle>& triangles,
                                                   const Grid_settings& settings,
                                                   std::vector<std::int32_t>* closest_triangles = nullptr)
{
  std::vector<char> in_band(grid.values().size(), 0);
  Progress_stage stage(0., progress_shares::gedt_band);
  for(std::size_t i = 0; i < triangles.size(); ++i) {
    sequential_step(i, triangles.size());
    mark_band_of_triangle(grid, triangles[i], settings.cutoff(), in_band);
  }
  stage.move_to(progress_shares::gedt_band, progress_shares::gedt_tree);
  Triangle_tree tree(triangles.begin(), triangles.end());
  build_triangle_tree(tree);
  tree.accelerate_distance_queries();
  tree.squared_distance(CGAL::ORIGIN); // builds the search structure before threads share the tree
  stage.move_to(progress_shares::gedt_tree, 1.);
  if(closest_triangles != nullptr) closest_triangles->assign(grid.values().size(), -1);
  fill_gaussian_of_band(grid, in_band, settings, [&](const Dpoint& p, std::size_t v) {
    const auto closest = tree.closest_point_and_primitive(p);
    if(closest_triangles != nullptr) (*closest_triangles)[v] = std::int32_t(closest.second - triangles.begin());
    return CGAL::squared_distance(p, closest.first);
  });
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
