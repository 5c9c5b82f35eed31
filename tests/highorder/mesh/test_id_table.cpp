#include "semimesh/mesh/id_table.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using semimesh::mesh::IdTable;

// Entities are plain keys here: id i has key keys[i], as a mesh's edge i has its vertices.
struct Keys {
  std::vector<std::uint64_t> keys;
  IdTable table;

  std::uint32_t find(std::uint64_t key) const {
    return table.find(IdTable::mix(key), [&](std::uint32_t id) { return keys[id] == key; });
  }
  std::uint32_t find_or_add(std::uint64_t key) {
    const auto id = static_cast<std::uint32_t>(keys.size());
    const std::uint32_t found = table.find_or_insert(
        IdTable::mix(key), [&](std::uint32_t i) { return keys[i] == key; }, id,
        [&](std::uint32_t i) { return IdTable::mix(keys[i]); });
    if (found != IdTable::kNone) return found;
    keys.push_back(key);
    return id;
  }
};

TEST(IdTable, FindsEveryIdAfterGrowingAndNoAbsentKey) {
  Keys k;
  // Keys like edges of a structured mesh: consecutive vertex ids in both halves.
  for (std::uint64_t a = 0; a < 300; ++a)
    for (std::uint64_t b = a + 1; b < a + 40; ++b) {
      const std::uint32_t id = k.find_or_add((a << 32) | b);
      ASSERT_EQ(id, k.keys.size() - 1);  // new: the next id
    }
  ASSERT_EQ(k.table.size(), k.keys.size());
  for (std::uint32_t id = 0; id < k.keys.size(); ++id) {
    ASSERT_EQ(k.find(k.keys[id]), id);
    ASSERT_EQ(k.find_or_add(k.keys[id]), id);  // found, not added twice
  }
  EXPECT_EQ(k.table.size(), k.keys.size());
  EXPECT_EQ(k.find((std::uint64_t{5} << 32) | 200), IdTable::kNone);
  EXPECT_EQ(Keys{}.find(7), IdTable::kNone);  // an empty table has no slot to probe
}

// Keys whose hashes share the slot index's bits but not the tag (the hash's top bits), and keys
// whose hashes are equal in both: each found by its own key, the absent one not found.
TEST(IdTable, TellsKeysApartWhateverBitsOfTheirHashesAreEqual) {
  std::vector<std::uint64_t> keys;
  IdTable table;
  std::vector<std::uint64_t> hashes;
  for (std::uint64_t k = 0; k < 64; ++k) hashes.push_back((k << 58) | 5);  // one index, 64 tags
  for (std::uint64_t k = 0; k < 64; ++k) hashes.push_back(5);              // one index, one tag
  auto hash_of = [&](std::uint32_t id) { return hashes[id]; };
  for (std::uint32_t id = 0; id < hashes.size(); ++id) {
    ASSERT_EQ(table.find_or_insert(hashes[id], [&](std::uint32_t i) { return i == id; }, id, hash_of), IdTable::kNone);
    keys.push_back(id);
  }
  for (std::uint32_t id = 0; id < hashes.size(); ++id)
    ASSERT_EQ(table.find(hashes[id], [&](std::uint32_t i) { return i == id; }), id);
  EXPECT_EQ(table.find(5, [](std::uint32_t) { return false; }), IdTable::kNone);
}

TEST(IdTable, RefusesAnIdAboveItsLimitNamingIt) {
  IdTable table;
  auto no_key = [](std::uint32_t) { return false; };
  auto hash_of = [](std::uint32_t id) { return IdTable::mix(id); };
  EXPECT_EQ(table.find_or_insert(IdTable::mix(1), no_key, IdTable::kMaxId, hash_of), IdTable::kNone);
  EXPECT_EQ(table.find(IdTable::mix(1), [](std::uint32_t id) { return id == IdTable::kMaxId; }), IdTable::kMaxId);
  try {
    table.find_or_insert(IdTable::mix(2), no_key, IdTable::kMaxId + 1, hash_of);
    FAIL() << "no error";
  } catch (const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(IdTable::kMaxId + 1)), std::string::npos) << e.what();
  }
}

TEST(IdTable, CostsAtMostElevenBytesAnIdAndAReservedTableDoesNotGrow) {
  Keys k;
  for (std::uint64_t key = 0; key < 100000; ++key) k.find_or_add(key * 7919);
  // At most 3/4 full after growth, at least 3/8: 4 bytes a slot.
  EXPECT_LE(k.table.memory_bytes(), k.keys.size() * 11);
  EXPECT_GE(k.table.memory_bytes(), k.keys.size() * 5);

  Keys reserved;
  reserved.table.reserve(100000, [](std::uint32_t) { return std::uint64_t{0}; });
  const std::size_t bytes = reserved.table.memory_bytes();
  for (std::uint64_t key = 0; key < 100000; ++key) reserved.find_or_add(key * 7919);
  EXPECT_EQ(reserved.table.memory_bytes(), bytes);
  reserved.table.clear();
  EXPECT_EQ(reserved.table.memory_bytes(), 0u);
  EXPECT_EQ(reserved.find(7919), IdTable::kNone);
}

}  // namespace
