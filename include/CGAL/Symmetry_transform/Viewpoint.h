// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_H
#define CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_H

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformViewpointRef
 * A viewing direction and its viewpoint score \f$ S(v) \f$ (see `viewpoint_score()`).
 * \tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Viewpoint
{
  /// The direction \f$ v \f$ the camera looks along (or from: \f$ v \f$ and \f$ -v \f$ are the same
  /// view), a unit vector, chosen with \f$ z > 0 \f$ (with \f$ z = 0 \f$: \f$ y > 0 \f$; with
  /// \f$ y = z = 0 \f$: \f$ x > 0 \f$).
  typename GeomTraits::Vector_3 direction;
  /// \f$ S(v) \f$.
  double score;
};

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_VIEWPOINT_H
