// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_JOINT_FRAME_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_JOINT_FRAME_H

// The joint choice of the three planes of a symmetry frame (the thesis's suggestion, section
// 4.1.4: "find the intersection of three orthogonal planes that contain the most symmetry"):
// every principal plane is tried as one of the three, completed by the principal planes nearly
// perpendicular to it (or, missing, by the strongest ones of the transform), and the triple of
// largest summed symmetry wins; and the centre of symmetry as the weighted least-squares
// intersection of the planes of the frame and of the principal planes nearly parallel to them;
// the axes ordered by strength or by the variance of the mass, the second and third possibly
// from inertia. Rules compared by benchmark/Symmetry_transform/alignment_experiment on partial
// scans (RESULTS.md, "Alignment"); symmetry_frame() keeps the thesis's greedy rule (frame_rules.h)
// by default and, with partial_data(true), takes the axes of partial_data_rule and the centre of
// the three most symmetric orthogonal planes of the whole transform (orthogonal_planes.h).

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/internal/alignment/frame_rules.h>
#include <CGAL/Symmetry_transform/internal/alignment/mass_distribution.h>
#include <CGAL/Symmetry_transform/internal/alignment/orthogonal_planes.h>
#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// How the three planes and the centre are chosen (the benchmark compares the variants).
struct Frame_rule
{
  bool joint = true;                  // the triple of largest summed symmetry, not the greedy choice
  bool support_weighted = false;      // a principal plane weighs its measure times its support
  bool least_squares_center = false;  // the centre from the frame's planes and those parallel to them
  bool accumulate_parallel = false;   // a triple scores every principal plane parallel to one of its planes
  bool order_by_accumulated = false;  // axes ordered by the weight of the principal planes parallel to them
  int variance_order = 0;             // 0: strongest first; 1: largest variance first; 2: planes of
                                      // measures within equal_measures of each other by variance
  double mass_prior = 0.;             // weight of the centre of mass in the least-squares centre
  double pca_below = 0.;              // the second and third axes from the principal axes of the mass
                                      // in the first plane when the second plane weighs less than this
                                      // fraction of the first (0: never)
  bool blend_only_when_weak = false;  // the least-squares centre and the mass prior only with axes from
                                      // inertia; otherwise the intersection of the three planes
};

// The weight of the centre of mass, along each normal, in the centre of partial data (the planes
// weigh their values, 0.5 to 1): from 0.1 to 1 it trades how often the centre of symmetry is the
// closer against how much closer it is; 0.4 is the weight that holds both on the two sets of scans,
// 0.5 falls below 1.5 times on the man-made set (RESULTS.md, "Alignment").
constexpr double partial_data_mass_prior = 0.4;

// A principal plane of at least this measure maps the surface onto itself: its refined offset
// is exact, where the transform's peak is known to a fraction of a bin.
constexpr double exact_symmetry = 0.98;

// The axes of symmetry_frame() with partial_data(true): the three planes chosen jointly, the axes
// ordered by variance, the second and third from inertia within the strongest plane wherever the
// second plane is weaker than the first (the centre: partial_data_center()).
constexpr Frame_rule partial_data_rule{true, false, false, false, false, 1, 0., 1., false};

// Principal planes whose measures differ by at most this are taken as equally strong (variance_order 2).
constexpr double equal_measures = 0.05;

// A principal plane and its weight in the choice.
struct Weighted_plane
{
  Dplane plane;
  double weight;
};

// The transform's value of a plane, 0 beyond its range (a plane farther than R from the centre).
template <typename GT>
double value_of(const Reflective_symmetry_transform<GT>& prst, const Dplane& p)
{
  const Plane_bins& bins = prst.bins();
  const double r = p.offset - p.normal.dot(Eigen::Vector3d(bins.center[0], bins.center[1], bins.center[2]));
  return std::abs(r) < bins.radius ? prst.value(to_plane<GT>(p)) : 0.;
}

