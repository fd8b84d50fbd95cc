// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

// The extension symmetry_transform._core: arrays and options in, plain tuples out; the package
// symmetry_transform (python/symmetry_transform/__init__.py) makes typed objects of them.

#include "common.h"

#include "input_files.h"

#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>

#include <cmath>

namespace symmetry_transform_python {

namespace {

std::string shape_text(const py::array& a)
{
  std::string text = "(";
  for(py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// The rows of an n x 3 array of floats, checked finite.
std::vector<std::array<double, 3>> float_rows(const py::array& a, const std::string& name)
{
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw std::invalid_argument(name + " must be an array of shape (n, 3), not " + shape_text(a));
  if(a.dtype().kind() != 'f')
    throw std::invalid_argument(name + " must hold floats (float32 or float64), not " + std::string(py::str(a.dtype())));
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  const auto r = values.unchecked<2>();
  std::vector<std::array<double, 3>> rows(std::size_t(r.shape(0)));
  for(py::ssize_t i = 0; i < r.shape(0); ++i) {
    rows[std::size_t(i)] = {r(i, 0), r(i, 1), r(i, 2)};
    if(!std::isfinite(r(i, 0)) || !std::isfinite(r(i, 1)) || !std::isfinite(r(i, 2)))
      throw std::invalid_argument(name + " row " + std::to_string(i) + " is not finite (NaN or infinite)");
  }
  return rows;
}

std::vector<Triangle> triangle_rows(const py::array& a, std::size_t number_of_points)
{
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw std::invalid_argument("faces must be an array of shape (m, 3), not " + shape_text(a));
  if(a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    throw std::invalid_argument("faces must hold integers (int32 or int64), not " + std::string(py::str(a.dtype())));
  const auto values = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  const auto r = values.unchecked<2>();
  std::vector<Triangle> triangles(std::size_t(r.shape(0)));
  for(py::ssize_t i = 0; i < r.shape(0); ++i)
    for(py::ssize_t j = 0; j < 3; ++j) {
      if(r(i, j) < 0 || std::size_t(r(i, j)) >= number_of_points)
        throw std::invalid_argument("faces row " + std::to_string(i) + " has the vertex index " + std::to_string(r(i, j)) +
                                    ", out of [0, " + std::to_string(number_of_points) + ")");
      triangles[std::size_t(i)][std::size_t(j)] = std::size_t(r(i, j));
    }
  if(triangles.empty()) throw std::invalid_argument("faces is empty: give None for a point set");
  return triangles;
}

// The option `name` if given (not None): an integer (a Python or NumPy one, not a bool) or a real
// number, as T asks.
template <typename T>
std::optional<T> option(const py::dict& keywords, const char* name)
{
  if(!keywords.contains(name) || keywords[name].is_none()) return std::nullopt;
  const py::object value = keywords[name];
  if constexpr(std::is_integral_v<T>) {
    if(!PyIndex_Check(value.ptr()) || py::isinstance<py::bool_>(value))
      throw std::invalid_argument(std::string(name) + " must be an integer");
    const long long integer = py::int_(value).cast<long long>();
    if(integer < 0) throw std::invalid_argument(std::string(name) + " must not be negative");
    return T(integer);
  } else {
    try {
      return py::float_(value).cast<T>();
    } catch(const py::error_already_set&) {
      throw std::invalid_argument(std::string(name) + " must be a number");
    }
  }
}

} // namespace

Shape shape_of(const py::array& vertices, const py::object& faces, const py::object& normals)
{
  Shape shape;
  for(const auto& v : float_rows(vertices, "vertices")) shape.points.emplace_back(v[0], v[1], v[2]);
  if(shape.points.empty()) throw std::invalid_argument("vertices is empty");
  if(!faces.is_none()) {
    if(!normals.is_none()) throw std::invalid_argument("normals are taken for a point set only (faces=None)");
    shape.triangles = triangle_rows(py::array::ensure(faces), shape.points.size());
    return shape;
  }
  std::vector<std::array<double, 3>> n(shape.points.size(), {0., 0., 0.});
  if(!normals.is_none()) {
    n = float_rows(py::array::ensure(normals), "normals");
    if(n.size() != shape.points.size())
      throw std::invalid_argument("normals has " + std::to_string(n.size()) + " rows for " +
                                  std::to_string(shape.points.size()) + " points");
    shape.has_normals = true;
  }
  for(std::size_t i = 0; i < n.size(); ++i) shape.oriented_points.emplace_back(shape.points[i], Vector(n[i][0], n[i][1], n[i][2]));
  return shape;
}

Mesh mesh_of(const Shape& shape)
{
  if(shape.is_point_set()) throw std::invalid_argument("this function needs faces: a mesh, not a point set");
  try { // oriented, non-manifold points duplicated, as the demo programs do
    return examples::mesh_of_soup<Mesh>(examples::Triangle_soup<Point>{shape.points, shape.triangles}, true);
  } catch(const std::runtime_error& e) {
    throw std::invalid_argument(std::string("the faces do not form a surface: ") + e.what());
  }
}

py::array_t<double> array_of(const std::vector<Point>& points)
{
  py::array_t<double> a({py::ssize_t(points.size()), py::ssize_t(3)});
  auto w = a.mutable_unchecked<2>();
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int j = 0; j < 3; ++j) w(py::ssize_t(i), j) = points[i][j];
  return a;
}

py::array_t<std::int64_t> array_of(const std::vector<Triangle>& triangles)
{
  py::array_t<std::int64_t> a({py::ssize_t(triangles.size()), py::ssize_t(3)});
  auto w = a.mutable_unchecked<2>();
  for(std::size_t i = 0; i < triangles.size(); ++i)
    for(int j = 0; j < 3; ++j) w(py::ssize_t(i), j) = std::int64_t(triangles[i][std::size_t(j)]);
  return a;
}

py::array_t<double> vector_array(const Vector& v)
{
  py::array_t<double> a(3);
  auto w = a.mutable_unchecked<1>();
  for(int j = 0; j < 3; ++j) w(j) = v[j];
  return a;
}

K::Plane_3 plane_of(const py::array& normal, double offset)
{
  const auto n = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(normal);
  if(!n || n.ndim() != 1 || n.shape(0) != 3) throw std::invalid_argument("a plane's normal must be 3 numbers");
  const Vector v(n.at(0), n.at(1), n.at(2));
  if(!(v.squared_length() > 0.) || !std::isfinite(v.squared_length()) || !std::isfinite(offset))
    throw std::invalid_argument("a plane needs a finite, non-zero normal and a finite offset");
  return K::Plane_3(v.x(), v.y(), v.z(), offset * std::sqrt(v.squared_length()));
}

std::pair<Vector, double> normal_and_offset(const K::Plane_3& plane)
{
  const double length = std::sqrt(plane.orthogonal_vector().squared_length());
  return {plane.orthogonal_vector() / length, plane.d() / length};
}

Options options_of(const py::dict& k)
{
  Options o;
  o.grid_resolution = option<long>(k, "grid_resolution");
  o.gaussian_width = option<double>(k, "gaussian_width");
  o.number_of_samples = option<std::size_t>(k, "number_of_samples");
  o.number_of_refinement_samples = option<std::size_t>(k, "number_of_refinement_samples");
  o.max_number_of_planes = option<std::size_t>(k, "max_number_of_planes");
  o.sde_samples = option<std::size_t>(k, "sde_samples");
  o.max_number_of_proxies = option<std::size_t>(k, "max_number_of_proxies");
  o.max_segmentation_depth = option<std::size_t>(k, "max_segmentation_depth");
  o.max_number_of_segments = option<std::size_t>(k, "max_number_of_segments");
  o.number_of_iterations = option<unsigned>(k, "number_of_iterations");
  o.random_seed = option<unsigned>(k, "random_seed");
  o.number_of_threads = option<unsigned>(k, "number_of_threads");
  o.symmetry_threshold = option<double>(k, "symmetry_threshold");
  o.laplacian_threshold = option<double>(k, "laplacian_threshold");
  o.max_order = option<int>(k, "max_order");
  return o;
}

unsigned threads_of(const Options& options)
{
  return options.number_of_threads.value_or(ST::internal::default_number_of_threads());
}

bool Progress::report(double progress)
{
  py::gil_scoped_acquire gil;
  if(cancelled_ || error_) return false;
  if(PyErr_CheckSignals() != 0) { // Ctrl-C: KeyboardInterrupt is pending
    error_ = std::make_unique<py::error_already_set>();
    return false;
  }
  if(callable_.is_none()) return true;
  try {
    const py::object answer = callable_(progress);
    cancelled_ = !answer.is_none() && !answer.cast<bool>();
  } catch(py::error_already_set& e) {
    error_ = std::make_unique<py::error_already_set>(std::move(e));
  }
  return !cancelled_ && !error_;
}

void Progress::raise_if_stopped()
{
  if(error_) {
    error_->restore();
    error_.reset();
    throw py::error_already_set();
  }
  if(cancelled_) throw Cancelled("the callback returned False: the work was cancelled");
}

} // namespace symmetry_transform_python

PYBIND11_MODULE(_core, m)
{
  namespace stp = symmetry_transform_python;
  m.doc() = "Bindings of CGAL Symmetry_transform; use the package symmetry_transform, which wraps them.";
  pybind11::register_exception<stp::Cancelled>(m, "Cancelled", PyExc_RuntimeError);
  stp::bind_files(m);
  stp::bind_planes(m);
  stp::bind_rotations(m);
  stp::bind_shapes(m);
  stp::bind_meshes(m);
}
