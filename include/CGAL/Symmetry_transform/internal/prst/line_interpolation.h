// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_LINE_INTERPOLATION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_LINE_INTERPOLATION_H

// Trilinear interpolation of a voxel grid at points evenly spaced along a line: the inner loop
// of the stratified-lines PRST estimator, which evaluates f at the reflections of a point
// through every offset of a direction (about 2·10^7 evaluations at 64^3).

#include <CGAL/Symmetry_transform/Voxel_grid.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The grid is copied in single precision with a border of zero samples, so that a cell's eight
// samples are read without bounds checks from half the memory: the copy of a 64^3 grid fits
// in a core's L2 cache, which the reflections, scattered over the grid, hit at random. Single
// precision changes the transform by about 1e-7 of its values, five orders below the Monte Carlo
// error. A coarse map of blocks of 4^3 cells that hold a non-zero sample lets the points in
// empty space, most of a line through a surface's thin band, return at once.
template <typename GT>
class Line_interpolation
{
public:
  explicit Line_interpolation(const Voxel_grid<GT>& f)
    : n_(long(f.resolution())), side_(std::size_t(n_) + 2), h_(f.voxel_size()), origin_(f.origin()),
      samples_(side_ * side_ * side_, 0.f), blocks_((side_ + block - 1) / block),
      occupied_(blocks_ * blocks_ * blocks_, 0)
  {
    const std::size_t n = f.resolution();
    for(std::size_t k = 0; k < n; ++k)
      for(std::size_t j = 0; j < n; ++j)
        for(std::size_t i = 0; i < n; ++i) {
          if(f(i, j, k) == 0.) continue;
          samples_[padded_index(i + 1, j + 1, k + 1)] = float(f(i, j, k));
          // Padded sample (i+1, j+1, k+1) belongs to the cells whose lower corner is i or i+1.
          for(std::size_t dk = 0; dk < 2; ++dk)
            for(std::size_t dj = 0; dj < 2; ++dj)
              for(std::size_t di = 0; di < 2; ++di) occupied_[block_index(i + di, j + dj, k + dk)] = 1;
        }
  }

  // Adds to out[m], m < count, the value of f at the point start + m·step (world coordinates).
  void add_along_line(const std::array<double, 3>& start, const std::array<double, 3>& step, long count,
                      double* out) const
  {
    double u0[3], du[3]; // in voxel units, sample i at u = i
    for(int a = 0; a < 3; ++a) {
      u0[a] = (start[a] - origin_[a]) / h_ - 0.5;
      du[a] = step[a] / h_;
    }
    for(long m = 0; m < count; ++m)
      out[m] += value(u0[0] + double(m) * du[0], u0[1] + double(m) * du[1], u0[2] + double(m) * du[2]);
  }

private:
  static constexpr std::size_t block = 4;

  // f at voxel coordinates (u, v, w); zero outside the grid and its one-voxel border of zeros.
  double value(double u, double v, double w) const
  {
    if(!(u > -1. && v > -1. && w > -1. && u < double(n_) && v < double(n_) && w < double(n_))) return 0.;
    const long i = long(u + 1.), j = long(v + 1.), k = long(w + 1.); // padded cell: floor + 1
    if(!occupied_[block_index(std::size_t(i), std::size_t(j), std::size_t(k))]) return 0.;
    const double a = u + 1. - double(i), b = v + 1. - double(j), c = w + 1. - double(k);
    const float* s = samples_.data() + padded_index(std::size_t(i), std::size_t(j), std::size_t(k));
    const std::size_t sj = side_, sk = side_ * side_;
    const double x00 = s[0] + a * (s[1] - s[0]), x10 = s[sj] + a * (s[sj + 1] - s[sj]);
    const double x01 = s[sk] + a * (s[sk + 1] - s[sk]), x11 = s[sk + sj] + a * (s[sk + sj + 1] - s[sk + sj]);
    const double y0 = x00 + b * (x10 - x00), y1 = x01 + b * (x11 - x01);
    return y0 + c * (y1 - y0);
  }

  std::size_t padded_index(std::size_t i, std::size_t j, std::size_t k) const { return (k * side_ + j) * side_ + i; }
  std::size_t block_index(std::size_t i, std::size_t j, std::size_t k) const
  {
    return ((k / block) * blocks_ + j / block) * blocks_ + i / block;
  }

  long n_;
  std::size_t side_;
  double h_;
  std::array<double, 3> origin_;
  std::vector<float> samples_;
  std::size_t blocks_;
  std::vector<char> occupied_;
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_LINE_INTERPOLATION_H
