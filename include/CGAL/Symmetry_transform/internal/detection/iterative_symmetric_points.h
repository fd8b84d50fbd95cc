// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_ITERATIVE_SYMMETRIC_POINTS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_ITERATIVE_SYMMETRIC_POINTS_H

// Iterative Symmetric Points (thesis, section 3.3): samples of the shape are reflected through
// the current plane and matched to their closest points on the shape; the plane is then
// re-fitted to the matches by weighted least squares, the weights exp(-d^2 / 2 sigma^2) of the
// match distances d being those of the Gaussian distance transform. On a mesh the fit
// minimises the distance of each reflected sample to the tangent plane at its match
// (Gauss-Newton: few iterations on symmetric shapes), or, where the normals leave the fit
// degenerate (a flat shape), to the plane across the direction from the match to it (at the
// border of the shape, where the distance grows in the shape's plane); on a point set, with no normals, it
// minimises the distance to the match itself (closed form). On a mesh, ISP walks with the
// approximate matches of a Closest_triangle_field and ends with exact searches in the AABB tree.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/small_matrices.h>
#include <CGAL/Symmetry_transform/internal/common/surface_samples.h>
#include <CGAL/Symmetry_transform/internal/detection/border_curve.h>
#include <CGAL/Symmetry_transform/internal/detection/matchers.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The coarse phase uses every coarse_sample_stride-th sample (the first ones, see isp_order());
// fewer than this many cannot locate a plane, and the coarse phase is skipped.
constexpr std::size_t min_coarse_samples = 100;
// A coarse step shorter than this (|change of the unit normal| + |change of offset| / R) is
// within about a bin (2e-2) of the limit: the coarse phase has settled.
constexpr double coarse_settled_step = 5e-3;
// A start that has not settled after this many coarse iterations is not near a maximum.
constexpr unsigned coarse_max_iterations = 12;
// Over-relaxed steps are doubled after each gain, up to this factor.
constexpr double max_step_factor = 32.;
// A plain step after an overshoot that raises the mean weight by less than this (relative) has
// reached the top: of a plateau, or, on an exact symmetry, within a few hundredths of a degree
// after the quadratic convergence of Gauss-Newton.
constexpr double min_relative_gain = 1e-3;
// The weights narrow (to half, then a quarter of sigma) while the mean weight at half the width
// is above this fraction of the mean weight: the matches are then much closer than sigma, an
// exact symmetry.
constexpr double exact_symmetry_weight_ratio = 0.85;
constexpr double narrower_widths[] = {0.5, 0.25};
// The exact steps that end a walk at narrowed weights (an exact symmetry: Gauss-Newton converges
// in a few), and the step below which it has converged.
constexpr unsigned exact_polish_steps = 4;
constexpr double polish_converged_step = 1e-7;
// Weights below this add nothing to the fit (exp(-27.6): farther than 7.4 widths).
constexpr double negligible_weight = 1e-12;
// Samples per chunk of work: the sums and the hints' chain are the chunk's own.
constexpr std::size_t samples_per_chunk = 64;
// An image whose offset from its match leans off the match's normal by more than this sine is
// matched on an edge or a corner of a triangle ...
constexpr double edge_match_min_sine = 1e-3;
// ... unless the offset across the normal is shorter than this many sigmas: rounding.
constexpr double edge_match_min_offset = 1e-9;
// A fit along the normals is degenerate when an eigenvalue of its normal matrix (its turns in
// units of the shape's radius) is below this fraction of the largest: on a flat shape, zero up to
// rounding (1e-30). The unknowns are not scaled to a unit diagonal: that would hide a column
// that is zero but for rounding (the offset of an in-plane mirror, along the shape's normal).
// Samples farther than 3e4 radii from the centre of the fit could make a fit look degenerate:
// the fit along the gradients, the same but at edges, then takes over, harmlessly.
constexpr double degenerate_fit_ratio = 1e-9;

// The direction along which the distance of `image` to the surface grows: the normal at its
// match inside a triangle, the direction from the match to it at an edge or a corner.
inline Eigen::Vector3d distance_gradient(const Eigen::Vector3d& image, const Match& match, double sigma)
{
  const Eigen::Vector3d away = image - match.first;
  const Eigen::Vector3d across = away - match.second.dot(away) * match.second;
  if(across.norm() <= (std::max)(edge_match_min_sine * away.norm(), edge_match_min_offset * sigma)) return match.second;
  return away.normalized();
}

