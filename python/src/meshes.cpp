// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

// What needs a mesh: the segmentation by symmetry (a label per face of F, in its order) and the
// symmetric remeshing (arrays out).

#include "detection.h"

#include <CGAL/Symmetry_transform/symmetric_remeshing.h>
#include <CGAL/Symmetry_transform/symmetry_segmentation.h>

#include <iterator>

namespace symmetry_transform_python {

namespace {

py::array_t<std::int64_t> segment(const py::array& vertices, const py::object& faces, const py::dict& keywords,
                                  const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, py::none());
  const Options o = options_of(keywords);
  const std::vector<std::int64_t> labels = run_without_gil(callback, [&](const std::function<bool(double)>& report) {
    const Mesh mesh = mesh_of(shape); // face i is triangle i
    std::vector<std::int64_t> ids(num_faces(mesh), 0);
    const auto segment_ids = CGAL::make_property_map(ids); // indexed by the face index
    const auto np = CGAL::parameters::max_segmentation_depth(o.max_segmentation_depth.value_or(defaults::max_segmentation_depth))
                      .random_seed(o.random_seed.value_or(defaults::random_seed))
                      .number_of_threads(threads_of(o))
                      .callback(report);
    if(o.max_number_of_segments)
      ST::segment_by_symmetry(mesh, segment_ids, np.max_number_of_segments(*o.max_number_of_segments));
    else
      ST::segment_by_symmetry(mesh, segment_ids, np);
    return ids;
  });
  py::array_t<std::int64_t> a(py::ssize_t(labels.size()));
  std::copy(labels.begin(), labels.end(), a.mutable_data());
  return a;
}

// The planes kept: those given, or the strongest principal symmetry.
std::vector<K::Plane_3> planes_to_keep(const Shape& shape, const py::object& planes, const Options& o)
{
  std::vector<K::Plane_3> kept;
  if(!planes.is_none()) {
    for(const py::handle p : planes) {
      const py::tuple plane = py::reinterpret_borrow<py::object>(p);
      kept.push_back(plane_of(py::array::ensure(plane[0]), plane[1].cast<double>()));
    }
    return kept;
  }
  py::gil_scoped_release release;
  Options strongest = o;
  strongest.max_number_of_planes = 1;
  const std::function<bool(double)> no_report = [](double) { return true; };
  for(const auto& s : principal_symmetries_of(shape, strongest, no_report)) kept.push_back(s.plane);
  return kept;
}

py::tuple symmetric_remesh(const py::array& vertices, const py::object& faces, const py::object& planes,
                           const py::dict& keywords, const py::object& callback)
{
  const Shape shape = shape_of(vertices, faces, py::none());
  const Options o = options_of(keywords);
  const std::vector<K::Plane_3> kept = planes_to_keep(shape, planes, o);
  std::vector<Point> anchors;
  std::vector<Triangle> triangles;
  const bool ok = run_without_gil(callback, [&](const std::function<bool(double)>& report) {
    const Mesh mesh = mesh_of(shape);
    const auto np = CGAL::parameters::anchors(std::back_inserter(anchors))
                      .triangles(std::back_inserter(triangles))
                      .random_seed(o.random_seed.value_or(defaults::random_seed))
                      .number_of_threads(threads_of(o))
                      .callback(report);
    return o.max_number_of_proxies
             ? ST::symmetric_approximate_triangle_mesh(mesh, kept, np.max_number_of_proxies(*o.max_number_of_proxies))
             : ST::symmetric_approximate_triangle_mesh(mesh, kept, np);
  });
  return py::make_tuple(array_of(anchors), array_of(triangles), ok);
}

} // namespace

void bind_meshes(py::module_& m)
{
  m.def("segment", &segment, py::arg("vertices"), py::arg("faces"), py::arg("options"), py::arg("callback"));
  m.def("symmetric_remesh", &symmetric_remesh, py::arg("vertices"), py::arg("faces"), py::arg("planes"),
        py::arg("options"), py::arg("callback"));
}

} // namespace symmetry_transform_python
