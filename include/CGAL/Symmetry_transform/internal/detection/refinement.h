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
#include <CGAL/Symmetry_transform/internal/detection/mirror_families.h>
#include <CGAL/Symmetry_transform/internal/detection/plane_group.h>
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
// A candidate that leaves its bin is kept if its refined plane maps this much of the shape onto
// itself: an exact symmetry (0.99 to 1 on meshes), not a creeping approximate one.
constexpr double exact_unstable_support = 0.99;
// Most candidates are dropped as duplicates or unstable; beyond this many per plane asked for,
// the weaker ones would be cut off anyway.
constexpr std::size_t candidates_per_plane = 10;
// Exact planes are maxima of the transform nearly as high as the strongest (0.95 to 1.03 of it
// on prisms and Platonic solids, against 0.7 at most for their partial symmetries).
constexpr double exact_candidate_fraction = 0.8;

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
  // An exact symmetry whose maximum of the transform lies beyond the reach of its bin (the
  // transform of a flat shape is blurred along its plane): refined to its end and kept.
  if(verdict != nullptr && !seen && settled && refined.support >= exact_unstable_support) {
    auto near_accepted = [&](const Dplane& plane) { return accepted.near(plane, merge_reach_in_bins); };
    const Isp_result free =
      iterative_symmetric_points(samples, refined.plane, matcher, settings, Isp_phase::FINE, near_accepted, walk_matcher);
    if(!near_accepted(free.plane) && free.support >= exact_unstable_support) refined = free, verdict = nullptr;
  }
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

// The image `image` of a plane by the reflection in another, refined from there (no coarse
// phase: the images of exact planes are exact). None if the refinement heads for an accepted
// plane or away from the image, or maps less of the shape than `least_support`.
template <typename Matcher, typename Walk_matcher>
std::optional<Isp_result> refined_image(const Dplane& image, double least_support, const std::vector<Eigen::Vector3d>& samples,
                                        const Matcher& matcher, const Isp_settings& settings,
                                        const Walk_matcher* walk_matcher, const Accepted_planes& accepted)
{
  auto away = [&](const Dplane& plane) {
    return accepted.near(plane, merge_reach_in_bins) ||
           !same_plane(image, plane, unstable_reach_in_bins * accepted.angle, unstable_reach_in_bins * accepted.distance,
                       accepted.center);
  };
  const Isp_result refined =
    iterative_symmetric_points(samples, image, matcher, settings, Isp_phase::FINE, away, walk_matcher);
  if(away(refined.plane) || !(refined.support >= least_support - group_support_tolerance)) return std::nullopt;
  return refined;
}

// The group the exact planes accepted so far generate (plane_group.h): which planes generate,
// how many of them have met all those before them, the images refined already, and how many
// planes the group added.
struct Plane_group_state
{
  std::vector<std::size_t> generators; // indices in the result
  std::size_t paired;
  Accepted_planes tried;
  std::size_t added;
  // Two exact planes met at an angle no pi m / n, and a plane turned between them about their line
  // is a mirror too: every plane through the line is one (mirror_families.h). Images are then no
  // longer generated: the family holds them all.
  std::vector<Plane_pencil> pencils;

  bool infinite() const { return !pencils.empty(); }

  // Whether `plane` belongs to the family of mirrors found (through the pencil's line, or through
  // the sphere's centre), to within `reach`.
  bool in_family(const Dplane& plane, const Accepted_planes& reach) const
  {
    return in_mirror_family(pencils, plane, merge_reach_in_bins * reach.angle, merge_reach_in_bins * reach.distance);
  }

  // Whether the common line of exact planes `a` and `b` may make a new pencil: not if one holds both.
  bool new_pencil(const Dplane& a, const Dplane& b, const Accepted_planes& reach) const
  {
    return pencils.size() < 2 && !(infinite() && in_family(a, reach) && in_family(b, reach));
  }
};