// Whether the normal matrix `jtj` of a fit of a shape of radius `radius` leaves a direction free.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool degenerate_fit(const Eigen::Matrix3d& jtj, double radius);

struct Isp_settings
{
  double sigma = 0.;            // width of the Gaussian weights of the support; the phases
                                // of ISP weigh with multiples of it
  double radius = 0.;           // size of the shape, for the convergence test
  unsigned max_iterations = defaults::isp_iterations; // at most this many re-fits per stage
  unsigned threads = 1;
  // Whether a point is farther than 3 sigma from the shape (the GEDT is zero there): its
  // weight is zero at the widths ISP uses (sigma and narrower), and the closest-point search, the
  // costliest step, is skipped. Made by beyond_band_of(), it refers to a GEDT that must outlive it.
  std::function<bool(const Eigen::Vector3d&)> beyond_band;
  // The centre of the shape: ISP fits its planes in coordinates relative to it, so that a shape
  // far from the origin is fitted as the same shape at the origin (isp::Local_frame).
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  // The border of a flat surface, if the shape is one (border_curve.h): the fine phase ends with
  // the fit of an in-plane mirror to the border, which the area leaves loose. Must outlive it.
  const Border_curve* border = nullptr;
};

// The band test of a GEDT, which it refers to (hence no temporary).
template <typename GT>
std::function<bool(const Eigen::Vector3d&)> beyond_band_of(const Voxel_grid<GT>& gedt)
{
  return [&gedt](const Eigen::Vector3d& p) { return gedt.trilinear_value(p.x(), p.y(), p.z()) == 0.; };
}
template <typename GT>
std::function<bool(const Eigen::Vector3d&)> beyond_band_of(const Voxel_grid<GT>&& gedt) = delete;

struct Isp_result
{
  Dplane plane;
  double support;  // mean weight of the samples at the last fit: the supported fraction of the shape
  bool converged;
  unsigned iterations = 0;
};

// Weighted normal equations of one fit, summed over samples.
struct Isp_sums
{
  Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();      // Gauss-Newton (mesh)
  Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
  // The same along the distance gradients (distance_gradient()), for a fit that the normals
  // leave degenerate: on a flat shape the normals are all the same, and only the gradients at its
  // border tell how an in-plane mirror is turned or shifted.
  Eigen::Matrix3d edge_jtj = Eigen::Matrix3d::Zero();
  Eigen::Vector3d edge_jtr = Eigen::Vector3d::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();  // point-to-point (point set): 4 C_m - C_u
  Eigen::Vector3d midpoint_sum = Eigen::Vector3d::Zero();
  double weight = 0.;          // of the fit
  double support = 0.;         // weights at sigma itself
  double narrower_weight = 0.; // weights at half the width, w^4, of the same matches

  // Adds sample p, reflected to `image` through `plane` (tangent basis t1, t2 of its normal) and
  // matched to `match`: to the support with weights of width `sigma`, to the fit with `fit_sigma`;
  // to the fit along the distance gradients too if `edge_gradients` (matches on triangles).
  template <bool has_normals>
  void add(const Eigen::Vector3d& p, const Eigen::Vector3d& image, const Match& match, const Dplane& plane,
           const Eigen::Vector3d& t1, const Eigen::Vector3d& t2, double sigma, double fit_sigma, bool edge_gradients)
  {
    const double d2 = (image - match.first).squaredNorm();
    const double at_sigma = std::exp(-d2 / (2. * sigma * sigma));
    support += at_sigma;
    // Most fits weigh at sigma itself: the same weight, one exponential fewer.
    const double w = fit_sigma == sigma ? at_sigma : std::exp(-d2 / (2. * fit_sigma * fit_sigma));
    if(w < negligible_weight) return;
    weight += w;
    narrower_weight += (w * w) * (w * w);
    const Eigen::Vector3d& n = plane.normal;
    if constexpr(has_normals) {
      const double height = n.dot(p) - plane.offset;
      // d(image)/d(normal) . delta = -2 ((delta . p) n + height delta); d(image)/d(offset) = 2 n
      auto add_along = [&](const Eigen::Vector3d& nu, Eigen::Matrix3d& sum_jtj, Eigen::Vector3d& sum_jtr) {
        const Eigen::Vector3d jacobian(-2. * (t1.dot(p) * nu.dot(n) + height * nu.dot(t1)),
                                       -2. * (t2.dot(p) * nu.dot(n) + height * nu.dot(t2)), 2. * nu.dot(n));
        sum_jtj += w * jacobian * jacobian.transpose();
        sum_jtr += w * nu.dot(image - match.first) * jacobian;
      };
      add_along(match.second, jtj, jtr);
      if(edge_gradients) add_along(distance_gradient(image, match, sigma), edge_jtj, edge_jtr);
    } else {
      const Eigen::Vector3d m = 0.5 * (p + match.first), u = p - match.first;
      moments += w * (4. * m * m.transpose() - u * u.transpose());
      midpoint_sum += w * m;
    }
  }

