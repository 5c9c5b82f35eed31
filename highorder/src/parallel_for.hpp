// A parallel loop over indices for the element-local stages (curving, splitting, certification).
// Each index writes only its own output slot, so the result does not depend on the thread count.
// An exception thrown by the body is caught inside the parallel region (it may not leave it) and
// the one of the lowest index is rethrown afterwards, the same one a serial loop would throw.
// Progress: every thread counts its finished indices; only the first thread (the caller's when
// serial) reports, so the callback never runs concurrently and costs the others one atomic add.
#pragma once

#include "semimesh/progress.hpp"

#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace semimesh::ho::detail {

/// While it lives, this thread's OpenMP loops run on one thread: work that goes beside another
/// process (TetGen's) on the core it leaves idle, not over both cores.
class OneThreadScope {
 public:
#ifdef _OPENMP
  OneThreadScope() : was_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~OneThreadScope() { omp_set_num_threads(was_); }
#else
  OneThreadScope() = default;
#endif
  OneThreadScope(const OneThreadScope&) = delete;
  OneThreadScope& operator=(const OneThreadScope&) = delete;

 private:
#ifdef _OPENMP
  int was_;
#endif
};

inline bool is_reporting_thread() {
#ifdef _OPENMP
  return omp_get_thread_num() == 0;
#else
  return true;
#endif
}

/// Runs body(i) for i in [0, n), over OpenMP threads when `parallel`, else in order on this thread
/// (e.g. when the CAD model is not thread-safe). `progress` receives the fraction of indices done
/// (throttled, see ProgressCounter), named `step`.
template <class Body>
void parallel_for(std::size_t n, bool parallel, const Body& body, const ProgressCallback& progress = {},
                  const std::string& step = {}) {
  std::mutex mutex;
  std::size_t failed_at = n;
  std::exception_ptr error;
  ProgressCounter counter(progress, n, step);
  const long count = static_cast<long>(n);
#pragma omp parallel for schedule(dynamic, 8) if (parallel)
  for (long i = 0; i < count; ++i) {
    try {
      body(static_cast<std::size_t>(i));
      counter.add();
      if (is_reporting_thread()) counter.report_if_due();
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (static_cast<std::size_t>(i) < failed_at) {
        failed_at = static_cast<std::size_t>(i);
        error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
  counter.finish();
}

/// The same as computing every result in parallel and then consuming them in index order, a block
/// of `block` indices at a time: compute(i) (a T) over the threads, then consume(i, T&) on this
/// thread in order. Only one block's results are held (a stage's whole set of per-entity results
/// cost ~1 GB on the paper's case); the output still does not depend on the thread count, and an
/// exception is the lowest index's, as a serial loop's.
template <class Compute, class Consume>
void parallel_blocks(std::size_t n, bool parallel, std::size_t block, const Compute& compute, const Consume& consume,
                     const ProgressCallback& progress = {}, const std::string& step = {}) {
  using Result = decltype(compute(std::size_t{0}));
  ProgressCounter counter(progress, n, step);
  std::vector<Result> results;
  for (std::size_t first = 0; first < n; first += block) {
    const std::size_t count = std::min(block, n - first);
    results.assign(count, Result{});
    parallel_for(count, parallel, [&](std::size_t k) { results[k] = compute(first + k); });
    for (std::size_t k = 0; k < count; ++k) consume(first + k, results[k]);
    counter.add(count);
    counter.report_if_due();
  }
  counter.finish();
}

/// The reference of overlapped_blocks: prepare, compute and consume of each block in turn, on this
/// thread.
template <class Prepare, class Compute, class Consume>
void serial_blocks(std::size_t n, std::size_t block, const Prepare& prepare, const Compute& compute,
                   const Consume& consume) {
  using Result = decltype(compute(std::size_t{0}));
  std::vector<Result> results;
  for (std::size_t first = 0; first < n; first += block) {
    const std::size_t count = std::min(block, n - first);
    prepare(first, count);
    results.assign(count, Result{});
    for (std::size_t k = 0; k < count; ++k) results[k] = compute(first + k);
    for (std::size_t k = 0; k < count; ++k) consume(first + k, results[k]);
  }
}

/// parallel_blocks with one block's consume beside the next block's compute: this thread (the
/// OpenMP team's first) consumes block k while the others compute block k + 1, and joins them when
/// done. prepare(first, count) runs on this thread before a block's compute, in block order, once
/// the block two before it is consumed (e.g. inputs that only a serial pass may make): a block
/// ahead of serial_blocks, so a consume error leaves the next block prepared, and prepare must not
/// read what consume writes either. Otherwise the same prepare, compute and consume calls, in the
/// same order with the same results, as serial_blocks (tests/highorder/ho_mesh/test_overlapped_blocks.cpp pins the two together),
/// as long as compute reads nothing that consume writes: the caller's promise (e.g. nodes appended
/// to an array reserved in advance, never reallocated, and only read below its old end). Two
/// blocks' results are held. An exception is the lowest index's, as in the serial loop: consume(k)'s
/// before compute(k + 1)'s. Not `parallel` (or one thread): the serial loop.
template <class Prepare, class Compute, class Consume>
void overlapped_blocks(std::size_t n, bool parallel, std::size_t block, const Prepare& prepare,
                       const Compute& compute, const Consume& consume, const ProgressCallback& progress = {},
                       const std::string& step = {}) {
  using Result = decltype(compute(std::size_t{0}));
  ProgressCounter counter(progress, n, step);
  std::vector<Result> current, next;
  current.resize(std::min(block, n));
  if (n > 0) prepare(std::size_t{0}, current.size());
  parallel_for(current.size(), parallel, [&](std::size_t k) { current[k] = compute(k); });
  for (std::size_t first = 0; first < n; first += block) {
    const std::size_t count = std::min(block, n - first), next_first = first + count;
    std::size_t next_count = std::min(block, n - next_first);
    std::exception_ptr prepare_error, consume_error, compute_error;
    try {
      if (next_count > 0) prepare(next_first, next_count);
    } catch (...) {
      prepare_error = std::current_exception();  // thrown after consume(k), as in the serial loop
      next_count = 0;
    }
    next.assign(next_count, Result{});
    std::size_t failed_at = n;
    std::mutex mutex;
#pragma omp parallel if (parallel)
    {
#pragma omp master
      {
        try {
          for (std::size_t k = 0; k < count; ++k) consume(first + k, current[k]);
        } catch (...) {
          consume_error = std::current_exception();
        }
      }
#pragma omp for schedule(dynamic, 8) nowait
      for (long k = 0; k < static_cast<long>(next_count); ++k) {
        const std::size_t i = next_first + static_cast<std::size_t>(k);
        try {
          next[static_cast<std::size_t>(k)] = compute(i);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(mutex);
          if (i < failed_at) failed_at = i, compute_error = std::current_exception();
        }
      }
    }
    if (consume_error) std::rethrow_exception(consume_error);
    if (prepare_error) std::rethrow_exception(prepare_error);
    if (compute_error) std::rethrow_exception(compute_error);
    std::swap(current, next);
    counter.add(count);
    counter.report_if_due();
  }
  counter.finish();
}

}  // namespace semimesh::ho::detail
