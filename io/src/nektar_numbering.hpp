// How semimesh elements become Nektar++ elements that pass Nektar++'s load-time checks.
//
// Nektar++ never reads an element's vertices: it derives them from the element's face list and
// each face's edge list (SetUpLocalEdges / SetUpLocalVertices in library/SpatialDomains/
// {Tet,Pyr,Prism,Hex}Geom.cpp), then SetUpFaceOrientation refuses a triangle whose first edge does
// not run along the element's own first axis of that face, i.e. whose third vertex (the one off its
// first edge) is not the collapsed vertex of the element. So:
//  - every triangle is written rotated (orientation kept) so that its highest-ranked vertex is third;
//  - vertex ranks are chosen so every element can agree: vertices on one prism stack line (joined
//    by prism lateral edges) rank together, so both triangles of a prism peak on the same lateral
//    edge (NekMesh's InputStar ResetNodes does the same along stacks), and every pyramid apex ranks
//    above its base (its four triangles all collapse at the apex);
//  - each element's Nektar vertex numbering follows from the ranks (tet: the two highest are
//    vertices 2 and 3, NekMesh's Tetrahedron::OrientTet; prism: the peaking lateral edge is 4-5,
//    Prism::OrientPrism), mirrored where needed so that the straight-sided Jacobian is positive.
// A mesh where a rule cannot hold (two pyramids sharing a triangle, a prism whose triangles peak on
// different lateral edges) throws std::runtime_error naming the element.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace semimesh::io {

struct NektarNumbering {
  /// Mesh node of each Nektar vertex id.
  std::vector<mesh::NodeId> vertex_node;

  /// Nektar vertex id of a mesh node (0xffffffff for a node that is not an element vertex): looked
  /// up in a hash of the vertices, not an array over every node (45 MB on the paper's case).
  std::uint32_t vertex_id(mesh::NodeId node) const {
    return by_node.find(mesh::IdTable::mix(node), [&](std::uint32_t id) { return vertex_node[id] == node; });
  }
  /// Indexes vertex_node anew (after it is filled or reordered).
  void index_vertices() {
    by_node.clear();
    by_node.reserve(vertex_node.size(), [&](std::uint32_t id) { return mesh::IdTable::mix(vertex_node[id]); });
    for (std::uint32_t id = 0; id < vertex_node.size(); ++id)
      by_node.find_or_insert(
          mesh::IdTable::mix(vertex_node[id]), [](std::uint32_t) { return false; }, id,
          [&](std::uint32_t other) { return mesh::IdTable::mix(vertex_node[other]); });
  }

  mesh::IdTable by_node;  ///< Nektar vertex ids by their mesh node
};

/// Nektar++ element letter (A tet, P pyramid, R prism, H hex).
char nektar_tag(ho::Shape shape);
/// Nektar++ local faces in Nektar local vertex numbers (TetGeom/PyrGeom/PrismGeom/HexGeom).
const std::vector<std::vector<int>>& nektar_faces(ho::Shape shape);

/// Ranks the vertices and numbers every element; throws std::runtime_error naming the element if a
/// rule cannot be met.
NektarNumbering number_for_nektar(const mesh::Mesh& mesh);

/// Element e's vertices in Nektar's local numbering (first num_vertices used), as number_for_nektar
/// checked them: derived again when written rather than kept (32 bytes an element).
std::array<mesh::NodeId, 8> nektar_element_vertices(const mesh::Mesh& mesh, const NektarNumbering& numbering,
                                                    std::size_t e);

/// The vertices of face `f` in the order written to the file: a triangle rotated so that its
/// highest Nektar id is third, a quadrilateral as stored. Its edges join consecutive vertices.
std::array<mesh::NodeId, 4> written_face_vertices(const mesh::Mesh& mesh, const NektarNumbering& numbering,
                                                  std::size_t f);

}  // namespace semimesh::io
