// The split's new nodes inside the one coarse element being split, by their key (split_layers.cpp,
// key kind 3): no other element names them, so the table starts afresh with each element. Open
// addressing whose entries count only when stamped with the current element: starting the next
// element clears nothing. A std::map cleared per element allocated and freed a tree node for each
// of the paper case's ~1.1 M such nodes, on the split's serial pass.
#pragma once

#include "semimesh/mesh/id_table.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace semimesh::ho::detail {

class InsideNodes {
 public:
  using Key = std::array<std::int64_t, 8>;

  /// Forgets every key: the next element's nodes begin.
  void next_element() {
    if (++stamp_ == 0) {  // the stamps wrapped: clear them once
      for (Entry& e : entries_) e.stamp = 0;
      stamp_ = 1;
    }
    count_ = 0;
  }

  /// The node id kept for `key` (mesh::kNoNode when new). The reference is valid until the next
  /// call (a new key may grow the table).
  mesh::NodeId& operator[](const Key& key) {
    if (4 * (count_ + 1) > 3 * entries_.size()) grow();
    const std::size_t mask = entries_.size() - 1;
    for (std::size_t i = hash(key) & mask;; i = (i + 1) & mask) {
      Entry& e = entries_[i];
      if (e.stamp != stamp_) {
        e = Entry{key, mesh::kNoNode, stamp_};
        ++count_;
        return e.id;
      }
      if (e.key == key) return e.id;
    }
  }

 private:
  struct Entry {
    Key key{};
    mesh::NodeId id = mesh::kNoNode;
    std::uint32_t stamp = 0;
  };

  static std::uint64_t hash(const Key& key) {
    std::uint64_t h = 0;
    for (std::int64_t word : key) h = mesh::IdTable::mix(h ^ static_cast<std::uint64_t>(word));
    return h;
  }

  void grow() {
    std::vector<Entry> old = std::move(entries_);
    entries_.assign(std::max<std::size_t>(64, 2 * old.size()), Entry{});
    count_ = 0;
    for (const Entry& e : old)
      if (e.stamp == stamp_) (*this)[e.key] = e.id;
  }

  std::vector<Entry> entries_;
  std::uint32_t stamp_ = 1;
  std::size_t count_ = 0;
};

}  // namespace semimesh::ho::detail
