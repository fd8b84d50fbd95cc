// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_DETECTION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_DETECTION_H

// The detection pipeline of the principal symmetries (thesis, section 3.3): a triangle surface
// or a point set, its GEDT and PRST, the candidate maxima, each refined by Iterative Symmetric
// Points. detect_principal_symmetries(), the symmetry frame and the segmentation all run it.

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/detection/candidates.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// ISP settings from the named parameters; the GEDT of the shape tells which points lie beyond
// its 3 sigma band.
template <typename GT, typename NamedParameters>
Isp_settings isp_settings(const NamedParameters& np, const Voxel_grid<GT>& gedt)
{
  const Grid_settings grid = grid_settings(np, gedt.radius());
  Isp_settings settings;
  settings.sigma = grid.sigma();
  settings.radius = gedt.radius();
  settings.max_iterations =
    unsigned(parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_iterations), defaults::isp_iterations));
  settings.threads = grid.threads;
  settings.beyond_band = [&gedt](const Eigen::Vector3d& p) { return gedt.trilinear_value(p.x(), p.y(), p.z()) == 0.; };
  return settings;
}

// The PRST of a detection. Its maxima need only be located to a bin or two, ISP doing the
// rest: 5e5 Monte Carlo samples suffice (a quarter of the transform's default) unless the
// user chose a number.
template <typename GT, typename NamedParameters>
Reflective_symmetry_transform<GT> detection_transform(const Voxel_grid<GT>& gedt, const NamedParameters& np)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::number_of_samples_t>::value)
    return reflective_symmetry_transform(gedt, np.number_of_samples(defaults::detection_monte_carlo_pairs));
  else
    return reflective_symmetry_transform(gedt, np);
}

// A triangle surface ready for refinement: its GEDT, the AABB tree of its triangles, and the
// closest triangle of each voxel of the GEDT's band (recorded with the GEDT) for the walk of ISP.
// Built in place: the tree and the field refer to the triangles.
template <typename GT>
class Triangle_surface
{
  std::vector<std::int32_t> closest_triangles_; // moved into the field

public:
  const std::vector<Dtriangle> triangles;
  const Voxel_grid<GT> gedt;
  const Triangle_matcher matcher;
  const Closest_triangle_field field;

  template <typename NamedParameters>
  Triangle_surface(std::vector<Dtriangle> surface_triangles, const NamedParameters& np)
    : triangles(std::move(surface_triangles)),
      gedt(gaussian_distance_transform_of_triangles<GT>(triangles, np, &closest_triangles_)), matcher(triangles),
      field(triangles, matcher, std::move(closest_triangles_), gedt.origin(), gedt.voxel_size(), gedt.resolution())
  {}
  Triangle_surface(const Triangle_surface&) = delete;
  Triangle_surface& operator=(const Triangle_surface&) = delete;
};

