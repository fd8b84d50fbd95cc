// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers
//
// The layout of the fuzzer's input, shared by the fuzz target (which reads it) and the seed writer
// (which writes it); plain C++, no CGAL, so that the seed writer compiles in a second.
//
// Bytes, in order (a byte past the end reads as 0):
//   entry        the public function called (Entry_point, modulo its count)
//   options      bit 0: grid 16 (else 8); bit 1: 2 threads (else 1); bit 2: coordinates as raw
//                doubles (else small integers scaled); bit 3: the exact PRST (grid 8 only);
//                bits 4-5: the Monte Carlo estimator; bit 6: a callback that cancels; bit 7: a
//                Gaussian width out of the accepted range
//   counts       bits 0-1: number_of_samples, 2-3: number_of_refinement_samples,
//                4-5: number_of_iterations, 6-7: max_number_of_planes / max_order
//   width_seed   bits 0-1: the Gaussian width, 2-3: number_of_points_on_faces, 4-7: random_seed
//   cancel_after the callback returns false from its (1 + this % 8)-th call
//   point_count  the number of points, at most max_points
//   placement    integer coordinates only: bits 0-2 the scale, 3-5 the offset of every coordinate
//   points       3 coordinates each: 8 bytes (a double, memcpy) or 1 byte (a signed integer / 16)
//   normals      as the points (read for every entry point; used where a normal map is taken)
//   plane        4 signed bytes: a, b, c, d of the plane of the symmetry distance error
//   triangles    3 bytes each, up to max_triangles: point indices; 255 reads as SIZE_MAX, and any
//                index may lie past the points

#ifndef CGAL_SYMMETRY_TRANSFORM_TEST_FUZZ_INPUT_H
#define CGAL_SYMMETRY_TRANSFORM_TEST_FUZZ_INPUT_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace st_fuzz {

enum Entry_point : std::uint8_t {
  PRINCIPAL_SYMMETRIES_OF_TRIANGLE_SOUP,
  PRINCIPAL_SYMMETRIES_OF_POINTS,
  PRINCIPAL_SYMMETRIES_OF_POINTS_WITH_NORMALS,
  ROTATIONAL_SYMMETRIES_OF_POINTS,
  REFLECTIVE_SYMMETRY_TRANSFORM_OF_POINTS,
  REFLECTIVE_SYMMETRY_TRANSFORM_OF_TRIANGLE_SOUP,
  POINT_SYMMETRY_TRANSFORM_OF_POINTS,
  POINT_SYMMETRY_TRANSFORM_OF_TRIANGLE_SOUP,
  SYMMETRY_FRAME_OF_POINTS,
  SYMMETRY_FRAME_OF_POINTS_WITH_NORMALS,
  SYMMETRY_FRAME_OF_TRIANGLE_SOUP,
  SYMMETRY_DISTANCE_ERROR_OF_TRIANGLE_SOUP,
  SYMMETRY_DISTANCE_ERROR_OF_POINTS,
  NUMBER_OF_ENTRY_POINTS
};

namespace option {
constexpr std::uint8_t grid_16 = 1, two_threads = 2, raw_doubles = 4, exact_prst = 8, cancel = 64,
                       bad_width = 128;
}

constexpr std::size_t max_points = 64;
constexpr std::size_t max_triangles = 64;

typedef std::array<double, 3> Triple;
typedef std::array<std::size_t, 3> Triangle;

// The decoded input: the parameters as the fuzz target passes them, and the shape.
struct Input
{
  Entry_point entry = PRINCIPAL_SYMMETRIES_OF_TRIANGLE_SOUP;
  int grid_resolution = 8;
  double gaussian_width = 0.5;
  unsigned number_of_threads = 1;
  bool exact_prst = false;
  int estimator = 0;  // 0..2, the order of Monte_carlo_estimator; 3 reads as the default
  bool cancel = false;
  int cancel_after = 1;
  std::size_t number_of_samples = 1, number_of_refinement_samples = 1, number_of_points_on_faces = 1;
  unsigned number_of_iterations = 0;
  std::size_t max_number_of_planes = 1;
  int max_order = 2;
  unsigned random_seed = 0;
  std::vector<Triple> points, normals;
  std::array<double, 4> plane{};
  std::vector<Triangle> triangles;
};

