#include "semimesh/progress.hpp"

#include <algorithm>
#include <utility>

namespace semimesh {

ProgressCallback progress_part(const ProgressCallback& whole, double from, double to) {
  if (!whole) return {};
  return [whole, from, to](double fraction, const std::string& step) {
    whole(from + std::clamp(fraction, 0.0, 1.0) * (to - from), step);
  };
}

ProgressCounter::ProgressCounter(ProgressCallback callback, std::size_t total, std::string step)
    : callback_(std::move(callback)), total_(total), step_(std::move(step)) {
  if (callback_) callback_(0.0, step_);
  next_mark_ = std::max<std::size_t>(1, total_ / kMarks);
}

void ProgressCounter::report_if_due() {
  if (!callback_ || finished_) return;
  const std::size_t done = done_.load(std::memory_order_relaxed);
  if (done < next_mark_ || total_ == 0) return;
  const std::size_t step = std::max<std::size_t>(1, total_ / kMarks);
  next_mark_ = (done / step + 1) * step;
  if (done >= total_) finished_ = true;
  callback_(std::min(1.0, static_cast<double>(done) / static_cast<double>(total_)), step_);
}

void ProgressCounter::finish() {
  if (!callback_ || finished_) return;
  finished_ = true;
  callback_(1.0, step_);
}

}  // namespace semimesh
