// Keys and tables of the mesh's edge and face entities, shared by the files that build them
// (mesh.cpp) and remap them (remap_entities.cpp). Internal to the mesh library.
#pragma once

#include "semimesh/ho/element_type.hpp"
#include "semimesh/mesh/id_table.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace semimesh::mesh::detail {

inline std::uint64_t edge_key(NodeId a, NodeId b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

inline std::array<NodeId, 4> face_key(const NodeId* v, int n) {
  std::array<NodeId, 4> key{kNoNode, kNoNode, kNoNode, kNoNode};
  // Insertion sort of n <= 4 ids (std::sort trips -Warray-bounds on a 4-array prefix).
  for (int i = 0; i < n; ++i) {
    int j = i;
    for (; j > 0 && key[j - 1] > v[i]; --j) key[j] = key[j - 1];
    key[j] = v[i];
  }
  return key;
}

// Key comparisons written out: std::array's operator== calls memcmp for these few bytes, ~1 s of
// the paper's case in the serial passes that build the entities.
inline bool same_edge(const std::array<NodeId, 2>& a, const std::array<NodeId, 2>& b) { return a[0] == b[0] && a[1] == b[1]; }

inline bool same_face(const std::array<NodeId, 4>& a, const std::array<NodeId, 4>& b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3];
}

inline std::uint64_t face_key_hash(const std::array<NodeId, 4>& k) {
  const std::uint64_t low = (static_cast<std::uint64_t>(k[0]) << 32) | k[1];
  const std::uint64_t high = (static_cast<std::uint64_t>(k[2]) << 32) | k[3];
  return IdTable::mix(IdTable::mix(low) ^ high);
}

// [shape][face][k]: the shape's local edge that is edge k of its face f (k in the order of the
// face's own shape's edges): a new face takes its edges' ids from its element's, no lookup.
using FaceEdges = std::vector<std::array<int, 4>>;

inline FaceEdges face_edges(ho::Shape shape) {
  FaceEdges table;
  if (ho::dimension(shape) != 3) return table;
  const auto& shape_edges = ho::edges(shape);
  for (const std::vector<int>& f : ho::faces(shape)) {
    const int n = static_cast<int>(f.size());
    std::array<int, 4> row{-1, -1, -1, -1};
    const auto& own = ho::edges(n == 3 ? ho::Shape::Triangle : ho::Shape::Quadrilateral);
    for (std::size_t k = 0; k < own.size(); ++k) {
      const int a = f[own[k][0]], b = f[own[k][1]];
      for (std::size_t e = 0; e < shape_edges.size(); ++e)
        if ((shape_edges[e][0] == a && shape_edges[e][1] == b) || (shape_edges[e][0] == b && shape_edges[e][1] == a))
          row[k] = static_cast<int>(e);
    }
    table.push_back(row);
  }
  return table;
}

inline const FaceEdges& face_edges_of(ho::Shape shape) {
  static const std::array<FaceEdges, 7> tables = {
      face_edges(ho::Shape::Segment),     face_edges(ho::Shape::Triangle), face_edges(ho::Shape::Quadrilateral),
      face_edges(ho::Shape::Tetrahedron), face_edges(ho::Shape::Pyramid),  face_edges(ho::Shape::Prism),
      face_edges(ho::Shape::Hexahedron)};
  return tables[static_cast<int>(shape)];
}

}  // namespace semimesh::mesh::detail
