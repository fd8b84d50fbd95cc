// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATION_DETECTION_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATION_DETECTION_H

// The detection of the rotational symmetries of a shape: candidate axes (candidate_axes.h),
// each placed and aligned on a coarse GEDT (coarse_alignment.h), the best refined on the
// surface (axis_refinement.h), their order found (rotation_order.h), measured, merged.

#include <CGAL/Symmetry_transform/Rotational_symmetry.h>
#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/detection/border_curve.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/detection/mirror_families.h>
#include <CGAL/Symmetry_transform/internal/detection/plane_group.h>
#include <CGAL/Symmetry_transform/internal/rotation/axis_refinement.h>
#include <CGAL/Symmetry_transform/internal/rotation/candidate_axes.h>
#include <CGAL/Symmetry_transform/internal/rotation/coarse_alignment.h>
#include <CGAL/Symmetry_transform/internal/rotation/group_closure.h>
#include <CGAL/Symmetry_transform/internal/rotation/rotation_order.h>
#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Samples of the coarse stage: the axis point search reads 256 of them per trial axis, the
// pattern search 512; the order test reads 2000 per angle (its supports then vary by about 1 %
// from one subset to another, a tenth of the margin of rotation_hold_ratio).
constexpr std::size_t axis_point_samples = 256;
constexpr std::size_t alignment_samples = 512;
constexpr std::size_t order_samples = 2000;
// The density of normals is built from 2000 samples' normals and probed at 256: the correlation
// then varies by about 1 % from one subset to another, far below the gap between the rotations
// that hold and the others.
constexpr std::size_t normal_density_samples = 2000;
constexpr std::size_t normal_density_probes = 256;
// Candidates whose coarse overlap is below this are not aligned: the coarse GEDT of a shape with
// a fifth cut away still overlaps its rotation by about 0.8 about the true axis.
constexpr double min_coarse_overlap = 0.5;
// A rotation is reported if it maps at least this fraction of the surface to within about
// sigma / 2 of the surface (the mean weight exp(-d^2 / 2 (sigma / 2)^2) of the rotated samples):
// a shape with a fifth of it missing keeps about 0.8; the best rotations of shapes with no
// rotational symmetry stay below 0.6 (random convex hulls; the flip of a vase, not symmetric top
// to bottom: 0.59).
constexpr double min_rotation_support = 0.7;
// Aligned candidates whose sharp overlap (at sigma / 2) is below this are not refined: it is
// within about 0.1 of the support at sigma / 2 after the refinement, and those below
// min_rotation_support are not reported.
constexpr double min_sharp_overlap = 0.6;
// At most this many candidates are aligned, in decreasing coarse overlap, and at most this many
// axes refined (a cube has 13): a shape has few axes, each found by several candidates (its
// orders' divisors, the axes of inertia and the search of directions).
constexpr std::size_t max_aligned_candidates = 24;
constexpr std::size_t max_refined_axes = 16;
// The group closure stops at this many axes: the largest finite rotation group has 31 (the
// icosahedron's 6 five-fold, 10 three-fold and 15 two-fold axes).
constexpr std::size_t max_group_axes = 31;
// The shares of the search's stages in the progress it reports (as progress_shares.h for the
// other long functions), from the stages' times (--verbose) on blade.off, pinion.off, bull.off
// and the icosahedron: the candidates, placed and aligned (0.1 s), until
// rotation_candidates_share; the refinements (0.03 to 0.07 s each), one equal part each, until
// rotation_refinements_end; then the closure of the group (about 10 ms per generated axis, none
// to 30 of them), by generated axes of its first round. The grids and samples before the search:
// rotation_grids_share of a mesh's rotation stage (the coarse GEDT), rotation_grids_share_of_points
// of a point set's (both GEDTs and the normals).
constexpr double rotation_candidates_share = 0.35, rotation_refinements_end = 0.8;
constexpr double rotation_grids_share = 0.1, rotation_grids_share_of_points = 0.4;
// Before all this, the mesh's surface (GEDT and trees) takes 20 to 60 % of a detection of
// rotations (the icosahedron, bull.off, pinion.off), far more than of a detection of planes:
// its share is that of a detection of planes, at least min_rotation_surface_share.
constexpr double min_rotation_surface_share = 0.4;
inline double rotation_surface_share(std::size_t faces)
{
  return (std::max)(min_rotation_surface_share, progress_shares::detection_surface_share(faces));
}

