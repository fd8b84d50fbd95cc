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
// (Gauss-Newton: few iterations on symmetric shapes); on a point set, with no normals, it
// minimises the distance to the match itself (closed form). On a mesh, ISP walks with the
// approximate matches of a Closest_triangle_field and ends with exact searches in the AABB tree.

#include <CGAL/Symmetry_transform/internal/common/nearest_point.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/common/shape_input.h>
#include <CGAL/Symmetry_transform/internal/common/triangle_tree.h>


#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <functional>
#include <type_traits>
#include <stdexcept>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// Closest points on a triangle soup, with the normal of the triangle they lie on.
class Triangle_matcher
{
  typedef Triangle_tree Tree;

public:
  static constexpr bool has_normals = true;

  explicit Triangle_matcher(const std::vector<Dtriangle>& triangles)
    : triangles_(triangles), tree_(triangles.begin(), triangles.end())
  {
    tree_.build();
    tree_.accelerate_distance_queries();
    tree_.closest_point(CGAL::ORIGIN); // builds the search structure before threads share the tree
  }

  // A previous match, on the surface and with its triangle: the search for a nearby query
  // starts from it.
  typedef typename Tree::Point_and_primitive_id Hint;

  // Closest point to p and the unit normal there; `hint` is used if `use_hint`, and updated.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> closest(const Eigen::Vector3d& p, Hint& hint, bool use_hint) const
  {
    const Dpoint query(p.x(), p.y(), p.z());
    hint = use_hint ? tree_.closest_point_and_primitive(query, hint) : tree_.closest_point_and_primitive(query);
    const auto& match = hint;
    const Dtriangle& t = *match.second;
    Eigen::Vector3d normal = to_eigen(CGAL::ORIGIN + CGAL::cross_product(t[1] - t[0], t[2] - t[0]));
    return {to_eigen(match.first), normal.normalized()};
  }

private:
  const std::vector<Dtriangle>& triangles_;
  Tree tree_;
};

// Approximate closest points on a triangle soup, about ten times cheaper than the exact search:
// the nearest of the triangles closest to the eight voxel centres around the query, read from
// a grid filled with the Gaussian distance transform. Within the band of the transform the
// distance is close to the true one (on a smooth surface the true closest triangle is a
// neighbour of these) and the normal that of the surface there; outside, the exact matcher
// answers. ISP walks with it and ends with exact searches.
class Closest_triangle_field
{
public:
  static constexpr bool has_normals = true;
  // The match found, a hint for the exact search of the same point.
  typedef Triangle_matcher::Hint Hint;

  // `closest_triangles`: per voxel (index (k n + j) n + i) the triangle closest to its centre,
  // or -1; `origin`: the corner of the grid, `voxel_size` and `resolution` its geometry.
  Closest_triangle_field(const std::vector<Dtriangle>& triangles, const Triangle_matcher& exact,
                         std::vector<std::int32_t> closest_triangles, const std::array<double, 3>& origin,
                         double voxel_size, std::size_t resolution)
    : triangles_(triangles), exact_(exact), closest_triangles_(std::move(closest_triangles)), origin_(origin),
      voxel_size_(voxel_size), resolution_(long(resolution))
  {
    corners_.reserve(triangles.size());
    normals_.reserve(triangles.size());
    for(const Dtriangle& t : triangles) {
      corners_.push_back({to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2])});
      normals_.push_back(to_eigen(CGAL::ORIGIN + CGAL::cross_product(t[1] - t[0], t[2] - t[0])).normalized());
    }
  }

  std::pair<Eigen::Vector3d, Eigen::Vector3d> closest(const Eigen::Vector3d& p, Hint& hint, bool) const
  {
    const auto [on_triangle, t] = nearest_in_cell(p);
    if(t < 0) return exact_.closest(p, hint, false);
    hint = {Dpoint(on_triangle.x(), on_triangle.y(), on_triangle.z()), triangles_.begin() + t};
    return {on_triangle, normals_[std::size_t(t)]};
  }

  // The point nearest to p on the closest triangles of the 8 voxels around p, and its triangle;
  // triangle -1 if none of these voxels lies in the band.
  std::pair<Eigen::Vector3d, std::int32_t> nearest_in_cell(const Eigen::Vector3d& p) const
  {
    // The cell of voxel centres around p.
    std::array<long, 3> corner;
    for(int a = 0; a < 3; ++a)
      corner[a] = (std::min)((std::max)(long(std::floor((p[a] - origin_[a]) / voxel_size_ - 0.5)), 0L), resolution_ - 2);
    std::array<std::int32_t, 8> seen;
    std::size_t count = 0;
    double best = std::numeric_limits<double>::infinity();
    std::pair<Eigen::Vector3d, std::int32_t> nearest(Eigen::Vector3d::Zero(), -1);
    for(long c = 0; c < 8; ++c) {
      const std::int32_t t = closest_triangles_[std::size_t(((corner[2] + (c >> 2)) * resolution_ + corner[1] + ((c >> 1) & 1)) * resolution_ +
                                                            corner[0] + (c & 1))];
      if(t < 0 || std::find(seen.begin(), seen.begin() + count, t) != seen.begin() + count) continue;
      seen[count++] = t;
      const std::array<Eigen::Vector3d, 3>& v = corners_[std::size_t(t)];
      const Eigen::Vector3d on_triangle = closest_point_on_triangle(p, v[0], v[1], v[2]);
      const double d2 = (p - on_triangle).squaredNorm();
      if(d2 < best) {
        best = d2;
        nearest = {on_triangle, t};
      }
    }
    return nearest;
  }