  void add(const Isp_sums& o)
  {
    support += o.support;
    narrower_weight += o.narrower_weight;
    jtj += o.jtj;
    jtr += o.jtr;
    edge_jtj += o.edge_jtj;
    edge_jtr += o.edge_jtr;
    moments += o.moments;
    midpoint_sum += o.midpoint_sum;
    weight += o.weight;
  }
};

// The sums of the fit with weights of width `width` sigma. `hints` (one per sample) keep the
// matches from one iteration to the next: the searches for nearby queries start there. Where the
// matches are on triangles and the normals leave the fit degenerate, it follows the distance
// gradients instead.
template <typename Matcher>
Isp_sums isp_sums(const std::vector<Eigen::Vector3d>& samples, const Dplane& plane, const Matcher& matcher,
                  const Isp_settings& settings, double width, std::vector<typename Matcher::Hint>& hints)
{
  constexpr bool edge_gradients = Matcher::matches_on_triangles;
  // Tangent basis of the normal: the Gauss-Newton unknowns are (rotation along t1, t2, offset).
  const Eigen::Vector3d t1 = plane.normal.unitOrthogonal(), t2 = plane.normal.cross(t1);
  // Adds sample i to the sums s; `previous` is the last sample of the same thread with a match.
  const std::size_t none = samples.size();
  auto add_sample = [&](std::size_t i, Isp_sums& s, std::size_t& previous) {
    const Eigen::Vector3d image = plane.reflect(samples[i]);
    if(settings.beyond_band && settings.beyond_band(image)) return;
    // No match of its own yet: that of the previous sample, close by, is a good start.
    if(!hints[i].valid && previous != none) hints[i] = hints[previous];
    const Match match = matcher.closest(image, hints[i]);
    previous = i;
    s.add<Matcher::has_normals>(samples[i], image, match, plane, t1, t2, settings.sigma, width * settings.sigma,
                                edge_gradients);
  };
  // The samples follow a Hilbert curve: contiguous slices would be regions of the shape, some
  // mapped far from the surface (costly searches) and some onto it; the threads take the chunks
  // in turn instead. Each chunk has its own sums and its own chain of hints, added in chunk order:
  // the result does not depend on the thread count.
  const std::size_t chunks = (samples.size() + samples_per_chunk - 1) / samples_per_chunk;
  std::vector<Isp_sums> partial(chunks);
  parallel_for_chunks(chunks, settings.threads, [&](std::size_t c) {
    std::size_t previous = none;
    Isp_sums sums; // on the thread's stack: the neighbouring chunks' sums share cache lines
    for(std::size_t i = c * samples_per_chunk; i < (std::min)((c + 1) * samples_per_chunk, samples.size()); ++i)
      add_sample(i, sums, previous);
    partial[c] = sums;
  });
  Isp_sums total;
  for(const Isp_sums& s : partial) total.add(s);
  if(edge_gradients && degenerate_fit(total.jtj, settings.radius)) {
    total.jtj = total.edge_jtj;
    total.jtr = total.edge_jtr;
  }
  return total;
}