class Reader
{
public:
  Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  double raw_double()
  {
    std::uint8_t bytes[8];
    for(std::uint8_t& b : bytes) b = byte();
    double x;
    std::memcpy(&x, bytes, sizeof x);
    return x;
  }
  bool at_end() const { return pos_ >= size_; }

private:
  const std::uint8_t* data_;
  std::size_t size_, pos_ = 0;
};

// Integer coordinates: (signed byte) / 16 in [-8, 8), times a scale, plus an offset: many equal,
// coplanar and collinear points, shapes far from the origin, tiny and huge ones.
inline double scale_of(int i)
{
  static const double scales[8] = {1., 0.25, 1e-3, 1e3, 1e-6, 1e6, 1e-99, 1e99};
  return scales[i & 7];
}
inline double offset_of(int i)
{
  static const double offsets[8] = {0., 0., 0.5, 100., 1e3, 1e6, 1e9, -1e12};
  return offsets[i & 7];
}

inline Triple read_triple(Reader& in, bool raw, double scale, double offset)
{
  Triple t;
  for(double& c : t)
    c = raw ? in.raw_double() : offset + scale * double(std::int8_t(in.byte()) / 16);
  return t;
}

inline Input decode(const std::uint8_t* data, std::size_t size)
{
  Reader in(data, size);
  Input input;
  input.entry = Entry_point(in.byte() % NUMBER_OF_ENTRY_POINTS);
  const std::uint8_t options = in.byte(), counts = in.byte(), width_seed = in.byte();
  input.cancel_after = 1 + in.byte() % 8;
  input.grid_resolution = (options & option::grid_16) ? 16 : 8;
  input.number_of_threads = (options & option::two_threads) ? 2 : 1;
  input.exact_prst = (options & option::exact_prst) && input.grid_resolution == 8;
  input.estimator = (options >> 4) & 3;
  input.cancel = options & option::cancel;
  // Accepted: more than 12 widths in the grid; then one width just too wide, and absurd ones.
  static const double widths_8[4] = {0.5, 0.6, 0.66, 0.3}, widths_16[4] = {0.6, 1.0, 1.3, 0.75};
  static const double bad_widths[4] = {0.67, 1.5, 0., -1.};
  const int w = width_seed & 3;
  input.gaussian_width = (options & option::bad_width) ? bad_widths[w]
                         : input.grid_resolution == 8   ? widths_8[w]
                                                        : widths_16[w];
  static const std::size_t samples[4] = {1, 200, 2000, 20000}, refinement[4] = {1, 10, 100, 500},
                           on_faces[4] = {1, 10, 100, 1000}, planes[4] = {1, 2, 4, 10};
  static const unsigned iterations[4] = {0, 1, 3, 8};
  static const int orders[4] = {2, 3, 4, 7};
  input.number_of_samples = samples[counts & 3];
  input.number_of_refinement_samples = refinement[(counts >> 2) & 3];
  input.number_of_iterations = iterations[(counts >> 4) & 3];
  input.max_number_of_planes = planes[(counts >> 6) & 3];
  input.max_order = orders[(counts >> 6) & 3];
  input.number_of_points_on_faces = on_faces[(width_seed >> 2) & 3];
  input.random_seed = width_seed >> 4;

  const std::size_t n = in.byte() % (max_points + 1);
  const bool raw = options & option::raw_doubles;
  const std::uint8_t placement = in.byte();
  const double scale = scale_of(placement), offset = offset_of(placement >> 3);
  for(std::size_t i = 0; i < n; ++i) input.points.push_back(read_triple(in, raw, scale, offset));
  for(std::size_t i = 0; i < n; ++i) input.normals.push_back(read_triple(in, raw, 1., 0.));
  for(double& c : input.plane) c = double(std::int8_t(in.byte()));
  while(!in.at_end() && input.triangles.size() < max_triangles) {
    Triangle t;
    for(std::size_t& v : t) {
      const std::uint8_t b = in.byte();
      v = b == 255 ? (std::numeric_limits<std::size_t>::max)() : std::size_t(b);
    }
    input.triangles.push_back(t);
  }
  return input;
}

} // namespace st_fuzz

#endif // CGAL_SYMMETRY_TRANSFORM_TEST_FUZZ_INPUT_H