template <typename GT>
std::vector<Weighted_plane> weighted_planes(const std::vector<Principal_symmetry<GT>>& symmetries, const Frame_rule& rule)
{
  std::vector<Weighted_plane> planes;
  for(const Principal_symmetry<GT>& s : symmetries)
    planes.push_back({to_dplane(s.plane), rule.support_weighted ? s.symmetry * s.support : s.symmetry});
  return planes;
}

// The strongest principal plane other than `excluded` whose normal is within the tolerance of
// `normal` (cos_tolerance: nearly parallel) or of perpendicular to it (sin_tolerance); -1 if none.
inline int strongest_principal(const std::vector<Weighted_plane>& planes, const Eigen::Vector3d& normal, bool parallel,
                               const std::array<int, 2>& excluded)
{
  const double cos_tolerance = std::cos(center_plane_tolerance_degrees * CGAL_PI / 180.),
               sin_tolerance = std::sin(second_plane_tolerance_degrees * CGAL_PI / 180.);
  int best = -1;
  for(int i = 0; i < int(planes.size()); ++i) {
    if(i == excluded[0] || i == excluded[1]) continue;
    const double c = std::abs(planes[std::size_t(i)].plane.normal.dot(normal));
    if((parallel ? c >= cos_tolerance : c <= sin_tolerance) &&
       (best < 0 || planes[std::size_t(i)].weight > planes[std::size_t(best)].weight))
      best = i;
  }
  return best;
}

// The triple started by principal plane `first` and principal plane `second` (or, with
// second < 0, the transform's strongest plane perpendicular to the first), completed by the
// strongest principal plane along their cross product or the transform's strongest plane of that
// normal; scored by the sum of the weights (a searched plane weighs its value in the transform).
template <typename GT>
std::pair<std::array<Frame_plane, 3>, double> completed_triple(const std::vector<Weighted_plane>& planes, int first,
                                                               int second, const Reflective_symmetry_transform<GT>& prst)
{
  std::array<Frame_plane, 3> triple;
  const Dplane& p1 = planes[std::size_t(first)].plane;
  triple[0] = {p1, first};
  double score = planes[std::size_t(first)].weight;
  if(second >= 0) {
    triple[1] = {planes[std::size_t(second)].plane, second};
    score += planes[std::size_t(second)].weight;
  } else {
    triple[1] = {strongest_plane_perpendicular_to(prst, p1.normal), searched_plane};
    score += value_of(prst, triple[1].plane);
  }
  const Eigen::Vector3d n1 = triple[1].plane.normal;
  const Eigen::Vector3d axis = p1.normal.cross(n1 - n1.dot(p1.normal) * p1.normal).normalized();
  const int third = strongest_principal(planes, axis, true, {first, second});
  if(third >= 0) {
    triple[2] = {planes[std::size_t(third)].plane, third};
    score += planes[std::size_t(third)].weight;
  } else {
    const std::pair<Dplane, double> searched = strongest_plane_of_normal(prst, axis);
    triple[2] = {searched.first, searched_plane};
    score += searched.second;
  }
  return {triple, score};
}

// The three planes in the order of the frame: the principal ones in their order (strongest
// first), the searched ones after them.
inline std::array<Frame_plane, 3> frame_order(std::array<Frame_plane, 3> triple)
{
  std::stable_sort(triple.begin(), triple.end(), [](const Frame_plane& a, const Frame_plane& b) {
    const unsigned ka = unsigned(a.principal), kb = unsigned(b.principal); // searched_plane (-1) last
    return ka < kb;
  });
  return triple;
}

