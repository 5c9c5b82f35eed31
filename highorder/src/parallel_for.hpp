// A parallel loop over indices for the element-local stages (curving, splitting, certification).
// Each index writes only its own output slot, so the result does not depend on the thread count.
// An exception thrown by the body is caught inside the parallel region (it may not leave it) and
// the one of the lowest index is rethrown afterwards, the same one a serial loop would throw.
// Progress: every thread counts its finished indices; only the first thread (the caller's when
// serial) reports, so the callback never runs concurrently and costs the others one atomic add.
#pragma once

#include "semimesh/progress.hpp"

#include <cstddef>
#include <exception>
#include <mutex>
#include <string>

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

}  // namespace semimesh::ho::detail
