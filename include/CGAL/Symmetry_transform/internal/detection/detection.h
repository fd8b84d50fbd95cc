// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_DETECTION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_DETECTION_H

// The detection pipeline of the principal symmetries (thesis, section 3.3): a triangle surface
// or a point set, its GEDT and PRST, the candidate maxima, each refined by Iterative Symmetric
// Points. detect_principal_symmetries(), the symmetry frame and the segmentation all run it.

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/detection/border_curve.h>
#include <CGAL/Symmetry_transform/internal/detection/candidates.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>
#include <CGAL/Symmetry_transform/internal/detection/parts_apart.h>
#include <CGAL/Symmetry_transform/internal/detection/refinement.h>
#include <CGAL/Symmetry_transform/internal/detection/settings.h>
#include <CGAL/Symmetry_transform/internal/detection/triangle_surface.h>
#include <CGAL/Symmetry_transform/internal/grid/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <algorithm>
#include <iterator>
#include <optional>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The PRST of a detection. Its maxima need only be located to a bin or two, ISP doing the
// rest: defaults::detection_monte_carlo_pairs Monte Carlo samples suffice unless the user chose
// a number. The transform reads its own options.
template <typename GT, typename NamedParameters>
Reflective_symmetry_transform<GT> detection_transform(const Voxel_grid<GT>& gedt, const NamedParameters& np)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::number_of_samples_t>::value)
    return reflective_symmetry_transform(gedt, np.number_of_samples(defaults::detection_monte_carlo_pairs));
  else
    return reflective_symmetry_transform(gedt, np);
}

// A detection and the transform it started from (the symmetry frame searches the transform too).
template <typename GT>
struct Detection
{
  std::vector<Principal_symmetry<GT>> symmetries;
  Reflective_symmetry_transform<GT> prst;
};

// The transform `prst`, its centre moved by `shift`: the same values, for the same planes moved.
template <typename GT>
Reflective_symmetry_transform<GT> shifted(Reflective_symmetry_transform<GT> prst, const Eigen::Vector3d& shift)
{
  prst.recenter(to_point<GT>(to_eigen(to_dpoint(prst.center())) + shift));
  return prst;
}

// Symmetries in the coordinates `local`, moved to the input's.
template <typename GT>
std::vector<Principal_symmetry<GT>> to_input(const Local_coordinates& local, std::vector<Principal_symmetry<GT>> symmetries)
{
  for(Principal_symmetry<GT>& s : symmetries) {
    s.plane = to_plane<GT>(local.to_input(to_dplane(s.plane)));
    if(s.family != Mirror_family::ONE_PLANE)
      s.axis = typename GT::Line_3(to_point<GT>(local.to_input(to_eigen(to_dpoint(s.axis.point())))), s.axis.to_vector());
  }
  return symmetries;
}

// A detection in the coordinates `local`, moved to the input's.
template <typename GT>
Detection<GT> to_input(const Local_coordinates& local, Detection<GT> detection)
{
  return {to_input(local, std::move(detection.symmetries)), shifted(std::move(detection.prst), local.center)};
}

// The candidates of `prst`, the transform of `surface` (both in the surface's local coordinates,
// as the planes returned), refined: ISP walks with the surface's closest-triangle field and ends
// with exact searches, then, on a flat surface, with the fit of in-plane mirrors to its border.
template <typename GT>
std::vector<Principal_symmetry<GT>> principal_symmetries_of_surface(const Triangle_surface<GT>& surface,
                                                                   const Reflective_symmetry_transform<GT>& prst,
                                                                   const Detection_settings& settings)
{
  Isp_settings isp = isp_settings(surface.grid, settings.isp_iterations, surface.gedt);
  const std::optional<Border_curve> border = border_curve(surface.triangles, surface.frame.radius, isp.sigma);
  isp.border = border ? &*border : nullptr;
  return refine_candidates(surface.gedt, prst, surface_samples(surface.triangles, settings.sampling), surface.matcher, isp,
                           settings.candidates, &surface.field);
}

