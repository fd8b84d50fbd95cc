// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PARTS_APART_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PARTS_APART_H

// Shapes whose parts lie far apart compared with their size (two copies of an object tens of
// radii apart, two cubes 1e4 apart). The grid covers the whole shape: each part is then a blob
// of a few voxels, whose transform cannot place a plane nor tell a symmetry from a near one.
// The parts are the connected regions of the GEDT's band. Any mirror of the whole maps the
// largest part P onto itself or onto a part Q like it; in the latter case it is the bisector of
// their centroids. The candidates are therefore the planes detected on P alone, at P's own
// scale, and these bisectors; each is refined by ISP on the whole shape with the weights of P's
// scale, which also measure it.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/detection/candidates.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Parts lie apart when the shape's radius exceeds this many times the largest part's: the
// transform of the whole finds the mirror between two copies up to about 16 times (gaps of 30
// radii), not at 26 (50 radii), on the sample meshes.
constexpr double parts_apart_radius_ratio = 8.;
// Two parts are alike when their areas and radii differ by less than this fraction.
constexpr double alike_parts_tolerance = 0.02;
// Refined planes closer than this (sine of the angle; offset over the part's radius) are one.
constexpr double same_part_plane_tolerance = 1e-4;
// The shares of the progress: the largest part's surface; then, of the rest, its detection; the
// refinements take the rest.
constexpr double parts_apart_surface_share = 0.1;
constexpr double parts_apart_detection_share = 0.5;
// The bisectors tried, those of the alike parts nearest to the largest: each is a refinement on
// the whole shape.
constexpr std::size_t max_bisector_candidates = 16;

struct Shape_part
{
  std::vector<std::size_t> triangles;
  double area = 0.;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(); // of the area
  double radius = 0.;                                  // farthest vertex from the centroid
};

// The connected regions of the non-zero samples of `gedt` (six neighbours): per sample its
// region, from 1, or 0 for a zero sample.
template <typename GT>
std::vector<int> band_regions(const Voxel_grid<GT>& gedt)
{
  const long n = long(gedt.resolution());
  std::vector<int> region(gedt.values().size(), 0);
  std::vector<long> stack;
  int count = 0;
  for(long start = 0; start < long(region.size()); ++start) {
    if(region[std::size_t(start)] != 0 || gedt.values()[std::size_t(start)] == 0.) continue;
    region[std::size_t(start)] = ++count;
    stack.push_back(start);
    while(!stack.empty()) {
      const long s = stack.back();
      stack.pop_back();
      const std::array<long, 3> ijk = {s % n, (s / n) % n, s / (n * n)};
      for(int axis = 0; axis < 3; ++axis)
        for(long step : {-1L, 1L}) {
          if(ijk[axis] + step < 0 || ijk[axis] + step >= n) continue;
          const long t = s + step * (axis == 0 ? 1 : axis == 1 ? n : n * n);
          if(region[std::size_t(t)] != 0 || gedt.values()[std::size_t(t)] == 0.) continue;
          region[std::size_t(t)] = count;
          stack.push_back(t);
        }
    }
  }
  return region;
}

