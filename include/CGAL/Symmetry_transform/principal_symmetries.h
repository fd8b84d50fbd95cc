// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
#define CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/detection/detection.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {


/*!
\ingroup PkgSymmetryTransformRef

Computes the principal symmetries of a triangle mesh from its reflective symmetry transform:
the local maxima of `prst` whose symmetry measure exceeds \f$ t\,(1 - |r|/R) \f$ and whose
negative discrete Laplacian exceeds \f$ l \f$, with \f$ t \f$ and \f$ l \f$ fractions of those
of the strongest maximum, each refined by Iterative Symmetric Points (ISP): surface samples
are reflected through the plane and matched to their closest points on the mesh, and the
plane re-fitted by least squares, with the Gaussian weights \f$ \exp(-d^2/2\sigma^2) \f$ of
the match distances \f$ d \f$, until the weights stop growing. The matches are first
approximate (the closest triangles of the voxels around the point, recorded with the GEDT),
then exact (`CGAL::AABB_tree`) for the last steps (\ref SymmetryTransformPrincipal).
If the matches are then much closer than \f$ \sigma \f$ (an exact symmetry), the refinement goes
on with weights of half and a quarter of that width, so that the parts of the shape the plane
does not map lose their say: the local symmetries of a part of a composite shape come out
exact. Candidates are refined in decreasing order of the transform. One that moves more than 3
bins away from its bin, or that a first refinement on an eighth of the samples cannot settle
(on a mesh), is dropped (an unstable maximum); candidates that converge to an accepted plane are merged. The
symmetry of each plane is then measured on the GEDT by `symmetry_measure()`.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param tm the mesh
\param prst its reflective symmetry transform, from `reflective_symmetry_transform(tm, np)`
\param np named parameters: those of `gaussian_distance_transform()` (the GEDT is recomputed
with them, and its width sets the Gaussian weights of ISP), and

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_refinement_samples}
    \cgalParamDescription{the number of surface samples reflected at each ISP iteration}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{10000}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of ISP iterations of each stage of a refinement; a
                           plane still moving then (on a flat ridge of an approximate symmetry)
                           is taken where it is}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{max_number_of_planes}
    \cgalParamDescription{the largest number of planes returned: the refinement of the
                           candidates, in decreasing order of the transform, stops when this
                           many planes have been accepted}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{10}
  \cgalParamNEnd
  \cgalParamNBegin{symmetry_threshold}
    \cgalParamDescription{\f$ t \f$ as a fraction of the symmetry measure of the strongest maximum}
    \cgalParamType{`double`}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{laplacian_threshold}
    \cgalParamDescription{\f$ l \f$ as a fraction of the negative Laplacian of the strongest maximum}
    \cgalParamType{`double`}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the surface samples}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{whether to print each candidate and its refinement on `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the principal symmetries, strongest first.
\throws std::invalid_argument on the bad inputs of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>>
principal_symmetries(
  const TriangleMesh& tm,
  const Reflective_symmetry_transform<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>& prst,
  const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const internal::Triangle_surface<GT> surface(internal::triangles_of_mesh(tm, np), np);
  return internal::refine_candidates(surface.gedt, prst, internal::surface_samples(surface.triangles, np),
                                     surface.matcher, np, &surface.field);
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the principal symmetries of a triangle mesh: its reflective symmetry transform by
`reflective_symmetry_transform(tm, np)`, then `principal_symmetries(tm, prst, np)`.
The named parameters are those of both functions, except that `number_of_samples` (the Monte
Carlo samples of the transform) defaults to \f$ 5 \cdot 10^5 \f$ here: the maxima need only be
located within a bin or two, the refinement does the rest.
\param tm the mesh
\param np the named parameters
\returns the principal symmetries, strongest first.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>>
detect_principal_symmetries(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  return internal::detection_of_mesh(tm, np).symmetries;
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the principal symmetries of a point set, as `detect_principal_symmetries()`, with
ISP matching reflected points to their nearest points (`CGAL::Kd_tree`) and fitting the plane
to the point pairs.
\param points the points
\param np the named parameters of `detect_principal_symmetries()`, and `point_map`
\returns the principal symmetries, strongest first.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Principal_symmetry<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>>
detect_principal_symmetries_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  return internal::detection_of_points(points, np).symmetries;
}

/*!
\ingroup PkgSymmetryTransformRef

Refines a rough plane of symmetry of a triangle mesh by Iterative Symmetric Points, as in
`principal_symmetries()`, without a transform: the plane converges to the nearest local
maximum of the Gaussian-weighted support (within `number_of_iterations` steps of each stage).
A plane that is already an exact local symmetry, of a part of a composite shape for instance,
stays where it is.
\param tm the mesh
\param plane the starting plane
\param np named parameters: `number_of_refinement_samples`, `number_of_iterations`,
          `random_seed`, and those of `gaussian_distance_transform()` that set the Gaussian width
          (`grid_resolution`, `gaussian_width`, `grid_margin`) and `vertex_point_map`
\returns the refined plane, with a unit normal; `plane` itself (normalised) if no reflected
sample lies near the surface.
\throws std::invalid_argument if `plane` is degenerate, or on the bad inputs of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3
refine_symmetry_plane(const TriangleMesh& tm,
                      const typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type::Plane_3& plane,
                      const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type GT;
  const internal::Triangle_surface<GT> surface(internal::triangles_of_mesh(tm, np), np);
  const internal::Isp_settings settings = internal::isp_settings(np, surface.gedt);
  return internal::to_plane<GT>(internal::iterative_symmetric_points(internal::surface_samples(surface.triangles, np),
                                                                     internal::to_dplane(plane), surface.matcher,
                                                                     settings, internal::Isp_phase::BOTH, {},
                                                                     &surface.field)
                                  .plane);
}

/*!
\ingroup PkgSymmetryTransformRef

Computes how much each face of a triangle mesh supports the reflection through `plane`
(thesis, Figure 3.7): the mean, over points of the face (its centroid and three interior
points), of \f$ \exp(-d^2/2\sigma^2) \f$, \f$ d \f$ the distance from the reflected point to
the mesh and \f$ \sigma \f$ the width of the Gaussian distance transform. 1 means the face
is mirrored onto the surface, 0 that its mirror image is far from it.
\tparam FaceSupportMap a model of `WritablePropertyMap` with the face descriptor as key and `double` as value
\param tm the mesh
\param plane the plane of reflection
\param face_support_map receives the support of each face, in \f$ [0,1] \f$
\param np named parameters: `grid_resolution`, `gaussian_width`, `grid_margin` (they set
          \f$ \sigma \f$ as in `gaussian_distance_transform()`), `number_of_threads`, `vertex_point_map`
\returns the supported fraction of the area: the area-weighted mean of the face supports.
\throws std::invalid_argument if `plane` is degenerate, or on the bad inputs of `gaussian_distance_transform()`.
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
  const internal::Dplane mirror = internal::to_dplane(plane);
  const double sigma = grid.sigma();

  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  std::vector<double> support(face_list.size()), area(face_list.size());
  internal::parallel_for(face_list.size(), grid.threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f) {
      const auto h = halfedge(face_list[f], tm);
      const Eigen::Vector3d a = internal::to_eigen(internal::to_dpoint(get(vpm, source(h, tm)))),
                            b = internal::to_eigen(internal::to_dpoint(get(vpm, target(h, tm)))),
                            c = internal::to_eigen(internal::to_dpoint(get(vpm, target(next(h, tm), tm))));
      area[f] = 0.5 * (b - a).cross(c - a).norm();
      double sum = 0.;
      internal::Triangle_matcher::Hint hint;
      for(const Eigen::Vector3d& p : {Eigen::Vector3d((a + b + c) / 3.), Eigen::Vector3d((4. * a + b + c) / 6.),
                                      Eigen::Vector3d((a + 4. * b + c) / 6.), Eigen::Vector3d((a + b + 4. * c) / 6.)}) {
        const Eigen::Vector3d image = mirror.reflect(p);
        sum += std::exp(-(image - matcher.closest(image, hint, false).first).squaredNorm() / (2. * sigma * sigma));
      }
      support[f] = sum / 4.;
    }
  });
  double supported = 0., total = 0.;
  for(std::size_t f = 0; f < face_list.size(); ++f) {
    put(face_support_map, face_list[f], support[f]);
    supported += area[f] * support[f];
    total += area[f];
  }
  return supported / total;
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRIES_H
