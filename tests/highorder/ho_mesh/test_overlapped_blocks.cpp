// overlapped_blocks (one block consumed while the next is computed: curving and splitting) against
// its reference, serial_blocks: the same prepare, compute and consume calls in the same order with
// the same results, on one and two threads, and the same error where one is thrown (the lowest
// index's, a consume's before a later compute's, a prepare's after the block before it is consumed;
// prepare runs a block ahead, so a consume error leaves the next block prepared).
#include "parallel_for.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace semimesh::ho::detail {
namespace {

constexpr std::size_t kNoThrow = ~std::size_t{0};

// What a run did: the blocks prepared, the results consumed in order, the error it ended with.
struct Calls {
  std::vector<std::pair<std::size_t, std::size_t>> prepared;
  std::vector<std::pair<std::size_t, double>> consumed;
  std::string error;
};

// Where each kind of call throws (index, or a block's first index for prepare).
struct Throws {
  std::size_t prepare = kNoThrow, compute = kNoThrow, consume = kNoThrow;
  std::size_t compute_also = kNoThrow;  // a second compute error, above the first
};

template <class Run>
Calls record(std::size_t n, const Throws& throws, const Run& run) {
  Calls calls;
  calls.consumed.reserve(n);  // consume appends while compute runs: never reallocated
  std::vector<double> input(n);
  for (std::size_t i = 0; i < n; ++i) input[i] = std::sin(0.1 * static_cast<double>(i));
  const auto prepare = [&](std::size_t first, std::size_t count) {
    if (first == throws.prepare) throw std::runtime_error("prepare " + std::to_string(first));
    calls.prepared.emplace_back(first, count);
  };
  const auto compute = [&](std::size_t i) {
    if (i == throws.compute || i == throws.compute_also) throw std::runtime_error("compute " + std::to_string(i));
    return std::exp(input[i]) * static_cast<double>(i % 7);
  };
  const auto consume = [&](std::size_t i, double x) {
    if (i == throws.consume) throw std::runtime_error("consume " + std::to_string(i));
    calls.consumed.emplace_back(i, x);
  };
  try {
    run(n, prepare, compute, consume);
  } catch (const std::runtime_error& e) {
    calls.error = e.what();
  }
  return calls;
}

void expect_same_calls(std::size_t n, std::size_t block, const Throws& throws, const char* what) {
  const Calls reference = record(n, throws, [&](std::size_t m, auto& p, auto& c, auto& k) {
    serial_blocks(m, block, p, c, k);
  });
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const Calls overlapped = record(n, throws, [&](std::size_t m, auto& p, auto& c, auto& k) {
      overlapped_blocks(m, true, block, p, c, k);
    });
    // A block ahead: after a consume error, the next block was prepared too.
    std::vector<std::pair<std::size_t, std::size_t>> prepared = reference.prepared;
    if (throws.consume != kNoThrow && throws.consume / block + 1 < (n + block - 1) / block)
      prepared.emplace_back((throws.consume / block + 1) * block, std::min(block, n - (throws.consume / block + 1) * block));
    EXPECT_EQ(overlapped.prepared, prepared) << what << ", " << threads << " thread(s)";
    EXPECT_EQ(overlapped.consumed, reference.consumed) << what << ", " << threads << " thread(s)";
    EXPECT_EQ(overlapped.error, reference.error) << what << ", " << threads << " thread(s)";
  }
  omp_set_num_threads(omp_get_num_procs());
}

TEST(OverlappedBlocks, SameCallsAndResultsAsTheSerialLoop) {
  const std::pair<std::size_t, std::size_t> sizes[] = {{0, 8}, {1, 8}, {63, 8}, {64, 64}, {65, 64}, {200, 1}, {1000, 7}};
  for (const auto& [n, block] : sizes)
    expect_same_calls(n, block, {}, ("n " + std::to_string(n) + ", block " + std::to_string(block)).c_str());
}

TEST(OverlappedBlocks, AnErrorIsTheOneTheSerialLoopThrows) {
  Throws compute;
  compute.compute = 300, compute.compute_also = 310;
  expect_same_calls(1000, 64, compute, "two compute errors: the lower one, after the block before");
  Throws consume_first;
  consume_first.consume = 250, consume_first.compute = 300;
  expect_same_calls(1000, 64, consume_first, "a consume error before a compute error of the next block");
  Throws prepare;
  prepare.prepare = 320;
  expect_same_calls(1000, 64, prepare, "a prepare error after the block before it is consumed");
  Throws first_block;
  first_block.compute = 3;
  expect_same_calls(1000, 64, first_block, "a compute error in the first block");
}

}  // namespace
}  // namespace semimesh::ho::detail
