// A table of reference-element data (an extension matrix, a spring network) built once per
// (shape, order, node set) on first use and kept for the process: thread-safe, each entry built
// under the table's lock and never moved afterwards. A hit reads one atomic pointer, no lock: the
// curving asks for every one of its ~650k faces from both threads, and the lock's contention was
// a fifth of the faces' time.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::ho::detail {

template <class T>
class PerElementType {
 public:
  /// The entry for (shape, order, set), made by build(shape, order, set) the first time. Throws
  /// std::invalid_argument for an order outside [0, kMaxOrder].
  template <class Build>
  const T& get(Shape shape, int order, NodeSet set, Build&& build) {
    if (order < 0 || order > kMaxOrder)
      throw std::invalid_argument("reference-element table: order " + std::to_string(order) + " outside [0, " +
                                  std::to_string(kMaxOrder) + "]");
    std::atomic<const T*>& slot =
        slots_[(static_cast<std::size_t>(shape) * (kMaxOrder + 1) + static_cast<std::size_t>(order)) * 2 +
               (set == NodeSet::GLL ? 1 : 0)];
    if (const T* made = slot.load(std::memory_order_acquire)) return *made;
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const T* made = slot.load(std::memory_order_relaxed)) return *made;
    owned_.push_back(std::make_unique<T>(build(shape, order, set)));
    slot.store(owned_.back().get(), std::memory_order_release);
    return *owned_.back();
  }

 private:
  static constexpr std::size_t kShapes = static_cast<std::size_t>(Shape::Hexahedron) + 1;
  std::array<std::atomic<const T*>, kShapes*(kMaxOrder + 1) * 2> slots_{};
  std::mutex mutex_;
  std::vector<std::unique_ptr<T>> owned_;
};

}  // namespace semimesh::ho::detail
