// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_POINT_GROUP_H
#define CGAL_SYMMETRY_TRANSFORM_POINT_GROUP_H

#include <CGAL/Symmetry_transform/Principal_symmetry.h>
#include <CGAL/Symmetry_transform/Rotational_symmetry.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformRotationRef
 * The point group of a shape: the group of its exact symmetries, in Schoenflies notation.
*/
struct Point_group
{
  /// The Schoenflies symbol in ASCII: `C1`, `Cs`, `Cn`, `Cnv`, `Cnh`, `Dn`, `Dnd`, `Dnh` (with
  /// the order n, as in `D6h`), `T`, `Td`, `Th`, `O`, `Oh`, `I`, `Ih`, or for a continuous group
  /// `Cinf`, `Cinfv`, `Dinfh` and `Kh` (a sphere).
  std::string name;
  /// The number of its elements (rotations, reflections and rotoreflections), 0 for a
  /// continuous group.
  std::size_t order;
};

namespace internal {

// Two exact directions are parallel or perpendicular to 1e-5 radian; approximate ones found to
// a tenth of a degree still are to this.
constexpr double point_group_angle_tolerance = 0.01;

struct Group_elements
{
  std::vector<Eigen::Vector3d> normals;         // of the mirror planes
  std::vector<Eigen::Vector3d> axes;            // unit directions
  std::vector<int> orders;                      // of the axes, 0 for continuous
};

inline bool parallel(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return a.cross(b).norm() < std::sin(point_group_angle_tolerance);
}

inline bool perpendicular(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::abs(a.dot(b)) < std::sin(point_group_angle_tolerance);
}

// A group with two axes of order 3 or more: tetrahedral, octahedral or icosahedral.
inline Point_group polyhedral_group(const Group_elements& g)
{
  const std::size_t planes = g.normals.size();
  if(std::any_of(g.orders.begin(), g.orders.end(), [](int k) { return k % 5 == 0; }))
    return planes >= 15 ? Point_group{"Ih", 120} : Point_group{"I", 60};
  if(std::any_of(g.orders.begin(), g.orders.end(), [](int k) { return k % 4 == 0; }))
    return planes >= 9 ? Point_group{"Oh", 48} : Point_group{"O", 24};
  return planes >= 6 ? Point_group{"Td", 24} : planes >= 3 ? Point_group{"Th", 24} : Point_group{"T", 12};
}

// A group with a continuous axis `axis` (a surface of revolution), or several (a sphere).
inline Point_group continuous_group(const Group_elements& g, const Eigen::Vector3d& axis)
{
  const auto continuous = std::count(g.orders.begin(), g.orders.end(), 0);
  if(continuous > 1) return {"Kh", 0};
  if(std::any_of(g.normals.begin(), g.normals.end(), [&](const Eigen::Vector3d& n) { return parallel(n, axis); }))
    return {"Dinfh", 0};
  if(std::any_of(g.normals.begin(), g.normals.end(), [&](const Eigen::Vector3d& n) { return perpendicular(n, axis); }))
    return {"Cinfv", 0};
  return {"Cinf", 0};
}

// A group with one principal axis `axis` of order n >= 2: cyclic or dihedral. One two-fold axis
// across the principal one implies n of them (the rotations about the principal axis turn it),
// and one plane along it n planes: one of each is enough.
inline Point_group axial_group(const Group_elements& g, const Eigen::Vector3d& axis, int n)
{
  const bool horizontal =
    std::any_of(g.normals.begin(), g.normals.end(), [&](const Eigen::Vector3d& m) { return parallel(m, axis); });
  const bool vertical =
    std::any_of(g.normals.begin(), g.normals.end(), [&](const Eigen::Vector3d& m) { return perpendicular(m, axis); });
  bool flip = false; // a two-fold axis across the principal one
  for(std::size_t i = 0; i < g.axes.size(); ++i)
    flip = flip || (g.orders[i] % 2 == 0 && g.orders[i] > 0 && perpendicular(g.axes[i], axis));
  const std::string order = std::to_string(n);
  const std::size_t elements = std::size_t(n);
  if(flip)
    return horizontal ? Point_group{"D" + order + "h", 4 * elements}
           : vertical ? Point_group{"D" + order + "d", 4 * elements}
                      : Point_group{"D" + order, 2 * elements};
  return horizontal ? Point_group{"C" + order + "h", 2 * elements}
         : vertical ? Point_group{"C" + order + "v", 2 * elements}
                    : Point_group{"C" + order, elements};
}

// The axis of highest order; among several (the three two-fold axes of D2d), the one with the
// most planes across it, then along it.
inline std::size_t principal_axis(const Group_elements& g)
{
  auto score = [&](std::size_t i) {
    std::size_t across = 0, along = 0;
    for(const Eigen::Vector3d& m : g.normals) {
      across += parallel(m, g.axes[i]) ? 1 : 0;
      along += perpendicular(m, g.axes[i]) ? 1 : 0;
    }
    return std::make_tuple(g.orders[i], across, along);
  };
  std::size_t best = 0;
  for(std::size_t i = 1; i < g.axes.size(); ++i)
    if(score(i) > score(best)) best = i;
  return best;
}

inline Point_group point_group_of(const Group_elements& g)
{
  const auto continuous = std::find(g.orders.begin(), g.orders.end(), 0);
  if(continuous != g.orders.end()) return continuous_group(g, g.axes[std::size_t(continuous - g.orders.begin())]);
  if(std::count_if(g.orders.begin(), g.orders.end(), [](int k) { return k >= 3; }) >= 2) return polyhedral_group(g);
  if(g.axes.empty()) return g.normals.empty() ? Point_group{"C1", 1} : Point_group{"Cs", 2};
  return axial_group(g, g.axes[principal_axis(g)], g.orders[principal_axis(g)]);
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformRotationRef
 *
 * The point group of a shape from its mirror planes and rotation axes, as
 * `detect_principal_symmetries()` and `detect_rotational_symmetries()` return them: only the
 * exact ones count, those whose support is at least `min_support`. The group is named from
 * the highest order of an axis, the number of axes of order 3 or more, the two-fold axes across
 * the principal one and the planes across and along it (\ref SymmetryTransformRotation).
 * Groups told apart only by a rotoreflection or the inversion, which the package does not
 * detect (\f$ S_{2n} \f$, \f$ C_i \f$), are named by their rotations and planes: \f$ C_n \f$,
 * \f$ C_1 \f$.
 *
 * \tparam GeomTraits a model of `Kernel`
 *
 * \param planes the mirror planes of the shape
 * \param rotations its rotation axes, with their orders (0: continuous)
 * \param min_support the support from which a symmetry counts as exact
 *
 * \returns the name and the order of the group.
 * \throws std::invalid_argument if `min_support` is not in [0, 1].
*/
template <typename GeomTraits>
Point_group point_group(const std::vector<Principal_symmetry<GeomTraits>>& planes,
                        const std::vector<Rotational_symmetry<GeomTraits>>& rotations, double min_support = 0.99)
{
  if(!(min_support >= 0. && min_support <= 1.))
    throw std::invalid_argument("min_support must be in [0, 1], not " + std::to_string(min_support));
  internal::Group_elements g;
  for(const Principal_symmetry<GeomTraits>& p : planes)
    if(p.support >= min_support) {
      const auto n = p.plane.orthogonal_vector();
      g.normals.push_back(Eigen::Vector3d(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())).normalized());
    }
  for(const Rotational_symmetry<GeomTraits>& r : rotations)
    if(r.support >= min_support) {
      const auto d = r.axis.to_vector();
      g.axes.push_back(Eigen::Vector3d(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z())).normalized());
      g.orders.push_back(r.order);
    }
  return internal::point_group_of(g);
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_POINT_GROUP_H
