// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_POINT_SYMMETRY_TRANSFORM_H
#define CGAL_SYMMETRY_TRANSFORM_POINT_SYMMETRY_TRANSFORM_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/common/fft.h>
#include <CGAL/Symmetry_transform/internal/grid/settings.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformPSTRef
 *
 * The Point Symmetry Transform (PST) of a function \f$ f \f$ sampled on a `Voxel_grid`: for every
 * sample \f$ p \f$ of the grid, the symmetry measure of \f$ f \f$ with respect to the point
 * reflection \f$ x \mapsto 2p - x \f$,
 * \f$ SM(p) = \sum_x f(x) f(2p - x) / \sum_x f(x)^2 \in [0,1] \f$.
 *
 * Built by `point_symmetry_transform()`.
 *
 * \tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
class Point_symmetry_transform
{
public:
  /// Point type of the traits.
  typedef typename GeomTraits::Point_3 Point_3;

  /// Wraps a grid of symmetry measures, on the same samples as the function they measure,
  /// and the point of strongest symmetry found when computing them.
  /// \param symmetry_measures the symmetry measure of each sample of the grid
  /// \param center_of_symmetry the point of largest symmetry measure
  Point_symmetry_transform(Voxel_grid<GeomTraits> symmetry_measures, const Point_3& center_of_symmetry)
    : grid_(std::move(symmetry_measures)), center_of_symmetry_(center_of_symmetry)
  {}

  /// The symmetry measure at each sample of the grid.
  /// \returns the grid of symmetry measures, on the samples of the function it was computed from
  const Voxel_grid<GeomTraits>& grid() const { return grid_; }

  /// Symmetry measure with respect to `p`, interpolated trilinearly between samples.
  /// \param p the centre of the point reflection
  /// \returns \f$ SM(p) \f$, 0 outside the grid
  double value(const Point_3& p) const { return grid_.value(p); }

  /*!
 *   The point of strongest point symmetry. `point_symmetry_transform()` finds it on a grid twice
 *   as fine as `grid()` (the self-convolution it computes has a sample at every midpoint of two
 *   samples of \f$ f \f$), then moves it by one Newton step on the logarithm of the measure,
 *   with the gradient and full Hessian of the 3×3×3 samples around the best one: near a
 *   symmetric centre the measure is close to a Gaussian, whose logarithm is quadratic.
 *   \returns the centre of symmetry
  */
  const Point_3& center_of_symmetry() const { return center_of_symmetry_; }

private:
  Voxel_grid<GeomTraits> grid_;
  Point_3 center_of_symmetry_;
};

