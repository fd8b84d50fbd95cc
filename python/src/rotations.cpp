// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

// Rotational symmetries of a mesh or a point set, and the symmetry fields of the BOP pose
// estimation benchmark, as the demo program rotational_symmetries writes them.

#include "detection.h"

#include <CGAL/Symmetry_transform/point_group.h>
#include <CGAL/Symmetry_transform/rotational_symmetries.h>

#include "bop_symmetries.h"

namespace symmetry_transform_python {

namespace {

// Detection's named parameters and the largest order tested.
template <typename Work>
auto with_rotation_parameters(const Options& o, const std::function<bool(double)>& callback, const Work& work)
{
  return with_detection_parameters(o, callback, [&](const auto& np) {
    return work(np.max_order(o.max_order.value_or(defaults::max_order)));
  });
}

std::vector<ST::Rotational_symmetry<K>> detect(const Shape& shape, const Options& o,
                                               const std::function<bool(double)>& callback)
{
  return with_rotation_parameters(o, callback, [&](const auto& np) {
    if(!shape.is_point_set()) return ST::detect_rotational_symmetries(mesh_of(shape), np);
    const auto with_points = np.point_map(Point_map());
    return shape.has_normals
             ? ST::detect_rotational_symmetries_of_points(shape.oriented_points, with_points.normal_map(Normal_map()))
             : ST::detect_rotational_symmetries_of_points(shape.oriented_points, with_points);
  });
}

py::list rotational_symmetries(const py::array& vertices, const py::object& faces, const py::object& normals,
                               const py::dict& keywords, const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, normals);
  const Options o = options_of(keywords);
  const auto symmetries =
    run_without_gil(callback, [&](const std::function<bool(double)>& report) { return detect(shape, o, report); });
  py::list list;
  for(const ST::Rotational_symmetry<K>& s : symmetries) {
    const Vector axis = s.axis.to_vector() / std::sqrt(s.axis.to_vector().squared_length());
    list.append(py::make_tuple(vector_array(axis), vector_array(s.axis.point() - CGAL::ORIGIN), s.order, double(s.symmetry),
                               double(s.support)));
  }
  return list;
}

// The BOP fields as JSON text, with the point group of the exact planes and axes.
std::string bop_symmetries(const py::array& vertices, const py::object& faces, const py::dict& keywords,
                           const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, py::none());
  const Options o = options_of(keywords);
  return run_without_gil(callback, [&](const std::function<bool(double)>& report) {
    const Mesh mesh = mesh_of(shape);
    return with_rotation_parameters(o, report, [&](const auto& np) {
      const auto rotations = ST::detect_rotational_symmetries(mesh, np);
      const ST::Point_group group = ST::point_group(ST::detect_principal_symmetries(mesh, np), rotations);
      return examples::bop_json(rotations, group.name);
    });
  });
}

} // namespace

void bind_rotations(py::module_& m)
{
  m.def("rotational_symmetries", &rotational_symmetries, py::arg("vertices"), py::arg("faces"), py::arg("normals"),
        py::arg("options"), py::arg("callback"));
  m.def("bop_symmetries", &bop_symmetries, py::arg("vertices"), py::arg("faces"), py::arg("options"),
        py::arg("callback"));
}

} // namespace symmetry_transform_python
