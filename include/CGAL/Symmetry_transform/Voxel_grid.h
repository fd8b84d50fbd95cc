// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_VOXEL_GRID_H
#define CGAL_SYMMETRY_TRANSFORM_VOXEL_GRID_H

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformGridRef
 *
 * A cube of `n`×`n`×`n` samples of a scalar function of space, centred on the centre of mass
 * of a shape and large enough to hold its bounding sphere: this placement does not depend on
 * the orientation of the shape, so transforms computed on the grid rotate with the shape.
 *
 * Sample `(i,j,k)` sits at the centre of its voxel,
 * `center() + voxel_size() * (i + 1/2 - n/2, j + 1/2 - n/2, k + 1/2 - n/2)`.
 * Values are stored as `double` whatever the number type of the traits (the transforms are
 * numerical kernels); `i` varies fastest in `values()`.
 *
 * \tparam GeomTraits a model of `Kernel`; only `FT`, `Point_3` and their coordinate access are used.
*/
template <typename GeomTraits>
class Voxel_grid
{
public:
  /// Number type of the traits.
  typedef typename GeomTraits::FT FT;
  /// Point type of the traits.
  typedef typename GeomTraits::Point_3 Point_3;

  /// Creates an empty grid (resolution 0).
  Voxel_grid() = default;

  /*!
 *   Creates a grid of `resolution`³ samples, all set to `value`, over the axis-aligned cube of
 *   side `side_length` centred on `center`.
 *   \param resolution the number \f$ n \f$ of samples along each axis
 *   \param center the centre of the cube, usually the centre of mass of the shape
 *   \param radius the radius of the shape the grid represents (the largest distance from `center` to the shape)
 *   \param side_length the side of the cube
 *   \param value the initial value of every sample
 *   \throws std::invalid_argument unless `resolution > 0`, `side_length > 0` and `radius >= 0`.
  */
  Voxel_grid(std::size_t resolution, const Point_3& center, FT radius, FT side_length,
             double value = 0.)
    : n_(resolution), radius_(CGAL::to_double(radius)),
      side_(CGAL::to_double(side_length)), values_(resolution * resolution * resolution, value)
  {
    if(resolution == 0 || !(side_ > 0.) || !(radius_ >= 0.))
      throw std::invalid_argument("Voxel_grid: the resolution and the side length must be positive, the radius non-negative");
    recenter(center);
  }

  /// \cond SKIP_IN_MANUAL
  // The same samples, the cube moved to be centred on `center`.
  void recenter(const Point_3& center)
  {
    center_ = center;
    origin_ = {CGAL::to_double(center.x()) - side_ / 2., CGAL::to_double(center.y()) - side_ / 2.,
               CGAL::to_double(center.z()) - side_ / 2.};
  }
  /// \endcond

  /// Number of samples along each axis.
  /// \returns \f$ n \f$ (0 for a default-constructed grid)
  std::size_t resolution() const { return n_; }
  /// Centre of the cube.
  /// \returns the `center` given at construction: the centre of mass of the shape for the grids of this package
  const Point_3& center() const { return center_; }
  /// Radius of the shape.
  /// \returns the largest distance from `center()` to the shape, as given at construction
  double radius() const { return radius_; }
  /// Side length of the cube.
  /// \returns the side of the cube, in the units of the points
  double side_length() const { return side_; }
  /// Distance between two neighbouring samples.
  /// \returns `side_length() / resolution()`
  double voxel_size() const { return side_ / double(n_); }

