// The reference for meshes whose entities were made other than by add_element (renamed, merged,
// adopted): a fresh mesh built from the same node lists, and an entity-for-entity comparison.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace semimesh::test {

using semimesh::mesh::Mesh;
using semimesh::mesh::NodeId;

// The reference: a fresh mesh given the kept nodes in order and the welded node lists.
inline Mesh built_afresh(const Mesh& m, const std::vector<NodeId>& to) {
  std::vector<char> used(m.num_nodes(), 0);
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    for (NodeId v : m.element_nodes(e)) used[to[v]] = 1;
  Mesh out(m.order(), m.node_set());
  std::vector<NodeId> new_id(m.num_nodes(), semimesh::mesh::kNoNode);
  for (NodeId v = 0; v < m.num_nodes(); ++v)
    if (used[v]) new_id[v] = out.add_node(m.node(v), m.cad_attachment(v));
  out.copy_regions_from(m);
  auto welded = [&](std::vector<NodeId> ids) {
    for (NodeId& v : ids) v = new_id[to[v]];
    return ids;
  };
  for (std::size_t e = 0; e < m.elements().size(); ++e)
    out.add_element(m.elements()[e].shape, welded(m.element_nodes(e)), m.elements()[e].region);
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    out.add_boundary_face(m.group_names()[m.boundary_faces()[b].group], m.boundary_faces()[b].shape,
                          welded(m.boundary_face_nodes(b)));
  return out;
}

// Every entity, pool and element of `m` as in `expected`, and the lookups rebuilt.
inline void expect_same_entities(const Mesh& m, const Mesh& expected) {
  EXPECT_EQ(m.nodes(), expected.nodes());
  EXPECT_EQ(m.edge_pool(), expected.edge_pool());
  EXPECT_EQ(m.face_pool(), expected.face_pool());
  EXPECT_EQ(m.interior_pool(), expected.interior_pool());
  ASSERT_EQ(m.edges().size(), expected.edges().size());
  for (std::size_t e = 0; e < m.edges().size(); ++e) {
    EXPECT_EQ(m.edges()[e].vertices, expected.edges()[e].vertices) << e;
    EXPECT_EQ(m.edges()[e].first_node, expected.edges()[e].first_node) << e;
  }
  ASSERT_EQ(m.faces().size(), expected.faces().size());
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    EXPECT_EQ(m.faces()[f].vertices, expected.faces()[f].vertices) << f;
    EXPECT_EQ(m.faces()[f].edges, expected.faces()[f].edges) << f;
    EXPECT_EQ(m.faces()[f].edge_reversed, expected.faces()[f].edge_reversed) << f;
    EXPECT_EQ(m.faces()[f].first_node, expected.faces()[f].first_node) << f;
  }
  ASSERT_EQ(m.elements().size(), expected.elements().size());
  for (std::size_t e = 0; e < m.elements().size(); ++e) {
    EXPECT_EQ(m.elements()[e].vertices, expected.elements()[e].vertices) << e;
    EXPECT_EQ(m.elements()[e].edges, expected.elements()[e].edges) << e;
    EXPECT_EQ(m.elements()[e].edge_reversed, expected.elements()[e].edge_reversed) << e;
    EXPECT_EQ(m.elements()[e].faces, expected.elements()[e].faces) << e;
    EXPECT_EQ(m.elements()[e].face_orientation, expected.elements()[e].face_orientation) << e;
    EXPECT_EQ(m.elements()[e].region, expected.elements()[e].region) << e;
    EXPECT_EQ(m.element_nodes(e), expected.element_nodes(e)) << e;
  }
  ASSERT_EQ(m.boundary_faces().size(), expected.boundary_faces().size());
  for (std::size_t b = 0; b < m.boundary_faces().size(); ++b)
    EXPECT_EQ(m.boundary_face_nodes(b), expected.boundary_face_nodes(b)) << b;
  EXPECT_EQ(m.group_names(), expected.group_names());
  for (std::size_t f = 0; f < m.faces().size(); ++f) {
    const auto& v = m.faces()[f].vertices;
    const std::vector<NodeId> vertices(v.begin(), v.begin() + m.faces()[f].num_vertices);
    ASSERT_EQ(m.find_face(vertices), static_cast<long>(f)) << "the lookup tables are rebuilt too";
  }
}

// `m`'s node lists built afresh by add_element in element order: the entities it must have.
inline Mesh built_afresh(const Mesh& m) {
  std::vector<NodeId> identity(m.num_nodes());
  for (NodeId v = 0; v < m.num_nodes(); ++v) identity[v] = v;
  return built_afresh(m, identity);
}

}  // namespace semimesh::test
