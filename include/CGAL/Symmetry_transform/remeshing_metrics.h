// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_REMESHING_METRICS_H
#define CGAL_SYMMETRY_TRANSFORM_REMESHING_METRICS_H

// How good a remeshed surface is: its distance to the original (geometric error) and to its own
// mirror image (symmetry error), both from area-uniform seeded samples and exact closest points
// (CGAL::AABB_tree).

#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/remeshing/sampled_distances.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformRemeshingRef
 * The distance between two surfaces, measured from samples of each to the other.
*/
struct Approximation_error
{
  /// The root mean square of the distances of the samples of both surfaces to the other surface.
  double rms;
  /// The largest of these distances (the sampled two-sided Hausdorff distance).
  double hausdorff;
};

/*!
 * \ingroup PkgSymmetryTransformRemeshingRef
 *
 * Measures how far two triangle meshes are from each other (such as an input mesh and its
 * approximation): area-uniform samples of each mesh are matched to their closest points on the
 * other, as `CGAL::Polygon_mesh_processing::approximate_Hausdorff_distance()` does one way.
 *
 * \tparam TriangleMesh1 a model of `FaceListGraph` whose faces are triangles
 * \tparam TriangleMesh2 a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters1 a sequence of \ref bgl_namedparameters "Named Parameters"
 * \tparam NamedParameters2 a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm1 the first mesh
 * \param tm2 the second mesh
 * \param np1 an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 * \param np2 an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin{Named Parameters of np1}
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the points of the vertices of `tm1` (those of `tm2` are given in `np2`)}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh1>::%vertex_descriptor` as key and a `Point_3` as value}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm1)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_points_on_faces}
 *     \cgalParamDescription{the number of samples on each of the two meshes}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{20000}
 *   \cgalParamNEnd
 *   \cgalParamRandomSeed{the seed of the samples of both meshes: the result is deterministic for a seed}
 *   \cgalParamThreads{the threads that match the samples of each mesh to their closest points\, at most 1024 (0: the default); they change the speed only\, never the result}
 * \cgalNamedParamsEnd
 *
 * \cgalNamedParamsBegin{Named Parameters of np2}
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the points of the vertices of `tm2` (its samples follow the options of `np1`)}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh2>::%vertex_descriptor` as key and a `Point_3` as value}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm2)`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \returns the root mean square and the largest of the distances of both sets of samples.
 * \throws std::invalid_argument if a mesh has no face, a face that is not a triangle, a non-finite
 * coordinate, or only degenerate faces, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename TriangleMesh1, typename TriangleMesh2, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Approximation_error approximation_error(const TriangleMesh1& tm1, const TriangleMesh2& tm2,
                                        const NamedParameters1& np1 = parameters::default_values(),
                                        const NamedParameters2& np2 = parameters::default_values())
{
  const std::vector<internal::Dtriangle> t1 = internal::triangles_of_mesh(tm1, np1), t2 = internal::triangles_of_mesh(tm2, np2);
  const auto identity = [](const Eigen::Vector3d& p) { return p; };
  std::vector<double> d = internal::distances_to(internal::metric_samples(t1, np1), identity, t2, internal::metric_threads(np1));
  const std::vector<double> back =
    internal::distances_to(internal::metric_samples(t2, np1), identity, t1, internal::metric_threads(np1));
  d.insert(d.end(), back.begin(), back.end());
  return {internal::root_mean_square(d), d.empty() ? 0. : *std::max_element(d.begin(), d.end())};
}

/*!
 * \ingroup PkgSymmetryTransformRemeshingRef
 *
 * Measures how far a triangle mesh is from its mirror image through `plane`, the symmetry error
 * of the thesis (Section 5.1.3): the root mean square of the distances from the reflections of
 * area-uniform samples of the mesh to the mesh; 0 for an exact symmetry.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param plane the plane of reflection
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{number_of_points_on_faces}
 *     \cgalParamDescription{the number of samples of `tm`, whose reflections are matched}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{20000}
 *   \cgalParamNEnd
 *   \cgalParamRandomSeed{the seed of the samples: the result is deterministic for a seed}
 *   \cgalParamThreads{the threads that match the reflected samples to their closest points\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the root mean square distance, in the units of the mesh.
 * \throws std::invalid_argument if `plane` is degenerate, or on the bad meshes and parameters of `approximation_error()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double symmetry_error(const TriangleMesh& tm,
                      const typename Geom_traits_of_mesh<TriangleMesh, NamedParameters>::Plane_3& plane,
                      const NamedParameters& np = parameters::default_values())
{
  const internal::Dplane mirror = internal::to_dplane(plane);
  const std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np);
  return internal::root_mean_square(internal::distances_to(internal::metric_samples(triangles, np),
                                                           [&mirror](const Eigen::Vector3d& p) { return mirror.reflect(p); },
                                                           triangles, internal::metric_threads(np)));
}

/*!
 * \ingroup PkgSymmetryTransformRemeshingRef
 *
 * Measures the symmetry error of a triangle mesh in the region where another mesh (typically the
 * original of a remeshed surface) is symmetric: as `symmetry_error(tm, plane, np)`, but over the
 * samples of `tm` whose mirror images lie within `max_distance` of `reference`. This leaves out
 * the parts of an approximately or partially symmetric shape that the plane does not map (a
 * turned head, a missing limb), whose error no remeshing can remove.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam ReferenceMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters1 a sequence of \ref bgl_namedparameters "Named Parameters"
 * \tparam NamedParameters2 a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param plane the plane of reflection
 * \param reference the mesh whose symmetric region is measured
 * \param max_distance the largest distance from a mirrored sample of `tm` to `reference` in the region
 * \param np1 an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 * \param np2 an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin{Named Parameters of np1}
 *   \cgalParamGeomTraits
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamThreads{the threads that match the reflected samples\, on `tm` and on `reference`\, to their closest points\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamNBegin{number_of_points_on_faces}
 *     \cgalParamDescription{the number of samples of `tm`}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{20000}
 *   \cgalParamNEnd
 *   \cgalParamRandomSeed{the seed of the samples of `tm`: the result is deterministic for a seed}
 * \cgalNamedParamsEnd
 *
 * \cgalNamedParamsBegin{Named Parameters of np2}
 *   \cgalParamVertexPointMap{reference,ReferenceMesh}
 * \cgalNamedParamsEnd
 *
 * \returns the root mean square distance over the region (0 if the region is empty).
 * \throws std::invalid_argument on the bad input of `symmetry_error()`, for `tm` or `reference`.
*/
template <typename TriangleMesh, typename ReferenceMesh, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
double symmetry_error(const TriangleMesh& tm,
                      const typename Geom_traits_of_mesh<TriangleMesh, NamedParameters1>::Plane_3& plane,
                      const ReferenceMesh& reference, double max_distance,
                      const NamedParameters1& np1 = parameters::default_values(),
                      const NamedParameters2& np2 = parameters::default_values())
{
  const internal::Dplane mirror = internal::to_dplane(plane);
  const std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np1),
                                         region = internal::triangles_of_mesh(reference, np2);
  const std::vector<Eigen::Vector3d> samples = internal::metric_samples(triangles, np1);
  const auto reflect = [&mirror](const Eigen::Vector3d& p) { return mirror.reflect(p); };
  const std::vector<double> to_reference = internal::distances_to(samples, reflect, region, internal::metric_threads(np1)),
                            to_self = internal::distances_to(samples, reflect, triangles, internal::metric_threads(np1));
  std::vector<double> inside;
  for(std::size_t i = 0; i < samples.size(); ++i)
    if(to_reference[i] <= max_distance) inside.push_back(to_self[i]);
  return internal::root_mean_square(inside);
}

