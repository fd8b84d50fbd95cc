// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

// Files: meshes and point sets read and repaired as the demo programs read them, and the batch
// command's record of a file, file list and resumption, so that a collection labelled from Python
// has the same records.

#include "common.h"

#include "batch_runner.h"
#include "batch_shape.h"
#include "input_files.h"

namespace symmetry_transform_python {

namespace {

py::tuple read_mesh(const std::string& file)
{
  examples::Soup_repairs repairs;
  examples::Triangle_soup<Point> soup;
  {
    py::gil_scoped_release release;
    soup = examples::read_triangle_soup<Point>(file, repairs);
  }
  return py::make_tuple(array_of(soup.points), array_of(soup.triangles));
}

py::tuple read_points(const std::string& file)
{
  typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
  typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
  std::vector<Point_with_normal> read;
  {
    py::gil_scoped_release release;
    read = examples::read_point_set<Point_with_normal>(file, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  }
  std::vector<Point> points, normals;
  bool has_normals = false;
  for(const Point_with_normal& p : read) {
    points.push_back(p.first);
    normals.push_back(CGAL::ORIGIN + p.second);
    has_normals = has_normals || p.second != CGAL::NULL_VECTOR;
  }
  return py::make_tuple(array_of(points), has_normals ? py::object(array_of(normals)) : py::object(py::none()));
}

examples::batch::Settings batch_settings(const py::dict& keywords)
{
  const Options o = options_of(keywords);
  examples::batch::Settings s;
  s.resolution = int(o.grid_resolution.value_or(s.resolution));
  s.max_planes = o.max_number_of_planes.value_or(s.max_planes);
  s.monte_carlo_samples = o.number_of_samples.value_or(s.monte_carlo_samples);
  s.sde_samples = o.sde_samples.value_or(s.sde_samples);
  s.seed = o.random_seed.value_or(s.seed);
  s.threads_per_shape = o.number_of_threads.value_or(s.threads_per_shape);
  return s;
}

std::string batch_record(const std::string& file, const py::dict& keywords)
{
  const examples::batch::Settings settings = batch_settings(keywords);
  py::gil_scoped_release release;
  return examples::batch::shape_record(file, settings);
}

} // namespace

void bind_files(py::module_& m)
{
  m.def("read_mesh", &read_mesh, py::arg("path"));
  m.def("read_points", &read_points, py::arg("path"));
  m.def("batch_record", &batch_record, py::arg("path"), py::arg("options"));
  m.def("files_done", &examples::batch::files_done, py::arg("output"), py::arg("retry_errors"));
  m.def("input_files", [](const std::vector<std::string>& arguments) { return examples::batch::input_files(arguments, {}); },
        py::arg("arguments"));
}

} // namespace symmetry_transform_python