namespace internal {

// FFTW's basic interface counts samples in int: the padded grid, (2n)^3 samples, must fit.
constexpr std::size_t max_point_symmetry_resolution = 512;
// The logarithms of the samples around a peak are taken of at least this, a positive number.
constexpr double smallest_logarithm_argument = 1e-300;

// Offset of the maximum of exp(q), q the quadratic through the logarithms of the 27 values
// sample(di, dj, dk), di, dj, dk in {-1, 0, 1}, around a largest sample; zero if the samples
// do not curve down, and at most one step along each axis.
template <typename Sample>
Eigen::Vector3d newton_step_to_peak(const Sample& sample)
{
  auto log_sample = [&](const long* d) { return std::log((std::max)(sample(d[0], d[1], d[2]), smallest_logarithm_argument)); };
  const long zero[3] = {0, 0, 0};
  Eigen::Vector3d gradient;
  Eigen::Matrix3d hessian;
  for(int a = 0; a < 3; ++a)
    for(int b = a + 1; b < 3; ++b) {
      long pp[3] = {0, 0, 0}, pm[3] = {0, 0, 0}, mp[3] = {0, 0, 0}, mm[3] = {0, 0, 0};
      pp[a] = pm[a] = 1;
      mp[a] = mm[a] = -1;
      pp[b] = mp[b] = 1;
      pm[b] = mm[b] = -1;
      hessian(a, b) = hessian(b, a) = 0.25 * (log_sample(pp) - log_sample(pm) - log_sample(mp) + log_sample(mm));
    }
  for(int a = 0; a < 3; ++a) {
    long p[3] = {0, 0, 0}, m[3] = {0, 0, 0};
    p[a] = 1;
    m[a] = -1;
    gradient[a] = 0.5 * (log_sample(p) - log_sample(m));
    hessian(a, a) = log_sample(p) - 2. * log_sample(zero) + log_sample(m);
  }
  if(!(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(hessian).eigenvalues().maxCoeff() < 0.))
    return Eigen::Vector3d::Zero();
  return (-hessian.inverse() * gradient).cwiseMax(-1.).cwiseMin(1.);
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformPSTRef
 *
 * Computes the Point Symmetry Transform of a function sampled on a grid, for instance a GEDT
 * from `gaussian_distance_transform()`: all the sums \f$ \sum_x f(x) f(2p - x) \f$ at once as
 * the self-convolution of \f$ f \f$, by FFT on a grid zero-padded to \f$ (2n)^3 \f$ (no
 * wrap-around), in \f$ O(n^3 \log n) \f$ time and \f$ 128\,n^3 \f$ bytes of memory.
 *
 * \tparam GeomTraits a model of `Kernel`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"; none is used
 *         by this overload, which accepts them so that the overloads on meshes and point sets can
 *         pass theirs on
 *
 * \param f the function, with \f$ n \f$ samples along each axis
 *
 * \returns the symmetry measure of every sample of `f`, on a grid with the same samples
 *
 * \throws std::invalid_argument if `f` is zero everywhere, its resolution exceeds 512, or the padded grid does not fit in memory.
*/
template <typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
Point_symmetry_transform<GeomTraits> point_symmetry_transform(const Voxel_grid<GeomTraits>& f,
                                                              const NamedParameters& = parameters::default_values())
{
  if(f.resolution() > internal::max_point_symmetry_resolution)
    throw std::invalid_argument("point_symmetry_transform: the resolution must be at most 512");
  const int n = int(f.resolution()), N = 2 * n;
  const std::size_t real_size = std::size_t(N) * N * N, complex_size = std::size_t(N) * N * (N / 2 + 1);
  internal::check_memory(double(real_size) * 8. + double(complex_size) * 16., "the point symmetry transform");
  double sum_of_squares = 0.;
  for(double x : f.values()) sum_of_squares += x * x;
  if(internal::stop_requested()) // cancelled in the GEDT of a shape: zero, as `f`
    return Point_symmetry_transform<GeomTraits>(f, f.center());
  if(!(sum_of_squares > 0.)) throw std::invalid_argument("Symmetry_transform: the grid is zero everywhere");

  auto padded = internal::fftw_buffer<double>(real_size);
  auto spectrum = internal::fftw_buffer<fftw_complex>(complex_size);
  const int dims[3] = {N, N, N};
  const internal::Fftw_plan forward = internal::real_to_complex_plan(3, dims, padded.get(), spectrum.get());
  const internal::Fftw_plan backward = internal::complex_to_real_plan(3, dims, spectrum.get(), padded.get());
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      std::copy_n(&f.values()[f.index(0, std::size_t(j), std::size_t(k))], n,
                  padded.get() + (std::size_t(k) * N + j) * N);
  fftw_execute(forward.get());
  for(std::size_t s = 0; s < complex_size; ++s) {
    const double re = spectrum[s][0], im = spectrum[s][1];
    spectrum[s][0] = re * re - im * im;
    spectrum[s][1] = 2. * re * im;
  }
  fftw_execute(backward.get());

  // (f*f)[m] sums the pairs of samples a, b with a + b = m, whose midpoint is at m/2 in sample
  // units: the even indices are the samples of f, the odd ones the midpoints between them.
  const double scale = 1. / (double(real_size) * sum_of_squares);
  auto convolution = [&](long i, long j, long k) {
    const long last = 2 * n - 2;
    if(i < 0 || j < 0 || k < 0 || i > last || j > last || k > last) return 0.;
    return padded[(std::size_t(k) * N + std::size_t(j)) * N + std::size_t(i)] * scale;
  };
  Voxel_grid<GeomTraits> result(f.resolution(), f.center(), f.radius(), f.side_length());
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) result(std::size_t(i), std::size_t(j), std::size_t(k)) = convolution(2 * i, 2 * j, 2 * k);

  long best[3] = {0, 0, 0};
  double best_value = -1.;
  for(long k = 0; k <= 2 * n - 2; ++k)
    for(long j = 0; j <= 2 * n - 2; ++j)
      for(long i = 0; i <= 2 * n - 2; ++i)
        if(convolution(i, j, k) > best_value) {
          best_value = convolution(i, j, k);
          best[0] = i; best[1] = j; best[2] = k;
        }
  const Eigen::Vector3d shift = internal::newton_step_to_peak(
    [&](long di, long dj, long dk) { return convolution(best[0] + di, best[1] + dj, best[2] + dk); });
  double position[3];
  for(int a = 0; a < 3; ++a)
    position[a] = f.origin()[a] + ((double(best[a]) + shift[a]) / 2. + 0.5) * f.voxel_size();
  return Point_symmetry_transform<GeomTraits>(std::move(result),
                                              typename GeomTraits::Point_3(position[0], position[1], position[2]));
}

/*!
 * \ingroup PkgSymmetryTransformPSTRef
 *
 * Computes the Point Symmetry Transform of a triangle mesh: its GEDT by
 * `gaussian_distance_transform(tm, np)`, then `point_symmetry_transform()` of that grid.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the input mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{a transform whose values are all zero\, its centre of symmetry the centre of the grid}
 * \cgalNamedParamsEnd
 *
 * \returns the Point Symmetry Transform of the GEDT of `tm`
 *
 * \throws std::invalid_argument as `gaussian_distance_transform()` and the overload on grids.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Point_symmetry_transform<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>
point_symmetry_transform(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  return internal::with_progress_scope(np, [&] { return point_symmetry_transform(gaussian_distance_transform(tm, np), np); });
}

/*!
 * \ingroup PkgSymmetryTransformPSTRef
 *
 * Computes the Point Symmetry Transform of a point set: its GEDT by
 * `gaussian_distance_transform_of_points(points, np)`, then `point_symmetry_transform()` of that grid.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the input points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{not read: the GEDT is the distance to the points, whatever their normals}
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{a transform whose values are all zero\, its centre of symmetry the centre of the grid}
 * \cgalNamedParamsEnd
 *
 * \returns the Point Symmetry Transform of the GEDT of `points`
 *
 * \throws std::invalid_argument as `gaussian_distance_transform_of_points()` and the overload on grids.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Point_symmetry_transform<Geom_traits_of_points<PointRange, NamedParameters>>
point_symmetry_transform_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  return internal::with_progress_scope(
    np, [&] { return point_symmetry_transform(gaussian_distance_transform_of_points(points, np), np); });
}

/*!
 * \ingroup PkgSymmetryTransformPSTRef
 *
 * Computes the Point Symmetry Transform of a triangle soup: its GEDT by
 * `gaussian_distance_transform_of_triangle_soup(points, triangles, np)`, then `point_symmetry_transform()` of that grid.
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 *   \cgalParamCallback{a transform whose values are all zero\, its centre of symmetry the centre of the grid}
 * \cgalNamedParamsEnd
 *
 * \returns the Point Symmetry Transform of the GEDT of the soup
 *
 * \throws std::invalid_argument as `gaussian_distance_transform_of_triangle_soup()` and the overload on grids.
*/
template <typename PointRange, typename TriangleRange, typename NamedParameters = parameters::Default_named_parameters>
Point_symmetry_transform<Geom_traits_of_points<PointRange, NamedParameters>>
point_symmetry_transform_of_triangle_soup(const PointRange& points, const TriangleRange& triangles,
                                          const NamedParameters& np = parameters::default_values())
{
  return internal::with_progress_scope(
    np, [&] { return point_symmetry_transform(gaussian_distance_transform_of_triangle_soup(points, triangles, np), np); });
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_POINT_SYMMETRY_TRANSFORM_H