// Two axes are the same when their directions are within 2 degrees and each passes within 2 % of
// the radius of the other's point nearest to the centre: refined axes of one symmetry agree to
// far less, coarse ones to about a degree.
constexpr double same_axis_degrees = 2.;
constexpr double same_axis_distance = 0.02;

inline bool same_axis(const Daxis& a, const Daxis& b, const Eigen::Vector3d& center, double radius)
{
  return same_axis(a, b, center, same_axis_degrees * CGAL_PI / 180., same_axis_distance * radius);
}

// Whether two axes meet at a right angle, within `factor` times the tolerances of same_axis().
inline bool meets_at_right_angle(const Daxis& a, const Daxis& b, double radius, double factor)
{
  return std::abs(a.direction.dot(b.direction)) < std::sin(factor * same_axis_degrees * CGAL_PI / 180.) &&
         line_distance(a, b) < factor * same_axis_distance * radius;
}
// Candidates from the coarse stage are within about a degree and 1 % of the radius of their
// refined axis: compared with refined axes, they get 2.5 times the tolerances.
constexpr double coarse_tolerance = 2.5;

// Two distinct parallel axes cannot both be rotational symmetries of a bounded shape (the
// rotations by opposite angles about them compose into a translation): of two axes within
// 2 degrees of parallel, only the better supported one is kept.
inline bool parallel_axes(const Daxis& a, const Daxis& b) { return angle_between(a, b) < same_axis_degrees * CGAL_PI / 180.; }

// About `count` samples spread over the shape: the samples are in ISP's order (every eighth
// first, then the rest, each along a Hilbert curve), so a regular stride covers the shape.
inline std::vector<Eigen::Vector3d> spread_subset(const std::vector<Eigen::Vector3d>& samples, std::size_t count)
{
  if(samples.size() <= count) return samples;
  std::vector<Eigen::Vector3d> subset;
  const double stride = double(samples.size()) / double(count);
  for(std::size_t i = 0; i < count; ++i) subset.push_back(samples[std::size_t(double(i) * stride)]);
  return subset;
}

// What the search of a shape's rotation axes reads.
template <typename GT, typename Matcher, typename Walk_matcher>
struct Rotation_search
{
  const Voxel_grid<GT>& gedt;           // the GEDT: its width is that of the refinement
  const Voxel_grid<GT>& coarse_gedt;    // the coarse stage's
  double coarse_sigma;                  // the coarse GEDT's Gaussian width
  const std::vector<Eigen::Vector3d>& samples; // in ISP's order
  const std::vector<Eigen::Vector3d>& normals; // of the samples
  const Mass_distribution& mass;
  const Matcher& matcher;               // exact closest points
  const Walk_matcher& walk_matcher;     // approximate ones, for the walk
  Isp_settings settings;
  int max_order;
  bool verbose;
  const Border_curve* border = nullptr; // of a flat surface: the order is tested there
};


// A candidate aligned by pattern searches, on the coarse GEDT then on the sharp overlap of the
// GEDT (its width sigma / 2).
struct Aligned_axis
{
  Daxis axis;
  double coarse = 0.; // overlap on the coarse GEDT
  double sharp = 0.;  // at sigma / 2
  bool done = false;
};

// The candidates coarse_axes() is likely to align, in order: those above min_coarse_overlap,
// each not next to an earlier one of them, up to max_aligned_candidates. A prediction only:
// coarse_axes() aligns any other candidate it reaches when it reaches it; a wrong guess costs
// time, not results.
inline std::vector<std::size_t> likely_aligned(const std::vector<Axis_candidate>& candidates,
                                               const Eigen::Vector3d& center, double radius)
{
  std::vector<std::size_t> result;
  for(std::size_t i = 0; i < candidates.size() && result.size() < max_aligned_candidates; ++i) {
    if(candidates[i].score < min_coarse_overlap) break;
    if(std::none_of(result.begin(), result.end(),
                    [&](std::size_t j) { return same_axis(candidates[i].axis, candidates[j].axis, center, radius); }))
      result.push_back(i);
  }
  return result;
}

