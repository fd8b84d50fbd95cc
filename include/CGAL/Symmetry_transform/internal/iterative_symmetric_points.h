// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ITERATIVE_SYMMETRIC_POINTS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ITERATIVE_SYMMETRIC_POINTS_H

// Iterative Symmetric Points (thesis, section 3.3): samples of the shape are reflected through
// the current plane and matched to their closest points on the shape; the plane is then
// re-fitted to the matches by weighted least squares, the weights exp(-d^2 / 2 sigma^2) of the
// match distances d being those of the Gaussian distance transform. On a mesh the fit
// minimises the distance of each reflected sample to the tangent plane at its match
// (Gauss-Newton: few iterations on symmetric shapes); on a point set, with no normals, it
// minimises the distance to the match itself (closed form).

#include <CGAL/Symmetry_transform/internal/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/shape_input.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <Eigen/Dense>

#include <array>
#include <functional>
#include <stdexcept>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Symmetry_transform {
namespace internal {

// The plane {x : normal . x = offset}, normal of unit length.
struct Dplane
{
  Eigen::Vector3d normal;
  double offset;

  Eigen::Vector3d reflect(const Eigen::Vector3d& p) const { return p - 2. * (normal.dot(p) - offset) * normal; }
};

inline Eigen::Vector3d to_eigen(const Dpoint& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

// A plane of any kernel as a Dplane; throws if it is degenerate.
template <typename Plane>
Dplane to_dplane(const Plane& plane)
{
  Eigen::Vector3d n(CGAL::to_double(plane.a()), CGAL::to_double(plane.b()), CGAL::to_double(plane.c()));
  const double length = n.norm();
  if(!(length > 0.) || !std::isfinite(length))
    throw std::invalid_argument("Symmetry_transform: degenerate plane");
  return {n / length, -CGAL::to_double(plane.d()) / length};
}

// Closest points on a triangle soup, with the normal of the triangle they lie on.
class Triangle_matcher
{
  typedef CGAL::AABB_triangle_primitive<Dkernel, std::vector<Dtriangle>::const_iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Dkernel, Primitive>> Tree;

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

// Closest points of a point set (no normals).
class Point_matcher
{
  typedef CGAL::Search_traits_3<Dkernel> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;

public:
  static constexpr bool has_normals = false;

  explicit Point_matcher(const std::vector<Dpoint>& points) : tree_(points.begin(), points.end()) { tree_.build(); }

  struct Hint {};

  std::pair<Eigen::Vector3d, Eigen::Vector3d> closest(const Eigen::Vector3d& p, Hint&, bool) const
  {
    Search search(tree_, Dpoint(p.x(), p.y(), p.z()), 1);
    return {to_eigen(search.begin()->first), Eigen::Vector3d::Zero()};
  }

private:
  typename Search::Tree tree_;
};

struct Isp_settings
{
  double sigma = 0.;            // width of the Gaussian weights
  double radius = 0.;           // size of the shape, for the convergence test
  unsigned max_iterations = 20; // at most this many re-fits
  unsigned threads = 1;
  bool sigma_is_base = true; // false while the coarse phase widens the weights
  // Whether a point is farther than 3 sigma from the shape (the GEDT is zero there): its
  // weight is zero at width sigma, and the closest-point search, the costliest step, is skipped.
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
  double weight = 0.;

  void add(const Isp_sums& o)
  {
    jtj += o.jtj;
    jtr += o.jtr;
    moments += o.moments;
    midpoint_sum += o.midpoint_sum;
    weight += o.weight;
  }
};

template <typename Matcher>
Isp_sums isp_sums(const std::vector<Eigen::Vector3d>& samples, const Dplane& plane, const Matcher& matcher,
                  const Isp_settings& settings, std::vector<typename Matcher::Hint>& hints,
                  std::vector<char>& has_hint)
{
  // Tangent basis of the normal: the Gauss-Newton unknowns are (rotation along t1, t2, offset).
  const Eigen::Vector3d& n = plane.normal;
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  std::vector<Isp_sums> partial(settings.threads);
  parallel_for(samples.size(), settings.threads, [&](unsigned thread, std::size_t begin, std::size_t end) {
    Isp_sums& s = partial[thread];
    for(std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d& p = samples[i];
      const Eigen::Vector3d image = plane.reflect(p);
      if(settings.sigma_is_base && settings.beyond_band && settings.beyond_band(image)) continue;
      const auto match = matcher.closest(image, hints[i], has_hint[i] != 0);
      has_hint[i] = 1;
      const double d2 = (image - match.first).squaredNorm();
      const double w = std::exp(-d2 / (2. * settings.sigma * settings.sigma));
      if(w < 1e-12) continue;
      s.weight += w;
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
    }
  });
  Isp_sums total;
  for(const Isp_sums& s : partial) total.add(s);
  return total;
}

// One fit: the plane that best maps the samples onto their matches, from the current one.
template <typename Matcher>
bool refit(const Isp_sums& s, Dplane& plane)
{
  if(s.weight <= 0.) return false;
  if(Matcher::has_normals) {
    const Eigen::Vector3d delta = s.jtj.ldlt().solve(-s.jtr);
    if(!delta.allFinite()) return false;
    const Eigen::Vector3d t1 = plane.normal.unitOrthogonal(), t2 = plane.normal.cross(t1);
    plane.normal = (plane.normal + delta[0] * t1 + delta[1] * t2).normalized();
    plane.offset += delta[2];
  } else {
    // Minimise sum w (4 (n.m - d)^2 - (n.u)^2): d = n.mean(m), n the eigenvector of the
    // smallest eigenvalue of 4 C_m - C_u (moments centred on the weighted mean midpoint).
    const Eigen::Vector3d mean = s.midpoint_sum / s.weight;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(s.moments - 4. * s.weight * mean * mean.transpose());
    const Eigen::Vector3d normal = solver.eigenvectors().col(0);
    plane.normal = normal.dot(plane.normal) < 0. ? Eigen::Vector3d(-normal) : normal;
    plane.offset = plane.normal.dot(mean);
  }
  return true;
}

// ISP from `plane`, in two phases; `abandon` may stop the fine phase early (no convergence). The coarse phase, far from the optimum, uses an eighth of
// the samples and wider weights (4 sigma, halved at each iteration down to sigma), so that
// matches a few sigma away pull the plane too, until the plane moves by less than 5e-3. The
// fine phase uses all samples and sigma, until the support stops growing: on a perfect
// symmetry it tends to 1; on an approximate one it reaches a plateau where matches merely
// switch between triangles.
enum class Isp_phase { COARSE, FINE, BOTH };

template <typename Matcher>
Isp_result iterative_symmetric_points(const std::vector<Eigen::Vector3d>& all_samples, Dplane plane,
                                      const Matcher& matcher, const Isp_settings& settings,
                                      Isp_phase phases = Isp_phase::BOTH,
                                      const std::function<bool(const Dplane&)>& abandon = {})
{
  const std::vector<Eigen::Vector3d> coarse_samples(all_samples.begin(),
                                                    all_samples.begin() + std::ptrdiff_t(all_samples.size() / 8));
  bool coarse = phases != Isp_phase::FINE && coarse_samples.size() >= 100;
  Isp_result best{plane, -1., false};
  std::vector<typename Matcher::Hint> hints(all_samples.size());
  std::vector<char> has_hint(all_samples.size(), 0);
  double width = coarse ? 4. : 1.;
  // Widths 4, 2, 1 then a few more: a candidate that has not settled by then is not a maximum.
  constexpr unsigned coarse_iterations = 12;
  for(unsigned iteration = 0; iteration < settings.max_iterations; ++iteration) {
    if(coarse && iteration == coarse_iterations) return {plane, 0., false, iteration};
    const std::vector<Eigen::Vector3d>& samples = coarse ? coarse_samples : all_samples;
    Isp_settings current = settings;
    current.sigma = settings.sigma * width;
    current.sigma_is_base = width == 1.;
    const Isp_sums s = isp_sums(samples, plane, matcher, current, hints, has_hint);
    best.iterations = iteration + 1;
    const double support = s.weight / double(samples.size());
    if(!coarse) {
      // A gain below 1e-6 is noise: on a perfect symmetry the plane is then within 1e-3 sigma.
      if(support <= best.support * (1. + 1e-6)) {
        best.converged = true;
        break;
      }
      best.plane = plane;
      best.support = support;
    }
    const Dplane previous = plane;
    if(!refit<Matcher>(s, plane)) break;
    if(!coarse && abandon && abandon(plane)) return {plane, support, false, iteration + 1};
    const double step = (plane.normal - previous.normal).norm() + std::abs(plane.offset - previous.offset) / settings.radius;
    width = (std::max)(1., width / 2.);
    // Steps shrink by about 0.8 per iteration on approximate symmetries: below 5e-3 the plane
    // is within about a bin (2e-2) of its limit, which is all the coarse phase is for.
    if(coarse && width == 1. && step < 5e-3) {
      if(phases == Isp_phase::COARSE) return {plane, support, true, iteration + 1};
      coarse = false;
    }
  }
  if(best.support < 0.) best.support = 0.;
  return best;
}

} // namespace internal
} // namespace Symmetry_transform
} // namespace CGAL

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ITERATIVE_SYMMETRIC_POINTS_H
