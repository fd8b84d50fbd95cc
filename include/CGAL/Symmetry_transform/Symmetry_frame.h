// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_FRAME_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_FRAME_H

#include <array>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformAlignmentRef
 *
 * A canonical coordinate frame of a shape: an origin and three unit, pairwise orthogonal axes
 * forming a right-handed basis (`axes[2]` \f$ = \f$ `axes[0]` \f$ \times \f$ `axes[1]`).
 *
 * Built by `symmetry_frame()` (centre of symmetry and principal symmetry axes, thesis section 4.1)
 * or by `pca_frame()` (centre of mass and principal axes of inertia, the classical baseline);
 * `to_canonical()` gives the rigid motion that takes the frame to the origin and the coordinate axes.
 *
 * \tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
struct Symmetry_frame
{
  /// The origin of the frame: the centre of symmetry, or the centre of mass.
  typename GeomTraits::Point_3 center;
  /// The three axes, unit and right-handed, most significant first.
  std::array<typename GeomTraits::Vector_3, 3> axes;
};

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_FRAME_H