private:
  const std::vector<Dtriangle>& triangles_;
  const Triangle_matcher& exact_;
  std::vector<std::array<Eigen::Vector3d, 3>> corners_;
  std::vector<Eigen::Vector3d> normals_;
  std::vector<std::int32_t> closest_triangles_;
  std::array<double, 3> origin_;
  double voxel_size_;
  long resolution_;
};

// Closest points of a point set (no normals).
class Point_matcher
{
public:
  static constexpr bool has_normals = false;

  explicit Point_matcher(const std::vector<Dpoint>& points) : nearest_(points) {}

  struct Hint {};

  std::pair<Eigen::Vector3d, Eigen::Vector3d> closest(const Eigen::Vector3d& p, Hint&, bool) const
  {
    return {to_eigen(nearest_.point(nearest_(p).index)), Eigen::Vector3d::Zero()};
  }

private:
  Nearest_point nearest_;
};

struct Isp_settings
{
  double sigma = 0.;            // width of the Gaussian weights of the support; the phases
                                // of ISP weigh with multiples of it
  double radius = 0.;           // size of the shape, for the convergence test
  unsigned max_iterations = 20; // at most this many re-fits
  unsigned threads = 1;
  // Whether a point is farther than 3 sigma from the shape (the GEDT is zero there): its
  // weight is zero at the widths ISP uses (sigma and narrower), and the closest-point search, the
  // costliest step, is skipped.
  std::function<bool(const Eigen::Vector3d&)> beyond_band;
};

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
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();  // point-to-point (point set): 4 C_m - C_u
  Eigen::Vector3d midpoint_sum = Eigen::Vector3d::Zero();
  double weight = 0.;          // of the fit
  double support = 0.;         // weights at sigma itself
  double narrower_weight = 0.; // weights at half the width, w^4, of the same matches

  void add(const Isp_sums& o)
  {
    support += o.support;
    narrower_weight += o.narrower_weight;
    jtj += o.jtj;
    jtr += o.jtr;
    moments += o.moments;
    midpoint_sum += o.midpoint_sum;
    weight += o.weight;
  }
};

// Matches kept from one iteration to the next: the searches for nearby queries start there.
template <typename Hint>
struct Match_hints
{
  explicit Match_hints(std::size_t n) : hints(n), has_hint(n, 0) {}
  std::vector<Hint> hints;
  std::vector<char> has_hint;
};

