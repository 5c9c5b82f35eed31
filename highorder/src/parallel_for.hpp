// A parallel loop over indices for the element-local stages (curving, splitting, certification).
// Each index writes only its own output slot, so the result does not depend on the thread count.
// An exception thrown by the body is caught inside the parallel region (it may not leave it) and
// the one of the lowest index is rethrown afterwards, the same one a serial loop would throw.
#pragma once

#include <cstddef>
#include <exception>
#include <mutex>

namespace semimesh::ho::detail {

/// Runs body(i) for i in [0, n), over OpenMP threads when `parallel`, else in order on this thread
/// (e.g. when the CAD model is not thread-safe).
template <class Body>
void parallel_for(std::size_t n, bool parallel, const Body& body) {
  std::mutex mutex;
  std::size_t failed_at = n;
  std::exception_ptr error;
  const long count = static_cast<long>(n);
#pragma omp parallel for schedule(dynamic, 8) if (parallel)
  for (long i = 0; i < count; ++i) {
    try {
      body(static_cast<std::size_t>(i));
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (static_cast<std::size_t>(i) < failed_at) {
        failed_at = static_cast<std::size_t>(i);
        error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace semimesh::ho::detail
