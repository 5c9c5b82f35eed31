// The split's node naming from per-shape recipes (split_layers) pinned to the reference that names
// every node of every piece by its key (detail::split_layers_by_keys): the same nodes, bit for bit,
// the same node lists and inherited bounds, on prisms and hexahedra split in one and two
// directions (faces between hexahedra cut both ways), orders 1-4, both node sets, 1-5 layers and a
// ratio field. And the pieces' bounds derived ahead (piece_bounds_ahead): taken where the element
// is unchanged, derived anew where a node moved, the split's bounds either way.
#include "semimesh/ho/splitting/split_layers.hpp"

#include "prisms_on_square.hpp"
#include "splitting/split_by_keys.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>

namespace semimesh::ho {
namespace {

// `count` elements of `shape` in a row along reference xi (the k-th shifted by 2k: hexahedra share
// their faces xi = +-1; prisms stand side by side, sharing nothing), nodes at a smooth bending of
// the reference points, one node per point.
mesh::Mesh bent_row(Shape shape, int order, NodeSet set, int count) {
  mesh::Mesh m(order, set);
  const Eigen::MatrixX3d r = reference_nodes(shape, order, set);
  std::map<std::array<long, 3>, mesh::NodeId> node_at;
  for (int k = 0; k < count; ++k) {
    std::vector<mesh::NodeId> ids;
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
      const Eigen::Vector3d q = r.row(i).transpose() + Eigen::Vector3d(2.0 * k, 0, 0);
      const std::array<long, 3> key{std::lround(q(0) * 1e9), std::lround(q(1) * 1e9), std::lround(q(2) * 1e9)};
      auto it = node_at.find(key);
      if (it == node_at.end()) {
        const Eigen::Vector3d x(q(0) + 0.04 * q(1) * q(2), q(1) + 0.1 * std::sin(0.7 * q(0)),
                                0.2 * (q(2) + 1.0) + 0.03 * std::cos(q(0)) * (1.0 + 0.5 * q(1)));
        it = node_at.emplace(key, m.add_node(x)).first;
      }
      ids.push_back(it->second);
    }
    m.add_element(shape, ids);
  }
  return m;
}

// Two prisms on the triangles (0, 1, 2) and (2, 1, 3) of the unit square, layer 0.2 thick, bent:
// their shared side face stands on the edge 1-2, which each names from its other end (the split's
// nodes on it are named from the lower id, so that both agree).
mesh::Mesh prism_pair(int order, NodeSet set) {
  return prisms_on_square(order, set, {{0, 1, 2}, {2, 1, 3}}, [](Eigen::Vector3d x, double zeta) {
    x(2) = 0.1 * (zeta + 1.0) + 0.05 * std::sin(2 * x(0)) * std::cos(x(1));
    return x;
  });
}

void expect_same_mesh(const mesh::Mesh& a, const mesh::Mesh& b) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  EXPECT_TRUE(a.nodes() == b.nodes());  // bit for bit, in the same order
  ASSERT_EQ(a.elements().size(), b.elements().size());
  for (std::size_t e = 0; e < a.elements().size(); ++e) ASSERT_EQ(a.element_nodes(e), b.element_nodes(e)) << e;
  EXPECT_EQ(a.edges().size(), b.edges().size());
  EXPECT_EQ(a.faces().size(), b.faces().size());
}

void expect_same_bounds(const std::vector<InheritedBounds>& a, const std::vector<InheritedBounds>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].element, b[k].element);
    EXPECT_EQ(a[k].fingerprint, b[k].fingerprint);
    EXPECT_EQ(a[k].bounds.min_lower, b[k].bounds.min_lower);
    EXPECT_EQ(a[k].bounds.max_upper, b[k].bounds.max_upper);
  }
}

struct Case {
  std::string name;
  Shape shape;
  int elements;  // in a bent row; 0: the prism pair
  std::vector<LayerSplit> split;
  std::vector<SplitFamily> families;
};

std::vector<Case> cases() {
  const RatioField field = [](const Eigen::Vector3d& x) { return 1.5 + 0.2 * x(0) + 0.1 * x(2); };
  std::vector<Case> all;
  for (int layers : {1, 2, 5}) {
    all.push_back({"prisms " + std::to_string(layers), Shape::Prism, 2, {{0, {2, -1}, {0, 0}}, {1, {2, -1}, {0, 0}}},
                   {{{layers, 2.0}, {}}}});
    all.push_back({"hexes along eta " + std::to_string(layers), Shape::Hexahedron, 3,
                   {{0, {1, -1}, {0, 0}}, {1, {1, -1}, {0, 0}}, {2, {1, -1}, {0, 0}}}, {{{layers, 1.7}, {}}}});
  }
  // Three hexahedra split across zeta then eta: the faces between them cut both ways.
  all.push_back({"hexes both ways", Shape::Hexahedron, 3,
                 {{0, {2, 1}, {0, 1}}, {1, {2, 1}, {0, 1}}, {2, {2, 1}, {0, 1}}},
                 {{{3, 1.5}, {}}, {{4, 2.0}, {}}}});
  all.push_back({"hexes both ways, ratio field", Shape::Hexahedron, 2, {{0, {2, 1}, {0, 1}}, {1, {2, 1}, {0, 1}}},
                 {{{2, 1.5}, {}}, {{3, 2.0}, field}}});
  all.push_back({"one of two hexes", Shape::Hexahedron, 2, {{1, {0, -1}, {0, 0}}}, {{{4, 1.3}, {}}}});
  all.push_back({"prism pair", Shape::Prism, 0, {{0, {2, -1}, {0, 0}}, {1, {2, -1}, {0, 0}}}, {{{4, 2.0}, field}}});
  return all;
}

