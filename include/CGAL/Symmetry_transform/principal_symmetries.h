// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
#define CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>
#include <CGAL/Symmetry_transform/internal/detection/face_support.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

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
 *   \cgalParamThreads{the number of threads}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the principal symmetries, strongest first.
 * \throws std::invalid_argument on the bad inputs of `gaussian_distance_transform()`, or if
 * `number_of_refinement_samples` is 0.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>>
principal_symmetries(
  const TriangleMesh& tm,
  const Reflective_symmetry_transform<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>& prst,
  const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np);
  const internal::Detection_settings settings = internal::detection_settings(np);
  const internal::Triangle_surface<GT> surface(std::move(triangles), settings.grid);
  return internal::principal_symmetries_of_surface(surface, prst, settings);
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
 *   \cgalParamThreads{the number of threads}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the principal symmetries, strongest first.
 * \throws std::invalid_argument on the bad inputs of `gaussian_distance_transform()` and
 * `reflective_symmetry_transform()`, or if `number_of_refinement_samples` is 0.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>>
detect_principal_symmetries(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  return internal::detection_of_mesh(tm, np).symmetries;
}

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 *
 * Computes the principal symmetries of a point set, as `detect_principal_symmetries()` does for
 * a mesh, with ISP matching the reflected points to their nearest points (`CGAL::Kd_tree`) and
 * fitting the plane to the pairs of points (\ref SymmetryTransformPrincipal).
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
 *   \cgalParamThreads{the number of threads}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the principal symmetries, strongest first.
 * \throws std::invalid_argument on the bad inputs of `gaussian_distance_transform_of_points()`
 * and `reflective_symmetry_transform()`, or if `number_of_refinement_samples` is 0.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>>
detect_principal_symmetries_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  return internal::detection_of_points(points, np).symmetries;
}

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
 *   \cgalParamThreads{the number of threads}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the refined plane, with a unit normal; `plane` itself (normalised) if no reflected
 * sample lies near the surface.
 * \throws std::invalid_argument if `plane` is degenerate, on the bad inputs of
 * `gaussian_distance_transform()`, or if `number_of_refinement_samples` is 0.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3
refine_symmetry_plane(const TriangleMesh& tm,
                      const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
                      const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np);
  const internal::Detection_settings settings = internal::detection_settings(np);
  const internal::Triangle_surface<GT> surface(std::move(triangles), settings.grid);
  const internal::Isp_settings isp = internal::isp_settings(surface.grid, settings.isp_iterations, surface.gedt);
  return internal::to_plane<GT>(internal::iterative_symmetric_points(internal::surface_samples(surface.triangles,
                                                                                               settings.sampling),
                                                                     internal::to_dplane(plane), surface.matcher, isp,
                                                                     internal::Isp_phase::BOTH, {}, &surface.field)
                                  .plane);
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
 *   \cgalParamThreads{the number of threads}
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
                        const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
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

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