// The sums of the fit with weights of width `width` sigma.
template <typename Matcher>
Isp_sums isp_sums(const std::vector<Eigen::Vector3d>& samples, const Dplane& plane, const Matcher& matcher,
                  const Isp_settings& settings, double width, Match_hints<typename Matcher::Hint>& match_hints)
{
  std::vector<typename Matcher::Hint>& hints = match_hints.hints;
  std::vector<char>& has_hint = match_hints.has_hint;
  const double sigma = width * settings.sigma;
  // Tangent basis of the normal: the Gauss-Newton unknowns are (rotation along t1, t2, offset).
  const Eigen::Vector3d& n = plane.normal;
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  // Adds sample i to the sums s; `previous` is the last sample of the same thread with a match.
  const std::size_t none = samples.size();
  auto add_sample = [&](std::size_t i, Isp_sums& s, std::size_t& previous) {
    const Eigen::Vector3d& p = samples[i];
    const Eigen::Vector3d image = plane.reflect(p);
    if(settings.beyond_band && settings.beyond_band(image)) return;
    // No match of its own yet: that of the previous sample, close by, is a good start.
    if(!has_hint[i] && previous != none) hints[i] = hints[previous];
    const auto match = matcher.closest(image, hints[i], has_hint[i] != 0 || previous != none);
    has_hint[i] = 1;
    previous = i;
    const double d2 = (image - match.first).squaredNorm();
    s.support += std::exp(-d2 / (2. * settings.sigma * settings.sigma));
    const double w = std::exp(-d2 / (2. * sigma * sigma));
    if(w < 1e-12) return;
    s.weight += w;
    s.narrower_weight += (w * w) * (w * w);
    if(Matcher::has_normals) {
      const Eigen::Vector3d& nu = match.second;
      const double height = n.dot(p) - plane.offset;
      // d(image)/d(normal) . delta = -2 ((delta . p) n + height delta); d(image)/d(offset) = 2 n
      const Eigen::Vector3d jacobian(-2. * (t1.dot(p) * nu.dot(n) + height * nu.dot(t1)),
                                     -2. * (t2.dot(p) * nu.dot(n) + height * nu.dot(t2)), 2. * nu.dot(n));
      const double residual = nu.dot(image - match.first);
      s.jtj += w * jacobian * jacobian.transpose();
      s.jtr += w * residual * jacobian;
    } else {
      const Eigen::Vector3d m = 0.5 * (p + match.first), u = p - match.first;
      s.moments += w * (4. * m * m.transpose() - u * u.transpose());
      s.midpoint_sum += w * m;
    }
  };
  // The samples follow a Hilbert curve: contiguous slices would be regions of the shape, some
  // mapped far from the surface (costly searches) and some onto it. Each thread takes every
  // threads-th chunk instead, a fixed share, so that sums are reproducible.
  constexpr std::size_t chunk = 64;
  const std::size_t chunks = (samples.size() + chunk - 1) / chunk;
  const unsigned threads = unsigned((std::max)(std::size_t(1), (std::min)(std::size_t(settings.threads), chunks)));
  std::vector<Isp_sums> partial(threads);
  parallel_for(threads, threads, [&](unsigned thread, std::size_t, std::size_t) {
    std::size_t previous = none;
    for(std::size_t c = thread; c < chunks; c += threads) {
      for(std::size_t i = c * chunk; i < (std::min)((c + 1) * chunk, samples.size()); ++i)
        add_sample(i, partial[thread], previous);
    }
  });
  Isp_sums total;
  for(const Isp_sums& s : partial) total.add(s);
  return total;
}

// One fit: the plane that best maps the samples onto their matches, from the current one,
// its step multiplied by `step_factor` (over-relaxation).
template <typename Matcher>
bool refit(const Isp_sums& s, Dplane& plane, double step_factor = 1.)
{
  if(s.weight <= 0.) return false;
  if(Matcher::has_normals) {
    const Eigen::Vector3d delta = step_factor * s.jtj.ldlt().solve(-s.jtr);
    if(!delta.allFinite()) return false;
    const Eigen::Vector3d t1 = plane.normal.unitOrthogonal(), t2 = plane.normal.cross(t1);
    plane.normal = (plane.normal + delta[0] * t1 + delta[1] * t2).normalized();
    plane.offset += delta[2];
  } else {
    // Minimise sum w (4 (n.m - d)^2 - (n.u)^2): d = n.mean(m), n the eigenvector of the
    // smallest eigenvalue of 4 C_m - C_u (moments centred on the weighted mean midpoint).
    const Eigen::Vector3d mean = s.midpoint_sum / s.weight;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(s.moments - 4. * s.weight * mean * mean.transpose());
    Eigen::Vector3d normal = solver.eigenvectors().col(0);
    if(normal.dot(plane.normal) < 0.) normal = -normal;
    const double offset = normal.dot(mean);
    const Eigen::Vector3d relaxed = plane.normal + step_factor * (normal - plane.normal);
    if(!(relaxed.norm() > 0.)) return false;
    plane.normal = relaxed.normalized();
    plane.offset += step_factor * (offset - plane.offset);
  }
  return true;
}

