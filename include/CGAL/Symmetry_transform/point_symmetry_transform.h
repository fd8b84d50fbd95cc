// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_POINT_SYMMETRY_TRANSFORM_H
#define CGAL_SYMMETRY_TRANSFORM_POINT_SYMMETRY_TRANSFORM_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/internal/fft.h>
#include <CGAL/Symmetry_transform/internal/grid_settings.h>
#include <CGAL/Symmetry_transform/internal/mesh_geom_traits.h>
#include <CGAL/Symmetry_transform/internal/named_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Symmetry_transform {

/*!
\ingroup PkgSymmetryTransformRef

The Point Symmetry Transform (PST) of a function \f$ f \f$ sampled on a `Voxel_grid`: for every
sample \f$ p \f$ of the grid, the symmetry measure of \f$ f \f$ with respect to the point
reflection \f$ x \mapsto 2p - x \f$,
\f$ SM(p) = \sum_x f(x) f(2p - x) / \sum_x f(x)^2 \in [0,1] \f$.

Built by `point_symmetry_transform()`.

\tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
class Point_symmetry_transform
{
public:
  /// Point type of the traits.
  typedef typename GeomTraits::Point_3 Point_3;

  /// Wraps a grid of symmetry measures, on the same samples as the function they measure.
  explicit Point_symmetry_transform(Voxel_grid<GeomTraits> symmetry_measures)
    : grid_(std::move(symmetry_measures))
  {}

  /// The symmetry measure at each sample of the grid.
  const Voxel_grid<GeomTraits>& grid() const { return grid_; }

  /// Symmetry measure with respect to `p`, interpolated trilinearly between samples.
  double value(const Point_3& p) const { return grid_.value(p); }

  /*!
  The point of strongest point symmetry: the sample of largest symmetry measure, moved to the
  maximum of the parabola through it and its two neighbours along each axis (sub-voxel accuracy).
  */
  Point_3 center_of_symmetry() const
  {
    const std::vector<double>& v = grid_.values();
    const std::size_t best = std::size_t(std::max_element(v.begin(), v.end()) - v.begin());
    const std::size_t n = grid_.resolution();
    const std::array<std::size_t, 3> ijk = {best % n, best / n % n, best / (n * n)};
    std::array<double, 3> position;
    for(int axis = 0; axis < 3; ++axis) {
      std::array<long, 3> lo = {long(ijk[0]), long(ijk[1]), long(ijk[2])}, hi = lo;
      --lo[axis];
      ++hi[axis];
      const double f0 = v[best], fm = grid_.sample_or_zero(lo[0], lo[1], lo[2]),
                   fp = grid_.sample_or_zero(hi[0], hi[1], hi[2]);
      const double curvature = fm - 2. * f0 + fp;
      const double shift = curvature < 0. ? std::clamp(0.5 * (fm - fp) / curvature, -0.5, 0.5) : 0.;
      position[axis] = grid_.origin()[axis] + (double(ijk[axis]) + 0.5 + shift) * grid_.voxel_size();
    }
    return Point_3(position[0], position[1], position[2]);
  }

private:
  Voxel_grid<GeomTraits> grid_;
};

/*!
\ingroup PkgSymmetryTransformRef

Computes the Point Symmetry Transform of a function sampled on a grid, for instance a GEDT
from `gaussian_distance_transform()`: all the sums \f$ \sum_x f(x) f(2p - x) \f$ at once as
the self-convolution of \f$ f \f$, by FFT on a grid zero-padded to \f$ (2n)^3 \f$ (no
wrap-around), in \f$ O(n^3 \log n) \f$ time and \f$ 128\,n^3 \f$ bytes of memory.

\throws std::invalid_argument if `f` is zero everywhere or the padded grid does not fit in memory.
*/
template <typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
Point_symmetry_transform<GeomTraits> point_symmetry_transform(const Voxel_grid<GeomTraits>& f,
                                                              const NamedParameters& = parameters::default_values())
{
  const int n = int(f.resolution()), N = 2 * n;
  const std::size_t real_size = std::size_t(N) * N * N, complex_size = std::size_t(N) * N * (N / 2 + 1);
  internal::check_memory(double(real_size) * 8. + double(complex_size) * 16., "the point symmetry transform");
  double sum_of_squares = 0.;
  for(double x : f.values()) sum_of_squares += x * x;
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

  // (f*f)[a + b] pairs samples a and b, whose midpoint is sample (a + b)/2: keep even indices.
  Voxel_grid<GeomTraits> result(f.resolution(), f.center(), f.radius(), f.side_length());
  const double scale = 1. / (double(real_size) * sum_of_squares);
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
        result(std::size_t(i), std::size_t(j), std::size_t(k)) =
          padded[(std::size_t(2 * k) * N + 2 * j) * N + 2 * i] * scale;
  return Point_symmetry_transform<GeomTraits>(std::move(result));
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the Point Symmetry Transform of a triangle mesh: its GEDT by
`gaussian_distance_transform(tm, np)`, then `point_symmetry_transform()` of that grid.
The named parameters are those of `gaussian_distance_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Point_symmetry_transform<typename internal::Mesh_geom_traits<TriangleMesh, NamedParameters>::type>
point_symmetry_transform(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  return point_symmetry_transform(gaussian_distance_transform(tm, np), np);
}

/*!
\ingroup PkgSymmetryTransformRef

Computes the Point Symmetry Transform of a point set: its GEDT by
`gaussian_distance_transform_of_points(points, np)`, then `point_symmetry_transform()` of that grid.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Point_symmetry_transform<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits>
point_symmetry_transform_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  return point_symmetry_transform(gaussian_distance_transform_of_points(points, np), np);
}

} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_POINT_SYMMETRY_TRANSFORM_H
