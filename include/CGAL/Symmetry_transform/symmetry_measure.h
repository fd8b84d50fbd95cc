// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_MEASURE_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_MEASURE_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/remeshing/sampled_distances.h>
#include <CGAL/Symmetry_transform/internal/rotation/rigid_motion.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace CGAL::Symmetry_transform {

namespace internal {

// sum_x f(x) f(reflect(x)) / sum_x f(x)^2 over the non-zero samples, f(reflect(x))
// interpolated with Catmull-Rom splines. The terms are computed on `threads` threads, layer by
// layer, and summed in the order of the samples: the same value for any thread count. No
// callback is polled meanwhile: a measure is always whole, even in a detection being cancelled.
template <typename GT, typename Reflection>
double symmetry_measure_of_reflection(const Voxel_grid<GT>& f, const Reflection& reflect, unsigned threads = 1)
{
  const std::size_t n = f.resolution();
  const double h = f.voxel_size();
  const auto& o = f.origin();
  const std::vector<double>& values = f.values();
  std::vector<double> terms(values.size(), 0.);
  threads = unsigned((std::min<std::size_t>)((std::max)(threads, 1u), n));
  run_slices(threads, [&](unsigned t) {
    for(std::size_t k = n * t / threads; k < n * (t + 1) / threads; ++k)
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i < n; ++i) {
          const std::size_t s = f.index(i, j, k);
          if(values[s] == 0.) continue;
          double x[3] = {o[0] + (double(i) + 0.5) * h, o[1] + (double(j) + 0.5) * h, o[2] + (double(k) + 0.5) * h};
          reflect(x);
          terms[s] = values[s] * f.cubic_value(x[0], x[1], x[2]);
        }
  });
  double dot = 0., norm = 0.;
  for(std::size_t s = 0; s < values.size(); ++s) {
    if(values[s] == 0.) continue;
    dot += terms[s];
    norm += values[s] * values[s];
  }
  if(!(norm > 0.)) throw std::invalid_argument("Symmetry_transform: the grid is zero everywhere");
  return dot / norm;
}

// The symmetry measure of the reflection through `plane` (symmetry_measure()), on `threads` threads.
template <typename GT>
double plane_symmetry_measure(const Voxel_grid<GT>& f, const typename GT::Plane_3& plane, unsigned threads)
{
  const double a = CGAL::to_double(plane.a()), b = CGAL::to_double(plane.b()), c = CGAL::to_double(plane.c()),
               d = CGAL::to_double(plane.d());
  const double nn = a * a + b * b + c * c;
  if(!(nn > 0.)) throw std::invalid_argument("Symmetry_transform: degenerate plane");
  return symmetry_measure_of_reflection(
    f,
    [&](double* x) {
      const double s = 2. * (a * x[0] + b * x[1] + c * x[2] + d) / nn;
      x[0] -= s * a;
      x[1] -= s * b;
      x[2] -= s * c;
    },
    threads);
}

// The symmetry distance error (symmetry_distance_error()): the mean of the distances `d` over
// the diagonal of the bounding box `box` of the input.
inline double mean_over_diagonal(const std::vector<double>& d, const CGAL::Bbox_3& box)
{
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  check_radius(diagonal);
  double sum = 0.;
  for(double x : d) sum += x;
  return sum / double(d.size()) / diagonal;
}

// On triangles: `number_of_points_on_faces` area-uniform samples, reflected, their distances to
// the triangles (closest points in the AABB tree).
template <typename NamedParameters>
double symmetry_distance_error_of_triangles(const std::vector<Dtriangle>& triangles, const Dplane& mirror,
                                            const NamedParameters& np)
{
  const std::vector<double> d = distances_to(metric_samples(triangles, np),
                                             [&mirror](const Eigen::Vector3d& p) { return mirror.reflect(p); }, triangles,
                                             metric_threads(np));
  return mean_over_diagonal(d, CGAL::bbox_3(triangles.begin(), triangles.end()));
}

