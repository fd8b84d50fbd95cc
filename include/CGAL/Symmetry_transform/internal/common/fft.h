// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_FFT_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_FFT_H

// Thin RAII layer over FFTW (double precision): aligned buffers, and plans created under one
// lock because FFTW's planner is not thread-safe (executing a plan is).

#include <fftw3.h>

#include <algorithm>
#include <complex>
#include <cstddef>
#include <memory>
#include <mutex>
#include <new>

namespace CGAL::Symmetry_transform::internal {

inline std::mutex& fftw_planner_mutex()
{
  static std::mutex m;
  return m;
}

template <typename T>
struct Fftw_deleter
{
  void operator()(T* p) const { fftw_free(p); }
};

template <typename T>
using Fftw_buffer = std::unique_ptr<T[], Fftw_deleter<T>>;

template <typename T>
Fftw_buffer<T> fftw_buffer(std::size_t size)
{
  T* p = static_cast<T*>(fftw_malloc(sizeof(T) * size));
  if(p == nullptr) throw std::bad_alloc();
  for(std::size_t i = 0; i < size; ++i) new(p + i) T();
  return Fftw_buffer<T>(p);
}

struct Fftw_plan_deleter
{
  void operator()(fftw_plan_s* p) const
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(p);
  }
};

typedef std::unique_ptr<fftw_plan_s, Fftw_plan_deleter> Fftw_plan;

// Forward real-to-complex transform of a real array of dimensions dims[0..rank).
inline Fftw_plan real_to_complex_plan(int rank, const int* dims, double* in, fftw_complex* out, int howmany = 1)
{
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  int real_size = 1, complex_size = 1;
  for(int d = 0; d < rank; ++d) {
    real_size *= dims[d];
    complex_size *= d + 1 < rank ? dims[d] : dims[d] / 2 + 1;
  }
  return Fftw_plan(fftw_plan_many_dft_r2c(rank, dims, howmany, in, nullptr, 1, real_size, out, nullptr, 1,
                                          complex_size, FFTW_ESTIMATE));
}

// Inverse (unnormalised) complex-to-real transform; destroys its input.
inline Fftw_plan complex_to_real_plan(int rank, const int* dims, fftw_complex* in, double* out)
{
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  return Fftw_plan(fftw_plan_dft_c2r(rank, dims, in, out, FFTW_ESTIMATE));
}

// Smallest size >= n whose prime factors are 2, 3 and 5: the sizes FFTW is fastest on.
inline int fft_friendly_size(int n)
{
  for(int m = (std::max)(n, 1);; ++m) {
    int r = m;
    for(int p : {2, 3, 5})
      while(r % p == 0) r /= p;
    if(r == 1) return m;
  }
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_FFT_H
