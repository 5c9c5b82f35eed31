// A copy of a CAD model whose curves and surfaces forward every query to the original and add its
// wall time to a counter: the share of a stage's time spent in CAD queries.
#pragma once

#include "semimesh/cad/model.hpp"

#include <atomic>
#include <memory>

namespace semimesh::bench {

struct CadClock {
  std::atomic<long long> nanoseconds{0};
  std::atomic<long long> calls{0};
};

/// Same entities, ids, names, topology and thread safety as `inner`, which must outlive the result.
std::unique_ptr<cad::Model> timed_model(const cad::Model& inner, CadClock& clock);

}  // namespace semimesh::bench