// The candidates placed (their best axis point on the coarse GEDT), strongest first; those above
// min_coarse_overlap aligned (Aligned_axis), and kept if the sharp overlap reaches
// min_sharp_overlap: the axes to refine, duplicates left out, in decreasing sharp overlap. The
// placements, and the alignments of the candidates likely to be aligned, run in parallel.
template <typename GT, typename M, typename W>
std::vector<Axis_candidate> coarse_axes(const Rotation_search<GT, M, W>& s, std::vector<Axis_candidate> candidates)
{
  const Eigen::Vector3d center = s.mass.center();
  const double radius = s.mass.radius();
  const Gedt_overlap<GT> placing(s.coarse_gedt, spread_subset(s.samples, axis_point_samples), s.coarse_sigma, center, radius);
  const Gedt_overlap<GT> aligning(s.coarse_gedt, spread_subset(s.samples, alignment_samples), s.coarse_sigma, center, radius);
  const Gedt_overlap<GT> sharp(s.gedt, spread_subset(s.samples, alignment_samples), s.settings.sigma, center, radius, 4);
  parallel_for(candidates.size(), s.settings.threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end && parallel_step(1); ++i) {
      Axis_candidate& c = candidates[i];
      c.axis = best_axis_point(placing, c.axis.point, radius, c.axis.direction, refinement_angles(c.order), c.score);
    }
  });
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Axis_candidate& a, const Axis_candidate& b) { return a.score > b.score; });
  std::vector<Aligned_axis> aligned(candidates.size());
  auto align = [&](std::size_t i) {
    Aligned_axis& a = aligned[i];
    const std::vector<double> angles = refinement_angles(candidates[i].order);
    a.axis = pattern_search(aligning, candidates[i].axis, angles, coarse_pattern_angle_step, a.coarse);
    a.axis = pattern_search(sharp, a.axis, angles, sharp_pattern_angle_step, a.sharp);
    a.done = true;
  };
  const std::vector<std::size_t> likely = likely_aligned(candidates, center, radius);
  parallel_for(likely.size(), s.settings.threads, [&](unsigned, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end && parallel_step(1); ++i) align(likely[i]);
  });
  std::vector<Axis_candidate> result;
  std::vector<Daxis> tried; // the placed axes aligned so far: a candidate next to one is not aligned again
  auto seen = [&](const Daxis& axis) {
    return std::any_of(result.begin(), result.end(), [&](const Axis_candidate& r) { return same_axis(axis, r.axis, center, radius); });
  };
  for(std::size_t i = 0; i < candidates.size(); ++i) {
    Axis_candidate c = candidates[i];
    if(c.score < min_coarse_overlap || result.size() == max_refined_axes || tried.size() == max_aligned_candidates) break;
    if(seen(c.axis) || std::any_of(tried.begin(), tried.end(), [&](const Daxis& t) { return same_axis(c.axis, t, center, radius); }))
      continue;
    tried.push_back(c.axis);
    if(!aligned[i].done) align(i);
    c.axis = aligned[i].axis;
    c.score = aligned[i].sharp;
    const bool kept = c.score >= min_sharp_overlap && !seen(c.axis);
    if(s.verbose)
      std::cerr << "  candidate axis (" << c.axis.direction.transpose() << ") order " << c.order << ": overlap "
                << aligned[i].coarse << ", sharp " << c.score << (kept ? "" : c.score < min_sharp_overlap ? ", dropped" : ", seen") << "\n";
    if(kept) result.push_back(c);
  }
  std::stable_sort(result.begin(), result.end(), [](const Axis_candidate& a, const Axis_candidate& b) { return a.score > b.score; });
  return result;
}

// A found axis, with its symmetry in the user's kernel.
template <typename GT>
struct Found_rotation
{
  Daxis axis;
  Rotational_symmetry<GT> symmetry;
  double sharp_support; // at sigma / 2
};

// The supports (all samples) at sigma and sigma / 2 and the symmetry measure on the GEDT of a
// symmetry of order `order` about `axis`: those of the rotation by 2 pi / order, or the least
// over the continuity angles. The matches are those of the walk (on a mesh, the closest
// triangles recorded with the GEDT: within 1e-3 of exact supports, at a tenth of the cost).
template <typename GT, typename M, typename W>
Found_rotation<GT> measured(const Rotation_search<GT, M, W>& s, const Daxis& axis, int order)
{
  std::vector<double> angles{2. * CGAL_PI / double((std::max)(order, 1))};
  if(order == 0) {
    const std::array<double, 3> continuity = continuity_angles();
    angles.assign(continuity.begin(), continuity.end());
  }
  double support = 1., sharp_support = 1., symmetry = 1.;
  for(double angle : angles) {
    std::vector<typename W::Hint> hints(s.samples.size());
    const Axis_fit_sums sums = axis_fit_sums(s.samples, axis, {angle}, s.walk_matcher, s.settings, 0.5, hints);
    support = (std::min)(support, sums.support / double(s.samples.size()));
    sharp_support = (std::min)(sharp_support, sums.weight / double(s.samples.size()));
    const Rigid_motion rotation = axis.rotation(angle);
    symmetry = (std::min)(symmetry, symmetry_measure_of_reflection(s.gedt, [&](double* x) { rotation.move(x); }));
  }
  const Daxis canonical = axis.canonical(s.mass.center());
  return {canonical, {to_line<GT>(canonical), order, typename GT::FT(symmetry), typename GT::FT(support)}, sharp_support};
}