// The weight of the principal planes nearly parallel to each plane of the triple (each counted
// once, for the nearest), plus the value of a searched plane.
template <typename GT>
std::array<double, 3> accumulated_weights(const std::array<Frame_plane, 3>& triple,
                                          const std::vector<Weighted_plane>& planes,
                                          const Reflective_symmetry_transform<GT>& prst)
{
  const double cos_tolerance = std::cos(center_plane_tolerance_degrees * CGAL_PI / 180.);
  std::array<double, 3> weights;
  for(std::size_t k = 0; k < 3; ++k)
    weights[k] = triple[k].principal == searched_plane ? value_of(prst, triple[k].plane) : 0.;
  for(const Weighted_plane& p : planes) {
    std::size_t nearest = 0;
    for(std::size_t k = 1; k < 3; ++k)
      if(std::abs(p.plane.normal.dot(triple[k].plane.normal)) > std::abs(p.plane.normal.dot(triple[nearest].plane.normal)))
        nearest = k;
    if(std::abs(p.plane.normal.dot(triple[nearest].plane.normal)) >= cos_tolerance) weights[nearest] += p.weight;
  }
  return weights;
}

// The triple of largest score over every principal plane as a start and every principal plane
// nearly perpendicular to it (or the searched one when there is none).
template <typename GT>
std::array<Frame_plane, 3> joint_triple(const std::vector<Weighted_plane>& planes,
                                        const Reflective_symmetry_transform<GT>& prst, const Frame_rule& rule)
{
  std::pair<std::array<Frame_plane, 3>, double> best{{}, -1.};
  const auto consider = [&](std::pair<std::array<Frame_plane, 3>, double> candidate) {
    if(rule.accumulate_parallel) {
      const std::array<double, 3> w = accumulated_weights(candidate.first, planes, prst);
      candidate.second = w[0] + w[1] + w[2];
    }
    if(candidate.second > best.second) best = candidate;
  };
  const double sin_tolerance = std::sin(second_plane_tolerance_degrees * CGAL_PI / 180.);
  for(int i = 0; i < int(planes.size()); ++i) {
    bool completed = false;
    for(int j = 0; j < int(planes.size()); ++j)
      if(j != i && std::abs(planes[std::size_t(i)].plane.normal.dot(planes[std::size_t(j)].plane.normal)) <= sin_tolerance) {
        consider(completed_triple(planes, i, j, prst));
        completed = true;
      }
    if(!completed) consider(completed_triple(planes, i, -1, prst));
  }
  if(!rule.order_by_accumulated) return frame_order(best.first);
  const std::array<double, 3> w = accumulated_weights(best.first, planes, prst);
  std::array<std::size_t, 3> order = {0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return w[a] > w[b]; });
  return {best.first[order[0]], best.first[order[1]], best.first[order[2]]};
}

// The point c minimising sum_p w_p (n_p . c - d_p)^2 over the frame's planes (weight: their value
// in the transform) and the principal planes within center_plane_tolerance_degrees of parallel
// to one of them (their weight).
template <typename GT>
Eigen::Vector3d least_squares_center(const std::array<Frame_plane, 3>& frame_planes,
                                     const std::vector<Weighted_plane>& planes,
                                     const Reflective_symmetry_transform<GT>& prst,
                                     const Eigen::Vector3d& mass_center, double mass_prior)
{
  const double cos_tolerance = std::cos(center_plane_tolerance_degrees * CGAL_PI / 180.);
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  // Solved for c - mass_center: offsets far from the origin would cancel in the sums.
  const auto add = [&](const Dplane& p, double w) {
    a += w * p.normal * p.normal.transpose();
    b += w * (p.offset - p.normal.dot(mass_center)) * p.normal;
  };
  for(const Frame_plane& f : frame_planes)
    if(f.principal == searched_plane) add(f.plane, value_of(prst, f.plane));
  for(const Weighted_plane& p : planes)
    for(const Frame_plane& f : frame_planes)
      if(std::abs(p.plane.normal.dot(f.plane.normal)) >= cos_tolerance) {
        add(p.plane, p.weight);
        break;
      }
  for(const Frame_plane& f : frame_planes) add({f.plane.normal, f.plane.normal.dot(mass_center)}, mass_prior);
  if(std::abs(a.determinant()) < 1e-12) return intersection(frame_planes);
  return mass_center + a.ldlt().solve(b);
}

