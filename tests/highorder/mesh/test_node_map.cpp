// The mesh's map from node ids to values (mesh/node_map.hpp) against std::unordered_map, the
// plain reference: random sets, replacements and erases over a small id range (so that runs of
// occupied slots form and erases shift entries back across them) and over ids hashed anywhere.
#include "semimesh/mesh/node_map.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <unordered_map>

namespace semimesh::mesh {
namespace {

struct Pair {
  int a = 0;
  double b = 0.0;
};

// Every id in [0, range) (and one beyond) finds what the reference holds; the sizes agree; for_each
// visits exactly the reference's entries.
void expect_same(const NodeMap<Pair>& map, const std::unordered_map<std::uint32_t, Pair>& reference,
                 std::uint32_t range) {
  ASSERT_EQ(map.size(), reference.size());
  for (std::uint32_t id = 0; id <= range; ++id) {
    const Pair* found = map.find(id);
    const auto it = reference.find(id);
    ASSERT_EQ(found != nullptr, it != reference.end()) << "id " << id;
    if (found) {
      EXPECT_EQ(found->a, it->second.a) << "id " << id;
      EXPECT_EQ(found->b, it->second.b) << "id " << id;
    }
  }
  std::size_t visited = 0;
  map.for_each([&](std::uint32_t id, const Pair& value) {
    ++visited;
    ASSERT_TRUE(reference.count(id)) << "id " << id;
    EXPECT_EQ(value.a, reference.at(id).a);
  });
  EXPECT_EQ(visited, reference.size());
}

TEST(NodeMap, AgreesWithAnUnorderedMapUnderRandomSetsAndErases) {
  for (const std::uint32_t range : {40u, 3000u}) {
    std::mt19937 random(11 + range);
    std::uniform_int_distribution<std::uint32_t> id_of(0, range - 1);
    NodeMap<Pair> map;
    std::unordered_map<std::uint32_t, Pair> reference;
    for (int step = 0; step < 20000; ++step) {
      const std::uint32_t id = id_of(random);
      if (random() % 3 == 0) {
        map.erase(id);
        reference.erase(id);
      } else {
        const Pair value{step, 0.5 * step};
        map.set(id, value);
        reference[id] = value;
      }
      if (step % 997 == 0) expect_same(map, reference, range);
    }
    expect_same(map, reference, range);
    // Emptied entry by entry, then refilled after a clear.
    for (std::uint32_t id = 0; id < range; ++id) map.erase(id), reference.erase(id);
    expect_same(map, reference, range);
    map.set(7, {1, 2.0});
    map.clear();
    EXPECT_EQ(map.find(7), nullptr);
    map.reserve(100);
    map.set(7, {3, 4.0});
    ASSERT_NE(map.find(7), nullptr);
    EXPECT_EQ(map.find(7)->a, 3);
  }
}

}  // namespace
}  // namespace semimesh::mesh
