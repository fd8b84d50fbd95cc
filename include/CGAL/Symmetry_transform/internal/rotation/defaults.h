// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_DEFAULTS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_DEFAULTS_H

// The defaults and the documented thresholds of the rotational symmetries, quoted by the manual.
// (Kept apart from common/defaults.h while that file is restructured; same namespace, so that
// moving them there changes no caller.)

namespace CGAL {
namespace Symmetry_transform {
namespace internal {
namespace defaults {

// Orders tested: 2 to 12 covers the rotational parts of most manufactured objects (gears and
// turbines with more teeth or blades are reported at the largest divisor of their order within
// the range).
constexpr int max_order = 12;

// A rotation is reported if it maps at least this fraction of the surface to within about
// sigma / 2 of the surface (the mean weight exp(-d^2 / 2 (sigma / 2)^2) of the rotated samples):
// a shape with a fifth of it missing keeps about 0.8; the best rotations of shapes with no
// rotational symmetry stay below 0.6 (random convex hulls; the flip of a vase, not symmetric top
// to bottom: 0.59).
constexpr double min_rotation_support = 0.7;

// A rotation holds about a refined axis when its support (at the final width of the refinement,
// at most sigma / 2) is at least this fraction of the best support of the rotations by a quarter
// turn or more. On exact symmetries the others fall far below it (a twisted star off its angles:
// under 0.4); a fifth of the shape cut away lowers the supports of the true rotations unequally,
// by up to 0.08 of the best (measured: half and third turns of a 6-fold star solid, 0.868 and
// 0.873); and a surface of revolution whose features cover less than a tenth of it is reported
// continuous.
constexpr double rotation_hold_ratio = 0.9;

} // namespace defaults
} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_DEFAULTS_H