// One fit: the plane that best maps the samples onto their matches, from the current one,
// its step multiplied by `step_factor` (over-relaxation).
template <typename Matcher>
bool refit(const Isp_sums& s, Dplane& plane, double step_factor = 1.)
{
  if(s.weight <= 0.) return false;
  if constexpr(Matcher::has_normals) {
    const Eigen::Vector3d delta = step_factor * solve_symmetric<3>(s.jtj, -s.jtr);
    if(!delta.allFinite()) return false;
    const Eigen::Vector3d t1 = plane.normal.unitOrthogonal(), t2 = plane.normal.cross(t1);
    plane.normal = (plane.normal + delta[0] * t1 + delta[1] * t2).normalized();
    plane.offset += delta[2];
  } else {
    // Minimise sum w (4 (n.m - d)^2 - (n.u)^2): d = n.mean(m), n the eigenvector of the
    // smallest eigenvalue of 4 C_m - C_u (moments centred on the weighted mean midpoint).
    const Eigen::Vector3d mean = s.midpoint_sum / s.weight;
    Eigen::Vector3d normal = symmetric_eigen(s.moments - 4. * s.weight * mean * mean.transpose()).vectors.col(0);
    if(normal.dot(plane.normal) < 0.) normal = -normal;
    const double offset = normal.dot(mean);
    const Eigen::Vector3d relaxed = plane.normal + step_factor * (normal - plane.normal);
    if(!(relaxed.norm() > 0.)) return false;
    plane.normal = relaxed.normalized();
    plane.offset += step_factor * (offset - plane.offset);
  }
  return true;
}

// The phases ISP runs from a plane (the manual, section Principal Symmetries, tells why):
// - coarse: on the first samples (every coarse_sample_stride-th of the shape), until a step
//   is shorter than coarse_settled_step, at most coarse_max_iterations; its weights are those of
//   the fine phase, as wider ones would let a big part of a composite shape pull the plane of a
//   small one away from it;
// - fine: on all samples (a walk first on the coarse ones: climb_from_coarse_samples()),
//   over-relaxed (steps doubled after each gain, up to max_step_factor; a step that does not
//   raise the mean weight is not taken and the next one is half the last that did), until the
//   mean weight stops growing; then, on an exact symmetry, with narrower weights. The mean
//   weight never decreases.
// `abandon` may stop either phase early (no convergence).
enum class Isp_phase { COARSE, FINE, BOTH };

