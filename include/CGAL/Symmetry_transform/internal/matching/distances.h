// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DISTANCES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DISTANCES_H

// The arithmetic of the descriptor distances (thesis, section 4.2), on their float arrays.

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL::Symmetry_transform::internal {

// sqrt(sum_i w_i sum_{j,k} (a - b)^2 / sum of the weights), w_i = row_weights[i]: the values
// of one index i are n^2 contiguous floats, summed in 8 float lanes (vectorised by the compiler)
// per index, then in double. (Eigen's sum of an ArrayXf adds its lanes in float, in another
// order: the distances would change in their last bits.)
inline double weighted_rms_difference(const float* a, const float* b, std::size_t n, const double* row_weights)
{
  const std::size_t row = n * n;
  double total = 0., weight_sum = 0.;
  for(std::size_t i = 0; i < n; ++i) {
    float lanes[8] = {0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f};
    const float* x = a + i * row;
    const float* y = b + i * row;
    std::size_t m = 0;
    for(; m + 8 <= row; m += 8)
      for(std::size_t l = 0; l < 8; ++l) {
        const float d = x[m + l] - y[m + l];
        lanes[l] += d * d;
      }
    double sum = 0.;
    for(; m < row; ++m) sum += double(x[m] - y[m]) * double(x[m] - y[m]);
    for(float s : lanes) sum += double(s);
    total += row_weights[i] * sum;
    weight_sum += row_weights[i] * double(row);
  }
  return std::sqrt(total / weight_sum);
}

template <typename Descriptor>
void check_same_resolution(const Descriptor& a, const Descriptor& b, const char* function)
{
  if(a.resolution() != b.resolution())
    throw std::invalid_argument(std::string(function) + ": the descriptors have different resolutions (" +
                                std::to_string(a.resolution()) + " and " + std::to_string(b.resolution()) + ")");
  if(a.resolution() == 0) throw std::invalid_argument(std::string(function) + ": empty descriptor");
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DISTANCES_H
