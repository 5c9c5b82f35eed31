// Mesh::add_linear_elements (two threads: edges, faces a block behind) against add_element one
// element at a time, the reference: the same elements, entities, ids and refusals.
#include "highorder/mesh/same_entities.hpp"

#include "semimesh/ho/element_type.hpp"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using semimesh::ho::Shape;
using semimesh::mesh::Mesh;
using semimesh::mesh::NodeId;
using semimesh::test::expect_same_entities;

// A linear mesh's nodes on an (n+1)^3 lattice, numbered in a scrambled order (so that edges run
// both ways against their sorted keys), and a region besides the default one.
struct Lattice {
  Mesh mesh{1};
  int n = 0;
  std::vector<NodeId> id;  // lattice point (i, j, k) -> node
  NodeId at(int i, int j, int k) const { return id[(static_cast<std::size_t>(i) * (n + 1) + j) * (n + 1) + k]; }
};

Lattice lattice(int n) {
  Lattice l;
  l.n = n;
  const std::size_t count = static_cast<std::size_t>(n + 1) * (n + 1) * (n + 1);
  l.id.resize(count);
  for (std::size_t p = 0; p < count; ++p) {
    const std::size_t scrambled = (p * 7919) % count;  // 7919 is prime, count is not a multiple
    const int i = static_cast<int>(scrambled / ((n + 1) * (n + 1))), j = static_cast<int>(scrambled / (n + 1) % (n + 1)),
              k = static_cast<int>(scrambled % (n + 1));
    l.id[scrambled] = l.mesh.add_node(Eigen::Vector3d(i, j, k));
  }
  l.mesh.region_index("farfield");
  return l;
}

// The six tetrahedra of the Kuhn split of each cube, 4 ids each, positively oriented or not (the
// mesh does not care).
std::vector<NodeId> kuhn_tetrahedra(const Lattice& l) {
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<NodeId> out;
  for (int ci = 0; ci < l.n; ++ci)
    for (int cj = 0; cj < l.n; ++cj)
      for (int ck = 0; ck < l.n; ++ck)
        for (const auto& path : paths) {
          std::array<int, 3> v{ci, cj, ck};
          out.push_back(l.at(v[0], v[1], v[2]));
          for (int s : path) ++v[s], out.push_back(l.at(v[0], v[1], v[2]));
        }
  return out;
}

// The lattice's cubes as hexahedra (canonical order: bottom 0-3, top 4-7).
std::vector<NodeId> hexahedra(const Lattice& l) {
  std::vector<NodeId> out;
  for (int i = 0; i < l.n; ++i)
    for (int j = 0; j < l.n; ++j)
      for (int k = 0; k < l.n; ++k)
        for (int dk : {0, 1}) {
          out.push_back(l.at(i, j, k + dk));
          out.push_back(l.at(i + 1, j, k + dk));
          out.push_back(l.at(i + 1, j + 1, k + dk));
          out.push_back(l.at(i, j + 1, k + dk));
        }
  return out;
}

// The reference: the same nodes and regions, elements [0, before) by add_element, then `more`
// also one by one.
Mesh one_by_one(const Mesh& nodes_and_regions, Shape shape, const std::vector<NodeId>& before,
                const std::vector<NodeId>& more, int region) {
  Mesh out(1);
  for (NodeId v = 0; v < nodes_and_regions.num_nodes(); ++v) out.add_node(nodes_and_regions.node(v));
  out.copy_regions_from(nodes_and_regions);
  const auto nv = static_cast<std::size_t>(semimesh::ho::num_vertices(shape));
  for (const std::vector<NodeId>* list : {&before, &more})
    for (std::size_t k = 0; k < list->size(); k += nv)
      out.add_element(shape, std::vector<NodeId>(list->begin() + static_cast<long>(k), list->begin() + static_cast<long>(k + nv)),
                      list == &more ? region : 0);
  return out;
}

// Splits a list of elements of nv ids at element `at`.
std::pair<std::vector<NodeId>, std::vector<NodeId>> split_at(const std::vector<NodeId>& all, std::size_t nv,
                                                              std::size_t at) {
  return {std::vector<NodeId>(all.begin(), all.begin() + static_cast<long>(at * nv)),
          std::vector<NodeId>(all.begin() + static_cast<long>(at * nv), all.end())};
}

