// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
#define CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>
#include <CGAL/Symmetry_transform/internal/detection/face_support.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <array>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Computes the principal symmetries of a triangle mesh from its reflective symmetry transform:
 * the local maxima of `prst` above the thresholds \f$ t\,(1 - |r|/R) \f$ and \f$ l \f$, each
 * refined by Iterative Symmetric Points (ISP) on the mesh, unstable ones dropped and duplicates
 * merged, measured on the GEDT by `symmetry_measure()` (\ref SymmetryTransformPrincipal).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param prst its reflective symmetry transform, from `reflective_symmetry_transform(tm, np)`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamRefinementSamples
 *   \cgalParamIspIterations
 *   \cgalParamMaxPlanes
 *   \cgalParamsCandidateThresholds
 *   \cgalParamRandomSeed{the seed of the surface samples}
 *   \cgalParamVerbose{whether to print each candidate and its refinement on `std::cerr`}
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the planes accepted before the cancel\, strongest first (none if it came before the refinements)}
 * \cgalNamedParamsEnd
 *
 * \returns the principal symmetries, strongest first.
 * \throws std::invalid_argument on the bad inputs of `gaussian_distance_transform()`, or if
 * a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>>
principal_symmetries(
  const TriangleMesh& tm,
  const Reflective_symmetry_transform<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>& prst,
  const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::with_progress(np, [&] {
    const double surface_share = internal::progress_shares::detection_surface_share(num_faces(tm));
    internal::Progress_stage stage(0., surface_share);
    std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np);
    const internal::Detection_settings settings = internal::detection_settings(np);
    const internal::Triangle_surface<GT> surface(std::move(triangles), settings.grid);
    stage.move_to(surface_share, 1.);
    const auto local_prst = internal::shifted(prst, Eigen::Vector3d(-surface.local.center));
    return internal::to_input(surface.local, internal::principal_symmetries_of_surface(surface, local_prst, settings));
  }, [] { return std::vector<Principal_symmetry<GT>>(); });
}

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Computes the principal symmetries of a triangle mesh: its reflective symmetry transform by
 * `reflective_symmetry_transform(tm, np)`, with fewer Monte Carlo samples by default, then
 * `principal_symmetries(tm, prst, np)` (\ref SymmetryTransformPrincipal).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPrstMethod
 *   \cgalParamDetectionSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRefinementSamples
 *   \cgalParamIspIterations
 *   \cgalParamMaxPlanes
 *   \cgalParamsCandidateThresholds
 *   \cgalParamRandomSeed{the seed of the surface samples and of the transform}
 *   \cgalParamVerbose{whether to print each candidate and its refinement on `std::cerr`}
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the planes accepted before the cancel\, strongest first (none if it came before the refinements)}
 * \cgalNamedParamsEnd
 *
 * \returns the principal symmetries, strongest first.
 * \throws std::invalid_argument on the bad inputs of `gaussian_distance_transform()` and
 * `reflective_symmetry_transform()`, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>>
detect_principal_symmetries(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::with_progress(np, [&] { return internal::detection_of_mesh(tm, np).symmetries; },
                                 [] { return std::vector<Principal_symmetry<GT>>(); });
}

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Computes the principal symmetries of a point set, as `detect_principal_symmetries()` does for
 * a mesh, with ISP matching the reflected points to their nearest points (`CGAL::Kd_tree`). With
 * the normals of the points (`normal_map`, as most scans have them), the plane is fitted to the
 * tangent planes at the matches, as on a mesh (point to plane); without, to the pairs of points
 * (point to point), which the spacing of the points limits (\ref SymmetryTransformPrincipal,
 * \ref SymmetryTransformRealWorld).
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPrstMethod
 *   \cgalParamDetectionSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRefinementSamples
 *   \cgalParamIspIterations
 *   \cgalParamMaxPlanes
 *   \cgalParamsCandidateThresholds
 *   \cgalParamRandomSeed{the seed of the points that ISP reflects and of the transform}
 *   \cgalParamVerbose{whether to print each candidate and its refinement on `std::cerr`}
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{if given\, ISP fits the plane point to plane with the normal of the point nearest to each
 *                       mirror image\, whose orientation does not matter; a zero normal leaves its point out of the fit}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the planes accepted before the cancel\, strongest first (none if it came before the refinements)}
 * \cgalNamedParamsEnd
 *
 * \returns the principal symmetries, strongest first.
 * \throws std::invalid_argument on the bad inputs of `gaussian_distance_transform_of_points()`
 * and `reflective_symmetry_transform()`, a NaN or infinite normal, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<Geom_traits_of_points<PointRange, NamedParameters>>>
