// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PROGRESS_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PROGRESS_H

// Progress and cancellation through CGAL's `callback` named parameter (std::function<bool(double)>).
//
// A public function that takes a callback opens a Progress_scope: while it runs, the calling
// thread (the owner) has an active Progress, which the long loops find without any change of
// their signatures. The owner reports fractions of the current stage (report_progress()); stages
// nest (Progress_stage) and map their [0, 1] onto a part of the enclosing one, so that the values
// passed to the user rise from 0 to 1 in proportion to the work. The user's function is called
// only on the owner thread, at most every callback_interval_seconds, and at 0 and 1: it needs no
// locking. When it returns false, the owner throws Operation_cancelled, which the public function
// catches to return its documented value. Inside parallel_for() the owner runs the first slice,
// calling the callback as it goes (parallel_step(), parallel_poll(), stop_requested()), then
// while it waits for the workers; the workers look at an atomic flag and return early. Without a
// callback nothing is installed: the loops pay one test of a thread-local pointer, and the
// results are those of a run without progress.

#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <optional>
#include <thread>
#include <utility>

namespace CGAL::Symmetry_transform::internal {

// Thrown on the owner thread when the user's callback returns false; the public functions catch
// it. It never leaves the package.
struct Operation_cancelled
{};

// A progress bar needs no more than 50 updates a second; a slow callback (one that prints) then
// costs nothing measurable.
constexpr double callback_interval_seconds = 0.02;
// Workers publish their count and look at the cancel flag every this many items: items take
// microseconds (a closest-point search, a voxel), so the flag is seen within a millisecond while
// the shared counter is touched rarely.
constexpr std::size_t items_per_check = 64;

// The state of a parallel_for() run under a Progress: items done, published by the workers.
struct Parallel_progress
{
  std::atomic<std::size_t> done{0};
  std::size_t count = 0;
  bool reports = false; // its fraction is the owner's report: not nested in another loop's body
};

// The loop of the current thread's parallel_for() body, with its unpublished items.
struct Loop_counter
{
  Parallel_progress* loop = nullptr;
  std::size_t pending = 0;
};
inline thread_local Loop_counter loop_counter;

class Progress
{
public:
  explicit Progress(std::function<bool(double)> callback)
    : callback_(std::move(callback)), owner_(std::this_thread::get_id())
  {}

  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  // The thread that calls the callback: the caller of the public function.
  bool is_callback_thread() const { return std::this_thread::get_id() == owner_; }
  // The owner outside the bodies of parallel_for(): the stages and the reports of the run are
  // its; in a body (slice 0 of a loop runs on the caller) it only keeps the callback called.
  bool on_owner_thread() const { return is_callback_thread() && loop_counter.loop == nullptr; }

  // The current stage, as a part [begin, end] of the whole run.
  std::pair<double, double> stage() const { return {begin_, end_}; }
  void set_stage(std::pair<double, double> stage) { std::tie(begin_, end_) = stage; }

  // On the owner: `fraction` of the current stage done; throws Operation_cancelled if cancelled.
  void report(double fraction)
  {
    if(!call(fraction, false)) throw Operation_cancelled();
  }

  // On the owner: calls the callback if callback_interval_seconds have passed (or if `force`);
  // false once cancelled. A negative `fraction` repeats the last value (work of unknown length).
  // A callback that throws cancels the work, then its exception goes on.
  bool call(double fraction, bool force)
  {
    if(cancelled()) return false;
    // Kept even between calls: the next call, often a poll of a parallel loop that repeats the
    // last value, reports it (else the values of a loop polled more often than 50 times a second,
    // the candidates of a detection, would never be seen).
    if(fraction >= 0.) { // monotone, whatever the stages' estimates
      const double value = std::clamp(begin_ + (std::min)(fraction, 1.) * (end_ - begin_), 0., 1.);
      reported_ = (std::max)(reported_, value);
    }
    const auto now = std::chrono::steady_clock::now();
    if(!force && now - last_call_ < std::chrono::duration<double>(callback_interval_seconds)) return true;
    last_call_ = now;
    bool go_on = false;
    try {
      go_on = callback_(reported_);
    } catch(...) {
      cancel();
      throw;
    }
    if(!go_on) cancel();
    return go_on;
  }

  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }

private:
  std::function<bool(double)> callback_;
  std::thread::id owner_;
  std::atomic<bool> cancelled_{false};
  double begin_ = 0., end_ = 1., reported_ = 0.;
  std::chrono::steady_clock::time_point last_call_{};
};

