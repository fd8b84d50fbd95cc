// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARALLEL_FOR_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARALLEL_FOR_H

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

inline unsigned default_number_of_threads()
{
  return std::max(1u, std::thread::hardware_concurrency());
}

// Runs body(thread, begin, end) on `threads` contiguous, fixed slices of [0, count): the
// split depends only on `count` and `threads`, so per-thread results are reproducible. The
// calling thread runs slice 0 itself: one thread fewer to start, which matters for the many
// short calls of ISP (a start costs tens of microseconds). The first exception thrown by a body
// is rethrown in the caller, once every slice is done.
template <typename Body>
void parallel_for(std::size_t count, unsigned threads, const Body& body)
{
  threads = unsigned(std::max<std::size_t>(1, std::min<std::size_t>(threads, count)));
  if(threads == 1) {
    body(0u, std::size_t(0), count);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  auto run = [&](unsigned t) {
    try {
      body(t, count * t / threads, count * (t + 1) / threads);
    } catch(...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  for(unsigned t = 1; t < threads; ++t) workers.emplace_back(run, t);
  run(0u);
  for(std::thread& w : workers) w.join();
  for(const std::exception_ptr& e : errors)
    if(e) std::rethrow_exception(e);
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARALLEL_FOR_H
