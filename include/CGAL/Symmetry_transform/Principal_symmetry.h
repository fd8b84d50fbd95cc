// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRY_H
#define CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRY_H

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 * The mirror planes that one principal symmetry stands for. Two exact mirror planes meeting at an
 * angle that is no rational fraction of \f$ \pi \f$ make every plane through their common line a
 * mirror: a surface of revolution has that whole pencil of planes, a sphere every plane through its
 * centre. Such a family is returned once, by its strongest member, rather than as a few arbitrary
 * members.
 */
enum class Mirror_family
{
  /// the plane alone
  ONE_PLANE,
  /// every plane through `Principal_symmetry::axis` (a cylinder, a cone, any surface of revolution)
  EVERY_PLANE_THROUGH_AXIS,
  /// every plane through `Principal_symmetry::axis.point()` (a sphere)
  EVERY_PLANE_THROUGH_POINT
};

/*!
 * \ingroup PkgSymmetryTransformPrincipalRef
 * A principal symmetry of a shape: a local maximum of its reflective symmetry transform,
 * refined to high precision.
 * \tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Principal_symmetry
{
  /// The plane of reflection, with a unit normal.
  typename GeomTraits::Plane_3 plane;
  /// Its symmetry measure in \f$ [0,1] \f$, evaluated on the Gaussian distance transform by `symmetry_measure()`.
  double symmetry;
  /// The fraction of the shape (of its area for a mesh, of its points for a point set) that the
  /// reflection maps onto the shape: the mean Gaussian weight \f$ \exp(-d^2/2\sigma^2) \f$ of the
  /// distance \f$ d \f$ from a reflected sample to the shape.
  double support;
  /// Whether `plane` stands for itself only or for a continuous family of mirror planes.
  Mirror_family family = Mirror_family::ONE_PLANE;
  /// For a family, a line in `plane`: the line that all its planes contain
  /// (`EVERY_PLANE_THROUGH_AXIS`), or one through the point they all contain, `axis.point()`
  /// (`EVERY_PLANE_THROUGH_POINT`). A default-constructed line for `ONE_PLANE`.
  typename GeomTraits::Line_3 axis = typename GeomTraits::Line_3();
};

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRY_H