  /// Position of sample `(i,j,k)` in the array returned by `values()`.
  /// \param i,j,k the indices of the sample along \f$ x \f$, \f$ y \f$ and \f$ z \f$, each in \f$ [0, n) \f$
  /// \returns \f$ (k n + j) n + i \f$
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return (k * n_ + j) * n_ + i; }
  /// Sample `(i,j,k)`, for writing.
  /// \param i,j,k the indices of the sample, each in \f$ [0, n) \f$ (not checked)
  /// \returns a reference to the sample
  double& operator()(std::size_t i, std::size_t j, std::size_t k) { return values_[index(i, j, k)]; }
  /// Sample `(i,j,k)`.
  /// \param i,j,k the indices of the sample, each in \f$ [0, n) \f$ (not checked)
  /// \returns the value of the sample
  double operator()(std::size_t i, std::size_t j, std::size_t k) const { return values_[index(i, j, k)]; }
  /// All samples, `i` fastest, then `j`, then `k`, for writing.
  /// \returns the \f$ n^3 \f$ samples, sample `(i,j,k)` at position `index(i,j,k)`
  std::vector<double>& values() { return values_; }
  /// All samples, `i` fastest, then `j`, then `k`.
  /// \returns the \f$ n^3 \f$ samples, sample `(i,j,k)` at position `index(i,j,k)`
  const std::vector<double>& values() const { return values_; }

  /// Position of sample `(i,j,k)`.
  /// \param i,j,k the indices of the sample
  /// \returns the centre of voxel `(i,j,k)`
  Point_3 point(std::size_t i, std::size_t j, std::size_t k) const
  {
    const double h = voxel_size();
    return Point_3(origin_[0] + (double(i) + 0.5) * h, origin_[1] + (double(j) + 0.5) * h,
                   origin_[2] + (double(k) + 0.5) * h);
  }

  /// Trilinear interpolation of the samples at `p`; the function is taken as zero outside the grid.
  /// \param p any point
  /// \returns the interpolated value, 0 farther than one voxel outside the samples
  double value(const Point_3& p) const
  {
    return trilinear_value(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  /// \cond SKIP_IN_MANUAL
  // Coordinate-level access used by the numerical kernels.
  const std::array<double, 3>& origin() const { return origin_; }

  double sample_or_zero(long i, long j, long k) const
  {
    const long n = long(n_);
    if(i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n) return 0.;
    return values_[index(std::size_t(i), std::size_t(j), std::size_t(k))];
  }

  double trilinear_value(double x, double y, double z) const
  {
    Cell cell;
    if(!cell_of(x, y, z, cell)) return 0.;
    const long i = cell.i, j = cell.j, k = cell.k;
    const long n = long(n_);
    if(i < -1 || j < -1 || k < -1 || i >= n || j >= n || k >= n) return 0.;
    const double a = cell.a, b = cell.b, c = cell.c;
    if(i >= 0 && j >= 0 && k >= 0 && i + 1 < n && j + 1 < n && k + 1 < n) {
      const double* s = values_.data() + index(std::size_t(i), std::size_t(j), std::size_t(k));
      const std::size_t sj = n_, sk = n_ * n_;
      const double x00 = s[0] + a * (s[1] - s[0]), x10 = s[sj] + a * (s[sj + 1] - s[sj]);
      const double x01 = s[sk] + a * (s[sk + 1] - s[sk]),
                   x11 = s[sk + sj] + a * (s[sk + sj + 1] - s[sk + sj]);
      const double y0 = x00 + b * (x10 - x00), y1 = x01 + b * (x11 - x01);
      return y0 + c * (y1 - y0);
    }
    double result = 0.;
    for(int dk = 0; dk < 2; ++dk)
      for(int dj = 0; dj < 2; ++dj)
        for(int di = 0; di < 2; ++di)
          result += (di ? a : 1. - a) * (dj ? b : 1. - b) * (dk ? c : 1. - c) *
                    sample_or_zero(i + di, j + dj, k + dk);
    return result;
  }

  // Catmull-Rom (cubic convolution) interpolation: third-order accurate, so a perfectly
  // symmetric Gaussian distance transform measures as symmetric to within 1e-3, where the
  // smoothing of trilinear interpolation costs about 1/(24 sigma^2) (2% at sigma = 1.5 voxels).
  double cubic_value(double x, double y, double z) const
  {
    Cell cell;
    if(!cell_of(x, y, z, cell)) return 0.;
    const long i = cell.i, j = cell.j, k = cell.k;
    const long n = long(n_);
    if(i < -2 || j < -2 || k < -2 || i > n || j > n || k > n) return 0.;
    std::array<double, 4> wu = catmull_rom_weights(cell.a), wv = catmull_rom_weights(cell.b),
                          ww = catmull_rom_weights(cell.c);
    const bool inside = i >= 1 && j >= 1 && k >= 1 && i + 2 < n && j + 2 < n && k + 2 < n;
    double result = 0.;
    for(int c = 0; c < 4; ++c) {
      double plane = 0.;
      for(int b = 0; b < 4; ++b) {
        double row = 0.;
        if(inside) {
          const double* s = values_.data() + index(std::size_t(i - 1), std::size_t(j - 1 + b),
                                                   std::size_t(k - 1 + c));
          row = wu[0] * s[0] + wu[1] * s[1] + wu[2] * s[2] + wu[3] * s[3];
        } else {
          for(int a = 0; a < 4; ++a) row += wu[a] * sample_or_zero(i - 1 + a, j - 1 + b, k - 1 + c);
        }
        plane += wv[b] * row;
      }
      result += ww[c] * plane;
    }
    return result;
  }
  /// \endcond

private:
  // The cell of the sample centres around a point: its lowest sample (i, j, k) and the position
  // (a, b, c) of the point in it, each in [0, 1).
  struct Cell
  {
    long i, j, k;
    double a, b, c;
  };

  // The cell of (x, y, z); false if the point is out of reach of the samples (or NaN).
  bool cell_of(double x, double y, double z, Cell& cell) const
  {
    const double h = voxel_size();
    const double u = (x - origin_[0]) / h - 0.5, v = (y - origin_[1]) / h - 0.5,
                 w = (z - origin_[2]) / h - 0.5;
    if(!in_reach(u) || !in_reach(v) || !in_reach(w)) return false; // also NaN: far outside the grid
    const double fu = floor_of(u), fv = floor_of(v), fw = floor_of(w);
    cell = {long(fu), long(fv), long(fw), u - fu, v - fv, w - fw};
    return true;
  }

  // Whether a continuous sample index can reach a sample (within 3 of the grid): beyond, the
  // value is zero and the index may not even fit in a long.
  bool in_reach(double u) const { return u > -3. && u < double(n_) + 2.; }

  // std::floor is a library call on x86-64 without SSE4.1; interpolation calls it millions of times.
  static double floor_of(double x)
  {
    const double t = double(static_cast<long>(x));
    return t > x ? t - 1. : t;
  }

  static std::array<double, 4> catmull_rom_weights(double t)
  {
    const double t2 = t * t, t3 = t2 * t;
    return {0.5 * (-t3 + 2. * t2 - t), 0.5 * (3. * t3 - 5. * t2 + 2.),
            0.5 * (-3. * t3 + 4. * t2 + t), 0.5 * (t3 - t2)};
  }

  std::size_t n_ = 0;
  Point_3 center_;
  double radius_ = 0.;
  double side_ = 0.;
  std::array<double, 3> origin_ = {0., 0., 0.};
  std::vector<double> values_;
};

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_VOXEL_GRID_H