// The planes ordered by the variance of the mass along their normals, largest first (mode 1), or
// by measure with neighbours of measures within equal_measures swapped into variance order (mode
// 2; searched planes last).
template <typename GT>
std::array<Frame_plane, 3> variance_ordered(std::array<Frame_plane, 3> planes,
                                            const std::vector<Principal_symmetry<GT>>& symmetries,
                                            const Mass_distribution& mass, int mode)
{
  const Eigen::Matrix3d covariance = mass.covariance();
  const auto variance = [&](const Frame_plane& p) { return p.plane.normal.dot(covariance * p.plane.normal); };
  if(mode == 1) {
    std::stable_sort(planes.begin(), planes.end(),
                     [&](const Frame_plane& a, const Frame_plane& b) { return variance(a) > variance(b); });
    return planes;
  }
  for(int pass = 0; pass < 2; ++pass)
    for(std::size_t k = 0; k + 1 < 3; ++k) {
      const Frame_plane &a = planes[k], &b = planes[k + 1];
      if(a.principal == searched_plane || b.principal == searched_plane) continue;
      if(std::abs(symmetries[std::size_t(a.principal)].symmetry - symmetries[std::size_t(b.principal)].symmetry) <=
           equal_measures &&
         variance(b) > variance(a))
        std::swap(planes[k], planes[k + 1]);
    }
  return planes;
}

// The first axis, then the principal axes of the mass projected on the plane perpendicular to it
// (largest variance first): symmetry where it is strong, inertia where it is weak.
inline std::array<Eigen::Vector3d, 3> first_axis_and_inertia(const Eigen::Vector3d& first, const Mass_distribution& mass)
{
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - first * first.transpose();
  const std::array<Eigen::Vector3d, 3> in_plane = principal_axes(across * mass.covariance() * across);
  return {first, in_plane[0], first.cross(in_plane[0])};
}

// The axes ordered by the variance of the mass along them, largest first, right-handed.
inline std::array<Eigen::Vector3d, 3> by_variance(std::array<Eigen::Vector3d, 3> axes, const Mass_distribution& mass)
{
  const Eigen::Matrix3d covariance = mass.covariance();
  std::stable_sort(axes.begin(), axes.end(), [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return a.dot(covariance * a) > b.dot(covariance * b);
  });
  axes[2] = axes[0].cross(axes[1]);
  return axes;
}

// The frame by `rule` from the principal planes (strongest first, at least one).
template <typename GT>
Frame_choice frame_choice(const Mass_distribution& mass, const std::vector<Principal_symmetry<GT>>& symmetries,
                          const Reflective_symmetry_transform<GT>& prst, const Frame_rule& rule)
{
  const std::vector<Weighted_plane> planes = weighted_planes(symmetries, rule);
  Frame_choice choice;
  if(rule.joint) choice.planes = joint_triple(planes, prst, rule);
  else choice = greedy_frame_choice(mass, planes_of(symmetries), prst);
  const double first_weight = choice.planes[0].principal == searched_plane ? 0. : planes[std::size_t(choice.planes[0].principal)].weight,
               second_weight = choice.planes[1].principal == searched_plane ? value_of(prst, choice.planes[1].plane)
                                                                           : planes[std::size_t(choice.planes[1].principal)].weight;
  const bool inertia = second_weight < rule.pca_below * first_weight;
  const Eigen::Vector3d strongest = choice.planes[0].plane.normal;
  if(rule.variance_order != 0) choice.planes = variance_ordered(choice.planes, symmetries, mass, rule.variance_order);
  std::array<Eigen::Vector3d, 3> axes;
  axes[0] = choice.planes[0].plane.normal;
  const Eigen::Vector3d& n1 = choice.planes[1].plane.normal;
  axes[1] = (n1 - n1.dot(axes[0]) * axes[0]).normalized();
  axes[2] = axes[0].cross(axes[1]);
  if(inertia) {
    axes = first_axis_and_inertia(strongest, mass);
    if(rule.variance_order == 1) axes = by_variance(axes, mass);
  }
  const bool blend = rule.least_squares_center && (inertia || !rule.blend_only_when_weak);
  const Eigen::Vector3d center =
    blend ? least_squares_center(choice.planes, planes, prst, mass.center(), rule.mass_prior) : intersection(choice.planes);
  choice.frame = {center, oriented_axes(axes, center, mass)};
  return choice;
}

