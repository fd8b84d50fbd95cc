// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DISTANCES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_MATCHING_DISTANCES_H

// The arithmetic of the descriptor distances (thesis, section 4.2), on their float arrays.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The PRST bins are compared as D^p, D = sqrt((1 - SM)/2) the plane's normalised symmetry
// distance (thesis, section 3.2.1): steep near D = 0, so that a plane perfect for one shape and
// merely good for the other weighs more than two middling values apart. p from the PSB
// *training* set (RESULTS.md, "Retrieval"): among 1/16, 1/8, 1/4, 1/2, 3/4, 1, 3/2 and 2 (SM =
// 1 - 2 D^2: p = 2 is the plain difference of the SM, the comparison before), 1/16 and 1/8
// retrieve best and 1/4 0.2 point less (NN + DCG); below 1/4 a copy of a box with vertex noise
// of 0.5 % of its radius is farther from it than an ellipsoid (test_symmetry_descriptor), so 1/4.
constexpr double compared_symmetry_distance_power = 1. / 4.;

// D^p of every symmetry measure SM in `measures` (a Monte Carlo estimate above 1 counts as 1);
// other powers than the library's for retrieval_benchmark's comparisons.
inline std::vector<float> compared_symmetry_values(const std::vector<float>& measures,
                                                   double power = compared_symmetry_distance_power)
{
  std::vector<float> result(measures.size());
  std::transform(measures.begin(), measures.end(), result.begin(), [power](float sm) {
    return float(std::pow(std::max(0., (1. - double(sm)) / 2.), power / 2.));
  });
  return result;
}

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
