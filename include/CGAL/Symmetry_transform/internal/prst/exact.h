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
#include <CGAL/Symmetry_transform/internal/grid/filters.h>
#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Symmetry measures of all bins, by convolution of f resampled (from its sharpened version)
// along the columns of each direction, divided by sum_x f(x)^2.
template <typename GT>
class Exact_reflective_symmetry
{
public:
  Exact_reflective_symmetry(const Voxel_grid<GT>& f_samples, const Plane_bins& bins)
    : f_(sharpened_for_trilinear_interpolation(f_samples)), bins_(bins), n_(bins.n), h_(f_.voxel_size()),
      step_(bins.offset_step()), support_(support_radius(f_))
  {
    // Column samples at w_a = (a - (m-1)/2) step, so that w_a + w_b = 2 r_k for a + b = 2k + m - n.
    const long half = long(std::ceil(support_ / step_));
    m_ = int((std::max)(long(n_), 2 * half + 1));
    fft_size_ = fft_friendly_size(2 * m_ - 1);
    columns_per_axis_ = long(std::ceil(support_ / h_));
    double sum_of_squares = 0.;
    for(double v : f_samples.values()) sum_of_squares += v * v;
    // A column sample stands for a cell of h * h * step, a grid sample for h^3.
    scale_ = step_ / (double(fft_size_) * sum_of_squares * h_);
  }

  void run(unsigned threads, std::vector<double>& values) const
  {
    const int P = fft_size_;
    auto plan_in = fftw_buffer<double>(std::size_t(P));
    auto plan_out = fftw_buffer<fftw_complex>(std::size_t(P / 2 + 1));
    const Fftw_plan forward = real_to_complex_plan(1, &P, plan_in.get(), plan_out.get());
    const Fftw_plan backward = complex_to_real_plan(1, &P, plan_out.get(), plan_in.get());
    parallel_for(n_ * n_, threads, [&](unsigned, std::size_t begin, std::size_t end) {
      auto column = fftw_buffer<double>(std::size_t(P));
      auto spectrum = fftw_buffer<fftw_complex>(std::size_t(P / 2 + 1));
      auto sum = fftw_buffer<fftw_complex>(std::size_t(P / 2 + 1));
      for(std::size_t direction = begin; direction < end && parallel_step(1); ++direction) {
        const std::size_t i = direction / n_, j = direction % n_;
        sum_squared_spectra(i, j, forward, column.get(), spectrum.get(), sum.get());
        fftw_execute_dft_c2r(backward.get(), sum.get(), column.get());
        for(std::size_t k = 0; k < n_; ++k)
          values[bins_.index(i, j, k)] = column[2 * k + std::size_t(m_) - n_] * scale_;
      }
    });
  }

private:
  // `sum` receives the sum of the squared spectra of the columns of direction (i, j); `column`
  // and `spectrum` are work space.
  void sum_squared_spectra(std::size_t i, std::size_t j, const Fftw_plan& forward, double* column,
                           fftw_complex* spectrum, fftw_complex* sum) const
  {
    const double t = bins_.theta(i), p = bins_.phi(j);
    const double nz[3] = {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
    const double e1[3] = {std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), -std::sin(t)};
    const double e2[3] = {-std::sin(p), std::cos(p), 0.};
    const int P = fft_size_;
    std::fill_n(&sum[0][0], 2 * (P / 2 + 1), 0.);
    for(long a = -columns_per_axis_; a <= columns_per_axis_; ++a)
      for(long b = -columns_per_axis_; b <= columns_per_axis_; ++b) {
        const double u = double(a) * h_, v = double(b) * h_;
        if(u * u + v * v > support_ * support_) continue;
        const double w0 = -0.5 * double(m_ - 1) * step_;
        double x[3];
        for(int d = 0; d < 3; ++d) x[d] = bins_.center[d] + u * e1[d] + v * e2[d] + w0 * nz[d];
        if(!sample_column(x, nz, column)) continue;
        std::fill(column + m_, column + P, 0.);
        fftw_execute_dft_r2c(forward.get(), column, spectrum);
        for(int s = 0; s <= P / 2; ++s) {
          const double re = spectrum[s][0], im = spectrum[s][1];
          sum[s][0] += re * re - im * im;
          sum[s][1] += 2. * re * im;
        }
      }
  }

  // The m samples of f from x along the unit vector nz, at steps of one offset bin; false if all are zero.
  bool sample_column(const double* x, const double* nz, double* column) const
  {
    bool empty = true;
    for(int s = 0; s < m_; ++s) {
      const double g = f_.trilinear_value(x[0] + s * step_ * nz[0], x[1] + s * step_ * nz[1], x[2] + s * step_ * nz[2]);
      column[s] = g;
      empty = empty && g == 0.;
    }
    return !empty;
  }

  const Voxel_grid<GT> f_;   // sharpened
  const Plane_bins& bins_;
  std::size_t n_;
  double h_, step_, support_;
  int m_;                    // samples per column
  int fft_size_;             // at least 2 m - 1: the convolution does not wrap around
  long columns_per_axis_;
  double scale_;
};

template <typename GT>
void exact_reflective_symmetry(const Voxel_grid<GT>& f_samples, const Plane_bins& bins, unsigned threads,
                               std::vector<double>& values)
{
  Exact_reflective_symmetry<GT>(f_samples, bins).run(threads, values);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_EXACT_H
