// Progress of a long computation, for a caller that shows it (the command line's % and ETA).
// Library code never prints: it calls a ProgressCallback with the fraction of its work done.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

namespace semimesh {

/// `fraction` of the work done, in [0, 1] and non-decreasing over one call of a library function;
/// `step` names the part that runs ("edges", "TetGen", a file name; may be empty). Called from one
/// thread at a time, at most a few hundred times per call of a library function (the library
/// throttles): it must be cheap and must not throw. An empty callback receives nothing.
using ProgressCallback = std::function<void(double fraction, const std::string& step)>;

/// The part [from, to] of `whole`: the part's fraction f is whole's from + f (to - from), so
/// consecutive parts of one computation report one non-decreasing fraction. Empty when `whole` is.
ProgressCallback progress_part(const ProgressCallback& whole, double from, double to);

/// Counts the items of a loop that are done, on any thread, and reports to the callback from one
/// thread at a time (one reporting thread, or any thread under the caller's lock), each time the
/// count has passed another of kMarks evenly spaced marks.
class ProgressCounter {
 public:
  static constexpr std::size_t kMarks = 100;

  ProgressCounter(ProgressCallback callback, std::size_t total, std::string step = {});

  /// Any thread: `items` more done (a relaxed atomic add).
  void add(std::size_t items = 1) { done_.fetch_add(items, std::memory_order_relaxed); }
  /// One thread at a time: calls the callback when a mark was passed since its last report.
  void report_if_due();
  /// The reporting thread, after the loop: reports 1 (unless it already did).
  void finish();

 private:
  ProgressCallback callback_;
  std::size_t total_;
  std::string step_;
  std::atomic<std::size_t> done_{0};
  std::size_t next_mark_ = 0;  ///< items done at which the next report is due
  bool finished_ = false;
};

}  // namespace semimesh
