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

}  // namespace semimesh::ho::detail
