// Which canonical nodes of an element lie on each of its faces, found geometrically from the
// reference nodes (a node is on a face when it lies in the face's reference plane), so the checks
// do not depend on the mesh's own node layout code.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <vector>

namespace semimesh::checks::detail {

/// [faces(shape)][nodes on that face] canonical node indices of an order-P element, ascending.
const std::vector<std::vector<int>>& nodes_on_faces(ho::Shape shape, int order, ho::NodeSet set);

/// What Mesh::element_nodes_at reads for the nodes of each face of an order-P element
/// (nodes_on_faces), from its layout: the local edges whose inner nodes lie on the face, ascending,
/// and whether the positions are exactly the face's vertices, the whole inner run of each of those
/// edges and the whole run of the face's own inner nodes, in every orientation. When `whole`, two
/// uses of a face that name the same face and edge entities read the same node set, so it need not
/// be gathered and compared; when not (never for a correct layout), it must be.
struct FaceSources {
  std::vector<int> edges;
  bool whole = false;
};
/// [faces(shape)] for a 3D shape; [1] (the face itself, all its nodes) for a triangle or quadrilateral.
const std::vector<FaceSources>& face_sources(ho::Shape shape, int order, ho::NodeSet set);

/// True when the cycles a (a0 a1 a2 [a3]) and b are the same up to rotation (same orientation).
bool same_cycle(const std::vector<unsigned>& a, const std::vector<unsigned>& b);

}  // namespace semimesh::checks::detail
