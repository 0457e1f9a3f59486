// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parallel loops of the three packages, in one place: TBB's parallel_for over index
// ranges, or, in the ThreadSanitizer build, the same chunks on std::threads; and two jobs side by
// side (a TBB task, or a std::thread there).

#ifndef CGAL_VVM_INTERNAL_PARALLEL_FOR_H
#define CGAL_VVM_INTERNAL_PARALLEL_FOR_H

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#ifdef CGAL_VVM_PARALLEL_FOR_STD_THREADS
// the ThreadSanitizer build's loops
#include <tbb/global_control.h>
#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>
#endif

#include <cstddef>
#include <exception>

namespace CGAL {
namespace VVM {
namespace internal {

typedef tbb::blocked_range<std::size_t> Index_range;

/// `body(range)` for ranges of at least `grain` indices covering [0, n), in parallel; the
/// ranges are independent. Built with `CGAL_VVM_PARALLEL_FOR_STD_THREADS` (set by
/// `VVM_SANITIZE=thread`), the ranges go to std::threads instead of TBB's workers:
/// ThreadSanitizer cannot see oneTBB's joins (made with `atomic_thread_fence`) and reports the
/// results read after every `tbb::parallel_for` as races; it sees a `std::thread::join()`.
template <class Body>
void parallel_for_ranges(std::size_t n, std::size_t grain, const Body& body)
{
#ifndef CGAL_VVM_PARALLEL_FOR_STD_THREADS
  tbb::parallel_for(Index_range(0, n, grain), body);
#else
  if(n == 0) return;
  const std::size_t threads = (std::max)(std::size_t(1), (std::min)(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism), std::size_t(std::thread::hardware_concurrency())));
  const std::size_t chunk = (std::max)(grain, n / (8 * threads) + 1), workers = (std::min)(threads, (n + chunk - 1) / chunk);
  // chunk k to thread k mod workers: an atomic handing out chunks would order them for ThreadSanitizer
  std::atomic<std::size_t> started(0);
  std::vector<std::exception_ptr> errors(workers); // as tbb::parallel_for: an exception reaches the caller
  auto work = [&](std::size_t t) {
    for(++started; started < workers;) std::this_thread::yield(); // all start: none runs the loop alone
    try {
      for(std::size_t b = t * chunk; b < n; b += workers * chunk)
        body(Index_range(b, (std::min)(n, b + chunk), chunk));
    } catch(...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for(std::size_t t = 1; t < workers; ++t) pool.emplace_back(work, t);
  work(0);
  for(std::thread& t : pool) t.join();
  for(const std::exception_ptr& e : errors)
    if(e) std::rethrow_exception(e);
#endif
}

/// `f(i)` for each i in [0, n), in parallel (each i independent)
template <class F>
void parallel_for_each_index(std::size_t n, const F& f, std::size_t grain = 256)
{
  parallel_for_ranges(n, grain, [&](const Index_range& r) {
    for(std::size_t i = r.begin(); i != r.end(); ++i) f(i);
  });
}

/// `beside()` on another thread while this one runs `main()`; both have ended when it returns.
/// A TBB task: with no free worker (one thread allowed, say) this thread runs it once `main()`
/// is done. An exception of `main()` is the one thrown (`beside()` is then cancelled if it has not
/// started, and its own exception dropped), else one of `beside()`.
template <class Beside, class Main>
void run_beside(const Beside& beside, const Main& main)
{
#ifndef CGAL_VVM_PARALLEL_FOR_STD_THREADS
  tbb::task_group group;
  group.run(beside);
  try {
    main();
  } catch(...) {
    group.cancel();
    try {
      group.wait();
    } catch(...) {
    }
    throw;
  }
  group.wait();
#else
  if(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) < 2) {
    main();
    beside();
    return;
  }
  std::exception_ptr error;
  std::thread other([&] {
    try {
      beside();
    } catch(...) {
      error = std::current_exception();
    }
  });
  try {
    main();
  } catch(...) {
    other.join();
    throw;
  }
  other.join();
  if(error) std::rethrow_exception(error);
#endif
}

} // namespace internal
} // namespace VVM
} // namespace CGAL

#endif // CGAL_VVM_INTERNAL_PARALLEL_FOR_H
