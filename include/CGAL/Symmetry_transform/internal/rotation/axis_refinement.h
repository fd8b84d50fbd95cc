// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_AXIS_REFINEMENT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_AXIS_REFINEMENT_H

// Iterative Rotated Points: the refinement of a rotation axis in the spirit of Iterative
// Symmetric Points (thesis, section 3.3). Surface samples are rotated about the current axis by
// a few angles at once (2 pi / k and a larger multiple, each for part of the samples), matched to their closest points on the
// shape, and the axis (2 parameters of direction, 2 of position) re-fitted by Gauss-Newton on
// the distances of the rotated samples to the tangent planes at their matches, weighted by
// exp(-d^2 / 2 w^2). As ISP: the walk uses the approximate matches of a Closest_triangle_field,
// exact matches end it; on an exact symmetry the weights narrow to w = sigma / 2 and sigma / 4.

#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/detection/iterative_symmetric_points.h>
#include <CGAL/Symmetry_transform/internal/rotation/axis.h>
#include <CGAL/Symmetry_transform/internal/rotation/coarse_alignment.h>

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Weighted normal equations of one fit, summed over the rotated samples.
struct Axis_fit_sums
{
  Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
  Eigen::Vector4d jtr = Eigen::Vector4d::Zero();
  double weight = 0.;          // of the fit
  double support = 0.;         // weights at sigma itself
  double narrower_weight = 0.; // weights at half the width of the fit, w^4

  Axis_fit_sums& operator+=(const Axis_fit_sums& o)
  {
    jtj += o.jtj, jtr += o.jtr;
    weight += o.weight, support += o.support, narrower_weight += o.narrower_weight;
    return *this;
  }
};

// The rotation of x about `axis` by the angle of (c, s) = (cos, sin), and the derivatives of the
// image along the unknowns: direction turned along t1, t2 (radians), point moved along t1, t2
// (in units of `length`).
struct Rotated_sample
{
  Eigen::Vector3d image;
  Eigen::Matrix<double, 3, 4> derivatives;
};

inline Rotated_sample rotated_sample(const Eigen::Vector3d& x, const Daxis& axis, const Rigid_motion& rotation,
                                     double c, double s, const Eigen::Vector3d& t1, const Eigen::Vector3d& t2,
                                     double length)
{
  const Eigen::Vector3d& a = axis.direction;
  const Eigen::Vector3d u = x - axis.point;
  Rotated_sample r;
  r.image = rotation(x);
  // Rodrigues: R u = c u + s (a x u) + (1 - c) (a.u) a; its derivative along a tangent t of a.
  for(int i = 0; i < 2; ++i) {
    const Eigen::Vector3d& t = i == 0 ? t1 : t2;
    r.derivatives.col(i) = s * t.cross(u) + (1. - c) * (a.dot(u) * t + t.dot(u) * a);
    r.derivatives.col(2 + i) = length * (t - rotation.linear * t);
  }
  return r;
}

// A thread for every 2500 samples at least: starting a thread costs as much as matching a few
// hundred samples with the Closest_triangle_field or the Kd-tree of a point set, and far more on a
// busy machine. Exact searches in the AABB tree of a mesh cost up to 20 times more: a thread for
// every 250 (the exact end of the refinement, 2500 samples, gets up to ten).
template <typename Matcher>
constexpr std::size_t min_samples_per_thread()
{
  return std::is_same<Matcher, Triangle_matcher>::value ? 250 : 2500;
}

// A trial step is given up when the weight its samples lost exceeds what it may lose and still
// win by this fraction of the sample count: a margin far above the rounding of the sums.
constexpr double give_up_rounding_margin = 1e-9;

// Adds `amount` to an atomic sum; returns the new sum.
inline double atomic_add(std::atomic<double>& sum, double amount)
{
  double old = sum.load(std::memory_order_relaxed);
  while(!sum.compare_exchange_weak(old, old + amount, std::memory_order_relaxed)) {}
  return old + amount;
}

