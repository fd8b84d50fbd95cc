// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_REFINEMENT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_REFINEMENT_H

// The candidates of a PRST refined by Iterative Symmetric Points, in decreasing order of the
// transform: kept if they stay near their bin, merged when they meet an accepted plane,
// measured on the GEDT, strongest first (thesis, section 3.3; the manual, Principal Symmetries).

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/detection/candidates.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/detection/settings.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iostream>
#include <optional>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The thesis drops a candidate that leaves its bin: an unstable maximum. Monte Carlo noise and
// the smoothing move maxima along flat ridges by a few bins, hence a reach of 3 bins.
constexpr double unstable_reach_in_bins = 3.;
// The coarse phase of ISP stops within about a bin of the optimum: a plane closer than two bins
// to an accepted one would only find that plane again.
constexpr double merge_reach_in_bins = 2.;
// Most candidates are dropped as duplicates or unstable; beyond this many per plane asked for,
// the weaker ones would be cut off anyway.
constexpr std::size_t candidates_per_plane = 10;

// The planes accepted so far (the coarse and the refined plane of each candidate accepted).
struct Accepted_planes
{
  std::vector<Dplane> planes;
  double angle, distance;  // one bin: its extent in theta, and in offset
  Eigen::Vector3d center;  // of the shape, from which offsets are compared

  bool near(const Dplane& plane, double bins) const
  {
    return std::any_of(planes.begin(), planes.end(), [&](const Dplane& p) {
      return same_plane(p, plane, bins * angle, bins * distance, center);
    });
  }
};

struct Candidate_outcome
{
  Isp_result coarse, refined;
  unsigned fine_iterations; // 0 if the fine phase did not run
  const char* verdict;      // why the candidate is dropped; nullptr if it is accepted
};

// ISP from the centre of bin `bin`, stopped as soon as the plane heads for an accepted one or
// out of reach of its bin. Candidates on one ridge of the transform converge to the same plane:
// the cheap coarse phase tells them apart, and only the first of each gets the fine phase. A
// start that the coarse phase cannot settle is on a slope or a ridge, not near a maximum; with
// no normals (a point set), the point-to-point fit creeps and needs the fine phase.
template <typename GT, typename Matcher, typename Walk_matcher>
Candidate_outcome refine_candidate(const Reflective_symmetry_transform<GT>& prst, const std::array<std::size_t, 3>& bin,
                                   const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher,
                                   const Isp_settings& settings, const Walk_matcher* walk_matcher,
                                   const Accepted_planes& accepted)
{
  auto abandon = [&](const Dplane& plane) {
    return accepted.near(plane, merge_reach_in_bins) || !stays_near_bin(prst, plane, bin, unstable_reach_in_bins);
  };
  const Isp_result coarse = iterative_symmetric_points(samples, to_dplane(prst.plane(bin)), matcher, settings,
                                                       Isp_phase::COARSE, abandon, walk_matcher);
  const bool seen = accepted.near(coarse.plane, merge_reach_in_bins),
             settled = coarse.converged || !Matcher::has_normals;
  Isp_result refined = coarse;
  if(!seen && settled)
    refined = iterative_symmetric_points(samples, coarse.plane, matcher, settings, Isp_phase::FINE, abandon, walk_matcher);
  const char* verdict = seen || accepted.near(refined.plane, merge_reach_in_bins)              ? "same as an accepted plane"
                        : !stays_near_bin(prst, refined.plane, bin, unstable_reach_in_bins) ? "left its bin"
                        : !settled || !(refined.support > 0.)                               ? "no convergence"
                                                                                            : nullptr;
  return {coarse, refined, seen || !settled ? 0u : refined.iterations, verdict};
}

template <typename GT>
void print_candidate(const Reflective_symmetry_transform<GT>& prst, const std::array<std::size_t, 3>& bin,
                     const Candidate_outcome& outcome, double seconds)
{
  std::cerr << "  candidate (" << bin[0] << "," << bin[1] << "," << bin[2] << ") SM " << prst.value(bin) << ": ISP "
            << seconds << " s (" << outcome.coarse.iterations << " + " << outcome.fine_iterations
            << " iterations), support " << outcome.refined.support
            << (outcome.verdict ? ", dropped: " : ", accepted") << (outcome.verdict ? outcome.verdict : "") << "\n";
}

// Candidates of the PRST refined by ISP (walking with `walk_matcher` if given), strongest first.
template <typename GT, typename Matcher, typename Walk_matcher = Matcher>
std::vector<Principal_symmetry<GT>> refine_candidates(const Voxel_grid<GT>& gedt, const Reflective_symmetry_transform<GT>& prst,
                                                      const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher,
                                                      const Isp_settings& settings, const Candidate_settings& options,
                                                      const Walk_matcher* walk_matcher = nullptr)
{
  Accepted_planes accepted{{}, prst.bins().theta_step(), prst.bins().offset_step(), center_of(prst.bins())};
  std::vector<Principal_symmetry<GT>> result;
  std::vector<std::array<std::size_t, 3>> candidates =
    symmetry_candidates(prst, options.symmetry_threshold, options.laplacian_threshold);
  if(candidates.size() > candidates_per_plane * options.max_planes)
    candidates.resize(candidates_per_plane * options.max_planes);
  for(const auto& bin : candidates) {
    if(result.size() == options.max_planes) break;
    const auto start = std::chrono::steady_clock::now();
    const std::optional<Candidate_outcome> refined = unless_cancelled([&] {
      report_progress(std::size_t(&bin - candidates.data()), candidates.size());
      return refine_candidate(prst, bin, samples, matcher, settings, walk_matcher, accepted);
    });
    if(!refined) break; // cancelled: the planes accepted so far (progress.h)
    const Candidate_outcome& outcome = *refined;
    if(options.verbose)
      print_candidate(prst, bin, outcome, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if(outcome.verdict != nullptr) continue;
    accepted.planes.push_back(outcome.coarse.plane);
    accepted.planes.push_back(outcome.refined.plane);
    const typename GT::Plane_3 plane = to_plane<GT>(outcome.refined.plane);
    result.push_back({plane, symmetry_measure(gedt, plane), outcome.refined.support});
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const Principal_symmetry<GT>& a, const Principal_symmetry<GT>& b) { return a.symmetry > b.symmetry; });
  if(result.size() > options.max_planes) result.resize(options.max_planes);
  return result;
}

// The same with the options of the named parameters, the GEDT made with them.
template <typename GT, typename Matcher, typename NamedParameters, typename Walk_matcher = Matcher>
std::vector<Principal_symmetry<GT>> refine_candidates(const Voxel_grid<GT>& gedt, const Reflective_symmetry_transform<GT>& prst,
                                                      const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher,
                                                      const NamedParameters& np, const Walk_matcher* walk_matcher = nullptr)
{
  return refine_candidates(gedt, prst, samples, matcher, isp_settings(np, gedt), candidate_settings(np), walk_matcher);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_REFINEMENT_H