// Whether every plane through the common line of exact planes `a` and `b` (at an angle no
// pi m / n) is a mirror: whether their member turned by pencil_test_angle from `a`, refined,
// stays there and maps the shape onto itself as well (refined_image()).
template <typename Matcher, typename Walk_matcher>
bool holds_a_pencil(const Dplane& a, const Dplane& b, double least_support, const std::vector<Eigen::Vector3d>& samples,
                    const Matcher& matcher, const Isp_settings& settings, const Walk_matcher* walk_matcher,
                    const Accepted_planes& accepted)
{
  const Dplane member = turned_about(common_line(a, b, accepted.center), a, pencil_test_angle);
  return refined_image(member, least_support, samples, matcher, settings, walk_matcher, accepted).has_value();
}

// The planes of the group that the exact planes of `result` generate, appended to it: each image
// of one by the reflection in another that is not there yet, refined and tested. Accepted exact
// images generate in turn; the group adds at most largest_plane_group() planes. False if cancelled.
template <typename GT, typename Matcher, typename Walk_matcher>
bool complete_plane_group(const Voxel_grid<GT>& gedt, const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher,
                          const Isp_settings& settings, int max_order, const Walk_matcher* walk_matcher,
                          Accepted_planes& accepted, Plane_group_state& group, std::vector<Principal_symmetry<GT>>& result)
{
  if(!result.empty() && result.back().support >= group_generator_support) group.generators.push_back(result.size() - 1);
  for(; group.paired < group.generators.size(); ++group.paired) // new generators join the loop
    for(std::size_t h = 0; h < group.paired; ++h) {
      const Principal_symmetry<GT> g_plane = result[group.generators[group.paired]], h_plane = result[group.generators[h]];
      const Dplane a = to_dplane(g_plane.plane), b = to_dplane(h_plane.plane);
      if(generated_order(a, b, max_order) == 0) {
        // Parallel planes (of a bounded shape, never both exact) generate nothing; others, if a
        // third plane through their line holds, a continuous family (a sphere's, a surface of
        // revolution's), which no list holds.
        if(parallel_planes(a, b) || !group.new_pencil(a, b, accepted)) continue;
        const std::optional<bool> pencil = unless_cancelled([&] {
          return holds_a_pencil(a, b, (std::min)(g_plane.support, h_plane.support), samples, matcher, settings,
                                walk_matcher, accepted);
        });
        if(!pencil) return false;
        if(*pencil) group.pencils.push_back(common_line(a, b, accepted.center));
        continue;
      }
      if(group.infinite()) continue;
      for(const Dplane& image : {reflected(a, b), reflected(b, a)}) {
        if(group.added >= largest_plane_group(max_order) || accepted.near(image, merge_reach_in_bins) ||
           group.tried.near(image, merge_reach_in_bins))
          continue;
        group.tried.planes.push_back(image);
        const std::optional<std::optional<Isp_result>> refined = unless_cancelled([&] {
          return refined_image(image, (std::min)(g_plane.support, h_plane.support), samples, matcher, settings, walk_matcher,
                               accepted);
        });
        if(!refined) return false;
        if(!*refined) continue;
        accepted.planes.push_back((*refined)->plane);
        const typename GT::Plane_3 plane = to_plane<GT>((*refined)->plane);
        result.push_back({plane, plane_symmetry_measure(gedt, plane, settings.threads), (*refined)->support});
        ++group.added;
        if((*refined)->support >= group_generator_support) group.generators.push_back(result.size() - 1);
      }
    }
  return true;
}

// Whether to refine the candidate at `bin` once `result` holds max_planes planes: only if exact
// planes were found (the shape has a group, whose other planes may come later among the
// candidates) and the candidate is nearly as strong as the strongest, as exact planes are.
template <typename GT>
bool worth_refining_beyond_cap(const Reflective_symmetry_transform<GT>& prst, const std::array<std::size_t, 3>& bin,
                               const std::array<std::size_t, 3>& strongest, const Plane_group_state& group)
{
  return !group.generators.empty() && !group.infinite() && prst.value(bin) >= exact_candidate_fraction * prst.value(strongest);
}