/*!
 * \ingroup PkgSymmetryTransformRemeshingRef
 *
 * Computes, for each face of a triangle mesh, the distance from the mirror image of its centroid
 * through `plane` to the mesh (0 where the mesh is symmetric), for instance to colour a remeshed
 * surface as in the thesis's Figure 5.6.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam FaceErrorMap a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key and `double` as value
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param plane the plane of reflection
 * \param face_error_map receives the distance of each face
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamGeomTraits
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamThreads{the number of threads that look for the points of `tm` nearest to the reflected centroids\, at most 1024 (0: the default); they change the speed only\, never the result}
 * \cgalNamedParamsEnd
 *
 * \returns the largest distance.
 * \throws std::invalid_argument on the bad input of `symmetry_error()`.
*/
template <typename TriangleMesh, typename FaceErrorMap, typename NamedParameters = parameters::Default_named_parameters>
double face_symmetry_errors(const TriangleMesh& tm,
                            const typename Geom_traits_of_mesh<TriangleMesh, NamedParameters>::Plane_3& plane,
                            FaceErrorMap face_error_map, const NamedParameters& np = parameters::default_values())
{
  const internal::Dplane mirror = internal::to_dplane(plane);
  const auto vpm = internal::vertex_point_map(tm, np);
  const std::vector<internal::Dtriangle> triangles = internal::triangles_of_mesh(tm, np);
  std::vector<Eigen::Vector3d> centroids;
  for(auto f : faces(tm)) centroids.push_back(internal::to_eigen(CGAL::centroid(internal::triangle_of_face(halfedge(f, tm), tm, vpm))));
  const std::vector<double> d = internal::distances_to(
    centroids, [&mirror](const Eigen::Vector3d& p) { return mirror.reflect(p); }, triangles, internal::metric_threads(np));
  double largest = 0.;
  std::size_t i = 0;
  for(auto f : faces(tm)) {
    put(face_error_map, f, d[i]);
    largest = (std::max)(largest, d[i++]);
  }
  return largest;
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_REMESHING_METRICS_H
