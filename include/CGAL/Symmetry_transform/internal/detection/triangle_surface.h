// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_TRIANGLE_SURFACE_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_TRIANGLE_SURFACE_H

// A triangle surface ready for the refinement of its symmetries: its GEDT, the AABB tree of its
// triangles (built once, for both), and the closest triangle of each voxel of the GEDT's band
// (recorded with the GEDT) for the walk of ISP. One is built per detection, and the segmentation uses it again for its
// features.

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>
#include <CGAL/Symmetry_transform/internal/grid/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Built in place, neither copied nor moved: the tree and the field refer to `triangles`, the
// field to the tree. The members are declared, hence built, in the order they depend on each other.
// Everything but `local` is in the coordinates `local`, centred on the shape, whatever its
// position (DESIGN.md, invariance): planes and points go through `local` on their way in and out.
template <typename GT>
class Triangle_surface
{
public:
  const Local_coordinates local;
  const std::vector<Dtriangle> triangles;
  const Shape_frame frame;   // centre of mass and radius
  const Grid_settings grid;  // of the GEDT
  const Triangle_matcher matcher; // its tree also serves the GEDT
  const Voxel_grid<GT> gedt;
  const Closest_triangle_field field;

  // `surface_triangles` in the input's coordinates.
  Triangle_surface(std::vector<Dtriangle> surface_triangles, const Grid_options& options)
    : Triangle_surface(std::move(surface_triangles), options, std::vector<std::int32_t>())
  {}

  template <typename NamedParameters>
  Triangle_surface(std::vector<Dtriangle> surface_triangles, const NamedParameters& np)
    : Triangle_surface(std::move(surface_triangles), grid_options(np))
  {}

  Triangle_surface(const Triangle_surface&) = delete;
  Triangle_surface& operator=(const Triangle_surface&) = delete;

private:
  // `closest_triangles`, empty, receives the closest triangle of each voxel from the GEDT and
  // goes to the field.
  Triangle_surface(std::vector<Dtriangle>&& surface_triangles, const Grid_options& options,
                   std::vector<std::int32_t>&& closest_triangles);
};

// Out of the class, so that a precompiled core (precompiled_core.h) can keep it out of user code.
template <typename GT>
Triangle_surface<GT>::Triangle_surface(std::vector<Dtriangle>&& surface_triangles, const Grid_options& options,
                                       std::vector<std::int32_t>&& closest_triangles)
  : local(local_coordinates_of(surface_triangles)), triangles(to_local(local, std::move(surface_triangles))),
    frame(frame_of_triangles(triangles)),
    grid(grid_settings(options, frame.radius)),
    matcher([&] { // the first part of the progress of a surface (progress.h)
      Progress_stage stage(0., progress_shares::surface_tree);
      return Triangle_matcher(triangles);
    }()),
    gedt([&] {
      Progress_stage stage(progress_shares::surface_tree, 1.);
      return gaussian_distance_transform_of_triangles<GT>(triangles, matcher.tree(), frame, grid, &closest_triangles);
    }()),
    field(triangles, matcher, std::move(closest_triangles), gedt.origin(), gedt.voxel_size(), gedt.resolution())
{}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_TRIANGLE_SURFACE_H