// The order of the rotations about `axis`, tested at `width` sigma on `order_probes`, or on the
// border of a flat surface (border_curve.h).
template <typename GT, typename M, typename W>
Rotation_order order_about(const Rotation_search<GT, M, W>& s, const std::vector<Eigen::Vector3d>& order_probes,
                           const Daxis& axis, double width)
{
  if(s.border != nullptr) return rotation_order(s.border->probes, axis, s.max_order, s.border->matcher, s.settings, width);
  return rotation_order(order_probes, axis, s.max_order, s.walk_matcher, s.settings, width);
}

// A found rotation whose support at sigma / 2 is at least 0.99 is exact to the accuracy of the
// samples (exact symmetries: 0.99 to 1; the approximate flips of blade.off, a thin blade not
// quite symmetric: 0.90 to 0.95). What two exact rotations generate needs no refinement: an
// image of an exact axis by an exact rotation is an axis of the same order, taken as it is, and
// the axis of their product is exact, only its order is tested, at the width the refinement
// narrows to on an exact symmetry, sigma / 4.
constexpr double exact_rotation_support = 0.99;
constexpr double exact_rotation_width = 0.25;

// Candidate axes of a flat surface within this (sine of an angle) of its plane, or of its
// normal, are refined as in-plane flips, or as the axis across it: the coarse alignment's reach.
inline double flat_axis_tolerance()
{
  return std::sin(coarse_tolerance * same_axis_degrees * CGAL_PI / 180.);
}

// On a flat surface, a flip about a line of its plane is the reflection in that plane after the
// one in the plane across it through the line. The flip is refined as that mirror, by ISP, which
// ends on the border (border_curve.h): exact where a fit of the axis to the normals is not (the
// normals are all alike); its axis is the line where the mirror meets the surface's plane. None
// for other axes.
template <typename GT, typename M, typename W>
std::optional<Daxis> refined_flip_of_flat_surface(const Rotation_search<GT, M, W>& s, const Axis_candidate& candidate)
{
  if(s.border == nullptr || candidate.order != 2) return std::nullopt;
  const Dplane& flat = s.border->plane;
  if(std::abs(candidate.axis.direction.dot(flat.normal)) > flat_axis_tolerance()) return std::nullopt;
  const Eigen::Vector3d normal = flat.normal.cross(candidate.axis.direction).normalized();
  const Isp_result mirror = iterative_symmetric_points(s.samples, Dplane{normal, normal.dot(candidate.axis.point)}, s.matcher,
                                                       s.settings, Isp_phase::BOTH, {}, &s.walk_matcher);
  if(parallel_planes(mirror.plane, flat)) return std::nullopt;
  const Plane_pencil line = common_line(mirror.plane, flat, s.mass.center());
  return Daxis{line.point, line.direction};
}

// On a flat surface, an axis across its plane: its order tested on the border at sigma / 2, and
// for an order of 2 or more, its centre fitted on the border (border_curve.h); through the
// centre of mass otherwise (a disc's). None for other axes.
template <typename GT, typename M, typename W>
std::optional<Axis_refinement> refined_turn_of_flat_surface(const Rotation_search<GT, M, W>& s,
                                                            const Axis_candidate& candidate, Rotation_order& order)
{
  if(s.border == nullptr) return std::nullopt;
  const Dplane& flat = s.border->plane;
  if(candidate.axis.direction.cross(flat.normal).norm() > flat_axis_tolerance()) return std::nullopt;
  Axis_refinement refined;
  refined.axis = Daxis{s.mass.center(), flat.normal};
  order = order_about(s, {}, refined.axis, 0.5);
  if(order.order >= 2)
    refined.axis.point = turn_center_on_border(*s.border, refined.axis.point, order.order, s.settings.sigma, s.mass.radius());
  refined.width = exact_rotation_width;
  return refined;
}

