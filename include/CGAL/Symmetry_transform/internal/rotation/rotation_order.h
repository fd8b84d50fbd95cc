// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATION_ORDER_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATION_ORDER_H

// The order of a rotational symmetry about a refined axis: the supports of the rotations by
// 2 pi / k, k = 2 ... max_order, and by three angles that are irrational fractions of 2 pi,
// compared with the best of them. Continuous when the three irrational angles hold; else the
// largest k that holds (a k-fold symmetry also holds at the divisors of k).

#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/rotation/axis_refinement.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// 2 pi (sqrt 2 - 1), 2 pi (2 - golden ratio) (the golden angle) and 2 pi (sqrt 3 - 1): 149.1,
// 137.5 and 263.5 degrees. Every k-fold symmetry with k <= 25 misses one of them by more than
// 4 degrees; they hold together only on surfaces of revolution (and on k-fold ones of k >= 60,
// finer than the test can tell at the widths of the refinement).
inline std::array<double, 3> continuity_angles()
{
  const double golden_ratio = (1. + std::sqrt(5.)) / 2.;
  return {2. * CGAL_PI * (std::sqrt(2.) - 1.), 2. * CGAL_PI * (2. - golden_ratio), 2. * CGAL_PI * (std::sqrt(3.) - 1.)};
}

// A rotation holds about a refined axis when its support (at the final width of the refinement,
// at most sigma / 2) is at least this fraction of the best support of the rotations by a quarter
// turn or more. On exact symmetries the others fall far below it (a twisted star off its angles:
// under 0.4); a fifth of the shape cut away lowers the supports of the true rotations unequally,
// by up to 0.08 of the best (measured: half and third turns of a 6-fold star solid, 0.868 and
// 0.873); and a surface of revolution whose features cover less than a tenth of it is reported
// continuous.
constexpr double rotation_hold_ratio = 0.9;

struct Rotation_order
{
  int order = -1; // k >= 2, 0 for continuous, -1 if no rotation holds
  // The support of the rotation by 2 pi j / k at the test width, at [k][j] for 1 <= j <= k / 2
  // with j and k coprime (the others are the same rotations, or their inverses).
  std::vector<std::vector<double>> supports;
  std::array<double, 3> continuity_supports{{0., 0., 0.}};
  double best = 0.;   // the best of the supports of rotations by a quarter turn or more
  int best_order = 2; // the k of the best support at 2 pi / k

  double support(int j, int k) const
  {
    const int g = std::gcd(j, k);
    return supports[std::size_t(k / g)][std::size_t(j / g)];
  }
};

// The supports and the order found, for the verbose output.
inline std::string describe(const Rotation_order& o)
{
  std::ostringstream out;
  out << "supports at 2 pi / k, k = 2 ...:";
  for(std::size_t k = 2; k < o.supports.size(); ++k) out << " " << o.supports[k][1];
  out << "; at the continuity angles: " << o.continuity_supports[0] << " " << o.continuity_supports[1] << " "
      << o.continuity_supports[2] << "; order " << o.order;
  return out.str();
}

// The mean weight at `width` sigma of the samples rotated by `angle` about `axis`.
template <typename Matcher>
double rotation_support(const std::vector<Eigen::Vector3d>& samples, const Daxis& axis, double angle,
                        const Matcher& matcher, const Isp_settings& settings, double width)
{
  std::vector<typename Matcher::Hint> hints(samples.size());
  return axis_fit_sums(samples, axis, {angle}, matcher, settings, width, hints).weight / double(samples.size());
}

// The supports of the rotations by 2 pi j / k (k <= max_order) and by the continuity angles,
// measured at `width` sigma (the final width of the refinement, at most sigma / 2: sharp on
// exact symmetries), and the order they give: a rotation holds if its support is at least
// rotation_hold_ratio of the best support of the rotations by a quarter turn or more (every
// k-fold symmetry has one: 2 pi floor(k / 2) / k; the continuity angles are all such): where a part
// of the shape is missing, small rotations map much of the hole onto itself and keep more
// support than the half turns, without being any truer. Continuous if the three continuity
// angles hold, else the largest k whose rotations 2 pi j / k all hold (a rotation by 2 pi / k
// that holds while one of its powers does not is not a symmetry: the supports are those of parts
// that happen to match).
template <typename Matcher>
Rotation_order rotation_order(const std::vector<Eigen::Vector3d>& samples, const Daxis& axis, int max_order,
                              const Matcher& matcher, const Isp_settings& settings, double width)
{
  // The rotations by 2 pi j / k, then by the continuity angles, their supports measured in parallel.
  std::vector<std::pair<int, int>> fractions;
  std::vector<double> angles;
  for(int k = 2; k <= max_order; ++k)
    for(int j = 1; 2 * j <= k; ++j)
      if(std::gcd(j, k) == 1) {
        fractions.emplace_back(j, k);
        angles.push_back(2. * CGAL_PI * double(j) / double(k));
      }
  const std::array<double, 3> continuity = continuity_angles();
  angles.insert(angles.end(), continuity.begin(), continuity.end());
  std::vector<double> supports(angles.size());
  parallel_for(angles.size(), settings.threads, [&](unsigned, std::size_t begin, std::size_t end) {
    Isp_settings one_thread = settings;
    one_thread.threads = 1;
    for(std::size_t i = begin; i < end && parallel_step(1); ++i)
      supports[i] = rotation_support(samples, axis, angles[i], matcher, one_thread, width);
  });
  Rotation_order result;
  result.supports.assign(std::size_t(max_order) + 1, {});
  for(int k = 2; k <= max_order; ++k) result.supports[std::size_t(k)].assign(std::size_t(k / 2) + 1, 0.);
  for(std::size_t i = 0; i < fractions.size(); ++i) {
    const auto [j, k] = fractions[i];
    result.supports[std::size_t(k)][std::size_t(j)] = supports[i];
    if(4 * j >= k) result.best = (std::max)(result.best, supports[i]);
    if(j == 1 && supports[i] > result.support(1, result.best_order)) result.best_order = k;
  }
  for(std::size_t i = 0; i < continuity.size(); ++i)
    result.best = (std::max)(result.best, result.continuity_supports[i] = supports[fractions.size() + i]);
  if(!(result.best > 0.)) return result;
  const double holds = rotation_hold_ratio * result.best;
  if(std::all_of(result.continuity_supports.begin(), result.continuity_supports.end(), [&](double s) { return s >= holds; })) {
    result.order = 0;
    return result;
  }
  for(int k = max_order; k >= 2 && result.order < 0; --k) {
    bool all = true;
    for(int j = 1; 2 * j <= k && all; ++j) all = result.support(j, k) >= holds;
    if(all) result.order = k;
  }
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATION_ORDER_H