detect_principal_symmetries_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::with_progress(np, [&] { return internal::detection_of_points(points, np).symmetries; },
                                 [] { return std::vector<Principal_symmetry<GT>>(); });
}

namespace internal {

// refine_symmetry_plane() on the triangles of a mesh or of a soup.
template <typename GT, typename NamedParameters>
typename GT::Plane_3 refined_plane(std::vector<Dtriangle> triangles, const typename GT::Plane_3& plane,
                                   const NamedParameters& np)
{
  return with_progress(np, [&] {
    const Detection_settings settings = detection_settings(np);
    const double surface_share = progress_shares::detection_surface_share(triangles.size());
    Progress_stage stage(0., surface_share);
    const Triangle_surface<GT> surface(std::move(triangles), settings.grid);
    stage.move_to(surface_share, 1.);
    const Isp_settings isp = isp_settings(surface.grid, settings.isp_iterations, surface.gedt);
    const Dplane start = surface.local.to_local(to_dplane(plane));
    return to_plane<GT>(surface.local.to_input(
      iterative_symmetric_points(surface_samples(surface.triangles, settings.sampling), start, surface.matcher, isp,
                                 Isp_phase::BOTH, {}, &surface.field)
        .plane));
  }, [&] { return plane; });
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Refines a rough plane of symmetry of a triangle mesh by Iterative Symmetric Points, as
 * `principal_symmetries()` does, without a transform: the plane converges to the nearest local
 * maximum of the Gaussian-weighted support. A plane that is already an exact local symmetry stays
 * where it is (\ref SymmetryTransformPrincipal).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param plane the starting plane
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamRefinementSamples
 *   \cgalParamIspIterations
 *   \cgalParamRandomSeed{the seed of the surface samples}
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{`plane` unchanged}
 * \cgalNamedParamsEnd
 *
 * \returns the refined plane, with a unit normal; `plane` itself (normalised) if no reflected
 * sample lies near the surface.
 * \throws std::invalid_argument if `plane` is degenerate, on the bad inputs of
 * `gaussian_distance_transform()`, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
typename Geom_traits_of_mesh<TriangleMesh, NamedParameters>::Plane_3
refine_symmetry_plane(const TriangleMesh& tm,
                      const typename Geom_traits_of_mesh<TriangleMesh, NamedParameters>::Plane_3& plane,
                      const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  return internal::refined_plane<GT>(internal::triangles_of_mesh(tm, np), plane, np);
}

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Computes how much each face of a triangle mesh supports the reflection through `plane`
 * (thesis, Figure 3.7): the mean of \f$ \exp(-d^2/2\sigma^2) \f$ over four points of the face,
 * \f$ d \f$ the distance from the reflected point to the mesh and \f$ \sigma \f$ the width of the
 * GEDT. 1 means the face is mirrored onto the surface, 0 that its mirror image is far from it
 * (\ref SymmetryTransformPrincipal).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam FaceSupportMap a model of `WritablePropertyMap` with the face descriptor as key and `double` as value
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param plane the plane of reflection
 * \param face_support_map receives the support of each face, in \f$ [0,1] \f$
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the supported fraction of the area: the area-weighted mean of the face supports.
 * \throws std::invalid_argument if `plane` is degenerate, or on the bad inputs of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename FaceSupportMap,
          typename NamedParameters = parameters::Default_named_parameters>
double symmetry_support(const TriangleMesh& tm,
                        const typename Geom_traits_of_mesh<TriangleMesh, NamedParameters>::Plane_3& plane,
                        FaceSupportMap face_support_map, const NamedParameters& np = parameters::default_values())
{
  const auto vpm = internal::vertex_point_map(tm, np);
  const std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np);
  const internal::Triangle_matcher matcher(triangles);
  const internal::Grid_settings grid = internal::grid_settings(np, internal::frame_of_triangles(triangles).radius);
  const internal::Face_supports<TriangleMesh> supports =
    internal::face_supports(tm, vpm, matcher, internal::to_dplane(plane), grid.sigma(), grid.threads);
  double supported = 0., total = 0.;
  for(std::size_t f = 0; f < supports.faces.size(); ++f) {
    put(face_support_map, supports.faces[f], supports.support[f]);
    supported += supports.area[f] * supports.support[f];
    total += supports.area[f];
  }
  return supported / total;
}

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Computes the principal symmetries of a triangle soup, as `detect_principal_symmetries()` does
 * for a mesh. The soup needs no repair (\ref SymmetryTransformRealWorld): orientation, duplicated
 * or unreferenced points, non-manifold edges and components do not matter, degenerate triangles
 * are ignored, and a triangle given twice (a double-sided face) counts twice in the area (the
 * centre of mass, hence the grid, and the samples that ISP reflects), which moves no exact plane.
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
 *   \cgalParamPrstMethod
 *   \cgalParamDetectionSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRefinementSamples
 *   \cgalParamIspIterations
 *   \cgalParamMaxPlanes
 *   \cgalParamsCandidateThresholds
 *   \cgalParamRandomSeed{the seed of the surface samples and of the transform}
 *   \cgalParamVerbose{whether to print each candidate and its refinement on `std::cerr`}
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{the planes accepted before the cancel\, strongest first (none if it came before the refinements)}
 * \cgalNamedParamsEnd
 *
 * \returns the principal symmetries, strongest first.
 * \throws std::invalid_argument on the bad inputs of `gaussian_distance_transform_of_triangle_soup()`
 * and `reflective_symmetry_transform()`, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename PointRange, typename TriangleRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<Geom_traits_of_points<PointRange, NamedParameters>>>
detect_principal_symmetries_of_triangle_soup(const PointRange& points, const TriangleRange& triangles,
                                             const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::with_progress(np, [&] { return internal::detection_of_triangle_soup(points, triangles, np).symmetries; },
                                 [] { return std::vector<Principal_symmetry<GT>>(); });
}

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Refines a rough plane of symmetry of a triangle soup by Iterative Symmetric Points, as
 * `refine_symmetry_plane()` does for a mesh (\ref SymmetryTransformPrincipal).
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param plane the starting plane
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamRefinementSamples
 *   \cgalParamIspIterations
 *   \cgalParamRandomSeed{the seed of the surface samples}
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{`plane` unchanged}
 * \cgalNamedParamsEnd
 *
 * \returns the refined plane, with a unit normal; `plane` itself (normalised) if no reflected
 * sample lies near the surface.
 * \throws std::invalid_argument if `plane` is degenerate, on the bad inputs of
 * `gaussian_distance_transform_of_triangle_soup()`, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename PointRange, typename TriangleRange, typename NamedParameters = parameters::Default_named_parameters>
typename Geom_traits_of_points<PointRange, NamedParameters>::Plane_3
refine_symmetry_plane_of_triangle_soup(
  const PointRange& points, const TriangleRange& triangles,
  const typename Geom_traits_of_points<PointRange, NamedParameters>::Plane_3& plane,
  const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  return internal::refined_plane<GT>(internal::triangles_of_soup(points, triangles, np), plane, np);
}

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Computes how much each triangle of a triangle soup supports the reflection through `plane`, as
 * `symmetry_support()` does for the faces of a mesh, the distances being to the union of the
 * triangles. Every triangle gets a value, in the order of `triangles`, degenerate ones too.
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 * \tparam OutputIterator an output iterator accepting `double`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param plane the plane of reflection
 * \param supports receives the support of each triangle, in \f$ [0,1] \f$, in the order of `triangles`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the supported fraction of the area: the area-weighted mean of the triangle supports
 * (a triangle given twice counts twice).
 * \throws std::invalid_argument if `plane` is degenerate, or on the bad inputs of
 * `gaussian_distance_transform_of_triangle_soup()`.
*/
template <typename PointRange, typename TriangleRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
double symmetry_support_of_triangle_soup(
  const PointRange& points, const TriangleRange& triangles,
  const typename Geom_traits_of_points<PointRange, NamedParameters>::Plane_3& plane,
  OutputIterator supports, const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  const std::vector<internal::Dtriangle> all =
    internal::all_triangles_of_soup(points, triangles, NP_helper::get_const_point_map(points, np));
  const std::vector<internal::Dtriangle> surface = internal::non_degenerate_triangles_of_soup(all);
  const internal::Triangle_matcher matcher(surface);
  const internal::Grid_settings grid = internal::grid_settings(np, internal::frame_of_triangles(surface).radius);
  std::vector<double> support, area;
  internal::triangle_supports(all.size(), [&all](std::size_t f) {
      return std::array<Eigen::Vector3d, 3>{internal::to_eigen(all[f][0]), internal::to_eigen(all[f][1]),
                                            internal::to_eigen(all[f][2])};
    }, matcher, internal::to_dplane(plane), grid.sigma(), grid.threads, support, area);
  double supported = 0., total = 0.;
  for(std::size_t f = 0; f < all.size(); ++f) {
    *supports++ = support[f];
    supported += area[f] * support[f];
    total += area[f];
  }
  return supported / total;
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
