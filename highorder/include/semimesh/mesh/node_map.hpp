// A map from node ids to values for the few nodes that have one (the CAD attachments of the
// boundary's nodes): open addressing with linear probing over (id, value) slots, at most 3/4 full,
// erasing by shifting the slots after it back (no tombstones). A std::unordered_map allocated a
// heap node per entry and freed them one by one, and its lookups went through a bucket pointer to
// the node: copying, compacting and dropping a mesh's attachments and the curving's lookups of them
// were that many allocations and cache misses.
#pragma once

#include "semimesh/mesh/id_table.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace semimesh::mesh {

template <typename Value>
class NodeMap {
 public:
  /// The id no node has (mesh::kNoNode): an empty slot.
  static constexpr std::uint32_t kEmpty = 0xffffffffu;

  std::size_t size() const { return size_; }
  std::size_t memory_bytes() const { return slots_.capacity() * sizeof(Slot); }

  /// Node `id`'s value, or null.
  const Value* find(std::uint32_t id) const {
    if (slots_.empty()) return nullptr;
    for (std::size_t i = home(id);; i = (i + 1) & mask_) {
      if (slots_[i].id == id) return &slots_[i].value;
      if (slots_[i].id == kEmpty) return nullptr;
    }
  }
  bool contains(std::uint32_t id) const { return find(id) != nullptr; }

  /// Gives node `id` (not kEmpty) the value `value`, replacing the one it had.
  void set(std::uint32_t id, const Value& value) {
    if (4 * (size_ + 1) > 3 * slots_.size()) grow(std::max<std::size_t>(16, 2 * slots_.size()));
    std::size_t i = home(id);
    while (slots_[i].id != kEmpty && slots_[i].id != id) i = (i + 1) & mask_;
    if (slots_[i].id == kEmpty) ++size_;
    slots_[i].id = id;
    slots_[i].value = value;
  }

  /// Removes node `id`'s value, if it has one.
  void erase(std::uint32_t id) {
    if (slots_.empty()) return;
    std::size_t hole = home(id);
    while (slots_[hole].id != id) {
      if (slots_[hole].id == kEmpty) return;
      hole = (hole + 1) & mask_;
    }
    // The entries after it in its run move back into the hole where their probe passes it (their
    // home is not between the hole and where they are), so that every probe still finds them.
    for (std::size_t j = (hole + 1) & mask_; slots_[j].id != kEmpty; j = (j + 1) & mask_)
      if (((j - home(slots_[j].id)) & mask_) >= ((j - hole) & mask_)) {
        slots_[hole] = slots_[j];
        hole = j;
      }
    slots_[hole].id = kEmpty;
    --size_;
  }

  void clear() {
    slots_ = {};
    mask_ = size_ = 0;
  }

  /// Room for `count` entries without growing.
  void reserve(std::size_t count) {
    std::size_t capacity = 16;
    while (3 * capacity < 4 * count) capacity *= 2;
    if (capacity > slots_.size()) grow(capacity);
  }

  /// f(id, value) for every entry, in no particular order.
  template <typename F>
  void for_each(F f) const {
    for (const Slot& s : slots_)
      if (s.id != kEmpty) f(s.id, s.value);
  }

 private:
  struct Slot {
    std::uint32_t id = kEmpty;
    Value value{};
  };
  std::size_t home(std::uint32_t id) const { return IdTable::mix(id) & mask_; }
  void grow(std::size_t capacity) {
    std::vector<Slot> old(capacity);
    old.swap(slots_);
    mask_ = capacity - 1;
    for (const Slot& s : old) {
      if (s.id == kEmpty) continue;
      std::size_t i = home(s.id);
      while (slots_[i].id != kEmpty) i = (i + 1) & mask_;
      slots_[i] = s;
    }
  }

  std::vector<Slot> slots_;  ///< a power of two of them (none before the first entry)
  std::size_t mask_ = 0, size_ = 0;
};

}  // namespace semimesh::mesh