// The sums of the fit with weights of width `width` sigma. Each sample is rotated by one of
// `angles`, in turn by runs of 64 consecutive samples (close to each other along the Hilbert
// curve, so that the match of one starts the search of the next); `hints` holds one match per
// sample. A fit whose sum of weights cannot exceed `reject_below` is given up as soon as the
// weight its samples lost (1 - w each, as w <= 1) shows it: its weight is then -infinity, the
// rest of the sums incomplete. Gauss-Newton rejects such steps all the same, and the long steps it
// rejects are the costly ones: their samples land far from the surface, where exact searches cost
// 3 to 5 times more (blade.off).
template <typename Matcher>
Axis_fit_sums axis_fit_sums(const std::vector<Eigen::Vector3d>& samples, const Daxis& axis,
                            const std::vector<double>& angles, const Matcher& matcher, const Isp_settings& settings,
                            double width, std::vector<typename Matcher::Hint>& hints,
                            double reject_below = -std::numeric_limits<double>::infinity())
{
  constexpr std::size_t chunk = 64;
  const double sigma = width * settings.sigma;
  const Eigen::Vector3d t1 = axis.direction.unitOrthogonal(), t2 = axis.direction.cross(t1);
  std::vector<Rigid_motion> rotations;
  std::vector<double> cosines, sines;
  for(double angle : angles) {
    rotations.push_back(axis.rotation(angle));
    cosines.push_back(std::cos(angle));
    sines.push_back(std::sin(angle));
  }
  const std::size_t n = samples.size(), none = n;
  auto add_sample = [&](std::size_t i, Axis_fit_sums& sums, std::size_t& previous, std::vector<typename Matcher::Hint>& chain) {
    const std::size_t a = (i / chunk) % angles.size();
    const Rotated_sample r = rotated_sample(samples[i], axis, rotations[a], cosines[a], sines[a], t1, t2, settings.radius);
    if(settings.beyond_band && settings.beyond_band(r.image)) return;
    if(!chain[i].valid && previous != none) chain[i] = chain[previous];
    const Match match = matcher.closest(r.image, chain[i]);
    previous = i;
    const double d2 = (r.image - match.first).squaredNorm();
    sums.support += std::exp(-d2 / (2. * settings.sigma * settings.sigma));
    const double w = std::exp(-d2 / (2. * sigma * sigma));
    if(w < 1e-12) return;
    sums.weight += w;
    sums.narrower_weight += (w * w) * (w * w);
    const Eigen::Vector4d j = r.derivatives.transpose() * match.second;
    sums.jtj += w * j * j.transpose();
    sums.jtr += w * match.second.dot(r.image - match.first) * j;
  };
  // As ISP: sums per chunk, added in chunk order. A fit given up stops wherever the threads
  // are, so it works on a copy of the hints, kept only when the fit is complete: the hints, like
  // the sums, then depend on the chunks alone, never on the thread count or the timing.
  const std::size_t chunks = (n + chunk - 1) / chunk;
  const unsigned threads =
    unsigned((std::max)(std::size_t(1), (std::min)(std::size_t(settings.threads), n / min_samples_per_thread<Matcher>())));
  std::vector<Axis_fit_sums> partial(chunks);
  std::vector<typename Matcher::Hint> updated_hints = hints;
  const double max_lost = double(n) * (1. + give_up_rounding_margin) - reject_below;
  std::atomic<double> lost{0.};
  std::atomic<bool> hopeless{false};
  parallel_for_chunks(chunks, threads, [&](std::size_t c) {
    if(hopeless.load(std::memory_order_relaxed)) return;
    std::size_t previous = none;
    const std::size_t end = (std::min)((c + 1) * chunk, n);
    for(std::size_t i = c * chunk; i < end; ++i) add_sample(i, partial[c], previous, updated_hints);
    // (a step can be given up only if it must beat a positive weight: max_lost < n)
    if(max_lost < double(n) && atomic_add(lost, double(end - c * chunk) - partial[c].weight) > max_lost)
      hopeless = true;
  });
  Axis_fit_sums total;
  if(hopeless) {
    total.weight = -std::numeric_limits<double>::infinity();
    return total;
  }
  hints.swap(updated_hints);
  for(const Axis_fit_sums& s : partial) total += s;
  return total;
}

// One Gauss-Newton step from `axis`, the step scaled by `factor`; the axis keeps its point
// nearest to `center`. Levenberg damping (1e-9 of the mean diagonal) keeps the step finite where
// the axis is not pinned down (a sphere: any direction through its centre).
inline bool axis_step(const Axis_fit_sums& s, Daxis& axis, const Eigen::Vector3d& center, double length, double factor)
{
  if(!(s.weight > 0.)) return false;
  const Eigen::Matrix4d damped = s.jtj + 1e-9 * (s.jtj.trace() / 4.) * Eigen::Matrix4d::Identity();
  const Eigen::Vector4d delta = factor * damped.ldlt().solve(-s.jtr);
  if(!delta.allFinite()) return false;
  axis = perturbed(axis, delta, length);
  axis.point = axis.projection(center);
  return true;
}

struct Axis_refinement
{
  Daxis axis;
  double support = 0.; // mean weight at sigma of the rotated samples at the last fit
  double width = 1.;   // of the last weights, in sigmas
  unsigned iterations = 0;
  bool abandoned = false;
};

// The exact end of a refinement reads one sample in this many.
constexpr std::size_t polish_stride = 4;

// Whether to give up the refinement of an axis (heading for one already found).
typedef std::function<bool(const Daxis&)> Axis_abandon;
// Whether to end a refinement with the exact matches, given the walk's result (no if the walk's
// axis turns out not to be worth it: its order is not the one assumed, and it is refined again).
typedef std::function<bool(const Axis_refinement&)> Axis_polish_if;