// On a point set: a seeded random subset of `number_of_points_on_faces` points (all if fewer),
// reflected, their distances to the nearest point of the set.
template <typename NamedParameters>
double symmetry_distance_error_of_point_set(const std::vector<Dpoint>& points, const Dplane& mirror,
                                            const NamedParameters& np)
{
  const std::vector<Eigen::Vector3d> samples = point_samples(points, metric_sampling(np));
  const Nearest_point nearest(points);
  std::vector<double> d(samples.size());
  parallel_for(samples.size(), metric_threads(np), [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i) d[i] = std::sqrt(nearest(mirror.reflect(samples[i])).squared_distance);
  });
  return mean_over_diagonal(d, CGAL::bbox_3(points.begin(), points.end()));
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
  return internal::plane_symmetry_measure(f, plane, 1);
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
 * The symmetry distance error (SDE) of a triangle mesh with respect to the reflection through
 * `plane`, the measure that learning methods of symmetry detection report (PRS-Net, E3Sym): the
 * mean distance from the mirror images of area-uniform random samples of the surface to the
 * surface, divided by the diagonal of the bounding box of the mesh,
 * \f[ SDE = \frac{1}{N\,D} \sum_{i=1}^{N} d(\gamma(x_i), S), \f]
 * \f$ x_i \f$ the samples, \f$ \gamma \f$ the reflection, \f$ d(\cdot, S) \f$ the exact distance
 * to the triangles (closest points in an AABB tree) and \f$ D \f$ the diagonal of the axis-aligned
 * bounding box of the non-degenerate faces. 0 for an exact symmetry (up to rounding); about
 * \f$ \theta\, c(a^2 + b^2) / ((ab + bc + ca)\, D) \f$ for a box of half-sides \f$ a, b, c \f$ and
 * its plane \f$ x = 0 \f$ turned by a small angle \f$ \theta \f$ about the \f$ z \f$ axis; invariant
 * under rigid motions and scaling. The samples are seeded: the result is deterministic for a seed,
 * and its sampling error falls as \f$ 1/\sqrt{N} \f$ (\ref SymmetryTransformMeasureSDE).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the mesh
 * \param plane the plane of reflection; its orientation does not matter
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamDistanceSamples{the number \f$ N \f$ of surface samples}
 *   \cgalParamRandomSeed{the seed of the samples: the result is deterministic for a seed}
 *   \cgalParamThreads{the threads that match the reflected samples to their closest points\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the SDE, a fraction of the diagonal (0.01: 1 % of it).
 * \throws std::invalid_argument if `plane` is degenerate, the mesh has no face, a face that is not
 * a triangle, only degenerate faces, or a NaN or infinite coordinate, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double symmetry_distance_error(const TriangleMesh& tm,
                               const typename Geom_traits_of_mesh<TriangleMesh, NamedParameters>::Plane_3& plane,
                               const NamedParameters& np = parameters::default_values())
{
  return internal::symmetry_distance_error_of_triangles(internal::triangles_of_mesh(tm, np), internal::to_dplane(plane), np);
}

/*!
 * \ingroup PkgSymmetryTransformMeasureRef
 *
 * The symmetry distance error of a triangle soup, as `symmetry_distance_error()` defines it for a
 * mesh, with the distances to the union of the triangles and the bounding box of the
 * non-degenerate ones. The soup needs no repair; a triangle given twice is sampled twice as often.
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param plane the plane of reflection; its orientation does not matter
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamDistanceSamples{the number \f$ N \f$ of surface samples}
 *   \cgalParamRandomSeed{the seed of the samples: the result is deterministic for a seed}
 *   \cgalParamThreads{the threads that match the reflected samples to their closest points\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the SDE, a fraction of the diagonal.
 * \throws std::invalid_argument if `plane` is degenerate, or on the bad soups of
 * `gaussian_distance_transform_of_triangle_soup()`, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename PointRange, typename TriangleRange, typename NamedParameters = parameters::Default_named_parameters>
double symmetry_distance_error_of_triangle_soup(
  const PointRange& points, const TriangleRange& triangles,
  const typename Geom_traits_of_points<PointRange, NamedParameters>::Plane_3& plane,
  const NamedParameters& np = parameters::default_values())
{
  return internal::symmetry_distance_error_of_triangles(internal::triangles_of_soup(points, triangles, np),
                                                        internal::to_dplane(plane), np);
}

/*!
 * \ingroup PkgSymmetryTransformMeasureRef
 *
 * The symmetry distance error of a point set: as `symmetry_distance_error()`, with the points
 * themselves as samples (a seeded random subset of \f$ N \f$ of them, all if there are fewer) and
 * the distance from a mirror image to the point set, that is to the nearest point
 * (`CGAL::Kd_tree`), over the diagonal of the bounding box of the points. The nearest point is
 * not the surface: even for an exact symmetry the SDE is then about the distance from a point of
 * the surface to the nearest sample, unless the point set itself is symmetric (every mirror image
 * a point of the set).
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points
 * \param plane the plane of reflection; its orientation does not matter
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamDistanceSamples{the number \f$ N \f$ of points reflected}
 *   \cgalParamRandomSeed{the seed of the subset of the points: the result is deterministic for a seed}
 *   \cgalParamThreads{the threads that look for the nearest points\, at most 1024 (0: the default); they change the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{not read: the distance is to the nearest point}
 *   \cgalParamGeomTraits
 * \cgalNamedParamsEnd
 *
 * \returns the SDE, a fraction of the diagonal.
 * \throws std::invalid_argument if `plane` is degenerate, the range is empty, all its points
 * coincide, or a coordinate is NaN or infinite, or if a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
double symmetry_distance_error_of_points(
  const PointRange& points,
  const typename Geom_traits_of_points<PointRange, NamedParameters>::Plane_3& plane,
  const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  return internal::symmetry_distance_error_of_point_set(internal::points_of_range(points, NP_helper::get_const_point_map(points, np)),
                                                        internal::to_dplane(plane), np);
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
