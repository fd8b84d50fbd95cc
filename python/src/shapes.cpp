// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

// What a shape's principal symmetries give: its symmetry frame, its symmetry descriptor for
// matching, its best viewpoints.

#include "detection.h"

#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Symmetry_transform/symmetry_alignment.h>
#include <CGAL/Symmetry_transform/symmetry_descriptor.h>
#include <CGAL/Symmetry_transform/viewpoint_selection.h>

#include <iterator>

namespace symmetry_transform_python {

namespace {

typedef ST::Symmetry_descriptor<K> Descriptor;

ST::Symmetry_frame<K> frame_of(const Shape& shape, const Options& o, const std::function<bool(double)>& callback)
{
  return with_detection_parameters(o, callback, [&](const auto& np) {
    if(!shape.is_point_set()) return ST::symmetry_frame_of_triangle_soup(shape.points, shape.triangles, np);
    const auto with_points = np.point_map(Point_map());
    return shape.has_normals ? ST::symmetry_frame_of_points(shape.oriented_points, with_points.normal_map(Normal_map()))
                             : ST::symmetry_frame_of_points(shape.oriented_points, with_points);
  });
}

// The centre and the axes (rows) of the frame.
py::tuple symmetry_frame(const py::array& vertices, const py::object& faces, const py::object& normals,
                         const py::dict& keywords, const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, normals);
  const Options o = options_of(keywords);
  const ST::Symmetry_frame<K> frame =
    run_without_gil(callback, [&](const std::function<bool(double)>& report) { return frame_of(shape, o, report); });
  std::vector<Point> axes;
  for(const Vector& a : frame.axes) axes.push_back(CGAL::ORIGIN + a);
  return py::make_tuple(vector_array(frame.center - CGAL::ORIGIN), array_of(axes));
}

// The descriptor of the mesh moved into its symmetry frame, so that descriptors of shapes in
// any pose compare.
Descriptor descriptor(const py::array& vertices, const py::object& faces, const py::dict& keywords,
                      const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, py::none());
  const Options o = options_of(keywords);
  return run_without_gil(callback, [&](const std::function<bool(double)>& report) {
    Mesh mesh = mesh_of(shape);
    CGAL::Polygon_mesh_processing::transform(ST::to_canonical(frame_of(shape, o, report)), mesh);
    return ST::symmetry_descriptor(
      mesh, CGAL::parameters::grid_resolution(int(o.grid_resolution.value_or(defaults::descriptor_grid_resolution)))
              .gaussian_width(o.gaussian_width.value_or(defaults::gaussian_width))
              .number_of_samples(o.number_of_samples.value_or(defaults::monte_carlo_pairs))
              .random_seed(o.random_seed.value_or(defaults::random_seed))
              .number_of_threads(threads_of(o)));
  });
}

py::list best_viewpoints(const py::array& vertices, const py::object& faces, const py::object& normals,
                         const py::dict& keywords, const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, normals);
  const Options o = options_of(keywords);
  const auto views = run_without_gil(callback, [&](const std::function<bool(double)>& report) {
    const auto symmetries = principal_symmetries_of(shape, o, report);
    std::vector<ST::Viewpoint<K>> result;
    ST::best_viewpoints(symmetries, std::back_inserter(result));
    return result;
  });
  py::list list;
  for(const ST::Viewpoint<K>& v : views) list.append(py::make_tuple(vector_array(v.direction), v.score));
  return list;
}

} // namespace

void bind_shapes(py::module_& m)
{
  m.def("symmetry_frame", &symmetry_frame, py::arg("vertices"), py::arg("faces"), py::arg("normals"),
        py::arg("options"), py::arg("callback"));
  py::class_<Descriptor>(m, "Descriptor", "The symmetry descriptor of a shape in its symmetry frame.");
  m.def("descriptor", &descriptor, py::arg("vertices"), py::arg("faces"), py::arg("options"), py::arg("callback"));
  m.def("descriptor_distance", [](const Descriptor& a, const Descriptor& b) { return ST::descriptor_distance(a, b); },
        py::arg("a"), py::arg("b"));
  m.def("best_viewpoints", &best_viewpoints, py::arg("vertices"), py::arg("faces"), py::arg("normals"),
        py::arg("options"), py::arg("callback"));
}

} // namespace symmetry_transform_python