// A coarse axis refined on the surface, its order found, measured; none if it heads for an axis
// already `found`, if no rotation holds, or if it maps less than min_rotation_support of the
// shape onto the shape. The order is tested on the walk's axis (at sigma / 2, or at the narrower
// width the walk reached), before the exact end of the refinement: if it is not a multiple of the
// candidate's, the walk fitted a rotation that does not hold, and is run again for the best
// supported order without the exact end of the first (on blade.off, two of four candidates).
template <typename GT, typename M, typename W>
std::optional<Found_rotation<GT>> refined_rotation(const Rotation_search<GT, M, W>& s, const Axis_candidate& candidate,
                                                   const std::vector<Eigen::Vector3d>& order_probes,
                                                   const std::vector<Found_rotation<GT>>& found)
{
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Vector3d center = s.mass.center();
  const Axis_abandon heading_for_found = [&](const Daxis& axis) {
    return std::any_of(found.begin(), found.end(), [&](const Found_rotation<GT>& f) { return parallel_axes(axis, f.axis); });
  };
  // The order is tested on the walk's axis, at sigma / 2 or at the narrower width the walk
  // reached; the exact end of the refinement is run only where the order is the one assumed.
  Rotation_order order;
  const Axis_polish_if test_order = [&](const Axis_refinement& r) {
    order = order_about(s, order_probes, r.axis, (std::min)(r.width, 0.5));
    return true;
  };
  auto wrong_order = [&]() { return order.order > 0 && order.order % candidate.order != 0; };
  auto refine = [&](const Daxis& axis, int k, const Axis_polish_if& polish_if) {
    return refine_axis(s.samples, axis, refinement_angles(k), s.matcher, s.walk_matcher, s.settings, center,
                       heading_for_found, polish_if);
  };
  Axis_refinement refined;
  if(const std::optional<Daxis> flip = refined_flip_of_flat_surface(s, candidate)) {
    refined.axis = *flip;
    refined.width = exact_rotation_width;
    refined.abandoned = heading_for_found(*flip);
    test_order(refined);
  } else if(const std::optional<Axis_refinement> turn = refined_turn_of_flat_surface(s, candidate, order)) {
    refined = *turn;
    refined.abandoned = heading_for_found(refined.axis);
  } else {
    refined =
      refine(candidate.axis, candidate.order, [&](const Axis_refinement& r) { return test_order(r) && !wrong_order(); });
    if(!refined.abandoned && wrong_order()) refined = refine(refined.axis, order.best_order, test_order);
  }
  std::optional<Found_rotation<GT>> result;
  if(!refined.abandoned && order.order >= 0) result = measured(s, refined.axis, order.order);
  const bool kept = result && result->sharp_support >= min_rotation_support;
  if(s.verbose) {
    std::cerr << "  refined (" << refined.axis.direction.transpose() << ") through (" << refined.axis.point.transpose()
              << "): " << refined.iterations << " iterations at width " << refined.width;
    if(refined.abandoned) std::cerr << ", heads for an axis found";
    else std::cerr << ", " << describe(order);
    if(result)
      std::cerr << ", support " << result->symmetry.support << " (at sigma / 2: " << result->sharp_support << "), symmetry "
                << result->symmetry.symmetry;
    std::cerr << (kept ? ", kept" : ", dropped") << " ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)\n";
  }
  if(!kept) result.reset();
  return result;
}

// Whether a found rotation says more than another about the same axis: continuous first, then
// the larger order, then the larger support.
template <typename GT>
bool says_more(const Rotational_symmetry<GT>& a, const Rotational_symmetry<GT>& b)
{
  if((a.order == 0) != (b.order == 0)) return a.order == 0;
  if(a.order != b.order) return a.order > b.order;
  return a.support > b.support;
}

// The rotations of a bounded shape fix its centre of mass: their axes meet there (for a part of a
// shape, at the centre of the symmetric part). Whether `axis` passes within `distance` of the
// point where the `axes` meet (the point nearest to all of them in the least-squares sense), or
// meets the only one.
inline bool concurrent(const Daxis& axis, const std::vector<Daxis>& axes, double distance)
{
  if(axes.empty()) return true;
  Eigen::Matrix3d normal_equations = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for(const Daxis& a : axes) {
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - a.direction * a.direction.transpose();
    normal_equations += across;
    right += across * a.point;
  }
  if(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(normal_equations).eigenvalues()[0] < 1e-6)
    return line_distance(axis, axes.front()) < distance; // all parallel: one line, in effect
  return axis.distance(normal_equations.ldlt().solve(right)) < distance;
}