namespace isp {

// Distance between two planes, for the convergence tests: |change of unit normal| + |change of
// offset| / R.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double step_length(const Dplane& a, const Dplane& b, double radius);

template <typename Matcher>
Isp_result coarse_phase(const std::vector<Eigen::Vector3d>& samples, Dplane plane, const Matcher& matcher,
                        const Isp_settings& settings, std::vector<typename Matcher::Hint>& hints,
                        const std::function<bool(const Dplane&)>& abandon)
{
  for(unsigned iteration = 0; iteration < coarse_max_iterations; ++iteration) {
    const Isp_sums s = isp_sums(samples, plane, matcher, settings, 1., hints);
    const Dplane previous = plane;
    if(!refit<Matcher>(s, plane)) return {plane, 0., false, iteration + 1};
    if(step_length(plane, previous, settings.radius) < coarse_settled_step)
      return {plane, s.support / double(samples.size()), true, iteration + 1};
    if(abandon && abandon(plane)) return {plane, 0., false, iteration + 1};
  }
  return {plane, 0., false, coarse_max_iterations};
}

// Over-relaxed ISP with weights of width `width` sigma, from result.plane whose sums are
// `start`, until a plain step after an overshoot gains less than min_relative_gain in mean
// weight, or a plain step gains nothing, or settings.max_iterations; `result` receives the best
// plane, its support (at sigma) and the iterations. Returns the sums of the best plane.
template <typename Matcher>
Isp_sums relaxed_ascent(const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher, const Isp_settings& settings,
                        double width, const Isp_sums& start, std::vector<typename Matcher::Hint>& hints,
                        const std::function<bool(const Dplane&)>& abandon, Isp_result& result)
{
  const double n = double(samples.size());
  Isp_sums best = start;
  result.support = best.support / n;
  result.converged = false;
  double step_factor = 1.;
  bool overshot = false; // a relaxed step has lowered the mean weight: the plane is near the top
  for(unsigned iteration = 1; iteration < settings.max_iterations; ++iteration) {
    Dplane trial = result.plane;
    if(!refit<Matcher>(best, trial, step_factor)) break;
    if(abandon && abandon(trial)) {
      result.plane = trial;
      break;
    }
    const Isp_sums s = isp_sums(samples, trial, matcher, settings, width, hints);
    ++result.iterations;
    if(s.weight > best.weight) {
      result.converged = overshot && step_factor == 1. && s.weight < best.weight * (1. + min_relative_gain);
      result.plane = trial;
      result.support = s.support / n;
      best = s;
      step_factor = (std::min)(2. * step_factor, max_step_factor);
    } else if(step_factor > 1.) {
      step_factor = (std::max)(1., step_factor / 4.); // half the last step that gained
      overshot = true;
    } else {
      result.converged = true;
    }
    if(result.converged) break;
  }
  return best;
}

// Plain ISP steps from result.plane, whose sums are `start`, while they raise the mean weight:
// at most `max_steps`, and none after a step below polish_converged_step (a converged exact
// symmetry). It ends a walk made with approximate matches.
template <typename Matcher>
Isp_sums polish(const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher, const Isp_settings& settings,
                double width, const Isp_sums& start, std::vector<typename Matcher::Hint>& hints, unsigned max_steps,
                Isp_result& result)
{
  Isp_sums best = start;
  result.support = best.support / double(samples.size());
  for(unsigned step = 0; step < max_steps; ++step) {
    Dplane trial = result.plane;
    if(!refit<Matcher>(best, trial)) break;
    const Isp_sums s = isp_sums(samples, trial, matcher, settings, width, hints);
    ++result.iterations;
    if(!(s.weight > best.weight)) break;
    const double moved = step_length(trial, result.plane, settings.radius);
    result.plane = trial;
    result.support = s.support / double(samples.size());
    best = s;
    if(moved < polish_converged_step) break;
  }
  return best;
}

// The fine phase with `matcher` from `start`; returns the width of its last weights. Narrower
// weights sharpen an exact symmetry, whose matches are much closer than sigma: parts of the
// shape that it does not map, matched a fraction of sigma away, lose their say (a local symmetry
// beside another part). On an approximate symmetry, whose mean weight would drop, they would fit
// the plane to the few samples that match best: the plane stays.
template <typename Matcher>
double climb(const std::vector<Eigen::Vector3d>& samples, const Dplane& start, const Matcher& matcher,
             const Isp_settings& settings, std::vector<typename Matcher::Hint>& hints,
             const std::function<bool(const Dplane&)>& abandon, Isp_result& fine)
{
  Isp_sums last = relaxed_ascent(samples, matcher, settings, 1., isp_sums(samples, start, matcher, settings, 1., hints),
                                 hints, abandon, fine);
  double width = 1.;
  for(const double narrower : narrower_widths) {
    if(last.narrower_weight < exact_symmetry_weight_ratio * last.weight || (abandon && abandon(fine.plane))) break;
    width = narrower;
    last = relaxed_ascent(samples, matcher, settings, width, isp_sums(samples, fine.plane, matcher, settings, width, hints),
                          hints, abandon, fine);
  }
  return width;
}

// The fine phase of a walk: its first iterations on the coarse samples, an eighth of the cost,
// up to their top at the width they settle on, then on all samples from there, which then take
// a few iterations only (most of a climb goes on far from the top). Returns the width.
template <typename Matcher>
double climb_from_coarse_samples(const std::vector<Eigen::Vector3d>& samples,
                                 const std::vector<Eigen::Vector3d>& coarse_samples, const Dplane& start,
                                 const Matcher& matcher, const Isp_settings& settings,
                                 std::vector<typename Matcher::Hint>& hints,
                                 const std::function<bool(const Dplane&)>& abandon, Isp_result& fine)
{
  if(coarse_samples.empty()) return climb(samples, start, matcher, settings, hints, abandon, fine);
  const double width = climb(coarse_samples, start, matcher, settings, hints, abandon, fine);
  if(abandon && abandon(fine.plane)) return width;
  relaxed_ascent(samples, matcher, settings, width, isp_sums(samples, fine.plane, matcher, settings, width, hints), hints,
                 abandon, fine);
  return width;
}

// The coordinates ISP works in: relative to the centre of the shape. In those of the input, a
// plane far from the origin turns about the origin, hence moves by its angle times the distance:
// its Gauss-Newton steps are ill-conditioned, its convergence test never settles, and the
// moments of the point-to-point fit cancel. The matchers and the band test keep the input's
// coordinates: the queries are moved there and their matches moved back.
struct Local_frame : Local_coordinates
{
  using Local_coordinates::to_local;