template <typename GT, typename NamedParameters>
std::vector<Principal_symmetry<GT>> symmetries_of_parts_apart(const Triangle_surface<GT>& surface,
                                                              const std::vector<Shape_part>& parts,
                                                              const Detection_settings& settings, const NamedParameters& np);

// The detection on a surface built with settings.grid, in the input's coordinates; the transform
// reads its own options from `np`. Unless `whole_only`, a surface whose parts lie far apart is
// detected at the scale of its parts (parts_apart.h).
template <typename GT, typename NamedParameters>
Detection<GT> detection_of_surface(const Triangle_surface<GT>& surface, const Detection_settings& settings,
                                   const NamedParameters& np, bool whole_only = false)
{
  Progress_stage stage(0., progress_shares::detection_transform);
  Reflective_symmetry_transform<GT> prst = detection_transform(surface.gedt, np);
  throw_if_cancelled(); // the transform is then zero
  stage.move_to(progress_shares::detection_transform, 1.);
  const std::vector<Shape_part> parts =
    whole_only ? std::vector<Shape_part>() : parts_of(surface.triangles, surface.gedt, surface.grid);
  std::vector<Principal_symmetry<GT>> symmetries = parts_lie_apart(parts, surface.frame.radius)
                                                     ? symmetries_of_parts_apart(surface, parts, settings, np)
                                                     : principal_symmetries_of_surface(surface, prst, settings);
  return to_input(surface.local, Detection<GT>{std::move(symmetries), std::move(prst)});
}

// The triangles of the largest of `parts` of `surface`.
template <typename GT>
std::vector<Dtriangle> largest_part(const Triangle_surface<GT>& surface, const std::vector<Shape_part>& parts)
{
  std::vector<Dtriangle> largest;
  for(std::size_t t : parts.front().triangles) largest.push_back(surface.triangles[t]);
  return largest;
}

// The settings of a refinement on the whole `surface` at the scale of its part `part`: the
// weights of the part's grid, the band of the whole.
template <typename GT>
Isp_settings part_scale_settings(const Triangle_surface<GT>& surface, const Triangle_surface<GT>& part,
                                 const Detection_settings& settings)
{
  Isp_settings isp = isp_settings(part.grid, settings.isp_iterations, surface.gedt);
  isp.radius = part.frame.radius;
  return isp;
}

// The planes of a surface whose parts lie far apart, in its local coordinates: those of its
// largest part `part`, detected alone, and the bisectors of alike parts, refined and measured on
// the whole surface at the part's scale.
template <typename GT, typename NamedParameters>
std::vector<Principal_symmetry<GT>> symmetries_at_part_scale(const Triangle_surface<GT>& surface,
                                                             const std::vector<Shape_part>& parts,
                                                             const Triangle_surface<GT>& part,
                                                             const Detection_settings& settings, const NamedParameters& np)
{
  Progress_stage stage(0., parts_apart_detection_share);
  std::vector<Dplane> candidates = bisectors_of_alike_parts(parts);
  for(const Principal_symmetry<GT>& s : detection_of_surface(part, settings, np, true).symmetries)
    candidates.push_back(to_dplane(s.plane));
  throw_if_cancelled(); // the part's detection keeps what it has; this one stops
  stage.move_to(parts_apart_detection_share, 1.);
  std::vector<Principal_symmetry<GT>> symmetries =
    refined_at_part_scale(candidates, parts.front().centroid, surface.gedt, surface_samples(surface.triangles, settings.sampling),
                          surface.matcher, part_scale_settings(surface, part, settings));
  keep_groups_and_strongest(symmetries, settings.candidates, false);
  return symmetries;
}

