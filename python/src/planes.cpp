// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

// Principal symmetries of a soup or a point set, each with its symmetry distance error, and the
// symmetry distance error of any plane.

#include "detection.h"

#include <CGAL/Symmetry_transform/symmetry_measure.h>

#include <limits>

namespace symmetry_transform_python {

namespace {

// The symmetry distance error of a plane, with the samples and seed of symmetry_distance_error()'s
// defaults (those of the batch command); NaN for
// sde_samples=0, which skips it (a detection alone, as the C++ function).
double sde_of(const Shape& shape, const K::Plane_3& plane, const Options& o)
{
  if(o.sde_samples == std::size_t(0)) return std::numeric_limits<double>::quiet_NaN();
  const auto np = CGAL::parameters::number_of_points_on_faces(o.sde_samples.value_or(defaults::metric_samples))
                    .random_seed(o.random_seed.value_or(defaults::random_seed))
                    .number_of_threads(threads_of(o));
  if(shape.is_point_set())
    return ST::symmetry_distance_error_of_points(shape.oriented_points, plane, np.point_map(Point_map()));
  return ST::symmetry_distance_error_of_triangle_soup(shape.points, shape.triangles, plane, np);
}

struct Plane_result
{
  Vector normal;
  double offset, symmetry, support, sde;
};

py::list principal_symmetries(const py::array& vertices, const py::object& faces, const py::object& normals,
                              const py::dict& keywords, const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, normals);
  const Options o = options_of(keywords);
  const std::vector<Plane_result> planes = run_without_gil(callback, [&](const std::function<bool(double)>& report) {
    std::vector<Plane_result> result;
    for(const ST::Principal_symmetry<K>& s : principal_symmetries_of(shape, o, report)) {
      const auto [normal, offset] = normal_and_offset(s.plane);
      result.push_back({normal, offset, s.symmetry, s.support, sde_of(shape, s.plane, o)});
    }
    return result;
  });
  py::list list;
  for(const Plane_result& p : planes)
    list.append(py::make_tuple(vector_array(p.normal), p.offset, p.symmetry, p.support, p.sde));
  return list;
}

double symmetry_distance_error(const py::array& vertices, const py::object& faces, const py::object& normals,
                               const py::array& normal, double offset, const py::dict& keywords)
{
  const Shape shape = shape_of(vertices, faces, normals);
  const K::Plane_3 plane = plane_of(normal, offset);
  const Options o = options_of(keywords);
  py::gil_scoped_release release;
  return sde_of(shape, plane, o);
}

} // namespace

void bind_planes(py::module_& m)
{
  m.def("principal_symmetries", &principal_symmetries, py::arg("vertices"), py::arg("faces"), py::arg("normals"),
        py::arg("options"), py::arg("callback"));
  m.def("symmetry_distance_error", &symmetry_distance_error, py::arg("vertices"), py::arg("faces"), py::arg("normals"),
        py::arg("normal"), py::arg("offset"), py::arg("options"));
}

} // namespace symmetry_transform_python
