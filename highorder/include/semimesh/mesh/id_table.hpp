// A hash index of entity ids whose keys live in the entities themselves (the mesh's edge and face
// lookups): open addressing with linear probing over 32-bit slots, at most 3/4 full, so 5-11 bytes
// an entry. A std::unordered_map from key to id costs a heap node per entry (40-48 bytes with the
// allocator's header) and a bucket pointer: ~120 MB on the paper's case, held by every stage.
// A slot holds a 26-bit id and 6 bits of its key's hash (bits the slot's index does not use): a
// probe reads the entity's key only when those bits match, so passing an occupied slot (most of an
// absent key's probes) costs no read of a random entity, which is where the lookups' time went.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace semimesh::mesh {

class IdTable {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  static constexpr int kIdBits = 26;
  /// The largest id a table holds (67,108,862: edges or faces of ~3 x 10^7 tetrahedra).
  static constexpr std::uint32_t kMaxId = (1u << kIdBits) - 2;

  /// A well-mixed 64-bit hash of a 64-bit key (the splitmix64 finalizer): the table uses the low
  /// bits, which raw vertex ids would fill in runs.
  static std::uint64_t mix(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    return x ^ (x >> 31);
  }

  std::size_t size() const { return size_; }
  std::size_t memory_bytes() const { return slots_.capacity() * sizeof(std::uint32_t); }

  /// The stored id whose key is the one of hash `hash` (is_key(id) tells), or kNone.
  template <typename IsKey>
  std::uint32_t find(std::uint64_t hash, IsKey is_key) const {
    if (slots_.empty()) return kNone;
    const std::uint32_t tag = tag_of(hash);
    for (std::size_t i = hash & mask_;; i = (i + 1) & mask_) {
      const std::uint32_t slot = slots_[i];
      if (slot == kNone) return kNone;
      if ((slot & kTagMask) == tag && is_key(slot & kIdMask)) return slot & kIdMask;
    }
  }

  /// Starts loading the slot where a lookup of `hash` begins (a hint, no effect on the contents):
  /// a caller with several lookups to make issues all their loads first, so that their cache
  /// misses overlap instead of coming one after another.
  void prefetch(std::uint64_t hash) const {
    if (!slots_.empty()) __builtin_prefetch(&slots_[hash & mask_]);
  }

  /// find; when absent, stores `id` (<= kMaxId, else std::length_error) and returns kNone.
  /// hash_of(stored id) rehashes on growth.
  template <typename IsKey, typename HashOf>
  std::uint32_t find_or_insert(std::uint64_t hash, IsKey is_key, std::uint32_t id, HashOf hash_of) {
    if (4 * (size_ + 1) > 3 * slots_.size()) rehash(2 * (size_ + 1), hash_of);
    const std::uint32_t tag = tag_of(hash);
    std::size_t i = hash & mask_;
    for (; slots_[i] != kNone; i = (i + 1) & mask_)
      if ((slots_[i] & kTagMask) == tag && is_key(slots_[i] & kIdMask)) return slots_[i] & kIdMask;
    if (id > kMaxId) throw_too_many(id);
    slots_[i] = id | tag;
    ++size_;
    return kNone;
  }

  /// Room for `count` ids without growing (a table sized once holds no discarded copies).
  template <typename HashOf>
  void reserve(std::size_t count, HashOf hash_of) {
    if (4 * count > 3 * slots_.size()) rehash(count + count / 3 + 1, hash_of);
  }

  /// Empties the table and frees its slots.
  void clear() { *this = IdTable(); }

 private:
  static constexpr std::uint32_t kIdMask = (1u << kIdBits) - 1;
  static constexpr std::uint32_t kTagMask = ~kIdMask;
  // The hash's top bits: the slot index takes its low ones (tables stay far below 2^58 slots).
  static std::uint32_t tag_of(std::uint64_t hash) { return static_cast<std::uint32_t>(hash >> 32) & kTagMask; }
  [[noreturn]] static void throw_too_many(std::uint32_t id) {
    throw std::length_error("mesh: entity id " + std::to_string(id) + " above the lookup's limit of " +
                            std::to_string(kMaxId) + " edges or faces in one mesh");
  }

  // At least `wanted` slots (a power of two), every stored id placed anew.
  template <typename HashOf>
  void rehash(std::size_t wanted, HashOf hash_of) {
    std::size_t slots = 16;
    while (slots < wanted) slots *= 2;
    std::vector<std::uint32_t> old = std::move(slots_);
    slots_.assign(slots, kNone);
    mask_ = slots - 1;
    for (std::uint32_t slot : old) {
      if (slot == kNone) continue;
      std::size_t i = hash_of(slot & kIdMask) & mask_;
      while (slots_[i] != kNone) i = (i + 1) & mask_;
      slots_[i] = slot;
    }
  }

  std::vector<std::uint32_t> slots_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace semimesh::mesh
