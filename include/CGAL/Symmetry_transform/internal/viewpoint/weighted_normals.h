// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_WEIGHTED_NORMALS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_WEIGHTED_NORMALS_H

// The viewpoint score of viewpoint_selection.h, S(v) = sum_u |v . u| M(u) over the principal
// planes u of measure M(u), and its exact ascent to a local maximum. In doubles, whatever the
// kernel of the planes.

#include <CGAL/Symmetry_transform/Principal_symmetry.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The ascent stops on the exact maximum after a few steps (see Weighted_normals::ascend()); this
// bound only guards against a cycle of rounding.
constexpr int max_ascent_steps = 100;
// A step of the ascent whose cosine with the previous direction exceeds 1 minus this is no move:
// the direction is settled to rounding.
constexpr double settled_direction_tolerance = 1e-15;

// The kernel of a range of Principal_symmetry<GT>.
template <typename Symmetry>
struct Kernel_of_symmetry;

template <typename GT>
struct Kernel_of_symmetry<Principal_symmetry<GT>>
{
  typedef GT type;
};

template <typename SymmetryRange>
struct Kernel_of_symmetry_range
{
  typedef typename Kernel_of_symmetry<typename std::iterator_traits<
    decltype(std::begin(std::declval<const SymmetryRange&>()))>::value_type>::type type;
};

typedef Eigen::Vector3d Vec3;

// v / |v|, or throws on a zero or non-finite vector.
inline Vec3 unit(const Vec3& v, const char* what)
{
  const double length = v.norm();
  if(!(length > 0.) || !std::isfinite(length)) throw std::invalid_argument(std::string("Symmetry_transform: ") + what);
  return v / length;
}

// A vector or a point of any kernel in doubles.
template <typename Vector_or_point>
Vec3 to_vec3(const Vector_or_point& v)
{
  return {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
}

// The principal planes as unit normals and weights M(u) > 0 (planes of zero measure add nothing).
struct Weighted_normals
{
  std::vector<Vec3> normals;
  std::vector<double> weights;

  template <typename SymmetryRange>
  explicit Weighted_normals(const SymmetryRange& symmetries)
  {
    for(const auto& s : symmetries) {
      const Vec3 u = unit(to_vec3(s.plane.orthogonal_vector()), "viewpoint selection: a principal plane has no normal");
      if(!(s.symmetry >= 0.) || !std::isfinite(s.symmetry))
        throw std::invalid_argument(
          "Symmetry_transform: viewpoint selection: a symmetry measure is negative or not finite");
      if(s.symmetry == 0.) continue;
      normals.push_back(u);
      weights.push_back(s.symmetry);
    }
  }

  double score(const Vec3& v) const // v a unit vector
  {
    double s = 0.;
    for(std::size_t k = 0; k < normals.size(); ++k) s += std::abs(v.dot(normals[k])) * weights[k];
    return s;
  }

  // w(v) = sum sign(v.u) M(u) u: S(x) >= w(v).x for every x, with equality at x = v.
  Vec3 linearisation(const Vec3& v) const
  {
    Vec3 w = {0., 0., 0.};
    for(std::size_t k = 0; k < normals.size(); ++k) {
      const double d = v.dot(normals[k]);
      const double s = d > 0. ? weights[k] : (d < 0. ? -weights[k] : 0.);
      for(int i = 0; i < 3; ++i) w[i] += s * normals[k][i];
    }
    return w;
  }

  // Local maximum reached from v by v <- w(v)/|w(v)|: each step maximises the minorant w(v).x of
  // S on the sphere, so S never decreases; S being linear on each cell of the arrangement of the
  // planes' great circles, the iteration stops on the exact maximum after a few steps.
  Vec3 ascend(Vec3 v) const
  {
    double s = score(v);
    for(int i = 0; i < max_ascent_steps; ++i) {
      const Vec3 w = linearisation(v);
      const double length = w.norm();
      if(!(length > 0.)) break;
      const Vec3 next = w / length;
      const double t = score(next);
      if(t < s) break; // rounding: keep the better one
      const bool moved = next.dot(v) < 1. - settled_direction_tolerance;
      v = next;
      s = t;
      if(!moved) break;
    }
    return v;
  }
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_VIEWPOINT_WEIGHTED_NORMALS_H