// Strongest first: the larger symmetry measure to three decimals (the measures of exact
// symmetries differ by their interpolation errors, about 1e-4), then the one that says more
// (continuous, then the larger order: the main axis of a gear before its flips), then the
// larger symmetry measure.
template <typename GT>
bool stronger(const Rotational_symmetry<GT>& a, const Rotational_symmetry<GT>& b)
{
  const long ka = std::lround(1000. * CGAL::to_double(a.symmetry)), kb = std::lround(1000. * CGAL::to_double(b.symmetry));
  if(ka != kb) return ka > kb;
  if((a.order == 0) != (b.order == 0)) return a.order == 0;
  if(a.order != b.order) return a.order > b.order;
  return a.symmetry > b.symmetry;
}

// Distinct axes of one order of a rotation group meet at 15 degrees or more (the flips of a
// 12-fold gear); of two that meet within 10 degrees, only the better supported one is a
// symmetry: the others are points of a ridge of approximate ones (a long flat blade has
// approximate flips about every line of its plane near its length).
constexpr double same_order_degrees = 10.;

template <typename GT>
bool close_axes_of_one_order(const Found_rotation<GT>& a, const Found_rotation<GT>& b, double radius)
{
  return a.symmetry.order == b.symmetry.order && angle_between(a.axis, b.axis) < same_order_degrees * CGAL_PI / 180. &&
         line_distance(a.axis, b.axis) < same_axis_distance * radius;
}

// The found rotations with duplicates merged (of two on the same line, the one that says more;
// of two parallel ones, the better supported), and, about each continuous axis, one 2-fold axis
// perpendicular to it and through it: the others are its images by the continuous rotations
// (the flips of a cylinder). Strongest first; an axis that misses the common point of stronger
// ones is left out (the approximate flips about points along a long bar, for one).
template <typename GT>
std::vector<Found_rotation<GT>> consistent(std::vector<Found_rotation<GT>> found, const Eigen::Vector3d& center,
                                           double radius)
{
  auto keep_first = [&](const auto& precedes, const auto& same) {
    std::stable_sort(found.begin(), found.end(), precedes);
    std::vector<Found_rotation<GT>> kept;
    for(const Found_rotation<GT>& f : found)
      if(std::none_of(kept.begin(), kept.end(), [&](const Found_rotation<GT>& k) { return same(f, k, kept); })) kept.push_back(f);
    found = std::move(kept);
  };
  keep_first([](const auto& a, const auto& b) { return says_more(a.symmetry, b.symmetry); },
             [&](const auto& f, const auto& k, const auto&) { return same_axis(f.axis, k.axis, center, radius); });
  // A flip about an axis meeting the continuous axis of c at a right angle.
  auto flip_of = [&](const Found_rotation<GT>& f, const Found_rotation<GT>& c) {
    return c.symmetry.order == 0 && f.symmetry.order == 2 && meets_at_right_angle(f.axis, c.axis, radius, 1.);
  };
  const std::vector<Found_rotation<GT>> all = found;
  keep_first([](const auto& a, const auto& b) { return a.symmetry.support > b.symmetry.support; },
             [&](const auto& f, const auto& k, const auto&) {
               return parallel_axes(f.axis, k.axis) || close_axes_of_one_order(f, k, radius) ||
                      std::any_of(all.begin(), all.end(), [&](const auto& c) { return flip_of(f, c) && flip_of(k, c); });
             });
  // Strongest first, each meeting the stronger ones at their common point; if the strongest passes
  // through the centre of mass (a whole shape), that point is the centre of mass.
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return stronger(a.symmetry, b.symmetry); });
  std::vector<Daxis> kept;
  if(!found.empty() && found.front().axis.distance(center) < same_axis_distance * radius) {
    const Eigen::Vector3d d = found.front().axis.direction.unitOrthogonal();
    kept.push_back({center, d}); // two lines through the centre pin it
    kept.push_back({center, d.cross(found.front().axis.direction)});
  }
  std::vector<Found_rotation<GT>> result;
  for(const Found_rotation<GT>& f : found)
    if(concurrent(f.axis, kept, same_axis_distance * radius)) {
      kept.push_back(f.axis);
      result.push_back(f);
    }
  return result;
}

