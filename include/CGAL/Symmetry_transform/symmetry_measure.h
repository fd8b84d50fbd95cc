// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_MEASURE_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_MEASURE_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/rotation/rigid_motion.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <stdexcept>

namespace CGAL::Symmetry_transform {

namespace internal {

// sum_x f(x) f(reflect(x)) / sum_x f(x)^2 over the non-zero samples, f(reflect(x))
// interpolated with Catmull-Rom splines.
template <typename GT, typename Reflection>
double symmetry_measure_of_reflection(const Voxel_grid<GT>& f, const Reflection& reflect)
{
  const std::size_t n = f.resolution();
  const double h = f.voxel_size();
  const auto& o = f.origin();
  double dot = 0., norm = 0.;
  for(std::size_t k = 0; k < n; ++k)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        const double v = f(i, j, k);
        if(v == 0.) continue;
        double x[3] = {o[0] + (double(i) + 0.5) * h, o[1] + (double(j) + 0.5) * h, o[2] + (double(k) + 0.5) * h};
        reflect(x);
        dot += v * f.cubic_value(x[0], x[1], x[2]);
        norm += v * v;
      }
  if(!(norm > 0.)) throw std::invalid_argument("Symmetry_transform: the grid is zero everywhere");
  return dot / norm;
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformMeasureRef
 *
 * Symmetry measure of a sampled function \f$ f \f$ with respect to the reflection \f$ \gamma \f$
 * through `plane`, evaluated directly on the grid:
 * \f$ SM(\gamma) = \sum_x f(x)\, f(\gamma(x)) / \sum_x f(x)^2 \f$, the sum running over the
 * samples and \f$ f(\gamma(x)) \f$ interpolated with cubic (Catmull-Rom) splines.
 *
 * For a non-negative \f$ f \f$, such as a Gaussian distance transform, it lies in \f$ [0,1] \f$:
 * 1 for a perfect symmetry (up to interpolation error, below \f$ 10^{-3} \f$ for a GEDT of
 * width 1.5 voxels), lower the less symmetric \f$ f \f$ is. It is the quantity the
 * reflective symmetry transform tabulates for all planes; use this function to measure a
 * given plane exactly, in \f$ O(n^3) \f$.
 *
 * \tparam GeomTraits a model of `Kernel`
 *
 * \param f the function, for instance a GEDT from `gaussian_distance_transform()`
 * \param plane the plane of the reflection; its orientation does not matter
 *
 * \returns \f$ SM(\gamma) \f$
 *
 * \throws std::invalid_argument if `plane` is degenerate or `f` is zero everywhere.
*/
template <typename GeomTraits>
double symmetry_measure(const Voxel_grid<GeomTraits>& f, const typename GeomTraits::Plane_3& plane)
{
  const double a = CGAL::to_double(plane.a()), b = CGAL::to_double(plane.b()), c = CGAL::to_double(plane.c()),
               d = CGAL::to_double(plane.d());
  const double nn = a * a + b * b + c * c;
  if(!(nn > 0.)) throw std::invalid_argument("Symmetry_transform: degenerate plane");
  return internal::symmetry_measure_of_reflection(f, [&](double* x) {
    const double s = 2. * (a * x[0] + b * x[1] + c * x[2] + d) / nn;
    x[0] -= s * a;
    x[1] -= s * b;
    x[2] -= s * c;
  });
}

/*!
 * \ingroup PkgSymmetryTransformMeasureRef
 *
 * Symmetry measure of a sampled function \f$ f \f$ with respect to the point reflection
 * \f$ x \mapsto 2p - x \f$ through `center`, evaluated directly on the grid as in
 * `symmetry_measure(const Voxel_grid<GeomTraits>&, const typename GeomTraits::Plane_3&)`.
 *
 * \tparam GeomTraits a model of `Kernel`
 *
 * \param f the function
 * \param center the centre \f$ p \f$ of the point reflection
 *
 * \returns \f$ \sum_x f(x)\, f(2p - x) / \sum_x f(x)^2 \f$
 *
 * \throws std::invalid_argument if `f` is zero everywhere.
*/
template <typename GeomTraits>
double symmetry_measure(const Voxel_grid<GeomTraits>& f, const typename GeomTraits::Point_3& center)
{
  const double p[3] = {CGAL::to_double(center.x()), CGAL::to_double(center.y()), CGAL::to_double(center.z())};
  return internal::symmetry_measure_of_reflection(f, [&](double* x) {
    for(int i = 0; i < 3; ++i) x[i] = 2. * p[i] - x[i];
  });
}

/*!
 * \ingroup PkgSymmetryTransformMeasureRef
 *
 * The symmetry transform's value \f$ \sqrt{(1 + SM)/2} \f$ as defined in the thesis
 * (Equation 3.1.1), from a symmetry measure \f$ SM \f$. It is a monotone function of
 * \f$ SM \f$: thresholds and comparisons in this package use \f$ SM \f$ itself.
 *
 * \param symmetry_measure a symmetry measure \f$ SM \f$, in \f$ [-1, 1] \f$
 *
 * \returns \f$ \sqrt{(1 + SM)/2} \f$, in \f$ [0, 1] \f$
*/
inline double symmetry_transform_value(double symmetry_measure)
{
  return std::sqrt((1. + symmetry_measure) / 2.);
}

/*!
 * \ingroup PkgSymmetryTransformMeasureRef
 *
 * Symmetry measure of a sampled function \f$ f \f$ with respect to a rotation (or any rigid
 * motion) \f$ \gamma \f$, evaluated directly on the grid as in
 * `symmetry_measure(const Voxel_grid<GeomTraits>&, const typename GeomTraits::Plane_3&)`:
 * \f$ SM(\gamma) = \sum_x f(x)\, f(\gamma(x)) / \sum_x f(x)^2 \f$, 1 when \f$ \gamma \f$
 * maps \f$ f \f$ onto itself. `rotation_about_axis()` builds the rotation about an axis.
 *
 * \tparam GeomTraits a model of `Kernel`
 *
 * \param f the function
 * \param rotation the rotation \f$ \gamma \f$: its linear part must be orthogonal (to \f$ 10^{-6} \f$)
 *
 * \returns \f$ SM(\gamma) \f$
 *
 * \throws std::invalid_argument if `rotation` is not a rigid motion or `f` is zero everywhere.
*/
template <typename GeomTraits>
double symmetry_measure(const Voxel_grid<GeomTraits>& f, const typename GeomTraits::Aff_transformation_3& rotation)
{
  const internal::Rigid_motion motion = internal::rigid_motion(rotation);
  return internal::symmetry_measure_of_reflection(f, [&](double* x) { motion.move(x); });
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_MEASURE_H