  std::vector<Eigen::Vector3d> to_local(const std::vector<Eigen::Vector3d>& points) const
  {
    std::vector<Eigen::Vector3d> result(points.size());
    std::transform(points.begin(), points.end(), result.begin(), [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(p - center); });
    return result;
  }

  Isp_settings to_local(Isp_settings settings) const
  {
    if(settings.beyond_band)
      settings.beyond_band = [band = settings.beyond_band, c = center](const Eigen::Vector3d& p) { return band(p + c); };
    settings.center = Eigen::Vector3d::Zero();
    return settings;
  }

  std::function<bool(const Dplane&)> to_local(const std::function<bool(const Dplane&)>& abandon) const
  {
    if(!abandon) return abandon;
    return [abandon, frame = *this](const Dplane& p) { return abandon(frame.to_input(p)); };
  }
};

// A matcher of the input's coordinates queried in local ones (it keeps the input's hints).
template <typename Matcher>
class Local_matcher
{
public:
  static constexpr bool has_normals = Matcher::has_normals;
  static constexpr bool matches_on_triangles = Matcher::matches_on_triangles;
  typedef typename Matcher::Hint Hint;

  Local_matcher(const Matcher& matcher, const Eigen::Vector3d& center) : matcher_(matcher), center_(center) {}

  Match closest(const Eigen::Vector3d& p, Hint& hint) const
  {
    Match match = matcher_.closest(p + center_, hint);
    match.first -= center_;
    return match;
  }

private:
  const Matcher& matcher_;
  Eigen::Vector3d center_;
};

} // namespace isp

// ISP from `plane`, in coordinates centred on the shape (the samples, the plane and the matches
// all in them): the coarse phase, then the fine phase (see Isp_phase). With a `walk_matcher`
// (approximate and cheaper matches), both phases walk with it, and a few plain steps with the
// exact `matcher` end the fine phase (`Isp_phase::COARSE` then uses only the walk matcher).
template <typename Matcher, typename Walk_matcher = Matcher>
Isp_result iterative_symmetric_points_from_center(const std::vector<Eigen::Vector3d>& samples, const Dplane& plane,
                                                  const Matcher& matcher, const Isp_settings& settings,
                                                  Isp_phase phases, const std::function<bool(const Dplane&)>& abandon,
                                                  const Walk_matcher* walk_matcher)
{
  const bool walks = walk_matcher != nullptr;
  // When the walk's matches are hints of the exact search (Closest_triangle_field), the exact
  // searches that end the walk start from them: most are then one test of a leaf.
  constexpr bool shared_hints = std::is_same<typename Matcher::Hint, typename Walk_matcher::Hint>::value;
  std::vector<typename Matcher::Hint> hints(samples.size());
  std::vector<typename Walk_matcher::Hint> own_walk_hints(shared_hints || !walks ? 0 : samples.size());
  auto& walk_hints = [&]() -> auto& {
    if constexpr(shared_hints) return hints;
    else return own_walk_hints;
  }();
  std::vector<Eigen::Vector3d> coarse_samples(samples.begin(),
                                              samples.begin() + std::ptrdiff_t(samples.size() / coarse_sample_stride));
  if(coarse_samples.size() < min_coarse_samples) coarse_samples.clear();
  Isp_result fine{plane, 0., false, 0};
  if(phases != Isp_phase::FINE && !coarse_samples.empty()) {
    const Isp_result coarse = walks ? isp::coarse_phase(coarse_samples, plane, *walk_matcher, settings, walk_hints, abandon)
                                    : isp::coarse_phase(coarse_samples, plane, matcher, settings, hints, abandon);
    if(phases == Isp_phase::COARSE) return coarse;
    // Not settled: the fine phase goes on from there all the same (a user's rough plane).
    fine.plane = coarse.plane;
    fine.iterations = coarse.iterations;
  }
  if(!walks) {
    isp::climb(samples, fine.plane, matcher, settings, hints, abandon, fine);
    return fine;
  }
  const double width =
    isp::climb_from_coarse_samples(samples, coarse_samples, fine.plane, *walk_matcher, settings, walk_hints, abandon, fine);
  if(abandon && abandon(fine.plane)) return fine;
  // The walk ends with exact matches: on an exact symmetry, a few Gauss-Newton steps from the top
  // of the walk reach the exact optimum; on an approximate one, whose ridge is flat (steps would
  // creep along it), the top of the walk stays, and its support is measured exactly.
  isp::polish(samples, matcher, settings, width, isp_sums(samples, fine.plane, matcher, settings, width, hints), hints,
              width < 1. ? exact_polish_steps : 0, fine);
  return fine;
}

