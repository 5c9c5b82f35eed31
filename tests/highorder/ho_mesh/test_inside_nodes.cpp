// The split's table of the nodes inside the element being split (splitting/inside_nodes.hpp)
// against a std::map cleared per element, its reference: the same ids for the same keys, nothing
// kept from one element to the next, through growth.
#include "splitting/inside_nodes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace semimesh::ho {
namespace {

TEST(InsideNodes, GivesTheIdsAMapClearedPerElementGives) {
  detail::InsideNodes table;
  std::mt19937 rng(7);
  mesh::NodeId next_id = 0;
  for (int element = 0; element < 300; ++element) {
    table.next_element();
    std::map<detail::InsideNodes::Key, mesh::NodeId> reference;
    // From a few keys to several hundred (the table grows past its first 64 entries), each asked
    // for several times, as pieces sharing a node ask for it; the same keys in every element (the
    // split's carry their element: here nothing may be kept from one to the next).
    const int distinct = 1 + static_cast<int>(rng() % (element % 10 == 0 ? 400 : 40));
    std::uniform_int_distribution<int> pick(0, distinct - 1);
    for (int ask = 0; ask < 3 * distinct; ++ask) {
      const int k = pick(rng);
      const detail::InsideNodes::Key key{3, 0, k % 4, k / 4 % 4, k / 16, k % 7, -1 - k % 2, 0};
      mesh::NodeId& id = table[key];
      auto [it, fresh] = reference.try_emplace(key, mesh::kNoNode);
      ASSERT_EQ(id, it->second) << "element " << element << " key " << k;
      if (id == mesh::kNoNode) id = it->second = next_id++;  // as node_for makes a node
    }
  }
}

}  // namespace
}  // namespace semimesh::ho
