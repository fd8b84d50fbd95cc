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
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
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
};


// The candidates placed (their best axis point on the coarse GEDT), strongest first; those above
// min_coarse_overlap aligned by pattern searches, on the coarse GEDT then on the sharp overlap
// of the GEDT (its width sigma / 2), and kept if the sharp overlap reaches min_sharp_overlap:
// the axes to refine, duplicates left out, in decreasing sharp overlap.
template <typename GT, typename M, typename W>
std::vector<Axis_candidate> coarse_axes(const Rotation_search<GT, M, W>& s, std::vector<Axis_candidate> candidates)
{
  const Eigen::Vector3d center = s.mass.center();
  const double radius = s.mass.radius();
  const Gedt_overlap<GT> placing(s.coarse_gedt, spread_subset(s.samples, axis_point_samples), s.coarse_sigma, center, radius);
  const Gedt_overlap<GT> aligning(s.coarse_gedt, spread_subset(s.samples, alignment_samples), s.coarse_sigma, center, radius);
  const Gedt_overlap<GT> sharp(s.gedt, spread_subset(s.samples, alignment_samples), s.settings.sigma, center, radius, 4);
  for(Axis_candidate& c : candidates)
    c.axis = best_axis_point(placing, c.axis.point, radius, c.axis.direction, refinement_angles(c.order), c.score);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Axis_candidate& a, const Axis_candidate& b) { return a.score > b.score; });
  std::vector<Axis_candidate> result;
  std::vector<Daxis> tried; // the placed axes aligned so far: a candidate next to one is not aligned again
  auto seen = [&](const Daxis& axis) {
    return std::any_of(result.begin(), result.end(), [&](const Axis_candidate& r) { return same_axis(axis, r.axis, center, radius); });
  };
  for(Axis_candidate c : candidates) {
    if(c.score < min_coarse_overlap || result.size() == max_refined_axes || tried.size() == max_aligned_candidates) break;
    if(seen(c.axis) || std::any_of(tried.begin(), tried.end(), [&](const Daxis& t) { return same_axis(c.axis, t, center, radius); }))
      continue;
    tried.push_back(c.axis);
    double coarse = 0.;
    c.axis = pattern_search(aligning, c.axis, refinement_angles(c.order), coarse_pattern_angle_step, coarse);
    c.axis = pattern_search(sharp, c.axis, refinement_angles(c.order), sharp_pattern_angle_step, c.score);
    const bool kept = c.score >= min_sharp_overlap && !seen(c.axis);
    if(s.verbose)
      std::cerr << "  candidate axis (" << c.axis.direction.transpose() << ") order " << c.order << ": overlap "
                << coarse << ", sharp " << c.score << (kept ? "" : c.score < min_sharp_overlap ? ", dropped" : ", seen") << "\n";
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

// A coarse axis refined on the surface, its order found, measured; none if it heads for an axis
// already `found`, if no rotation holds, or if it maps less than min_rotation_support of the
// shape onto the shape. If the order found is not a multiple of the candidate's, the refinement
// fitted a rotation that does not hold: it is run again for the best supported order.
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
  auto refine = [&](const Daxis& axis, int k) {
    return refine_axis(s.samples, axis, refinement_angles(k), s.matcher, s.walk_matcher, s.settings, center, heading_for_found);
  };
  // The order is tested at sigma / 2, or at the narrower width the refinement reached.
  auto test_order = [&](const Axis_refinement& r) {
    return rotation_order(order_probes, r.axis, s.max_order, s.walk_matcher, s.settings, (std::min)(r.width, 0.5));
  };
  Axis_refinement refined = refine(candidate.axis, candidate.order);
  Rotation_order order;
  if(!refined.abandoned) {
    order = test_order(refined);
    if(order.order > 0 && order.order % candidate.order != 0) {
      refined = refine(refined.axis, order.best_order);
      if(!refined.abandoned) order = test_order(refined);
    }
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

// Rotations generate the group only if they are symmetries, not approximations of ones: the
// group closure starts from the axes whose support at sigma / 2 is at least 0.95 (exact ones
// measure above 0.99; with 0.2 % vertex noise, 0.99).
constexpr double min_generator_support = 0.95;

// The axes of the group the consistent ones found generate (group_closure.h), refined and tested,
// added to `found`, until no new one holds (three rounds at most: enough for the dihedral groups, whose
// second class of 2-fold axes comes from products of the first, and for the cube's). The flips
// about a continuous axis are left out, as generators and as results: they generate one another
// without end, and one of them stands for all.
template <typename GT, typename M, typename W>
void close_group(const Rotation_search<GT, M, W>& s, const std::vector<Eigen::Vector3d>& order_probes,
                 std::vector<Found_rotation<GT>>& found)
{
  const Eigen::Vector3d center = s.mass.center();
  const double radius = s.mass.radius();
  auto flip_of_continuous = [&](const Daxis& axis) {
    return std::any_of(found.begin(), found.end(), [&](const Found_rotation<GT>& f) {
      return f.symmetry.order == 0 && (parallel_axes(axis, f.axis) || meets_at_right_angle(axis, f.axis, radius, 1.));
    });
  };
  for(int round = 0; round < 3; ++round) {
    std::vector<Axis_candidate> discrete; // the generators: the consistent axes found
    for(const Found_rotation<GT>& f : consistent(found, center, radius))
      if(f.symmetry.order >= 2 && f.sharp_support >= min_generator_support && !flip_of_continuous(f.axis))
        discrete.push_back({f.axis, f.symmetry.order, 0.});
    const std::vector<Axis_candidate> generated = group_closure(
      discrete, s.max_order, center, radius, [&](const Daxis& a, const Daxis& b) { return same_axis(a, b, center, radius); });
    const std::size_t before = found.size();
    for(const Axis_candidate& c : generated) {
      if(found.size() == max_group_axes) break;
      if(flip_of_continuous(c.axis)) continue;
      if(std::optional<Found_rotation<GT>> f = refined_rotation(s, c, order_probes, found)) found.push_back(*f);
    }
    if(found.size() == before) break;
  }
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
  std::vector<Axis_candidate> candidates = inertia_candidates(s.mass, s.max_order);
  const Normal_density density(spread_subset(s.normals, normal_density_samples),
                               spread_subset(s.normals, normal_density_probes));
  const std::vector<Axis_candidate> searched = normal_density_candidates(density, s.max_order, center);
  candidates.insert(candidates.end(), searched.begin(), searched.end());
  candidates.insert(candidates.end(), extra.begin(), extra.end());
  if(s.verbose) std::cerr << "  " << candidates.size() << " candidates (" << seconds() << " s)\n";
  const std::vector<Axis_candidate> axes = coarse_axes(s, std::move(candidates));
  if(s.verbose) std::cerr << "  " << axes.size() << " axes to refine (" << seconds() << " s)\n";
  const std::vector<Eigen::Vector3d> order_probes = spread_subset(s.samples, order_samples);
  std::vector<Found_rotation<GT>> found;
  bool flip_refined = false; // about a continuous axis found: its flips are all alike, one is refined
  for(const Axis_candidate& c : axes) {
    const bool flip = std::any_of(found.begin(), found.end(), [&](const Found_rotation<GT>& f) {
      return f.symmetry.order == 0 && meets_at_right_angle(c.axis, f.axis, s.mass.radius(), coarse_tolerance);
    });
    if(flip && flip_refined) continue;
    flip_refined = flip_refined || flip;
    if(std::optional<Found_rotation<GT>> f = refined_rotation(s, c, order_probes, found)) found.push_back(*f);
  }
  close_group(s, order_probes, found);
  if(s.verbose) std::cerr << "  " << found.size() << " axes (" << seconds() << " s)\n";
  std::vector<Rotational_symmetry<GT>> result;
  for(const Found_rotation<GT>& f : consistent(std::move(found), center, s.mass.radius())) result.push_back(f.symmetry);
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_ROTATION_DETECTION_H
