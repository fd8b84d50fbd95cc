// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef SYMMETRY_TRANSFORM_PYTHON_COMMON_H
#define SYMMETRY_TRANSFORM_PYTHON_COMMON_H

// What the bindings share: NumPy arrays to the package's inputs and back, the keyword options
// to named parameters, and the Python callback as the package's `callback`, which also stops the
// work on Ctrl-C. Every check of a Python object is done holding the GIL, before the work, which
// runs without it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Symmetry_transform/internal/common/defaults.h>

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace symmetry_transform_python {

namespace py = pybind11;
namespace ST = CGAL::Symmetry_transform;
namespace defaults = CGAL::Symmetry_transform::internal::defaults;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef std::array<std::size_t, 3> Triangle;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::pair<Point, Vector> Point_with_normal;

// What a shape given from Python is: triangles (a soup) or points, with or without normals.
struct Shape
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;   // empty for a point set
  std::vector<Point_with_normal> oriented_points; // the point set, normals NULL_VECTOR if none
  bool has_normals = false;
  bool is_point_set() const { return triangles.empty(); }
};

// The shape of V (n x 3 floats), F (m x 3 integers or None) and N (n x 3 floats or None);
// throws std::invalid_argument, Python's ValueError, naming the array and what is wrong.
Shape shape_of(const py::array& vertices, const py::object& faces, const py::object& normals);
// The mesh of a soup, face i its triangle i: oriented, its non-manifold points duplicated;
// throws std::invalid_argument if even that gives no surface.
Mesh mesh_of(const Shape& shape);

py::array_t<double> array_of(const std::vector<Point>& points);
py::array_t<std::int64_t> array_of(const std::vector<Triangle>& triangles);
py::array_t<double> vector_array(const Vector& v);
K::Plane_3 plane_of(const py::array& normal, double offset);
// The unit normal n and offset o of a plane, n.x + o = 0.
std::pair<Vector, double> normal_and_offset(const K::Plane_3& plane);

// The keyword options of a call, each unset unless given; the binding of each function reads
// those it takes (Python rejects the others) and uses the package's default for the rest.
struct Options
{
  std::optional<long> grid_resolution;
  std::optional<double> gaussian_width;
  std::optional<std::size_t> number_of_samples, number_of_refinement_samples, max_number_of_planes, sde_samples,
    max_number_of_proxies, max_segmentation_depth, max_number_of_segments;
  std::optional<unsigned> number_of_iterations, random_seed, number_of_threads;
  std::optional<double> symmetry_threshold, laplacian_threshold;
  std::optional<int> max_order;
};
Options options_of(const py::dict& keywords);
unsigned threads_of(const Options& options);

// The named parameters of a detection of principal symmetries (and of what builds on one): the
// package's defaults where the options are unset. `max_number_of_planes` is passed only if
// given: unset, whole groups of planes are returned.
template <typename Callback, typename Work>
auto with_detection_parameters(const Options& o, const Callback& callback, const Work& work)
{
  const auto np =
    CGAL::parameters::grid_resolution(int(o.grid_resolution.value_or(defaults::grid_resolution)))
      .gaussian_width(o.gaussian_width.value_or(defaults::gaussian_width))
      .number_of_samples(o.number_of_samples.value_or(defaults::detection_monte_carlo_pairs))
      .number_of_refinement_samples(o.number_of_refinement_samples.value_or(defaults::refinement_samples))
      .number_of_iterations(o.number_of_iterations.value_or(defaults::isp_iterations))
      .symmetry_threshold(o.symmetry_threshold.value_or(defaults::symmetry_threshold))
      .laplacian_threshold(o.laplacian_threshold.value_or(defaults::laplacian_threshold))
      .random_seed(o.random_seed.value_or(defaults::random_seed))
      .number_of_threads(threads_of(o))
      .callback(callback);
  return o.max_number_of_planes ? work(np.max_number_of_planes(*o.max_number_of_planes)) : work(np);
}

// The state of a call's progress: the Python callable, and why the work stopped if it did.
class Progress
{
public:
  explicit Progress(py::object callable) : callable_(std::move(callable)) {}
  bool report(double progress);   // the package's callback: takes the GIL
  void raise_if_stopped();        // KeyboardInterrupt, the callable's error, or Cancelled

private:
  py::object callable_;
  bool cancelled_ = false;
  std::unique_ptr<py::error_already_set> error_;
};

// The C++ exception that the module raises as symmetry_transform.Cancelled.
struct Cancelled : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Runs work(callback) without the GIL, then raises what stopped it, if anything. The callback
// holds the progress by a shared pointer: the package copies it without the GIL, which a
// Python object's reference count cannot take.
template <typename Work>
auto run_without_gil(const py::object& callable, const Work& work)
{
  auto progress = std::make_shared<Progress>(callable);
  const std::function<bool(double)> callback = [progress](double p) { return progress->report(p); };
  std::optional<decltype(work(callback))> result;
  {
    py::gil_scoped_release release;
    result.emplace(work(callback));
  }
  progress->raise_if_stopped();
  return std::move(*result);
}

void bind_files(py::module_& m);
void bind_planes(py::module_& m);
void bind_rotations(py::module_& m);
void bind_shapes(py::module_& m);
void bind_meshes(py::module_& m);

} // namespace symmetry_transform_python

#endif // SYMMETRY_TRANSFORM_PYTHON_COMMON_H