// The parts of `triangles` (each in the region of its centroid's voxel), largest area first;
// none if the band of the GEDT `gedt`, made with `grid`, may not hold every triangle's voxel in
// one region (a Gaussian width below a voxel).
template <typename GT>
std::vector<Shape_part> parts_of(const std::vector<Dtriangle>& triangles, const Voxel_grid<GT>& gedt,
                                 const Grid_settings& grid)
{
  if(grid.cutoff() < std::sqrt(3.) * grid.voxel_size()) return {};
  const std::vector<int> region = band_regions(gedt);
  const int count = region.empty() ? 0 : *std::max_element(region.begin(), region.end());
  if(count < 2) return {}; // one region: nothing lies apart, and no triangle need be read
  std::vector<Shape_part> parts(std::size_t(count) + 1); // parts[0]: triangles off the band (none)
  const long n = long(gedt.resolution());
  for(std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3d c = (to_eigen(triangles[t][0]) + to_eigen(triangles[t][1]) + to_eigen(triangles[t][2])) / 3.;
    std::array<long, 3> ijk;
    for(int a = 0; a < 3; ++a)
      ijk[a] = std::clamp(long(std::floor((c[a] - gedt.origin()[a]) / gedt.voxel_size())), 0L, n - 1);
    Shape_part& part = parts[std::size_t(region[gedt.index(std::size_t(ijk[0]), std::size_t(ijk[1]), std::size_t(ijk[2]))])];
    const double area = std::sqrt(triangles[t].squared_area());
    part.triangles.push_back(t);
    part.area += area;
    part.centroid += area * c;
  }
  if(!parts.front().triangles.empty()) return {}; // a triangle off the band: no parts to trust
  parts.erase(parts.begin());
  parts.erase(std::remove_if(parts.begin(), parts.end(), [](const Shape_part& p) { return !(p.area > 0.); }), parts.end());
  for(Shape_part& part : parts) {
    part.centroid /= part.area;
    for(std::size_t t : part.triangles)
      for(int v = 0; v < 3; ++v) part.radius = (std::max)(part.radius, (to_eigen(triangles[t][v]) - part.centroid).norm());
  }
  std::stable_sort(parts.begin(), parts.end(), [](const Shape_part& a, const Shape_part& b) { return a.area > b.area; });
  return parts;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool parts_lie_apart(const std::vector<Shape_part>& parts, double shape_radius);

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool alike(const Shape_part& a, const Shape_part& b);

// The mirrors that may map the largest part onto another: the bisectors of their centroids, of
// the max_bisector_candidates alike parts nearest to it.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Dplane> bisectors_of_alike_parts(const std::vector<Shape_part>& parts);

// The candidates refined by ISP with `settings` (the weights of the part's scale), each in
// coordinates centred on the point of the candidate nearest to `part_center` (the largest part's:
// a fit centred far from the samples it turns is ill-conditioned), and measured by the smaller of
// its support there and its symmetry on the GEDT of the whole; one plane of each set of planes
// refined to the same, strongest first.
template <typename GT, typename Matcher>
std::vector<Principal_symmetry<GT>> refined_at_part_scale(const std::vector<Dplane>& candidates,
                                                          const Eigen::Vector3d& part_center, const Voxel_grid<GT>& gedt,
                                                          const std::vector<Eigen::Vector3d>& samples,
                                                          const Matcher& matcher, Isp_settings settings)
{
  std::vector<Principal_symmetry<GT>> result;
  std::vector<Dplane> kept;
  const double tolerance = same_part_plane_tolerance;
  for(const Dplane& candidate : candidates) {
    settings.center = part_center - candidate.signed_distance(part_center) * candidate.normal;
    const std::optional<Isp_result> refined = unless_cancelled([&] {
      report_progress(std::size_t(&candidate - candidates.data()), candidates.size());
      return iterative_symmetric_points(samples, candidate, matcher, settings);
    });
    if(!refined) break; // cancelled: the planes refined so far (progress.h)
    if(!(refined->support > 0.) ||
       std::any_of(kept.begin(), kept.end(), [&](const Dplane& p) {
         return same_plane(p, refined->plane, tolerance, tolerance * settings.radius, part_center);
       }))
      continue;
    kept.push_back(refined->plane);
    const typename GT::Plane_3 plane = to_plane<GT>(refined->plane);
    const double measure = plane_symmetry_measure(gedt, plane, settings.threads);
    result.push_back({plane, (std::min)(measure, refined->support), refined->support});
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const Principal_symmetry<GT>& a, const Principal_symmetry<GT>& b) { return a.symmetry > b.symmetry; });
  return result;
}

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool parts_lie_apart(const std::vector<Shape_part>& parts, double shape_radius)
{
  return parts.size() >= 2 && parts.front().radius * parts_apart_radius_ratio < shape_radius;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool alike(const Shape_part& a, const Shape_part& b)
{
  auto close = [](double x, double y) { return std::abs(x - y) <= alike_parts_tolerance * (std::max)(x, y); };
  return close(a.area, b.area) && close(a.radius, b.radius);
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE std::vector<Dplane> bisectors_of_alike_parts(const std::vector<Shape_part>& parts)
{
  const Shape_part& largest = parts.front();
  std::vector<const Shape_part*> alike_parts;
  for(std::size_t q = 1; q < parts.size(); ++q)
    if(alike(largest, parts[q]) && (parts[q].centroid - largest.centroid).norm() > largest.radius)
      alike_parts.push_back(&parts[q]);
  auto distance = [&](const Shape_part* q) { return (q->centroid - largest.centroid).norm(); };
  std::stable_sort(alike_parts.begin(), alike_parts.end(),
                   [&](const Shape_part* a, const Shape_part* b) { return distance(a) < distance(b); });
  alike_parts.resize((std::min)(alike_parts.size(), max_bisector_candidates));
  std::vector<Dplane> bisectors;
  for(const Shape_part* q : alike_parts) {
    const Eigen::Vector3d normal = (q->centroid - largest.centroid).normalized();
    bisectors.push_back({normal, normal.dot(0.5 * (largest.centroid + q->centroid))});
  }
  return bisectors;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_PARTS_APART_H