template <typename GT, typename NamedParameters>
std::vector<Principal_symmetry<GT>> symmetries_of_parts_apart(const Triangle_surface<GT>& surface,
                                                              const std::vector<Shape_part>& parts,
                                                              const Detection_settings& settings, const NamedParameters& np)
{
  Progress_stage stage(0., parts_apart_surface_share);
  const Triangle_surface<GT> part(largest_part(surface, parts), settings.grid);
  stage.move_to(parts_apart_surface_share, 1.);
  return symmetries_at_part_scale(surface, parts, part, settings, np);
}

// The detection on a surface built with the grid options of `np`.
template <typename GT, typename NamedParameters>
Detection<GT> detection_of_surface(const Triangle_surface<GT>& surface, const NamedParameters& np)
{
  return detection_of_surface(surface, detection_settings(np), np);
}

template <typename TriangleMesh, typename NamedParameters>
Detection<typename Mesh_geom_traits<TriangleMesh, NamedParameters>::type> detection_of_mesh(const TriangleMesh& tm,
                                                                                          const NamedParameters& np)
{
  typedef typename Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const double surface_share = progress_shares::detection_surface_share(num_faces(tm));
  Progress_stage stage(0., surface_share);
  std::vector<Dtriangle> triangles = triangles_of_mesh(tm, np);
  const Detection_settings settings = detection_settings(np);
  const Triangle_surface<GT> surface(std::move(triangles), settings.grid);
  stage.move_to(surface_share, 1.);
  return detection_of_surface(surface, settings, np);
}

// The detection on the non-degenerate triangles of a soup, which needs no repair.
template <typename PointRange, typename TriangleRange, typename NamedParameters>
Detection<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>
detection_of_triangle_soup(const PointRange& points, const TriangleRange& triangles, const NamedParameters& np)
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GT;
  const Detection_settings settings = detection_settings(np);
  const double surface_share = progress_shares::detection_surface_share(std::size(triangles));
  Progress_stage stage(0., surface_share);
  const Triangle_surface<GT> surface(triangles_of_soup(points, triangles, np), settings.grid);
  stage.move_to(surface_share, 1.);
  return detection_of_surface(surface, settings, np);
}

// In coordinates centred on the points. With a `normal_map`, ISP matches with the normals of
// the points and fits point to plane.
template <typename PointRange, typename NamedParameters>
Detection<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>
detection_of_points(const PointRange& points, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits GT;
  const std::vector<Dpoint> input = points_of_range(points, NP_helper::get_const_point_map(points, np));
  const Local_coordinates local = local_coordinates_of(input);
  const std::vector<Dpoint> shape = to_local(local, input);
  const Detection_settings settings = detection_settings(np);
  const Shape_frame frame = frame_of_points(shape);
  const Grid_settings grid = grid_settings(settings.grid, frame.radius);
  const double gedt_share = progress_shares::detection_surface_share(shape.size()),
               refinements = gedt_share + (1. - gedt_share) * progress_shares::detection_transform;
  Progress_stage stage(0., gedt_share);
  const Voxel_grid<GT> gedt = gaussian_distance_transform_of_points<GT>(shape, frame, grid);
  stage.move_to(gedt_share, refinements);
  Reflective_symmetry_transform<GT> prst = detection_transform(gedt, np);
  throw_if_cancelled(); // the transform is then zero
  stage.move_to(refinements, 1.);
  auto refined = [&](const auto& matcher) {
    return refine_candidates(gedt, prst, point_samples(shape, settings.sampling), matcher,
                             isp_settings(grid, settings.isp_iterations, gedt), settings.candidates);
  };
  std::vector<Principal_symmetry<GT>> symmetries;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::normal_t>::value)
    symmetries = refined(Oriented_point_matcher(shape, unit_normals_of_range(points, NP_helper::get_normal_map(points, np))));
  else
    symmetries = refined(Point_matcher(shape));
  return to_input(local, Detection<GT>{std::move(symmetries), std::move(prst)});
}

} // namespace CGAL::Symmetry_transform::internal

#include <CGAL/Symmetry_transform/internal/detection/precompiled_core.h>

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_DETECTION_H
