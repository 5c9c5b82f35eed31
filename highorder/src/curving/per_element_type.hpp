// A table of reference-element data (an extension matrix, a spring network) built once per
// (shape, order, node set) on first use and kept for the process: thread-safe, each entry built
// under the table's lock and never moved afterwards.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace semimesh::ho::detail {

template <class T>
class PerElementType {
 public:
  /// The entry for (shape, order, set), made by build(shape, order, set) the first time.
  template <class Build>
  const T& get(Shape shape, int order, NodeSet set, Build&& build) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& slot = entries_[{shape, order, set}];
    if (!slot) slot = std::make_unique<T>(build(shape, order, set));
    return *slot;
  }

 private:
  std::mutex mutex_;
  std::map<std::tuple<Shape, int, NodeSet>, std::unique_ptr<T>> entries_;
};

}  // namespace semimesh::ho::detail