// ISP from `plane`, in two phases.
//
// The coarse phase uses an eighth of the samples, until the plane moves by less than 5e-3
// (within about a bin, 2e-2, of its limit); a start that has not settled after 12 iterations is
// not near a maximum. Its weights are those of the fine phase: wider ones would widen the reach
// of ISP, but let a big part of a composite shape pull the plane of a small one away from it,
// and the starts (bins of the transform, rough planes) are within a few sigma of their limit.
//
// The fine phase uses all samples, and stops when the mean weight stops growing: on a perfect
// symmetry it tends to 1; on an approximate one it reaches a plateau. There, plain ISP creeps
// along the flat ridge of the symmetry measure by steps of a fraction of a degree, all in the
// same direction (bull.off: about 0.1 degree per step, over several degrees). The steps are
// therefore over-relaxed (as for EM and ICP): doubled, up to 32 times, after each step that
// raised the mean weight; a step that did not is not taken, and the next one is half the last
// that did. The mean weight never decreases. Then, on an exact symmetry, the weights narrow (see
// iterative_symmetric_points()).
//
// `abandon` may stop either phase early (no convergence).
enum class Isp_phase { COARSE, FINE, BOTH };

namespace isp {

template <typename Matcher>
Isp_result coarse_phase(const std::vector<Eigen::Vector3d>& samples, Dplane plane, const Matcher& matcher,
                        const Isp_settings& settings, Match_hints<typename Matcher::Hint>& hints,
                        const std::function<bool(const Dplane&)>& abandon)
{
  constexpr unsigned max_iterations = 12;
  for(unsigned iteration = 0; iteration < max_iterations; ++iteration) {
    const Isp_sums s = isp_sums(samples, plane, matcher, settings, 1., hints);
    const Dplane previous = plane;
    if(!refit<Matcher>(s, plane)) return {plane, 0., false, iteration + 1};
    const double step = (plane.normal - previous.normal).norm() + std::abs(plane.offset - previous.offset) / settings.radius;
    if(step < 5e-3) return {plane, s.support / double(samples.size()), true, iteration + 1};
    if(abandon && abandon(plane)) return {plane, 0., false, iteration + 1};
  }
  return {plane, 0., false, max_iterations};
}

// Over-relaxed ISP with weights of width `width` sigma, from result.plane whose sums are
// `start`, until a plain step after an overshoot gains less than `min_gain` (relative) in mean
// weight, or a plain step gains nothing, or `max_iterations`; `result` receives the best plane,
// its support (at sigma) and the iterations. Returns the sums of the best plane.
template <typename Matcher>
Isp_sums relaxed_ascent(const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher,
                        const Isp_settings& settings, double width, const Isp_sums& start, Match_hints<typename Matcher::Hint>& hints,
                        const std::function<bool(const Dplane&)>& abandon, double min_gain, Isp_result& result)
{
  constexpr double max_step_factor = 32.;
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
      result.converged = overshot && step_factor == 1. && s.weight < best.weight * (1. + min_gain);
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
// at most `max_steps`, and none after a step below 1e-7 (a converged exact symmetry). It ends a
// walk made with approximate matches.
template <typename Matcher>
Isp_sums polish(const std::vector<Eigen::Vector3d>& samples, const Matcher& matcher, const Isp_settings& settings,
                double width, const Isp_sums& start, Match_hints<typename Matcher::Hint>& hints, unsigned max_steps, Isp_result& result)
{
  Isp_sums best = start;
  result.support = best.support / double(samples.size());
  for(unsigned step = 0; step < max_steps; ++step) {
    Dplane trial = result.plane;
    if(!refit<Matcher>(best, trial)) break;
    const Isp_sums s = isp_sums(samples, trial, matcher, settings, width, hints);
    ++result.iterations;
    if(!(s.weight > best.weight)) break;
    const double moved = (trial.normal - result.plane.normal).norm() + std::abs(trial.offset - result.plane.offset) / settings.radius;
    result.plane = trial;
    result.support = s.support / double(samples.size());
    best = s;
    if(moved < 1e-7) break;
  }
  return best;
}

} // namespace isp

// ISP from `plane`: the coarse phase, then the fine phase (see above). With a `walk_matcher`
// (approximate and cheaper matches), both phases walk with it, and a few plain steps with the
// exact `matcher` end the fine phase (`Isp_phase::COARSE` then uses only the walk matcher).
template <typename Matcher, typename Walk_matcher = Matcher>
Isp_result iterative_symmetric_points(const std::vector<Eigen::Vector3d>& samples, const Dplane& plane,
                                      const Matcher& matcher, const Isp_settings& settings,
                                      Isp_phase phases = Isp_phase::BOTH,
                                      const std::function<bool(const Dplane&)>& abandon = {},
                                      const Walk_matcher* walk_matcher = nullptr)
{
  const bool walks = walk_matcher != nullptr;
  // When the walk's matches are hints of the exact search (Closest_triangle_field), the exact
  // searches that end the walk start from them: most are then one test of a leaf.
  constexpr bool shared_hints = std::is_same<typename Matcher::Hint, typename Walk_matcher::Hint>::value;
  Match_hints<typename Matcher::Hint> hints(samples.size());
  Match_hints<typename Walk_matcher::Hint> own_walk_hints(shared_hints || !walks ? 0 : samples.size());
  auto& walk_hints = [&]() -> auto& {
    if constexpr(shared_hints) return hints;
    else return own_walk_hints;
  }();
  std::vector<Eigen::Vector3d> coarse_samples(samples.begin(), samples.begin() + std::ptrdiff_t(samples.size() / 8));
  if(coarse_samples.size() < 100) coarse_samples.clear(); // too few to locate anything
  Dplane start = plane;
  unsigned coarse_iterations = 0;
  if(phases != Isp_phase::FINE && !coarse_samples.empty()) {
    const Isp_result coarse = walks ? isp::coarse_phase(coarse_samples, plane, *walk_matcher, settings, walk_hints, abandon)
                                    : isp::coarse_phase(coarse_samples, plane, matcher, settings, hints, abandon);
    if(phases == Isp_phase::COARSE) return coarse;
    // Not settled: the fine phase goes on from there all the same (a user's rough plane).
    start = coarse.plane;
    coarse_iterations = coarse.iterations;
  }
  // A gain below 1e-3 after an overshoot: the top of a plateau, or, on a perfect symmetry, a
  // plane within a few hundredths of a degree after the quadratic convergence of Gauss-Newton.
  constexpr double min_gain = 1e-3;
  Isp_result fine{start, 0., false, coarse_iterations};
  // The fine phase with matcher m; returns the width of its last weights. Narrower weights
  // sharpen an exact symmetry, whose matches are much closer than sigma: parts of the shape that
  // it does not map, matched a fraction of sigma away, lose their say (a local symmetry beside
  // another part). On an approximate symmetry, whose mean weight would drop, they would fit the
  // plane to the few samples that match best: the plane stays.
  auto climb = [&](const auto& m, auto& m_hints) {
    Isp_sums last = isp::relaxed_ascent(samples, m, settings, 1., isp_sums(samples, start, m, settings, 1., m_hints), m_hints,
                                        abandon, min_gain, fine);
    double width = 1.;
    for(const double narrower : {0.5, 0.25}) {
      if(last.narrower_weight < 0.85 * last.weight || (abandon && abandon(fine.plane))) break;
      width = narrower;
      last = isp::relaxed_ascent(samples, m, settings, width, isp_sums(samples, fine.plane, m, settings, width, m_hints),
                                 m_hints, abandon, min_gain, fine);
    }
    return width;
  };
  if(!walks) {
    climb(matcher, hints);
    return fine;
  }
  const double width = climb(*walk_matcher, walk_hints);
  if(abandon && abandon(fine.plane)) return fine;
  // The walk ends with exact matches: on an exact symmetry, a few Gauss-Newton steps from the top
  // of the walk reach the exact optimum; on an approximate one, whose ridge is flat (steps would
  // creep along it), the top of the walk stays, and its support is measured exactly.
  isp::polish(samples, matcher, settings, width, isp_sums(samples, fine.plane, matcher, settings, width, hints), hints,
              width < 1. ? 4 : 0, fine);
  return fine;
}

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_ITERATIVE_SYMMETRIC_POINTS_H
