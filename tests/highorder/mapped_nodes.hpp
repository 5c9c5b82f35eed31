// Elements made by a known map: the map applied to the reference nodes (validity tests).
#pragma once

#include "semimesh/ho/basis.hpp"

#include <Eigen/Core>

#include <functional>

namespace semimesh::ho::testing {

using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

/// Nodes of the element whose map is `map` applied to the reference nodes; (num_nodes, 3).
inline Eigen::MatrixX3d mapped_nodes(Shape shape, int order, NodeSet set, const Map& map) {
  Eigen::MatrixX3d nodes = reference_nodes(shape, order, set);
  for (int i = 0; i < nodes.rows(); ++i) nodes.row(i) = map(nodes.row(i).transpose()).transpose();
  return nodes;
}

}  // namespace semimesh::ho::testing
