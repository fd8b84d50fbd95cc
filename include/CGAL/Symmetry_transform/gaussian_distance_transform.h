// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_GAUSSIAN_DISTANCE_TRANSFORM_H
#define CGAL_SYMMETRY_TRANSFORM_GAUSSIAN_DISTANCE_TRANSFORM_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/grid/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <type_traits>
#include <vector>

namespace CGAL::Symmetry_transform {

namespace internal {

// The GEDT of a shape of frame `frame` filled by fill(grid, settings) under the callback of `np`:
// zero everywhere if the user cancels.
template <typename GT, typename NamedParameters, typename Fill>
Voxel_grid<GT> cancellable_gaussian_distance_transform(const Shape_frame& frame, const NamedParameters& np, const Fill& fill)
{
  const Grid_settings settings = grid_settings(np, frame.radius);
  Voxel_grid<GT> grid = empty_grid<GT>(frame, settings);
  with_progress(np, [&] { fill(grid, settings); return true; }, [&] {
    std::fill(grid.values().begin(), grid.values().end(), 0.);
    return false;
  });
  return grid;
}

// The transform of `shape` (triangles or points, in the input's coordinates), computed in
// coordinates centred on it (DESIGN.md, invariance), the grid then placed on the input.
template <typename GT, typename Item, typename NamedParameters>
Voxel_grid<GT> cancellable_gaussian_distance_transform_of(const std::vector<Item>& shape, const NamedParameters& np)
{
  const Local_coordinates local = local_coordinates_of(shape);
  const std::vector<Item> local_shape = to_local(local, shape);
  Shape_frame frame;
  if constexpr(std::is_same_v<Item, Dtriangle>) frame = frame_of_triangles(local_shape);
  else frame = frame_of_points(local_shape);
  Voxel_grid<GT> grid = cancellable_gaussian_distance_transform<GT>(frame, np,
    [&](Voxel_grid<GT>& g, const Grid_settings& settings) {
      if constexpr(std::is_same_v<Item, Dtriangle>) fill_gaussian_distance_transform_of_triangles(g, local_shape, settings);
      else fill_gaussian_distance_transform_of_points(g, local_shape, settings);
    });
  grid.recenter(to_point<GT>(local.to_input(to_eigen(frame.center))));
  return grid;
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformGridRef
 *
 * Computes the Gaussian Euclidean Distance Transform (GEDT) of a triangle mesh: the function
 * \f$ f(x) = \exp(-d(x)^2 / 2\sigma^2) \f$, \f$ d(x) \f$ the exact distance from \f$ x \f$ to the
 * surface, sampled on a `Voxel_grid` centred on the area-weighted centre of mass, zero beyond
 * \f$ 3\sigma \f$ and normalised to a unit sum of squared samples (\ref SymmetryTransformGEDT,
 * \ref SymmetryTransformGEDTMethod). Degenerate faces (zero area) are ignored.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the input mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the grid of the same geometry\, all its values zero}
 * \cgalNamedParamsEnd
 *
 * \returns the normalised GEDT on a grid whose `center()` is the centre of mass of the surface
 * and whose `radius()` is the largest distance from it to a vertex of a non-degenerate face.
 *
 * \throws std::invalid_argument if the mesh has no face, a face that is not a triangle, only
 * degenerate faces, a coordinate that is NaN or infinite, a radius out of \f$ [10^{-100}, 10^{100}] \f$, or if a numeric named parameter lies out
 * of its range: `grid_resolution` from 8 to the largest whose transforms fit in 3/4 of the physical memory.
*/
template <typename TriangleMesh,
          typename NamedParameters = parameters::Default_named_parameters>
Voxel_grid<typename GetGeomTraits<TriangleMesh, NamedParameters>::type>
gaussian_distance_transform(const TriangleMesh& tm,
                            const NamedParameters& np = parameters::default_values())
{
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;

  return internal::cancellable_gaussian_distance_transform_of<GT>(
    internal::without_progress([&] { return internal::triangles_of_mesh(tm, np); }), np);
}

/*!
 * \ingroup PkgSymmetryTransformGridRef
 *
 * Computes the Gaussian Euclidean Distance Transform of a point set: as
 * `gaussian_distance_transform()`, with \f$ d(x) \f$ the distance to the nearest point (found
 * in a `CGAL::Kd_tree`), the grid centred on the mean of the points.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the input points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{not read: the GEDT is the distance to the points, whatever their normals}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the grid of the same geometry\, all its values zero}
 * \cgalNamedParamsEnd
 *
 * \returns the normalised GEDT on a grid whose `center()` is the mean of the points and whose
 * `radius()` is the largest distance from it to a point.
 *
 * \throws std::invalid_argument if the range is empty, all its points coincide, a coordinate is
 * NaN or infinite, a radius out of \f$ [10^{-100}, 10^{100}] \f$, or if a numeric named parameter lies out of its range (as `gaussian_distance_transform()`).
*/
template <typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
Voxel_grid<Geom_traits_of_points<PointRange, NamedParameters>>
gaussian_distance_transform_of_points(const PointRange& points,
                                      const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits GT;

  const std::vector<internal::Dpoint> samples =
    internal::points_of_range(points, NP_helper::get_const_point_map(points, np));
  return internal::cancellable_gaussian_distance_transform_of<GT>(samples, np);
}

/*!
 * \ingroup PkgSymmetryTransformGridRef
 *
 * Computes the Gaussian Euclidean Distance Transform of a triangle soup, as
 * `gaussian_distance_transform()` does for a mesh: \f$ d(x) \f$ is the distance to the union of
 * the triangles, the grid is centred on their area-weighted centre of mass. The soup needs no
 * repair (\ref SymmetryTransformRealWorld): orientation, duplicated or unreferenced points,
 * non-manifold edges and components do not matter; degenerate triangles (zero area) are ignored.
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 *         (as `std::array<std::size_t, 3>`), as `CGAL::Polygon_mesh_processing::sample_triangle_soup()` takes
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the grid of the same geometry\, all its values zero}
 * \cgalNamedParamsEnd
 *
 * \returns the normalised GEDT on a grid whose `center()` is the centre of mass of the triangles
 * and whose `radius()` is the largest distance from it to a corner of a non-degenerate triangle.
 *
 * \throws std::invalid_argument if a triangle refers to a point out of range or has not three
 * corners, if there is no triangle or only degenerate ones, if a corner has a NaN or infinite
 * coordinate, a radius out of \f$ [10^{-100}, 10^{100}] \f$, or if a numeric named parameter lies out of its range (as `gaussian_distance_transform()`).
*/
template <typename PointRange, typename TriangleRange,
          typename NamedParameters = parameters::Default_named_parameters>
Voxel_grid<Geom_traits_of_points<PointRange, NamedParameters>>
gaussian_distance_transform_of_triangle_soup(const PointRange& points, const TriangleRange& triangles,
                                             const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::cancellable_gaussian_distance_transform_of<GT>(
    internal::without_progress([&] { return internal::triangles_of_soup(points, triangles, np); }), np);
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_GAUSSIAN_DISTANCE_TRANSFORM_H
