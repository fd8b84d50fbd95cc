// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_PLANE_BINS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_PLANE_BINS_H

// The discretisation of the space of planes (DESIGN.md): a plane is (theta, phi, r), with unit
// normal n = (sin t cos p, sin t sin p, cos t), t in [0, pi/2], p in [0, 2 pi), and signed
// offset r in [-R, R] from the centre c: the plane n.(x - c) = r. n bins along each axis,
// samples at bin centres. Planes with n_z < 0 are flipped to (-n, -r).

#include <CGAL/number_type_config.h>

#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL::Symmetry_transform::internal {

struct Plane_bins
{
  std::size_t n;
  std::array<double, 3> center;
  double radius;

  double theta_step() const { return CGAL_PI / 2. / double(n); }
  double phi_step() const { return 2. * CGAL_PI / double(n); }
  double offset_step() const { return 2. * radius / double(n); }
  double bin_volume() const { return theta_step() * phi_step() * offset_step(); }

  double theta(std::size_t i) const { return (double(i) + 0.5) * theta_step(); }
  double phi(std::size_t j) const { return (double(j) + 0.5) * phi_step(); }
  double offset(std::size_t k) const { return -radius + (double(k) + 0.5) * offset_step(); }
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return (i * n + j) * n + k; }

  std::array<double, 3> normal(std::size_t i, std::size_t j) const
  {
    const double t = theta(i), p = phi(j);
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
  }

  // Continuous bin coordinates (bin centres at integers) of the plane {x : normal.x = d}, with
  // `normal` of unit length; false if the plane lies farther than R from the centre.
  bool coordinates(std::array<double, 3> normal, double d, std::array<double, 3>& u) const
  {
    double r = d - (normal[0] * center[0] + normal[1] * center[1] + normal[2] * center[2]);
    if(normal[2] < 0.) {
      for(double& c : normal) c = -c;
      r = -r;
    }
    if(std::abs(r) > radius) return false;
    double p = std::atan2(normal[1], normal[0]);
    if(p < 0.) p += 2. * CGAL_PI;
    u[0] = std::acos((std::min)(1., normal[2])) / theta_step() - 0.5;
    u[1] = p / phi_step() - 0.5;
    u[2] = (r + radius) / offset_step() - 0.5;
    return true;
  }

  // Index of any integer bin coordinates, through the identifications of the parameter space:
  // phi wraps; theta < 0 is (-theta, phi + pi, r) across the pole; theta > pi/2 is
  // (pi - theta, phi + pi, -r) across the equator. Offsets beyond +-R are clamped.
  std::size_t wrapped_index(long i, long j, long k) const
  {
    const long m = long(n);
    if(i < 0) {
      i = -1 - i;
      j += m / 2;
    } else if(i >= m) {
      i = 2 * m - 1 - i;
      j += m / 2;
      k = m - 1 - k;
    }
    j = ((j % m) + m) % m;
    k = k < 0 ? 0 : (k >= m ? m - 1 : k);
    return index(std::size_t(i), std::size_t(j), std::size_t(k));
  }
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_PLANE_BINS_H