// Gauss-Newton from result.axis, whose sums are given, with weights of width `width` sigma. A
// step is taken if it raises the sum of the weights; one that does not is halved, and the
// descent stops at the second in a row. It also stops after a step of less than 1e-8 (radians
// plus radii: the quadratic convergence on an exact symmetry), a relative gain below 1e-4 (the
// top of an approximate one, where the axis would creep along a flat ridge by a fraction of a
// degree per step), `max_steps` steps, or when `abandon` says so. Returns the sums of the final
// axis; `hints` are its matches: a rejected step's are dropped, for the next search to start near
// its answer (exact searches from a rejected step's matches, several sigma off, cost 3 to 5 times
// more on blade.off).
template <typename Matcher>
Axis_fit_sums gauss_newton(const std::vector<Eigen::Vector3d>& samples, const std::vector<double>& angles,
                           const Matcher& matcher, const Isp_settings& settings, const Eigen::Vector3d& center,
                           double width, Axis_fit_sums sums, std::vector<typename Matcher::Hint>& hints,
                           Axis_refinement& result, unsigned max_steps, const Axis_abandon& abandon)
{
  double factor = 1.;
  std::vector<typename Matcher::Hint> trial_hints;
  for(unsigned step = 0; step < max_steps; ++step) {
    Daxis trial = result.axis;
    if(!axis_step(sums, trial, center, settings.radius, factor)) break;
    trial_hints = hints;
    const Axis_fit_sums s = axis_fit_sums(samples, trial, angles, matcher, settings, width, trial_hints, sums.weight);
    ++result.iterations;
    if(!(s.weight > sums.weight)) {
      if(factor < 1.) break;
      factor = 0.5;
      continue;
    }
    const double moved = angle_between(trial, result.axis) + result.axis.distance(trial.point) / settings.radius;
    const bool flat = s.weight < sums.weight * (1. + 1e-4);
    result.axis = trial;
    sums = s;
    hints.swap(trial_hints);
    factor = 1.;
    if(abandon && abandon(result.axis)) {
      result.abandoned = true;
      break;
    }
    if(moved < 1e-8 || flat) break;
  }
  result.support = sums.support / double(samples.size());
  return sums;
}

// Iterative Rotated Points from `start` for the rotation by `angles`: Gauss-Newton on an eighth
// of the samples at twice the width (a wider basin for a start from the coarse stage), then on
// all of them at sigma, narrowed to sigma / 2 and sigma / 4 while the matches are much closer
// than the width (the mean weight at half the width above 85 % of it, as ISP: an exact
// symmetry), all walking with `walk_matcher`; then up to four steps with the exact `matcher`, on
// a fourth of the samples, if `polish_if` (when given) says so of the walk's result.
// `abandon` may stop it (an axis heading for one already found).
template <typename Matcher, typename Walk_matcher>
Axis_refinement refine_axis(const std::vector<Eigen::Vector3d>& samples, const Daxis& start,
                            const std::vector<double>& angles, const Matcher& matcher, const Walk_matcher& walk_matcher,
                            const Isp_settings& settings, const Eigen::Vector3d& center, const Axis_abandon& abandon = {},
                            const Axis_polish_if& polish_if = {})
{
  Axis_refinement result{start};
  const std::vector<Eigen::Vector3d> coarse(samples.begin(), samples.begin() + std::ptrdiff_t(samples.size() / 8));
  auto climb = [&](const std::vector<Eigen::Vector3d>& x, double width, std::vector<typename Walk_matcher::Hint>& h) {
    return gauss_newton(x, angles, walk_matcher, settings, center, width,
                        axis_fit_sums(x, result.axis, angles, walk_matcher, settings, width, h), h, result,
                        settings.max_iterations, abandon);
  };
  if(coarse.size() >= 100) {
    std::vector<typename Walk_matcher::Hint> coarse_hints(coarse.size());
    climb(coarse, 2., coarse_hints);
    if(result.abandoned) return result;
  }
  std::vector<typename Walk_matcher::Hint> hints(samples.size());
  Axis_fit_sums last = climb(samples, 1., hints);
  for(const double narrower : {0.5, 0.25}) {
    if(result.abandoned || last.narrower_weight < 0.85 * last.weight) break;
    result.width = narrower;
    last = climb(samples, narrower, hints);
  }
  if(result.abandoned || (polish_if && !polish_if(result))) return result;
  // The exact end reads every fourth sample (in ISP's order, a regular stride covers the shape):
  // on an exact symmetry any of them give the same axis, and exact searches cost up to 20 times
  // the walk's on thin shapes, whose triangles' boxes overlap (blade.off: 0.8 s for all samples).
  // They start from the walk's matches when these are hints of the exact matcher
  // (Closest_triangle_field): most are then one test of a leaf of the tree.
  std::vector<Eigen::Vector3d> subset;
  std::vector<typename Matcher::Hint> exact_hints;
  for(std::size_t i = 0; i < samples.size(); i += polish_stride) {
    subset.push_back(samples[i]);
    exact_hints.emplace_back();
    if constexpr(std::is_same<typename Matcher::Hint, typename Walk_matcher::Hint>::value) exact_hints.back() = hints[i];
  }
  gauss_newton(subset, angles, matcher, settings, center, result.width,
               axis_fit_sums(subset, result.axis, angles, matcher, settings, result.width, exact_hints), exact_hints,
               result, 4, {});
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_AXIS_REFINEMENT_H
