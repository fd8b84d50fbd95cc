// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_ORTHOGONAL_PLANES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_ORTHOGONAL_PLANES_H

// The thesis's suggestion of section 4.1.4, searched in the whole transform: the three mutually
// orthogonal directions whose strongest planes hold the most symmetry together. The thesis left
// it for its cost over planes (O(n^6) triples); over directions it is cheap, because once each
// direction bin keeps its largest value over the offsets, a triple is scored by three look-ups.
// Every direction bin is tried as the first normal, with orthogonal_search_turns normals
// perpendicular to it and the third their cross product (0.11 to 0.15 s at 64^3;
// RESULTS.md, "Alignment").

#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Second normals tried per first normal, over half a turn: one per degree, finer than the bins
// (1.4 x 5.6 degrees at 64^3).
constexpr int orthogonal_search_turns = 180;

// The largest value of each direction bin (i, j) over its offsets, at i * n + j.
template <typename GT>
std::vector<double> direction_maxima(const Reflective_symmetry_transform<GT>& prst)
{
  const std::size_t n = prst.resolution();
  std::vector<double> maxima(n * n, 0.);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t k = 0; k < n; ++k) maxima[i * n + j] = (std::max)(maxima[i * n + j], prst.value(i, j, k));
  return maxima;
}

// The turn, fractional, in the middle of the run of equal scores around the first largest one,
// and that score. The scores are constant while both normals stay in their bins: the middle of
// the run lies nearer the bins' centres than its ends. Turns wrap around: half a turn brings
// both normals back, up to sign.
inline std::pair<double, double> middle_of_best_run(const std::vector<double>& scores)
{
  const int m = int(scores.size());
  const int first = int(std::max_element(scores.begin(), scores.end()) - scores.begin());
  const double best = scores[std::size_t(first)];
  int before = 0, after = 0;
  while(before + 1 < m && scores[std::size_t((first - before - 1 + m) % m)] == best) ++before;
  while(before + after + 1 < m && scores[std::size_t((first + after + 1) % m)] == best) ++after;
  return {first + 0.5 * (after - before), best};
}

// The three orthonormal directions of largest summed direction maxima; the first is the normal
// of a direction bin's centre.
template <typename GT>
std::array<Eigen::Vector3d, 3> most_symmetric_orthogonal_normals(const Reflective_symmetry_transform<GT>& prst)
{
  typedef typename GT::Plane_3 Plane_3;
  const Plane_bins& bins = prst.bins();
  const std::size_t n = bins.n;
  const std::vector<double> maxima = direction_maxima(prst);
  const Eigen::Vector3d center(bins.center[0], bins.center[1], bins.center[2]);
  const auto value_along = [&](const Eigen::Vector3d& v) {
    const auto b = prst.bin(Plane_3(v.x(), v.y(), v.z(), -v.dot(center)));
    return maxima[b[0] * n + b[1]];
  };
  std::array<Eigen::Vector3d, 3> best;
  double best_score = -1.;
  std::vector<double> scores(orthogonal_search_turns);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j) {
      const std::array<double, 3> u = bins.normal(i, j);
      const Eigen::Vector3d n1 = Eigen::Vector3d(u[0], u[1], u[2]).normalized();
      const Eigen::Vector3d e1 = n1.unitOrthogonal(), e2 = n1.cross(e1);
      const auto second = [&](double turn) {
        const double angle = CGAL_PI * turn / orthogonal_search_turns;
        return Eigen::Vector3d(std::cos(angle) * e1 + std::sin(angle) * e2);
      };
      for(int t = 0; t < orthogonal_search_turns; ++t)
        scores[std::size_t(t)] = maxima[i * n + j] + value_along(second(t)) + value_along(n1.cross(second(t)));
      const std::pair<double, double> turn = middle_of_best_run(scores);
      if(turn.second > best_score) {
        best_score = turn.second;
        best = {n1, second(turn.first), n1.cross(second(turn.first))};
      }
    }
  return best;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_ORTHOGONAL_PLANES_H
