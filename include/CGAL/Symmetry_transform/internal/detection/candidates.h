// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_CANDIDATES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_CANDIDATES_H

// Candidates of principal symmetries among the local maxima of a discrete PRST (thesis,
// section 3.3; thresholds of DESIGN.md), and the tests that tell two planes apart.

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// Negative discrete Laplacian at a bin (6 neighbours, through the wraps): the depth of a maximum.
inline double maximum_depth(const Plane_bins& bins, const std::vector<double>& values, const std::array<std::size_t, 3>& b)
{
  const long i = long(b[0]), j = long(b[1]), k = long(b[2]);
  const double v = values[bins.index(b[0], b[1], b[2])];
  double depth = 0.;
  for(int axis = 0; axis < 3; ++axis)
    for(long step : {-1L, 1L}) {
      long d[3] = {i, j, k};
      d[axis] += step;
      depth += v - values[bins.wrapped_index(d[0], d[1], d[2])];
    }
  return depth;
}

// The transform smoothed by the binomial filter [1 2 1]/4 along each axis, through the wraps.
// Monte Carlo noise makes many local maxima along the flat ridges of the transform, each of
// which ISP would refine to the same plane; one pass of the filter leaves one per ridge.
template <typename GT>
Reflective_symmetry_transform<GT> smoothed(const Reflective_symmetry_transform<GT>& prst)
{
  Reflective_symmetry_transform<GT> result = prst;
  const Plane_bins& bins = prst.bins();
  const long n = long(bins.n);
  for(int axis = 0; axis < 3; ++axis) {
    const std::vector<double> input = result.values();
    for(long i = 0; i < n; ++i)
      for(long j = 0; j < n; ++j)
        for(long k = 0; k < n; ++k) {
          long lo[3] = {i, j, k}, hi[3] = {i, j, k};
          --lo[axis];
          ++hi[axis];
          result.values()[bins.index(std::size_t(i), std::size_t(j), std::size_t(k))] =
            0.5 * input[bins.index(std::size_t(i), std::size_t(j), std::size_t(k))] +
            0.25 * (input[bins.wrapped_index(lo[0], lo[1], lo[2])] + input[bins.wrapped_index(hi[0], hi[1], hi[2])]);
        }
  }
  return result;
}

// Local maxima of the smoothed transform above t (1 - |r|/R) and deeper than l, with t and l
// the given fractions of the value and depth of the strongest maximum; strongest first.
template <typename GT>
std::vector<std::array<std::size_t, 3>> symmetry_candidates(const Reflective_symmetry_transform<GT>& transform,
                                                            double symmetry_fraction, double depth_fraction)
{
  const Reflective_symmetry_transform<GT> prst = smoothed(transform);
  std::vector<std::array<std::size_t, 3>> maxima, candidates;
  prst.local_maxima(std::back_inserter(maxima));
  if(maxima.empty()) return candidates;
  const double t = symmetry_fraction * prst.value(maxima.front());
  const double l = depth_fraction * maximum_depth(prst.bins(), prst.values(), maxima.front());
  for(const auto& b : maxima)
    if(prst.value(b) >= t * (1. - std::abs(prst.offset(b[2])) / prst.radius()) &&
       maximum_depth(prst.bins(), prst.values(), b) >= l)
      candidates.push_back(b);
  return candidates;
}

// Two planes are the same symmetry when their normals (up to sign) differ by less than the
// given chord and their offsets from `center` (the shape's) by less than `distance`; offsets from
// the origin would make the test depend on where the shape lies.
inline bool same_plane(const Dplane& a, const Dplane& b, double angle, double distance, const Eigen::Vector3d& center)
{
  const double sign = a.normal.dot(b.normal) < 0. ? -1. : 1.;
  return (a.normal - sign * b.normal).norm() < angle &&
         std::abs((a.offset - a.normal.dot(center)) - sign * (b.offset - b.normal.dot(center))) < distance;
}

inline Eigen::Vector3d center_of(const Plane_bins& bins)
{
  return Eigen::Vector3d(bins.center[0], bins.center[1], bins.center[2]);
}

// Whether `plane` lies within `reach` bin sizes of the centre of bin b: the angle measured
// against the larger of the bin's extents in theta and (sin theta) phi, so that it means the
// same at the pole, where phi is undefined, and at the equator, where phi bins are widest.
template <typename GT>
bool stays_near_bin(const Reflective_symmetry_transform<GT>& prst, const Dplane& plane,
                    const std::array<std::size_t, 3>& b, double reach)
{
  const Plane_bins& bins = prst.bins();
  const double bin_angle = (std::max)(bins.theta_step(), std::sin(bins.theta(b[0])) * bins.phi_step());
  return same_plane(to_dplane(prst.plane(b)), plane, reach * bin_angle, reach * bins.offset_step(), center_of(bins));
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_DETECTION_CANDIDATES_H
