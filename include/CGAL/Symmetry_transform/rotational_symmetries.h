// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRIES_H
#define CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRIES_H

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Rotational_symmetry.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/rotation/rotations_of_shape.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformRotationRef
 *
 * Computes the rotational symmetries of a triangle mesh: the axes about which rotations map the
 * surface onto itself, each with its order (the largest \f$ k \leq \f$ `max_order` such that the
 * rotations by \f$ 2\pi j/k \f$ hold, or 0 for a surface of revolution), strongest first
 * (\ref SymmetryTransformRotation).
 *
 * - <b>Candidates.</b> The three axes of inertia through the centre of mass, for every order (a
 *   shape invariant under a rotation by \f$ 2\pi/k \f$, \f$ k \geq 3 \f$, has its axis as the
 *   distinct eigenvector of its second-moment tensor; a 2-fold axis is one of its eigenvectors);
 *   and the directions where the density of the surface normals on the sphere correlates best
 *   with its rotation by \f$ 2\pi/k \f$ (800 directions of a hemisphere, the three best local
 *   maxima per order). The normals need no axis point: they find the direction when the centre of
 *   mass is off the axis (a part of the shape missing), and with no mirror plane (twisted
 *   propellers, screws) as well as with.
 * - <b>Coarse alignment.</b> On a GEDT at \f$ 32^3 \f$ (its width about \f$ 0.13 R \f$), each
 *   candidate gets the axis point (in a disc of radius \f$ 0.3 R \f$ around the centre of mass)
 *   whose rotation overlaps best; those overlapping by at least 0.5 are aligned by a pattern search
 *   on the direction and the point, best first, a candidate next to one already aligned skipped
 *   (at most 24 aligned, 16 refined).
 * - <b>Refinement.</b> Iterative Rotated Points, as Iterative Symmetric Points for planes:
 *   \f$ 10^4 \f$ surface samples are rotated by \f$ 2\pi/k \f$ and by its largest multiple up to
 *   \f$ \pi \f$, matched to their closest points on the mesh, and the axis (two parameters of
 *   direction, two of position) re-fitted by Gauss-Newton on the distances to the tangent planes
 *   at the matches, weighted by \f$ \exp(-d^2/2w^2) \f$: \f$ w = 2\sigma \f$ on an eighth of the
 *   samples, then \f$ \sigma \f$, then \f$ \sigma/2 \f$ and \f$ \sigma/4 \f$ on an exact symmetry;
 *   approximate matches for the walk, exact ones (`CGAL::AABB_tree`, on a fourth of the samples)
 *   for the last steps.
 * - <b>Order.</b> About the refined axis, the supports at the final width of the rotations by
 *   \f$ 2\pi/k \f$, \f$ k = 2 \ldots \f$ `max_order`, and by \f$ 2\pi(\sqrt 2 - 1) \f$,
 *   \f$ 2\pi(2 - \varphi) \f$ and \f$ 2\pi(\sqrt 3 - 1) \f$: a rotation holds if its support is
 *   at least 0.9 of the best support of the turns by a quarter or more. Continuous if the three
 *   irrational angles hold, else the largest \f$ k \f$ that holds.
 * - <b>Result.</b> An axis is returned if its rotation maps at least 0.7 of the area onto the
 *   surface (within about \f$ \sigma/2 \f$). Axes found twice are merged; about a continuous
 *   axis, one 2-fold axis perpendicular to it is kept (the others are its images by the
 *   continuous rotations); the axes the found ones generate as a group (the flips of a dihedral
 *   symmetry) are refined and tested in turn.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamMaxOrder
 *   \cgalParamNBegin{number_of_refinement_samples}
 *     \cgalParamDescription{the number of surface samples (of points, for a point set) rotated at
 *                           each step of the refinement}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{10000}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_iterations}
 *     \cgalParamDescription{the largest number of Gauss-Newton steps of each stage of a refinement}
 *     \cgalParamType{`unsigned int`}
 *     \cgalParamDefault{20}
 *   \cgalParamNEnd
 *   \cgalParamRandomSeed{the seed of the surface samples}
 *   \cgalParamVerbose{whether to print each candidate and its refinement on `std::cerr`}
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width; its width \f$ \sigma \f$ sets the Gaussian weights of the refinement}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{an empty vector}
 * \cgalNamedParamsEnd
 *
 * \returns the rotational symmetries, strongest first: by decreasing `symmetry` rounded to three
 * decimals (the measures of exact symmetries differ by their interpolation errors, about
 * \f$ 10^{-4} \f$), then continuous ones first and by decreasing order (the main axis of a gear
 * before its flips), then by decreasing `symmetry`.
 * \throws std::invalid_argument if `max_order` lies out of [2, 1000] or another numeric named parameter out of its range, or on the bad inputs of
 * `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Rotational_symmetry<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>>
detect_rotational_symmetries(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  const int max_order = internal::max_order(np); // checked before the work
  return internal::with_progress(np, [&] {
    const double surface_share = internal::rotation_surface_share(num_faces(tm));
    internal::Progress_stage stage(0., surface_share);
    const internal::Triangle_surface<GT> surface(internal::triangles_of_mesh(tm, np), np);
    stage.move_to(surface_share, 1.);
    return internal::rotations_of_surface(surface, max_order, {}, np);
  }, [] { return std::vector<Rotational_symmetry<GT>>(); });
}

/*!
 * \ingroup PkgSymmetryTransformRotationRef
 *
 * Computes the rotational symmetries of a triangle mesh as `detect_rotational_symmetries()`, with,
 * as further candidates, the lines where two of its known planes of symmetry meet at an angle
 * \f$ \pi k'/k \f$ (within one degree, \f$ k \leq \f$ `max_order`): the rotation by
 * \f$ 2\pi k'/k \f$ is the product of the two reflections, so that the \f$ k \f$ mirror planes of
 * a dihedral symmetry give its axis.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param planes its planes of symmetry, for instance from `detect_principal_symmetries(tm, np)`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters": those of
 * `detect_rotational_symmetries()`
 *
 * \returns the rotational symmetries, strongest first.
 * \throws std::invalid_argument if a plane is degenerate, `max_order` lies out of [2, 1000] or another numeric named parameter out of its range, or on the bad
 * inputs of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Rotational_symmetry<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>>
rotational_symmetries(
  const TriangleMesh& tm,
  const std::vector<Principal_symmetry<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>>& planes,
  const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_mesh<TriangleMesh, NamedParameters> GT;
  const int max_order = internal::max_order(np);
  std::vector<internal::Dplane> dplanes;
  for(const Principal_symmetry<GT>& p : planes) dplanes.push_back(internal::to_dplane(p.plane));
  return internal::with_progress(np, [&] {
    const double surface_share = internal::rotation_surface_share(num_faces(tm));
    internal::Progress_stage stage(0., surface_share);
    const internal::Triangle_surface<GT> surface(internal::triangles_of_mesh(tm, np), np);
    stage.move_to(surface_share, 1.);
    const Eigen::Vector3d center = surface.local.to_input(internal::to_eigen(internal::to_dpoint(surface.gedt.center())));
    return internal::rotations_of_surface(surface, max_order, internal::plane_pair_candidates(dplanes, max_order, center), np);
  }, [] { return std::vector<Rotational_symmetry<GT>>(); });
}

/*!
 * \ingroup PkgSymmetryTransformRotationRef
 *
 * Computes the rotational symmetries of a point set, as `detect_rotational_symmetries()` does for
 * a mesh: the normals are those of the least-squares planes of the 18 nearest neighbours of each
 * point (`CGAL::pca_estimate_normals()`), the closest points those of the set (`CGAL::Kd_tree`),
 * the centre of mass the mean of the points, and the support the fraction of the points that a
 * rotation maps onto the set.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters": those of
 * `detect_rotational_symmetries()` but `vertex_point_map`, and
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPointMap
 *   \cgalParamCallback{an empty vector}
 * \cgalNamedParamsEnd
 *
 * \returns the rotational symmetries, strongest first.
 * \throws std::invalid_argument if `max_order` lies out of [2, 1000] or another numeric named parameter out of its range, or on the bad inputs of
 * `gaussian_distance_transform_of_points()`.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Rotational_symmetry<Geom_traits_of_points<PointRange, NamedParameters>>>
detect_rotational_symmetries_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef Geom_traits_of_points<PointRange, NamedParameters> GT;
  const int max_order = internal::max_order(np);
  return internal::with_progress(np, [&] { return internal::rotations_of_points(points, max_order, np); },
                                 [] { return std::vector<Rotational_symmetry<GT>>(); });
}

/*!
 * \ingroup PkgSymmetryTransformRotationRef
 *
 * The rotation by `angle` about `axis`, counterclockwise as seen from the tip of the axis's
 * direction: for instance the rotations \f$ 2\pi j/k \f$ of a `Rotational_symmetry` of order
 * \f$ k \f$ (the `symmetries_discrete` of the BOP benchmark) or those of a continuous one.
 *
 * \tparam Line_3 the line type of a model of `Kernel`
 *
 * \param axis the axis of the rotation
 * \param angle the angle, in radians
 *
 * \returns the rotation, whose linear part is orthogonal and whose translation fixes the axis.
 * \throws std::invalid_argument if the axis is degenerate (zero or non-finite direction or point).
*/
template <typename Line_3>
typename CGAL::Kernel_traits<Line_3>::Kernel::Aff_transformation_3 rotation_about_axis(const Line_3& axis, double angle)
{
  typedef typename CGAL::Kernel_traits<Line_3>::Kernel GT;
  return internal::to_transformation<GT>(internal::to_daxis(axis).rotation(angle));
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRIES_H