// Whether `axis` is a continuous axis found, or a flip about one.
template <typename GT>
bool flip_of_continuous(const Daxis& axis, const std::vector<Found_rotation<GT>>& found, double radius)
{
  return std::any_of(found.begin(), found.end(), [&](const Found_rotation<GT>& f) {
    return f.symmetry.order == 0 && (parallel_axes(axis, f.axis) || meets_at_right_angle(axis, f.axis, radius, 1.));
  });
}

// Rotations generate the group only if they are symmetries, not approximations of ones: the
// group closure starts from the axes whose support at sigma / 2 is at least 0.95 (exact ones
// measure above 0.99; with 0.2 % vertex noise, 0.99).
constexpr double min_generator_support = 0.95;

// The generators of the group: the consistent discrete axes found whose support at sigma / 2 is
// at least `min_support`, each scored by that support; flips about continuous axes left out
// (they generate one another without end, and one of them stands for all).
template <typename GT>
std::vector<Axis_candidate> group_generators(const std::vector<Found_rotation<GT>>& found, const Eigen::Vector3d& center,
                                            double radius, double min_support)
{
  std::vector<Axis_candidate> generators;
  for(const Found_rotation<GT>& f : consistent(found, center, radius))
    if(f.symmetry.order >= 2 && f.sharp_support >= min_support && !flip_of_continuous(f.axis, found, radius))
      generators.push_back({f.axis, f.symmetry.order, f.sharp_support});
  return generators;
}

// An axis the group closure generated from found ones: refined and tested as the others if one
// of them is not exact; else measured as it is, with the order of the axis it is an image of,
// or, for the axis of a product, the order tested there (refined as the others if that order is
// not a multiple of the product's, or not continuous where the product's angle is irrational).
// None if it maps less than min_rotation_support of the shape onto the shape.
template <typename GT, typename M, typename W>
std::optional<Found_rotation<GT>> generated_rotation(const Rotation_search<GT, M, W>& s, const Axis_candidate& c,
                                                     bool image, const std::vector<Eigen::Vector3d>& order_probes,
                                                     const std::vector<Found_rotation<GT>>& found)
{
  if(c.order == 0 && c.score < exact_rotation_support) return std::nullopt; // approximate: the angle says nothing
  if(c.score < exact_rotation_support) return refined_rotation(s, c, order_probes, found);
  int order = c.order;
  if(!image) {
    const Rotation_order tested = order_about(s, order_probes, c.axis, exact_rotation_width);
    const bool holds = c.order == 0 ? tested.order == 0 : tested.order == 0 || (tested.order > 0 && tested.order % c.order == 0);
    if(!holds && c.order == 0) return std::nullopt; // no continuous axis: nothing to refine towards
    if(!holds) return refined_rotation(s, c, order_probes, found);
    order = tested.order;
  }
  const Found_rotation<GT> result = measured(s, c.axis, order);
  const bool kept = result.sharp_support >= min_rotation_support;
  if(s.verbose)
    std::cerr << "  generated (" << c.axis.direction.transpose() << ") order " << order << (image ? " (image)" : " (product)")
              << ": support " << result.symmetry.support << " (at sigma / 2: " << result.sharp_support << "), symmetry "
              << result.symmetry.symmetry << (kept ? ", kept\n" : ", dropped\n");
  if(!kept) return std::nullopt;
  return result;
}

// The axes of the group the consistent ones found generate (group_closure.h), added to `found`
// (generated_rotation()), until no new one holds (three rounds at most: enough for the dihedral
// groups, whose second class of 2-fold axes comes from products of the first, and for the
// cube's). The flips about a continuous axis are left out, as generators and as results.
template <typename GT, typename M, typename W>
void close_group(const Rotation_search<GT, M, W>& s, const std::vector<Eigen::Vector3d>& order_probes,
                 std::vector<Found_rotation<GT>>& found)
{
  const Eigen::Vector3d center = s.mass.center();
  const double radius = s.mass.radius();
  for(int round = 0; round < 3; ++round) {
    const Generated_axes generated =
      group_closure(group_generators(found, center, radius, min_generator_support), s.max_order, center, radius,
                    [&](const Daxis& a, const Daxis& b) { return same_axis(a, b, center, radius); });
    const std::size_t before = found.size(), count = generated.images.size() + generated.products.size();
    std::size_t done = 0;
    for(const bool image : {true, false})
      for(const Axis_candidate& c : image ? generated.images : generated.products) {
        report_progress(done++, count);
        if(found.size() == max_group_axes) break;
        if(flip_of_continuous(c.axis, found, radius)) continue;
        if(std::optional<Found_rotation<GT>> f = generated_rotation(s, c, image, order_probes, found)) found.push_back(*f);
      }
    if(found.size() == before) break;
  }
}

