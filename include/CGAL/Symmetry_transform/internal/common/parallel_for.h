// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARALLEL_FOR_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARALLEL_FOR_H

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/worker_pool.h>

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

inline unsigned default_number_of_threads()
{
  return std::max(1u, std::thread::hardware_concurrency());
}

// A reference to a loop body body(thread, begin, end) of any type: the loops below are compiled
// once for all their callers, which only add the call through a function pointer (one per slice).
class Slice_body
{
public:
  template <typename Body>
  Slice_body(const Body& body)
    : body_(&body), call_([](const void* b, unsigned thread, std::size_t begin, std::size_t end) {
        (*static_cast<const Body*>(b))(thread, begin, end);
      })
  {}
  void operator()(unsigned thread, std::size_t begin, std::size_t end) const { call_(body_, thread, begin, end); }

private:
  const void* body_;
  void (*call_)(const void*, unsigned, std::size_t, std::size_t);
};

// Runs run(t) for every t in [0, threads): t = 0 on the calling thread, the others on the
// workers of Worker_pool, or on threads of their own when the pool is busy (another caller's
// loop, or a loop nested in a worker). `run` must not throw. While the caller waits for the
// others, it calls `waiting` (if any) every callback_interval_seconds.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void run_slices(unsigned threads, const std::function<void(unsigned)>& run,
                                                    const std::function<void()>& waiting = {});

// parallel_for() under a Progress: every slice sees it (parallel_step(), stop_requested()). The
// owner, which runs slice 0 when it calls the loop, calls the callback as it goes and while it
// waits for the others, then throws Operation_cancelled if the work was cancelled; a loop nested
// in a body reports no fraction of its own. A callback that throws stops the workers, and its
// exception goes on before theirs.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void parallel_for_with_progress(Progress& progress, std::size_t count, unsigned threads, Slice_body body);

// Runs body(thread, begin, end) on `threads` contiguous slices of [0, count). The slices change
// with the thread count: each item's result must depend on the item alone (results summed over
// items go through parallel_for_chunks(), whose chunks do not depend on the threads). The
// calling thread runs slice 0 itself: one thread fewer to start, which matters for the many
// short calls of ISP. The first exception thrown by a body is rethrown in the caller, once every
// slice is done. Under a callback (progress.h), bodies call parallel_step() after each item, or
// test stop_requested(), and return when cancelled.
CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void parallel_for(std::size_t count, unsigned threads, Slice_body body);

// Runs body(chunk) for every chunk of [0, chunks), thread t taking the chunks t, t + threads, ...
// (interleaved: neighbouring chunks often cost alike, so every thread gets its share). For work
// whose results are kept per chunk and combined in chunk order by the caller: they then depend on
// the chunks alone, never on the thread count. Stops early when the work is cancelled.
template <typename Body>
void parallel_for_chunks(std::size_t chunks, unsigned threads, const Body& body)
{
  threads = unsigned(std::max<std::size_t>(1, std::min<std::size_t>(threads, chunks)));
  parallel_for(threads, threads, [&](unsigned thread, std::size_t, std::size_t) {
    for(std::size_t c = thread; c < chunks && parallel_poll(); c += threads) body(c);
  });
}

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void run_slices(unsigned threads, const std::function<void(unsigned)>& run,
                                                    const std::function<void()>& waiting)
{
  if(threads == 1) return run(0u);
  if(Worker_pool::instance().run(threads, run, waiting, callback_interval_seconds)) return;
  std::mutex mutex;
  std::condition_variable finished;
  unsigned running = threads - 1;
  std::vector<std::thread> workers;
  for(unsigned t = 1; t < threads; ++t)
    workers.emplace_back([&, t] {
      run(t);
      std::lock_guard<std::mutex> lock(mutex);
      --running;
      finished.notify_one();
    });
  run(0u);
  const auto done = [&] { return running == 0; };
  if(waiting) {
    wait_calling(mutex, finished, done, waiting, callback_interval_seconds);
  } else {
    std::unique_lock<std::mutex> lock(mutex);
    finished.wait(lock, done);
  }
  for(std::thread& w : workers) w.join();
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void parallel_for_with_progress(Progress& progress, std::size_t count, unsigned threads, Slice_body body)
{
  Parallel_progress loop;
  loop.count = count;
  loop.reports = progress.on_owner_thread();
  std::vector<std::exception_ptr> errors(threads + 1); // the last for the callback's
  run_slices(
    threads,
    [&](unsigned t) {
      try {
        Worker_progress_scope scope(&progress, &loop);
        body(t, count * t / threads, count * (t + 1) / threads);
      } catch(...) {
        errors[t] = std::current_exception();
      }
    },
    [&] {
      if(!progress.is_callback_thread()) return;
      try {
        progress.call(loop.reports ? double(loop.done.load(std::memory_order_relaxed)) / double(count) : -1., false);
      } catch(...) {
        if(!errors[threads]) errors[threads] = std::current_exception();
      }
    });
  if(errors[threads]) std::rethrow_exception(errors[threads]);
  for(const std::exception_ptr& e : errors)
    if(e) std::rethrow_exception(e);
  if(progress.cancelled()) throw Operation_cancelled();
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void parallel_for(std::size_t count, unsigned threads, Slice_body body)
{
  threads = unsigned(std::max<std::size_t>(1, std::min<std::size_t>(threads, count)));
  if(active_progress != nullptr)
    return parallel_for_with_progress(*active_progress, count, threads, body);
  std::vector<std::exception_ptr> errors(threads);
  run_slices(threads, [&](unsigned t) {
    try {
      body(t, count * t / threads, count * (t + 1) / threads);
    } catch(...) {
      errors[t] = std::current_exception();
    }
  });
  for(const std::exception_ptr& e : errors)
    if(e) std::rethrow_exception(e);
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PARALLEL_FOR_H
