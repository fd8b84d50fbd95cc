// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_EXACT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_EXACT_H

// The exact (convolution) method: for each normal direction, resample f in a frame whose
// third axis is the normal; along each column the sums sum_w g(w) g(2r - w) for all offsets r
// are one self-convolution, and the sum over columns of those convolutions is the inverse FFT
// of the sum of the squared column spectra. O(n^2) directions x O(n^3 log n) each.

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/fft.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// Largest distance from the grid centre to a non-zero sample, plus half a voxel diagonal.
template <typename GT>
double support_radius(const Voxel_grid<GT>& f)
{
  const std::size_t n = f.resolution();
  const double h = f.voxel_size();
  const auto& o = f.origin();
  const double c[3] = {CGAL::to_double(f.center().x()), CGAL::to_double(f.center().y()),
                       CGAL::to_double(f.center().z())};
  double r2 = 0.;
  for(std::size_t v = 0; v < f.values().size(); ++v)
    if(f.values()[v] != 0.) {
      const double x = o[0] + (double(v % n) + 0.5) * h - c[0], y = o[1] + (double(v / n % n) + 0.5) * h - c[1],
                   z = o[2] + (double(v / (n * n)) + 0.5) * h - c[2];
      r2 = (std::max)(r2, x * x + y * y + z * z);
    }
  return std::sqrt(r2) + h * std::sqrt(3.) / 2.;
}

// Trilinear interpolation at a random offset smoothes: on average it returns
// f + (h^2 / 12) f'' along each axis, which lowers the symmetry measure of a GEDT of width
// sigma voxels by about 1 / (24 sigma^2) (2% at 1.5 voxels). Interpolating instead
// f - (1/12) (second difference of f along each axis) cancels that term, so that sums of
// interpolated values agree with the cubic interpolation of symmetry_measure() to O(h^4).
template <typename GT>
Voxel_grid<GT> sharpened_for_trilinear_interpolation(const Voxel_grid<GT>& f)
{
  Voxel_grid<GT> result = f;
  const long n = long(f.resolution());
  for(long k = 0; k < n; ++k)
    for(long j = 0; j < n; ++j)
      for(long i = 0; i < n; ++i) {
        const double c = f.sample_or_zero(i, j, k);
        const double laplacian = f.sample_or_zero(i - 1, j, k) + f.sample_or_zero(i + 1, j, k) +
                                 f.sample_or_zero(i, j - 1, k) + f.sample_or_zero(i, j + 1, k) +
                                 f.sample_or_zero(i, j, k - 1) + f.sample_or_zero(i, j, k + 1) - 6. * c;
        result(std::size_t(i), std::size_t(j), std::size_t(k)) = c - laplacian / 12.;
      }
  return result;
}

// Symmetry measures of all bins, by convolution of f resampled (from its sharpened version)
// along the columns of each direction, divided by sum_x f(x)^2.
template <typename GT>
void exact_reflective_symmetry(const Voxel_grid<GT>& f_samples, const Plane_bins& bins, unsigned threads,
                               std::vector<double>& values)
{
  const Voxel_grid<GT> f = sharpened_for_trilinear_interpolation(f_samples);
  const std::size_t n = bins.n;
  const double h = f.voxel_size(), step = bins.offset_step();
  const double support = support_radius(f);
  // Column samples at w_a = (a - (m-1)/2) step, so that w_a + w_b = 2 r_k for a + b = 2k + m - n.
  const long half = long(std::ceil(support / step));
  const int m = int((std::max)(long(n), 2 * half + 1));
  const int P = fft_friendly_size(2 * m - 1);
  const long columns_per_axis = long(std::ceil(support / h));

  auto plan_in = fftw_buffer<double>(std::size_t(P));
  auto plan_out = fftw_buffer<fftw_complex>(std::size_t(P / 2 + 1));
  const Fftw_plan forward = real_to_complex_plan(1, &P, plan_in.get(), plan_out.get());
  const Fftw_plan backward = complex_to_real_plan(1, &P, plan_out.get(), plan_in.get());
  double sum_of_squares = 0.;
  for(double v : f_samples.values()) sum_of_squares += v * v;
  // A column sample stands for a cell of h * h * step, a grid sample for h^3.
  const double scale = step / (double(P) * sum_of_squares * h);
  const double c[3] = {bins.center[0], bins.center[1], bins.center[2]};

  parallel_for(n * n, threads, [&](unsigned, std::size_t begin, std::size_t end) {
    auto column = fftw_buffer<double>(std::size_t(P));
    auto spectrum = fftw_buffer<fftw_complex>(std::size_t(P / 2 + 1));
    auto sum = fftw_buffer<fftw_complex>(std::size_t(P / 2 + 1));
    for(std::size_t direction = begin; direction < end; ++direction) {
      const std::size_t i = direction / n, j = direction % n;
      const double t = bins.theta(i), p = bins.phi(j);
      const double nz[3] = {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
      const double e1[3] = {std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), -std::sin(t)};
      const double e2[3] = {-std::sin(p), std::cos(p), 0.};
      std::fill_n(&sum[0][0], 2 * (P / 2 + 1), 0.);
      for(long a = -columns_per_axis; a <= columns_per_axis; ++a)
        for(long b = -columns_per_axis; b <= columns_per_axis; ++b) {
          const double u = double(a) * h, v = double(b) * h;
          if(u * u + v * v > support * support) continue;
          const double w0 = -0.5 * double(m - 1) * step;
          double x[3];
          for(int d = 0; d < 3; ++d) x[d] = c[d] + u * e1[d] + v * e2[d] + w0 * nz[d];
          bool empty = true;
          for(int s = 0; s < m; ++s) {
            const double g = f.trilinear_value(x[0] + s * step * nz[0], x[1] + s * step * nz[1],
                                               x[2] + s * step * nz[2]);
            column[s] = g;
            empty = empty && g == 0.;
          }
          if(empty) continue;
          std::fill(column.get() + m, column.get() + P, 0.);
          fftw_execute_dft_r2c(forward.get(), column.get(), spectrum.get());
          for(int s = 0; s <= P / 2; ++s) {
            const double re = spectrum[s][0], im = spectrum[s][1];
            sum[s][0] += re * re - im * im;
            sum[s][1] += 2. * re * im;
          }
        }
      fftw_execute_dft_c2r(backward.get(), sum.get(), column.get());
      for(std::size_t k = 0; k < n; ++k)
        values[bins.index(i, j, k)] = column[2 * k + std::size_t(m) - n] * scale;
    }
  });
}

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_EXACT_H
