// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATIONS_OF_SHAPE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATIONS_OF_SHAPE_H

// The rotational symmetries of a triangle surface or of a point set: what the search reads
// (samples and their normals, the GEDT and a coarse one, the centre of mass, the closest-point
// matchers), prepared from the named parameters.

#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/internal/rotation/point_normals.h>
#include <CGAL/Symmetry_transform/internal/rotation/rotation_detection.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The coarse stage reads a GEDT at 32^3 (or the user's resolution if lower): its width, about
// 0.13 R, is the reach of the axis point search and of the pattern search.
constexpr long coarse_grid_resolution = 32;

template <typename NamedParameters>
int max_order(const NamedParameters& np)
{
  check_named_parameters(np); // the first reader of the rotational symmetries: all, before the work
  return int(read_count(np, internal_np::st_max_order, defaults::max_order, parameter_ranges::max_order));
}

template <typename NamedParameters>
long coarse_resolution(const NamedParameters& np)
{
  const long n = read_grid_resolution(np, defaults::grid_resolution);
  return (std::min)(n, coarse_grid_resolution);
}

// The normal of the shape at each sample, from the matcher.
template <typename Matcher>
std::vector<Eigen::Vector3d> normals_at(const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher)
{
  std::vector<Eigen::Vector3d> normals;
  for(const Eigen::Vector3d& x : samples) {
    typename Matcher::Hint none;
    normals.push_back(matcher.closest(x, none).second);
  }
  return normals;
}

// Rotations in the coordinates `local`, moved to the input's.
template <typename GT>
std::vector<Rotational_symmetry<GT>> to_input(const Local_coordinates& local, std::vector<Rotational_symmetry<GT>> rotations)
{
  for(Rotational_symmetry<GT>& r : rotations)
    r.axis = typename GT::Line_3(to_point<GT>(local.to_input(to_eigen(to_dpoint(r.axis.point())))), r.axis.to_vector());
  return rotations;
}

// The rotations of a surface whose parts lie far apart (parts_apart.h), in its local coordinates:
// the products of its exact mirrors (found at the scale of its largest part), each measured on
// the whole surface at that scale, its order tested there. The search of directions and the
// refinement, on a grid that sees each part as a blob, would find round blobs and continuous axes.
template <typename GT, typename NamedParameters>
std::vector<Rotational_symmetry<GT>> rotations_of_parts_apart(const Triangle_surface<GT>& surface,
                                                              const std::vector<Shape_part>& parts, int max_order,
                                                              const NamedParameters& np)
{
  Progress_stage stage(0., parts_apart_surface_share);
  const Detection_settings settings = detection_settings(np);
  const Triangle_surface<GT> part(largest_part(surface, parts), settings.grid);
  stage.move_to(parts_apart_surface_share, 1.);
  std::vector<Dplane> mirrors;
  for(const Principal_symmetry<GT>& s : symmetries_at_part_scale(surface, parts, part, settings, np))
    if(s.support >= group_generator_support) mirrors.push_back(to_dplane(s.plane));
  const std::vector<Eigen::Vector3d> samples = surface_samples(surface.triangles, np);
  const std::vector<Eigen::Vector3d> normals = normals_at(samples, surface.matcher);
  const Mass_distribution mass(surface.triangles);
  const Isp_settings isp = part_scale_settings(surface, part, settings);
  const Rotation_search<GT, Triangle_matcher, Triangle_matcher> search{
    surface.gedt, surface.gedt, isp.sigma, samples, normals, mass, surface.matcher, surface.matcher, isp, max_order,
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::verbose), false)};
  const std::vector<Eigen::Vector3d> order_probes = spread_subset(samples, order_samples);
  std::vector<Found_rotation<GT>> found;
  for(const Axis_candidate& c : plane_pair_candidates(mirrors, max_order, mass.center())) {
    const Rotation_order order = order_about(search, order_probes, c.axis, exact_rotation_width);
    if(order.order < 0) continue;
    Found_rotation<GT> f = measured(search, c.axis, order.order);
    // The grid sees blobs: its measure is that of the parts' places, the support that of their shapes.
    f.symmetry.symmetry = (std::min)(f.symmetry.symmetry, f.symmetry.support);
    if(f.sharp_support >= min_rotation_support) found.push_back(f);
  }
  std::vector<Rotational_symmetry<GT>> result;
  for(const Found_rotation<GT>& f : consistent(std::move(found), mass.center(), part.frame.radius)) result.push_back(f.symmetry);
  return result;
}

