// Which canonical nodes of an element lie on each of its faces, found geometrically from the
// reference nodes (a node is on a face when it lies in the face's reference plane), so the checks
// do not depend on the mesh's own node layout code.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <vector>

namespace semimesh::checks::detail {

/// [faces(shape)][nodes on that face] canonical node indices of an order-P element, ascending.
const std::vector<std::vector<int>>& nodes_on_faces(ho::Shape shape, int order, ho::NodeSet set);

/// True when the cycles a (a0 a1 a2 [a3]) and b are the same up to rotation (same orientation).
bool same_cycle(const std::vector<unsigned>& a, const std::vector<unsigned>& b);

}  // namespace semimesh::checks::detail