// The planes to return, strongest first: every exact one unless the user chose the cap or the
// exact planes form a continuous family (a finite group is not cut), then the strongest others
// up to max_planes in all.
template <typename GT>
void keep_groups_and_strongest(std::vector<Principal_symmetry<GT>>& result, const Candidate_settings& options,
                               bool infinite_group)
{
  std::stable_sort(result.begin(), result.end(),
                   [](const Principal_symmetry<GT>& a, const Principal_symmetry<GT>& b) { return a.symmetry > b.symmetry; });
  const std::size_t max_planes = options.max_planes;
  auto exact = [&](const Principal_symmetry<GT>& s) {
    return !options.max_planes_given && !infinite_group && s.support >= group_generator_support;
  };
  std::size_t others = max_planes - (std::min)(max_planes, std::size_t(std::count_if(result.begin(), result.end(), exact)));
  std::vector<Principal_symmetry<GT>> kept;
  for(const Principal_symmetry<GT>& s : result)
    if(exact(s) || others > 0) {
      if(!exact(s)) --others;
      kept.push_back(s);
    }
  result = std::move(kept);
}

// Candidates of the PRST refined by ISP (walking with `walk_matcher` if given), strongest first.
// The group that exact planes generate joins as they are accepted; beyond options.max_planes,
// only strong candidates are refined and only exact planes accepted, so that no group is cut.
template <typename GT, typename Matcher, typename Walk_matcher = Matcher>
std::vector<Principal_symmetry<GT>> refine_candidates(const Voxel_grid<GT>& gedt, const Reflective_symmetry_transform<GT>& prst,
                                                      const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher,
                                                      const Isp_settings& settings, const Candidate_settings& options,
                                                      const Walk_matcher* walk_matcher = nullptr)
{
  Accepted_planes accepted{{}, prst.bins().theta_step(), prst.bins().offset_step(), center_of(prst.bins())};
  Plane_group_state group{{}, 0, {{}, accepted.angle, accepted.distance, accepted.center}, 0, {}};
  std::vector<Principal_symmetry<GT>> result;
  std::vector<std::array<std::size_t, 3>> candidates =
    symmetry_candidates(prst, options.symmetry_threshold, options.laplacian_threshold);
  if(candidates.size() > candidates_per_plane * options.max_planes)
    candidates.resize(candidates_per_plane * options.max_planes);
  for(const auto& bin : candidates) {
    const bool beyond_cap = result.size() >= options.max_planes;
    if(beyond_cap && (options.max_planes_given || !worth_refining_beyond_cap(prst, bin, candidates.front(), group))) continue;
    if(group.in_family(to_dplane(prst.plane(bin)), accepted)) continue; // a member of the family found
    const auto start = std::chrono::steady_clock::now();
    const std::optional<Candidate_outcome> refined = unless_cancelled([&] {
      report_progress(std::size_t(&bin - candidates.data()), candidates.size());
      return refine_candidate(prst, bin, samples, matcher, settings, walk_matcher, accepted);
    });
    if(!refined) break; // cancelled: the planes accepted so far (progress.h)
    const Candidate_outcome& outcome = *refined;
    if(options.verbose)
      print_candidate(prst, bin, outcome, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if(outcome.verdict != nullptr || (beyond_cap && outcome.refined.support < group_generator_support)) continue;
    accepted.planes.push_back(outcome.coarse.plane);
    accepted.planes.push_back(outcome.refined.plane);
    if(group.in_family(outcome.refined.plane, accepted)) continue;
    const typename GT::Plane_3 plane = to_plane<GT>(outcome.refined.plane);
    result.push_back({plane, plane_symmetry_measure(gedt, plane, settings.threads), outcome.refined.support});
    if(!complete_plane_group(gedt, samples, matcher, settings, options.max_order, walk_matcher, accepted, group, result))
      break;
  }
  report_mirror_families(result, group.pencils, merge_reach_in_bins * accepted.angle, merge_reach_in_bins * accepted.distance);
  keep_groups_and_strongest(result, options, group.infinite());
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