// The centre of symmetry of partial data: the least-squares point of the three most symmetric
// orthogonal planes of the transform (weights: their values) and of the centre of mass (weight
// partial_data_mass_prior along each of their normals). Each normal is replaced by that of the
// strongest principal plane within center_plane_tolerance_degrees of it, and its offset searched
// again to a fraction of a bin: the search's normals lie up to a bin off the true ones, the
// principal planes' are refined. An exact principal plane (exact_symmetry) within a bin of that
// offset keeps its own. Other principal planes keep only their normals: on partial scans their
// refined offsets, drawn to the visible part, measured worse than the transform's peak.
template <typename GT>
Eigen::Vector3d partial_data_center(const Mass_distribution& mass, const std::vector<Principal_symmetry<GT>>& symmetries,
                                    const Reflective_symmetry_transform<GT>& prst)
{
  const std::vector<Weighted_plane> principal = weighted_planes(symmetries, Frame_rule{});
  const std::array<Eigen::Vector3d, 3> normals = most_symmetric_orthogonal_normals(prst);
  std::array<Frame_plane, 3> planes;
  for(std::size_t k = 0; k < 3; ++k) {
    const int nearest = strongest_principal(principal, normals[k], true, {-1, -1});
    const Eigen::Vector3d& normal = nearest >= 0 ? principal[std::size_t(nearest)].plane.normal : normals[k];
    planes[k] = {peak_plane_of_normal(prst, normal), searched_plane};
    if(nearest >= 0 && principal[std::size_t(nearest)].weight >= exact_symmetry &&
       std::abs(principal[std::size_t(nearest)].plane.offset - planes[k].plane.offset) <= prst.bins().offset_step())
      planes[k].plane = principal[std::size_t(nearest)].plane;
  }
  return least_squares_center(planes, {}, prst, mass.center(), partial_data_mass_prior);
}

// The frame of partial data: the axes of partial_data_rule, the centre of partial_data_center().
template <typename GT>
Eigen_frame partial_data_frame(const Mass_distribution& mass, const std::vector<Principal_symmetry<GT>>& symmetries,
                               const Reflective_symmetry_transform<GT>& prst)
{
  const Eigen_frame axes = frame_choice(mass, symmetries, prst, partial_data_rule).frame;
  const Eigen::Vector3d center = partial_data_center(mass, symmetries, prst);
  return {center, oriented_axes(axes.axes, center, mass)};
}

// The frame of a detection by the rule that `partial_data` selects (named parameter).
template <typename GT, typename NamedParameters>
Eigen_frame frame_of_detection(const Mass_distribution& mass, const std::vector<Principal_symmetry<GT>>& symmetries,
                               const Reflective_symmetry_transform<GT>& prst, const NamedParameters& np)
{
  const bool partial = parameters::choose_parameter(parameters::get_parameter(np, internal_np::st_partial_data),
                                                    defaults::partial_data);
  if(!partial || symmetries.empty()) return symmetry_frame(mass, symmetries, prst);
  return partial_data_frame(mass, symmetries, prst);
}

// The symmetry frame of a shape under the callback of `np`: detect() then mass(), in that order
// so that the mass's copy of the triangles does not live through the detection's peak. Once
// cancelled, the PCA frame, its mass made with no progress polled.
template <typename NamedParameters, typename Detect, typename Mass>
Eigen_frame symmetry_frame_under_progress(const NamedParameters& np, const Detect& detect, const Mass& mass)
{
  return with_progress(np, [&] {
    const auto detection = detect();
    throw_if_cancelled(); // the planes found so far would make another frame
    return frame_of_detection(mass(), detection.symmetries, detection.prst, np);
  }, [&] { return pca_frame(without_progress(mass)); });
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ALIGNMENT_JOINT_FRAME_H