TEST(AddLinearElements, ManyTetrahedraGetTheEntitiesAndIdsOfAddingThemOneByOne) {
  Lattice l = lattice(12);  // 10,368 tetrahedra, 9,368 in the batch: 37 of the edge pass's blocks
  const std::vector<NodeId> all = kuhn_tetrahedra(l);
  // Some elements already there, by add_element: the batch finds their entities.
  const auto [before, more] = split_at(all, 4, 1000);
  const Mesh expected = one_by_one(l.mesh, Shape::Tetrahedron, before, more, 1);
  for (std::size_t k = 0; k < before.size(); k += 4)
    l.mesh.add_element(Shape::Tetrahedron, {before[k], before[k + 1], before[k + 2], before[k + 3]});
  l.mesh.add_linear_elements(Shape::Tetrahedron, more, 1);
  expect_same_entities(l.mesh, expected);
  ASSERT_EQ(l.mesh.elements().size(), expected.elements().size());
  for (std::size_t e = 0; e < expected.elements().size(); ++e) {
    EXPECT_EQ(l.mesh.elements()[e].region, expected.elements()[e].region) << e;
    EXPECT_EQ(l.mesh.elements()[e].faces, expected.elements()[e].faces) << e;
    EXPECT_EQ(l.mesh.elements()[e].face_orientation, expected.elements()[e].face_orientation) << e;
    EXPECT_EQ(l.mesh.element_nodes(e), expected.element_nodes(e)) << e;
  }
  for (const auto& edge : expected.edges()) EXPECT_GE(l.mesh.find_edge(edge.vertices[0], edge.vertices[1]), 0);
}

TEST(AddLinearElements, HexahedraSharingQuadrilateralsGetTheirOrientationCodes) {
  Lattice l = lattice(9);  // 729 hexahedra: faces in every orientation code the lattice makes
  const std::vector<NodeId> all = hexahedra(l);
  const Mesh expected = one_by_one(l.mesh, Shape::Hexahedron, {}, all, 0);
  l.mesh.add_linear_elements(Shape::Hexahedron, all);
  expect_same_entities(l.mesh, expected);
  for (std::size_t e = 0; e < expected.elements().size(); ++e) {
    EXPECT_EQ(l.mesh.elements()[e].faces, expected.elements()[e].faces) << e;
    EXPECT_EQ(l.mesh.elements()[e].face_orientation, expected.elements()[e].face_orientation) << e;
  }
}

TEST(AddLinearElements, RefusesUnknownIdsAndRepeatedVerticesBeforeAddingAnything) {
  Lattice l = lattice(3);
  std::vector<NodeId> tets = kuhn_tetrahedra(l);
  const std::size_t nodes = l.mesh.num_nodes();
  std::vector<NodeId> unknown = tets, repeated = tets;
  unknown[4 * 100 + 2] = static_cast<NodeId>(nodes);
  repeated[4 * 77 + 3] = repeated[4 * 77 + 1];
  try {
    l.mesh.add_linear_elements(Shape::Tetrahedron, unknown);
    FAIL() << "an unknown node id was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown node id " + std::to_string(nodes)), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("100"), std::string::npos) << "names the element: " << e.what();
  }
  try {
    l.mesh.add_linear_elements(Shape::Tetrahedron, repeated);
    FAIL() << "a repeated vertex was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("appears twice"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("77"), std::string::npos) << "names the element: " << e.what();
  }
  EXPECT_TRUE(l.mesh.elements().empty());
  EXPECT_TRUE(l.mesh.edges().empty());
  EXPECT_TRUE(l.mesh.faces().empty());
  tets.pop_back();
  EXPECT_THROW(l.mesh.add_linear_elements(Shape::Tetrahedron, tets), std::invalid_argument);  // not whole tets
  EXPECT_THROW(l.mesh.add_linear_elements(Shape::Triangle, {0, 1, 2}), std::invalid_argument);
  EXPECT_THROW(l.mesh.add_linear_elements(Shape::Tetrahedron, {0, 1, 2, 3}, 5), std::invalid_argument);  // no region 5
  Mesh quadratic(2);
  for (int k = 0; k < 4; ++k) quadratic.add_node(Eigen::Vector3d(k == 1, k == 2, k == 3));
  EXPECT_THROW(quadratic.add_linear_elements(Shape::Tetrahedron, {0, 1, 2, 3}), std::logic_error);
  EXPECT_TRUE(l.mesh.elements().empty());
}

TEST(AddLinearElements, ATwistedQuadrilateralIsRefusedAsAddElementRefusesIt) {
  Lattice l = lattice(2);
  std::vector<NodeId> hexes = hexahedra(l);
  // Element 7 meets element 6 on their shared face: its top given in another cycle (two ids swapped).
  std::vector<NodeId> twisted = hexes;
  std::swap(twisted[8 * 7 + 0], twisted[8 * 7 + 1]);
  std::string expected_error;
  try {
    one_by_one(l.mesh, Shape::Hexahedron, {}, twisted, 0);
  } catch (const std::invalid_argument& e) {
    expected_error = e.what();
  }
  ASSERT_NE(expected_error.find("twisted"), std::string::npos) << "the reference refuses it: " << expected_error;
  try {
    l.mesh.add_linear_elements(Shape::Hexahedron, twisted);
    FAIL() << "a twisted quadrilateral was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), expected_error);
  }
  EXPECT_TRUE(l.mesh.elements().empty()) << "none of the batch's elements stays";
  l.mesh.add_linear_elements(Shape::Hexahedron, hexes);  // the mesh still takes sound elements
  EXPECT_EQ(l.mesh.elements().size(), 8u);
}

}  // namespace