// Candidates of the PRST refined by ISP (walking with `walk_matcher` if given), kept if they
// stay near their bin, measured on the GEDT, merged when equal, strongest first.
template <typename GT, typename Matcher, typename NamedParameters, typename Walk_matcher = Matcher>
std::vector<Principal_symmetry<GT>> refine_candidates(const Voxel_grid<GT>& gedt,
                                                      const Reflective_symmetry_transform<GT>& prst,
                                                      const std::vector<Eigen::Vector3d>& samples,
                                                      const Matcher& matcher, const NamedParameters& np,
                                                      const Walk_matcher* walk_matcher = nullptr)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t max_planes = std::size_t(choose_parameter(get_parameter(np, internal_np::st_max_number_of_planes), defaults::max_number_of_planes));
  const double t = double(choose_parameter(get_parameter(np, internal_np::st_symmetry_threshold), defaults::symmetry_threshold));
  const double l = double(choose_parameter(get_parameter(np, internal_np::st_laplacian_threshold), defaults::laplacian_threshold));
  const bool verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);
  const Isp_settings settings = isp_settings(np, gedt);

  // Candidates on one ridge of the transform converge to the same plane: the cheap coarse phase
  // of ISP tells them apart, and only the first of each gets the fine phase.
  std::vector<Dplane> accepted; // the coarse and the refined plane of each accepted candidate
  std::vector<Principal_symmetry<GT>> result;
  const double angle = prst.bins().theta_step(), distance = prst.bins().offset_step();
  const Eigen::Vector3d center = center_of(prst.bins());
  // The thesis drops a candidate that leaves its bin: an unstable maximum. Monte Carlo noise
  // and the smoothing move maxima along flat ridges by a few bins, hence a reach of 3 bins.
  constexpr long unstable_reach = 3;
  std::vector<std::array<std::size_t, 3>> candidates = symmetry_candidates(prst, t, l);
  // Most candidates are dropped as duplicates or unstable; beyond a few per plane asked for, the
  // weaker ones would be cut off anyway.
  if(candidates.size() > 10 * max_planes) candidates.resize(10 * max_planes);
  for(const auto& bin : candidates) {
    if(result.size() == max_planes) break;
    const auto start = std::chrono::steady_clock::now();
    auto near_accepted = [&](const Dplane& plane, double factor) {
      return std::any_of(accepted.begin(), accepted.end(),
                         [&](const Dplane& p) { return same_plane(p, plane, factor * angle, factor * distance, center); });
    };
    // Stop refining as soon as the plane heads for an accepted one or out of reach of its bin.
    auto abandon = [&](const Dplane& plane) {
      return near_accepted(plane, 2.) || !stays_near_bin(prst, plane, bin, unstable_reach);
    };
    const Isp_result coarse = iterative_symmetric_points(samples, to_dplane(prst.plane(bin)), matcher, settings,
                                                         Isp_phase::COARSE, abandon, walk_matcher);
    // The coarse phase stops within about a bin of the optimum: closer than two bins to an
    // accepted plane, the fine phase would only find that plane again.
    // A start that the coarse phase cannot settle is on a slope or a ridge, not near a maximum;
    // with no normals (a point set), the point-to-point fit creeps and needs the fine phase.
    const bool seen = near_accepted(coarse.plane, 2.), settled = coarse.converged || !Matcher::has_normals;
    Isp_result refined = coarse;
    if(!seen && settled)
      refined = iterative_symmetric_points(samples, coarse.plane, matcher, settings, Isp_phase::FINE, abandon, walk_matcher);
    const char* verdict = seen || near_accepted(refined.plane, 2.)              ? "same as an accepted plane"
                          : !stays_near_bin(prst, refined.plane, bin, unstable_reach) ? "left its bin"
                          : !settled || !(refined.support > 0.)                      ? "no convergence"
                                                                                     : nullptr;
    if(verbose)
      std::cerr << "  candidate (" << bin[0] << "," << bin[1] << "," << bin[2] << ") SM " << prst.value(bin)
                << ": ISP " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
                << " s (" << coarse.iterations << " + " << (seen || !settled ? 0u : refined.iterations)
                << " iterations), support " << refined.support << (verdict ? ", dropped: " : ", accepted") << (verdict ? verdict : "")
                << "\n";
    if(verdict != nullptr) continue;
    accepted.push_back(coarse.plane);
    accepted.push_back(refined.plane);
    const typename GT::Plane_3 plane = to_plane<GT>(refined.plane);
    result.push_back({plane, symmetry_measure(gedt, plane), refined.support});
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const Principal_symmetry<GT>& a, const Principal_symmetry<GT>& b) { return a.symmetry > b.symmetry; });
  if(result.size() > max_planes) result.resize(max_planes);
  return result;
}

// A detection and the transform it started from (the symmetry frame searches the transform too).
template <typename GT>
struct Detection
{
  std::vector<Principal_symmetry<GT>> symmetries;
  Reflective_symmetry_transform<GT> prst;
};

template <typename GT, typename NamedParameters>
Detection<GT> detection_of_surface(const Triangle_surface<GT>& surface, const NamedParameters& np)
{
  Reflective_symmetry_transform<GT> prst = detection_transform(surface.gedt, np);
  std::vector<Principal_symmetry<GT>> symmetries = refine_candidates(
    surface.gedt, prst, surface_samples(surface.triangles, np), surface.matcher, np, &surface.field);
  return {std::move(symmetries), std::move(prst)};
}

template <typename TriangleMesh, typename NamedParameters>
Detection<typename Mesh_geom_traits<TriangleMesh, NamedParameters>::type> detection_of_mesh(const TriangleMesh& tm,
                                                                                          const NamedParameters& np)
{
  typedef typename Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const Triangle_surface<GT> surface(triangles_of_mesh(tm, np), np);
  return detection_of_surface(surface, np);
}

template <typename PointRange, typename NamedParameters>
Detection<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>
detection_of_points(const PointRange& points, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits GT;
  const std::vector<Dpoint> samples = points_of_range(points, NP_helper::get_const_point_map(points, np));
  const Voxel_grid<GT> gedt = gaussian_distance_transform_of_points(points, np);
  Reflective_symmetry_transform<GT> prst = detection_transform(gedt, np);
  const Point_matcher matcher(samples);
  std::vector<Principal_symmetry<GT>> symmetries = refine_candidates(gedt, prst, point_samples(samples, np), matcher, np);
  return {std::move(symmetries), std::move(prst)};
}

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_DETECTION_H