TEST(SplitRecipe, NamesEveryNodeAsTheKeysDo) {
  for (const Case& c : cases())
    for (int order = 1; order <= 4; ++order)
      for (NodeSet set : {NodeSet::Equispaced, NodeSet::GLL}) {
        SCOPED_TRACE(c.name + ", order " + std::to_string(order) + (set == NodeSet::GLL ? ", GLL" : ""));
        const mesh::Mesh coarse = c.elements ? bent_row(c.shape, order, set, c.elements) : prism_pair(order, set);
        std::vector<InheritedBounds> by_recipe, by_keys;
        const mesh::Mesh fast = split_layers(coarse, c.split, c.families, nullptr, nullptr, {}, &by_recipe);
        const mesh::Mesh reference = detail::split_layers_by_keys(coarse, c.split, c.families, &by_keys);
        expect_same_mesh(fast, reference);
        expect_same_bounds(by_recipe, by_keys);
      }
}

// The bounds derived ahead are the split's own; entries whose element is unchanged are taken (a
// doctored entry's bounds come out), an element with a moved node gets bounds derived anew.
TEST(PieceBoundsAhead, TakenWhereTheElementIsUnchangedElseDerivedAnew) {
  const std::vector<LayerSplit> split{{0, {2, 1}, {0, 1}}, {1, {2, 1}, {0, 1}}, {2, {2, 1}, {0, 1}}};
  const std::vector<SplitFamily> families{{{3, 1.5}, {}}, {{2, 2.0}, {}}};
  const mesh::Mesh coarse = bent_row(Shape::Hexahedron, 3, NodeSet::GLL, 3);
  const std::atomic<bool> go{false};
  const PieceBoundsAhead ahead = piece_bounds_ahead(coarse, split, families, go);
  ASSERT_EQ(ahead.size(), 3u);

  std::vector<InheritedBounds> own, taken;
  const mesh::Mesh fine = split_layers(mesh::Mesh(coarse), split, families, nullptr, nullptr, {}, &own);
  const mesh::Mesh with_ahead = split_layers(mesh::Mesh(coarse), split, families, nullptr, nullptr, {}, &taken,
                                             SplitEntities::Canonical, &ahead);
  expect_same_mesh(with_ahead, fine);
  expect_same_bounds(taken, own);
  ASSERT_EQ(own.size(), 18u);  // every piece of the three hexahedra

  // Element 1's entry doctored: its six pieces carry the doctored bounds, the others their own.
  std::vector<PieceBoundsAhead::Entry> entries = ahead.entries();
  for (auto& bounds : entries[1].bounds) bounds->min_lower = -1.0;
  const PieceBoundsAhead doctored(entries);
  std::vector<InheritedBounds> from_doctored;
  split_layers(mesh::Mesh(coarse), split, families, nullptr, nullptr, {}, &from_doctored, SplitEntities::Canonical,
               &doctored);
  ASSERT_EQ(from_doctored.size(), own.size());
  for (std::size_t k = 0; k < own.size(); ++k)
    EXPECT_EQ(from_doctored[k].bounds.min_lower, k >= 6 && k < 12 ? -1.0 : own[k].bounds.min_lower) << k;

  // A node of element 1 moved after the bounds were derived: the doctored entry no longer holds.
  mesh::Mesh moved = coarse;
  const mesh::NodeId inner = moved.element_nodes(1).back();
  moved.place_node(inner, moved.node(inner) + Eigen::Vector3d(1e-3, 0, 0));
  std::vector<InheritedBounds> reference, after_move;
  split_layers(mesh::Mesh(moved), split, families, nullptr, nullptr, {}, &reference);
  split_layers(mesh::Mesh(moved), split, families, nullptr, nullptr, {}, &after_move, SplitEntities::Canonical,
               &doctored);
  expect_same_bounds(after_move, reference);
  EXPECT_NE(after_move[6].bounds.min_lower, -1.0);
}

TEST(PieceBoundsAhead, StopsWhenToldAndRefusesUnorderedEntries) {
  const std::vector<LayerSplit> split{{0, {2, -1}, {0, 0}}, {1, {2, -1}, {0, 0}}};
  const std::atomic<bool> stop{true};
  EXPECT_EQ(piece_bounds_ahead(bent_row(Shape::Prism, 2, NodeSet::GLL, 2), split, {{{3, 2.0}, {}}}, stop).size(), 0u);
  EXPECT_THROW(PieceBoundsAhead({{1, 0, {}}, {0, 0, {}}}), std::invalid_argument);
  EXPECT_THROW(PieceBoundsAhead({{1, 0, {}}, {1, 0, {}}}), std::invalid_argument);
}

}  // namespace
}  // namespace semimesh::ho
