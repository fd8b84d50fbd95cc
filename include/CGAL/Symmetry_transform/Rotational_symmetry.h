// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRY_H
#define CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRY_H

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformRotationRef
 *
 * A rotational symmetry of a shape: an axis and the order of the rotations about it that map the
 * shape onto itself, refined to high precision.
 *
 * \tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Rotational_symmetry
{
  /// The axis, through its point nearest to the centre of mass, its direction a unit vector
  /// whose largest coordinate (in absolute value) is positive. A rotation by \f$ \alpha \f$
  /// about it turns counterclockwise as seen from the tip of the direction.
  typename GeomTraits::Line_3 axis;
  /// The order \f$ k \geq 2 \f$: the rotations by \f$ 2\pi j/k \f$ map the shape onto itself,
  /// and \f$ k \f$ is the largest such order up to `max_order`; or 0 for a continuous symmetry
  /// (a surface of revolution: every angle).
  int order;
  /// The symmetry measure in \f$ [0,1] \f$ of the rotation by \f$ 2\pi/k \f$ (for a continuous
  /// symmetry, the smallest over the three test angles), evaluated on the Gaussian distance
  /// transform by `symmetry_measure()`.
  typename GeomTraits::FT symmetry;
  /// The fraction of the shape (of its area for a mesh, of its points for a point set) that the
  /// rotation by \f$ 2\pi/k \f$ (for a continuous symmetry, the least of the three test angles)
  /// maps onto the shape: the mean Gaussian weight \f$ \exp(-d^2/2\sigma^2) \f$ of the distance
  /// \f$ d \f$ from a rotated sample to the shape.
  typename GeomTraits::FT support;
};

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_ROTATIONAL_SYMMETRY_H