// The Progress of the public call running on this thread (or, in a worker of parallel_for(), of
// the call that started it); nullptr without a callback.
inline thread_local Progress* active_progress = nullptr;

// Any thread: whether the user has cancelled the work (false without a callback). In a
// parallel_for() body on the owner, it calls the callback when due.
inline bool stop_requested()
{
  Progress* progress = active_progress;
  if(progress == nullptr) return false;
  if(loop_counter.loop != nullptr && progress->is_callback_thread()) progress->call(-1., false);
  return progress->cancelled();
}

// On the owner thread: `fraction` of the current stage done. Throws Operation_cancelled once the
// callback has returned false. In a parallel_for() body, the owner only calls the callback when
// due (the fraction is the loop's); a worker does nothing, nor does anyone without a callback.
inline void report_progress(double fraction)
{
  Progress* progress = active_progress;
  if(progress == nullptr) return;
  if(progress->on_owner_thread())
    progress->report(fraction);
  else if(progress->is_callback_thread() && !progress->call(-1., false))
    throw Operation_cancelled();
}

// The same for item `done` of `count`.
inline void report_progress(std::size_t done, std::size_t count)
{
  if(active_progress != nullptr) report_progress(count == 0 ? 1. : double(done) / double(count));
}

// In work of unknown length (a flooding): on the owner thread, calls the callback now and then
// with the last value; on any thread, throws Operation_cancelled once the work is cancelled (on a
// worker of parallel_for(), the exception reaches the owner).
inline void poll_progress()
{
  Progress* progress = active_progress;
  if(progress == nullptr) return;
  if(progress->is_callback_thread() ? !progress->call(-1., false) : progress->cancelled()) throw Operation_cancelled();
}

// In a sequential loop on the owner thread, at item `i` of `count`: reports every
// sequential_items_per_report items.
constexpr std::size_t sequential_items_per_report = 4096;
inline void sequential_step(std::size_t i, std::size_t count)
{
  if(active_progress != nullptr && i % sequential_items_per_report == 0) report_progress(i, count);
}

// f(), or nothing if the work is cancelled before or while it runs: for a loop that keeps what it
// has (a detection, the planes accepted so far).
template <typename F>
std::optional<decltype(std::declval<const F&>()())> unless_cancelled(const F& f)
{
  try {
    return f();
  } catch(const Operation_cancelled&) {
    return std::nullopt;
  }
}

// Throws Operation_cancelled if the work was cancelled: after a stage that returns early when
// cancelled (a detection returns the planes it has), before using its result. On a worker of
// parallel_for(), the exception reaches the owner.
inline void throw_if_cancelled()
{
  if(stop_requested()) throw Operation_cancelled();
}

// While it lives, the stage [begin, end] of the enclosing stage (fractions of it) is the current
// one. Nothing without a callback.
class Progress_stage
{
public:
  Progress_stage(double begin, double end) : progress_(active_progress)
  {
    if(progress_ == nullptr || !progress_->on_owner_thread()) {
      progress_ = nullptr;
      return;
    }
    enclosing_ = progress_->stage();
    const double width = enclosing_.second - enclosing_.first;
    progress_->set_stage({enclosing_.first + begin * width, enclosing_.first + end * width});
    progress_->call(0., false); // a cancel is seen by the stage's work
  }
  // Moves on to the stage [begin, end] of the same enclosing stage.
  void move_to(double begin, double end)
  {
    if(progress_ == nullptr) return;
    const double width = enclosing_.second - enclosing_.first;
    progress_->set_stage({enclosing_.first + begin * width, enclosing_.first + end * width});
    progress_->call(0., false);
  }
  ~Progress_stage()
  {
    if(progress_ != nullptr) progress_->set_stage(enclosing_);
  }
  Progress_stage(const Progress_stage&) = delete;
  Progress_stage& operator=(const Progress_stage&) = delete;

private:
  Progress* progress_;
  std::pair<double, double> enclosing_;
};