// Whether a coarse candidate is an axis that the exact rotations found generate (group_closure()
// run to its end, up to max_group_axes): close_group() then adds it without refinement.
template <typename GT>
bool generated_by_exact(const Axis_candidate& c, const std::vector<Found_rotation<GT>>& found,
                        const Eigen::Vector3d& center, double radius, int max_order)
{
  auto same = [&](const Daxis& a, const Daxis& b) { return same_axis(a, b, center, radius); };
  std::vector<Axis_candidate> group = group_generators(found, center, radius, exact_rotation_support);
  for(int round = 0; round < 3 && group.size() < max_group_axes; ++round) {
    const Generated_axes generated = group_closure(group, max_order, center, radius, same);
    if(generated.images.empty() && generated.products.empty()) break;
    group.insert(group.end(), generated.images.begin(), generated.images.end());
    group.insert(group.end(), generated.products.begin(), generated.products.end());
  }
  return std::any_of(group.begin(), group.end(), [&](const Axis_candidate& g) {
    return same_axis(c.axis, g.axis, center, coarse_tolerance * same_axis_degrees * CGAL_PI / 180.,
                     coarse_tolerance * same_axis_distance * radius);
  });
}

// The rotational symmetries found from the axes of inertia, the search of directions and the
// `extra` candidates (the meeting lines of known planes), strongest first.
template <typename GT, typename M, typename W>
std::vector<Rotational_symmetry<GT>> rotational_symmetries(const Rotation_search<GT, M, W>& s,
                                                           const std::vector<Axis_candidate>& extra)
{
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const Eigen::Vector3d center = s.mass.center();
  Progress_stage stage(0., rotation_candidates_share);
  std::vector<Axis_candidate> candidates = inertia_candidates(s.mass, s.max_order);
  const Normal_density density(spread_subset(s.normals, normal_density_samples),
                               spread_subset(s.normals, normal_density_probes));
  const std::vector<Axis_candidate> searched = normal_density_candidates(density, s.max_order, center, s.settings.threads);
  candidates.insert(candidates.end(), searched.begin(), searched.end());
  candidates.insert(candidates.end(), extra.begin(), extra.end());
  if(s.verbose) std::cerr << "  " << candidates.size() << " candidates (" << seconds() << " s)\n";
  const std::vector<Axis_candidate> axes = coarse_axes(s, std::move(candidates));
  if(s.verbose) std::cerr << "  " << axes.size() << " axes to refine (" << seconds() << " s)\n";
  const std::vector<Eigen::Vector3d> order_probes = spread_subset(s.samples, order_samples);
  std::vector<Found_rotation<GT>> found;
  bool flip_refined = false; // about a continuous axis found: its flips are all alike, one is refined
  // An axis the exact rotations found generate is left to close_group(), which maps it there
  // (the icosahedron: 2 of its 15 coarse axes refined, the 29 others generated).
  for(std::size_t i = 0; i < axes.size(); ++i) {
    const Axis_candidate& c = axes[i];
    const double share = (rotation_refinements_end - rotation_candidates_share) / double(axes.size());
    stage.move_to(rotation_candidates_share + double(i) * share, rotation_candidates_share + double(i + 1) * share);
    const bool flip = std::any_of(found.begin(), found.end(), [&](const Found_rotation<GT>& f) {
      return f.symmetry.order == 0 && meets_at_right_angle(c.axis, f.axis, s.mass.radius(), coarse_tolerance);
    });
    if((flip && flip_refined) || generated_by_exact(c, found, center, s.mass.radius(), s.max_order)) continue;
    flip_refined = flip_refined || flip;
    if(std::optional<Found_rotation<GT>> f = refined_rotation(s, c, order_probes, found)) found.push_back(*f);
  }
  stage.move_to(rotation_refinements_end, 1.);
  close_group(s, order_probes, found);
  if(s.verbose) std::cerr << "  " << found.size() << " axes (" << seconds() << " s)\n";
  std::vector<Rotational_symmetry<GT>> result;
  for(const Found_rotation<GT>& f : consistent(std::move(found), center, s.mass.radius())) result.push_back(f.symmetry);
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATION_DETECTION_H
