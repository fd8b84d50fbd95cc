// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRY_H
#define CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRY_H

namespace CGAL::Symmetry_transform {

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
};

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_PRINCIPAL_SYMMETRY_H
