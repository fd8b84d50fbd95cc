// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_WORKER_POOL_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_WORKER_POOL_H

// Threads kept from one parallel loop to the next. A detection runs hundreds of loops of a
// fraction of a millisecond each (the fits of ISP): starting a thread costs tens of
// microseconds, and so does waking a sleeping one. The workers wait for the next loop spinning
// for a while, then asleep. The pool serves one loop at a time; a loop that finds it busy
// (another caller's, or one nested in a worker) starts threads of its own.

#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace CGAL::Symmetry_transform::internal {

// How long a worker, or the caller waiting for the workers, spins before it sleeps: longer than
// the gap between two fits of ISP (tens of microseconds), short enough to cost nothing when the
// work is over.
constexpr double worker_spin_seconds = 2e-4;

// Waits on `signal` until `ready()`, calling `waiting()` every `interval` seconds meanwhile.
template <typename Ready>
void wait_calling(std::mutex& mutex, std::condition_variable& signal, const Ready& ready,
                  const std::function<void()>& waiting, double interval)
{
  std::unique_lock<std::mutex> lock(mutex);
  while(!signal.wait_for(lock, std::chrono::duration<double>(interval), ready)) {
    lock.unlock();
    waiting();
    lock.lock();
  }
}

class Worker_pool
{
public:
  // The pool of this process. A child made by fork() has none of its parent's threads: it gets a
  // pool of its own, and the parent's, whose threads it cannot join, is left alone.
  static Worker_pool& instance();

  // Runs task(t) for every t in [0, threads): t = 0 on the calling thread, the others on workers.
  // `task` must not throw. Returns false, having run nothing, if the pool is busy. While the
  // caller waits for the workers, it calls `waiting` (if any) every `waiting_interval` seconds.
  bool run(unsigned threads, const std::function<void(unsigned)>& task, const std::function<void()>& waiting = {},
           double waiting_interval = 0.);

private:
  Worker_pool() : process_(current_process()) {}

  static long current_process();

  static bool& in_worker();

  // Returns once `ready()`: spinning for worker_spin_seconds, then asleep on `signal`.
  template <typename Ready>
  void wait_until(const Ready& ready, std::condition_variable& signal)
  {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(worker_spin_seconds);
    while(!ready())
      if(std::chrono::steady_clock::now() > end) {
        std::unique_lock<std::mutex> lock(mutex_);
        signal.wait(lock, ready);
        return;
      }
  }

  // Worker `index` runs task(index) of every loop that has that many participants.
  void serve(unsigned index);

  const long process_;
  std::atomic<bool> busy_{false};
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void(unsigned)>* task_ = nullptr;
  unsigned participants_ = 0;
  std::atomic<unsigned> pending_{0};
  std::atomic<std::size_t> generation_{0};
};

#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE Worker_pool& Worker_pool::instance()
{
  static Worker_pool* pool = new Worker_pool(); // never destroyed: its workers wait until exit
  static std::mutex replacing;
  if(pool->process_ != current_process()) {
    std::lock_guard<std::mutex> lock(replacing);
    if(pool->process_ != current_process()) pool = new Worker_pool();
  }
  return *pool;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool Worker_pool::run(unsigned threads, const std::function<void(unsigned)>& task,
                                                          const std::function<void()>& waiting, double waiting_interval)
{
  if(in_worker() || busy_.exchange(true, std::memory_order_acquire)) return false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    while(workers_.size() + 1 < threads) {
      const unsigned index = unsigned(workers_.size()) + 1;
      workers_.emplace_back([this, index] { serve(index); });
    }
    task_ = &task;
    participants_ = threads;
    pending_.store(threads - 1, std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  task(0u);
  const auto finished = [&] { return pending_.load(std::memory_order_acquire) == 0; };
  if(waiting)
    wait_calling(mutex_, done_, finished, waiting, waiting_interval);
  else
    wait_until(finished, done_);
  busy_.store(false, std::memory_order_release);
  return true;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE long Worker_pool::current_process()
{
#if defined(__unix__) || defined(__APPLE__)
  return long(getpid());
#else
  return 0;
#endif
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE bool& Worker_pool::in_worker()
{
  static thread_local bool flag = false;
  return flag;
}

CGAL_SYMMETRY_TRANSFORM_CORE_INLINE void Worker_pool::serve(unsigned index)
{
  in_worker() = true;
  std::size_t seen = 0;
  for(;;) {
    wait_until([&] { return generation_.load(std::memory_order_acquire) != seen; }, wake_);
    const std::function<void(unsigned)>* task;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      seen = generation_.load(std::memory_order_relaxed);
      if(index >= participants_) continue;
      task = task_;
    }
    (*task)(index);
    std::lock_guard<std::mutex> lock(mutex_); // so that the caller cannot miss the signal
    if(pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) done_.notify_one();
  }
}

#endif // CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_WORKER_POOL_H
