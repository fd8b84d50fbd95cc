// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef SYMMETRY_TRANSFORM_PYTHON_DETECTION_H
#define SYMMETRY_TRANSFORM_PYTHON_DETECTION_H

// The principal symmetries of a shape from Python, for the functions that return them or build
// on them (viewpoints).

#include "common.h"

#include <CGAL/Symmetry_transform/principal_symmetries.h>

namespace symmetry_transform_python {

typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

// A soup's, or a point set's with its normals if it has some.
inline std::vector<ST::Principal_symmetry<K>> principal_symmetries_of(const Shape& shape, const Options& o,
                                                                      const std::function<bool(double)>& callback)
{
  return with_detection_parameters(o, callback, [&](const auto& np) {
    if(!shape.is_point_set()) return ST::detect_principal_symmetries_of_triangle_soup(shape.points, shape.triangles, np);
    const auto with_points = np.point_map(Point_map());
    return shape.has_normals
             ? ST::detect_principal_symmetries_of_points(shape.oriented_points, with_points.normal_map(Normal_map()))
             : ST::detect_principal_symmetries_of_points(shape.oriented_points, with_points);
  });
}

} // namespace symmetry_transform_python

#endif // SYMMETRY_TRANSFORM_PYTHON_DETECTION_H