// `extra`: further candidate axes, in the input's coordinates, as the result.
template <typename GT, typename NamedParameters>
std::vector<Rotational_symmetry<GT>> rotations_of_surface(const Triangle_surface<GT>& surface, int max_order,
                                                          const std::vector<Axis_candidate>& extra, const NamedParameters& np)
{
  const std::vector<Shape_part> parts = parts_of(surface.triangles, surface.gedt, surface.grid);
  if(parts_lie_apart(parts, surface.frame.radius))
    return to_input(surface.local, rotations_of_parts_apart(surface, parts, max_order, np));
  Progress_stage stage(0., rotation_grids_share);
  const auto coarse_np = np.grid_resolution(int(coarse_resolution(np)));
  const Voxel_grid<GT> coarse = gaussian_distance_transform_of_triangles<GT>(
    surface.triangles, surface.matcher.tree(), surface.frame, grid_settings(coarse_np, surface.frame.radius));
  const std::vector<Eigen::Vector3d> samples = surface_samples(surface.triangles, np);
  const std::vector<Eigen::Vector3d> normals = normals_at(samples, surface.field);
  const Mass_distribution mass(surface.triangles);
  Isp_settings isp = isp_settings(np, surface.gedt);
  const std::optional<Border_curve> border = border_curve(surface.triangles, surface.frame.radius, isp.sigma);
  isp.border = border ? &*border : nullptr;
  stage.move_to(rotation_grids_share, 1.);
  const Rotation_search<GT, Triangle_matcher, Closest_triangle_field> search{
    surface.gedt, coarse, grid_settings(coarse_np, coarse.radius()).sigma(), samples, normals, mass, surface.matcher,
    surface.field, isp, max_order, parameters::choose_parameter(parameters::get_parameter(np, internal_np::verbose), false),
    border ? &*border : nullptr};
  std::vector<Axis_candidate> local_extra = extra;
  for(Axis_candidate& c : local_extra) c.axis.point = surface.local.to_local(c.axis.point);
  return to_input(surface.local, rotational_symmetries(search, local_extra));
}

template <typename PointRange, typename NamedParameters>
std::vector<Rotational_symmetry<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>>
rotations_of_points(const PointRange& points, int max_order, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits GT;
  const std::vector<Dpoint> read = points_of_range(points, NP_helper::get_const_point_map(points, np));
  const Local_coordinates local = local_coordinates_of(read);
  const std::vector<Dpoint> input = to_local(local, read); // centred on the points
  Progress_stage stage(0., rotation_grids_share_of_points);
  const Shape_frame frame = frame_of_points(input);
  const Voxel_grid<GT> gedt = gaussian_distance_transform_of_points<GT>(input, frame, grid_settings(np, frame.radius));
  const auto coarse_np = np.grid_resolution(int(coarse_resolution(np)));
  const Voxel_grid<GT> coarse =
    gaussian_distance_transform_of_points<GT>(input, frame, grid_settings(coarse_np, frame.radius));
  const Point_normal_matcher matcher(input);
  const std::vector<Eigen::Vector3d> samples = point_samples(input, np);
  const std::vector<Eigen::Vector3d> normals = normals_at(samples, matcher);
  const Mass_distribution mass(input);
  stage.move_to(rotation_grids_share_of_points, 1.);
  const Rotation_search<GT, Point_normal_matcher, Point_normal_matcher> search{
    gedt, coarse, grid_settings(coarse_np, coarse.radius()).sigma(), samples, normals, mass, matcher, matcher,
    isp_settings(np, gedt), max_order,
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::verbose), false)};
  return to_input(local, rotational_symmetries(search, {}));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATIONS_OF_SHAPE_H
