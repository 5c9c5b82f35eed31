// Items (triangles, faces) by their directed edges a -> b: one array of (edge, item) sorted once
// and searched, instead of a map node per edge. Where items share a directed edge, the one added
// last is found (as a map assigned item by item keeps).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

namespace semimesh::mesh {

class DirectedEdgeIndex {
 public:
  void reserve(std::size_t edges) { entries_.reserve(edges); }
  void add(std::uint32_t a, std::uint32_t b, std::size_t item) { entries_.emplace_back(key(a, b), item); }
  /// After the last add, before the first find.
  void sort() {
    std::stable_sort(entries_.begin(), entries_.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  }
  /// The item last added with the edge a -> b, if any.
  std::optional<std::size_t> find(std::uint32_t a, std::uint32_t b) const {
    const std::uint64_t k = key(a, b);
    const auto after = std::upper_bound(entries_.begin(), entries_.end(), k,
                                        [](std::uint64_t x, const auto& entry) { return x < entry.first; });
    if (after == entries_.begin() || std::prev(after)->first != k) return std::nullopt;
    return std::prev(after)->second;
  }

 private:
  static std::uint64_t key(std::uint32_t a, std::uint32_t b) { return static_cast<std::uint64_t>(a) << 32 | b; }
  std::vector<std::pair<std::uint64_t, std::size_t>> entries_;
};

}  // namespace semimesh::mesh
