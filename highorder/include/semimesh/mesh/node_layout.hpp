// Where each node of an element's canonical (Gmsh) node list lives among the shared entities.
//
// An element of order P lists its nodes in canonical order (see semimesh/ho/element_type.hpp). In
// the mesh, a node inside an edge is owned by the edge, a node inside a face by the face, the rest
// by the element. A NodeLayout tells, for every canonical position, which local vertex / edge /
// face / interior slot holds the node, and at which slot of the shared entity it sits for every
// possible orientation of that entity relative to the element.
//
// The layout is derived geometrically from the equispaced reference nodes (exact lattice points),
// so it does not depend on how the element library orders its blocks. The same combinatorial
// layout is used for every node set: a GLL node set is the equispaced lattice warped in place, so
// the i-th node of both sets plays the same role.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace semimesh::mesh {

/// Permutations relating a face seen by an element to the face's stored vertex order:
/// element-local face vertex k is stored vertex `face_permutations(n)[code][k]`.
/// Triangles have 6 codes, quadrilaterals 8 (rotations, then reflections); code 0 is identity.
const std::vector<std::array<int, 4>>& face_permutations(int num_face_vertices);

/// Orientation code of a face whose element-local vertices are `local` and whose stored vertices
/// are `stored` (both of length n, the same set); -1 if no permutation relates them.
int face_orientation_code(const std::uint32_t* local, const std::uint32_t* stored, int n);

struct NodeSlot {
  enum Kind : std::uint8_t { Vertex, Edge, Face, Interior };
  Kind kind = Vertex;
  /// Local vertex, edge or face index (0 for Interior; for 2D shapes the face is the shape itself).
  std::uint8_t local = 0;
  /// Slot in the entity's own node list: for Vertex unused; for Edge [0] as stored, [1] when the
  /// element traverses the edge backwards; for Face one per orientation code; Interior uses [0].
  std::array<std::uint16_t, 8> slot{};
};

struct NodeLayout {
  ho::Shape shape{};
  int order = 1;
  int num_interior = 0;     ///< nodes owned by the element itself (0 for 2D shapes)
  /// One per canonical node, shape (num_nodes). In blocks, as Gmsh's order gives them (checked
  /// when the layout is built): the vertices in order, then each edge's P - 1 nodes in order (slot
  /// j as stored, P - 2 - j backwards), then each face's in order (slot j at code 0), then the
  /// interior's in order; Mesh gathers an element's nodes by these runs.
  std::vector<NodeSlot> slots;
};

/// Layout of the order-P element of `shape`; computed once per (shape, order) and cached.
/// Thread-safe. Throws std::invalid_argument for order < 1 or > ho::kMaxOrder, or for Segment.
const NodeLayout& node_layout(ho::Shape shape, int order);

/// Number of nodes strictly inside an edge / a face (triangle or quad) of order P.
int edge_interior_count(int order);
int face_interior_count(int num_face_vertices, int order);

}  // namespace semimesh::mesh