// Opened by each public function that takes a `callback`: installs its Progress on the calling
// thread, calls the callback with 0 at once and with 1 at finish(). A public function called by
// another (the transform of a mesh computes its GEDT) reports into its caller's current stage
// instead: only the outermost scope installs.
class Progress_scope
{
public:
  template <typename NamedParameters>
  explicit Progress_scope(const NamedParameters& np)
  {
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::callback_t>::value) {
      std::function<bool(double)> callback = parameters::get_parameter(np, internal_np::callback);
      if(callback && active_progress == nullptr) {
        own_.emplace(std::move(callback));
        active_progress = &*own_;
        start_ = own_->call(0., true);
      }
    }
  }
  ~Progress_scope()
  {
    if(own_) active_progress = nullptr;
  }
  Progress_scope(const Progress_scope&) = delete;
  Progress_scope& operator=(const Progress_scope&) = delete;

  // Throws Operation_cancelled if the callback returned false at the first call.
  void started() const
  {
    if(!start_) throw Operation_cancelled();
  }
  // The work is done: reports 1 (the callback's answer no longer matters).
  void finish()
  {
    if(own_ && !own_->cancelled()) own_->call(1., true);
  }

private:
  std::optional<Progress> own_;
  bool start_ = true;
};

// The body of a public function: work() under the callback of `np`, or if_cancelled() when the
// user cancels, the documented value. A nested public function returns its value as well: its
// caller, whose next report throws, tests stop_requested() before using it.
template <typename NamedParameters, typename Work, typename If_cancelled>
auto with_progress(const NamedParameters& np, const Work& work, const If_cancelled& if_cancelled) -> decltype(work())
{
  Progress_scope scope(np);
  try {
    scope.started();
    auto result = work();
    scope.finish();
    return result;
  } catch(const Operation_cancelled&) {
    return if_cancelled();
  }
}

// work() under the callback of `np`, for a public function made of public functions that return
// their own documented values when cancelled (the transform of a mesh: its GEDT, then the transform).
template <typename NamedParameters, typename Work>
auto with_progress_scope(const NamedParameters& np, const Work& work) -> decltype(work())
{
  Progress_scope scope(np);
  auto result = work();
  scope.finish();
  return result;
}

// f() with no progress reported nor polled on this thread: for work that a cancel must not
// interrupt, as the reading of the triangles whose frame places a GEDT (a cancelled GEDT is a grid
// of zeros of that geometry).
template <typename F>
auto without_progress(const F& f) -> decltype(f())
{
  struct Pause
  {
    Progress* saved = active_progress;
    Loop_counter saved_counter = loop_counter;
    Pause()
    {
      active_progress = nullptr;
      loop_counter = {};
    }
    ~Pause()
    {
      active_progress = saved;
      loop_counter = saved_counter;
    }
  } pause;
  return f();
}

// In a parallel_for() body, after each item: false when the work is cancelled, the body then
// returns at once. Counts the items for the owner's report; `check_every`: 1 for items that take
// milliseconds. Does nothing without a callback.
inline bool parallel_step(std::size_t check_every = items_per_check)
{
  Loop_counter& counter = loop_counter;
  if(counter.loop == nullptr || ++counter.pending < check_every) return true;
  const std::size_t done = counter.loop->done.fetch_add(counter.pending, std::memory_order_relaxed) + counter.pending;
  counter.pending = 0;
  Progress* progress = active_progress;
  if(progress->is_callback_thread()) // slice 0 of a loop run by the owner
    progress->call(counter.loop->reports ? double(done) / double(counter.loop->count) : -1., false);
  return !progress->cancelled();
}

// In a parallel_for() body whose items are not counted (each thread walks its own chunks): false
// when the work is cancelled. On the owner it keeps the callback called.
inline bool parallel_poll()
{
  Progress* progress = active_progress;
  if(progress == nullptr) return true;
  if(progress->is_callback_thread()) progress->call(-1., false);
  return !progress->cancelled();
}

// Installs `progress` and the loop counter on a thread for the time of a parallel_for() body.
class Worker_progress_scope
{
public:
  Worker_progress_scope(Progress* progress, Parallel_progress* loop)
    : previous_progress_(active_progress), previous_counter_(loop_counter)
  {
    active_progress = progress;
    loop_counter = {loop, 0};
  }
  ~Worker_progress_scope()
  {
    active_progress = previous_progress_;
    loop_counter = previous_counter_;
  }
  Worker_progress_scope(const Worker_progress_scope&) = delete;
  Worker_progress_scope& operator=(const Worker_progress_scope&) = delete;

private:
  Progress* previous_progress_;
  Loop_counter previous_counter_;
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_PROGRESS_H