// The supported fraction of the shape that the reflection in `plane` maps onto it (weights at
// sigma, exact matches).
template <typename Matcher>
double measured_support(const std::vector<Eigen::Vector3d>& samples, const Dplane& plane, const Matcher& matcher,
                        const Isp_settings& settings)
{
  std::vector<typename Matcher::Hint> hints(samples.size());
  return isp_sums(samples, plane, matcher, settings, 1., hints).support / double(samples.size());
}

// ISP from `plane` (see iterative_symmetric_points_from_center()), in the input's coordinates:
// the fit runs in coordinates relative to settings.center, and its plane comes back in the input's.
// On a flat surface (settings.border) an in-plane mirror ends on its border (border_curve.h), its
// support measured there; the fine phase alone fits it on the border only: near an exact mirror
// the inside maps onto the inside whichever way it turns, and the walk, pulled only by the few
// samples mapped beyond the border, may creep away from it (an image of exact planes of a flat
// octagon, 8 degrees).
template <typename Matcher, typename Walk_matcher = Matcher>
Isp_result iterative_symmetric_points(const std::vector<Eigen::Vector3d>& samples, const Dplane& plane,
                                      const Matcher& matcher, const Isp_settings& settings,
                                      Isp_phase phases = Isp_phase::BOTH,
                                      const std::function<bool(const Dplane&)>& abandon = {},
                                      const Walk_matcher* walk_matcher = nullptr)
{
  const bool on_border = settings.border != nullptr && phases != Isp_phase::COARSE;
  auto fitted_on_border = [&](const Dplane& start) {
    const Dplane fitted = mirror_refined_on_border(*settings.border, start, settings.sigma, settings.radius);
    return Isp_result{fitted, measured_support(samples, fitted, matcher, settings), true, 0};
  };
  if(on_border && phases == Isp_phase::FINE && is_in_plane_mirror(*settings.border, plane)) return fitted_on_border(plane);
  const isp::Local_frame frame{{settings.center}};
  const isp::Local_matcher<Matcher> local_matcher(matcher, frame.center);
  std::optional<isp::Local_matcher<Walk_matcher>> local_walk_matcher;
  if(walk_matcher != nullptr) local_walk_matcher.emplace(*walk_matcher, frame.center);
  Isp_result result = iterative_symmetric_points_from_center(
    frame.to_local(samples), frame.to_local(plane), local_matcher, frame.to_local(settings), phases,
    frame.to_local(abandon), local_walk_matcher ? &*local_walk_matcher : nullptr);
  result.plane = frame.to_input(result.plane);
  if(on_border && is_in_plane_mirror(*settings.border, result.plane)) {
    const unsigned iterations = result.iterations;
    result = fitted_on_border(result.plane);
    result.iterations = iterations;
  }
  return result;
}

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool degenerate_fit(const Eigen::Matrix3d& jtj, double radius)
{
  const Eigen::DiagonalMatrix<double, 3> scale(1. / radius, 1. / radius, 1.); // the turns carry a length
  const Eigen::Matrix3d scaled = scale * jtj * scale;
  const Eigen::Vector3d eigenvalues = symmetric_eigen(scaled).values;
  return eigenvalues[0] <= degenerate_fit_ratio * eigenvalues[2];
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE double isp::step_length(const Dplane& a, const Dplane& b, double radius)
{
  return (a.normal - b.normal).norm() + std::abs(a.offset - b.offset) / radius;
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_ITERATIVE_SYMMETRIC_POINTS_H
