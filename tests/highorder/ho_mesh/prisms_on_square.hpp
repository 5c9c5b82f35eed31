// Two prisms of order P on triangles of the unit square, their nodes placed element by element
// through a map and merged where they coincide: the split tests' small layered meshes.
#pragma once

#include "semimesh/ho/basis.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace semimesh::ho {

/// The prisms on `triangles` (corner indices of the unit square (0,0), (1,0), (0,1), (1,1)), each
/// node at place(point of the square, zeta in [-1, 1]); nodes within 1e-9 of each other are one.
template <typename Place>
mesh::Mesh prisms_on_square(int order, NodeSet set, const std::vector<std::array<int, 3>>& triangles,
                            const Place& place) {
  const Eigen::Vector3d corners[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh::Mesh m(order, set);
  const Eigen::MatrixX3d r = reference_nodes(Shape::Prism, order, set);
  std::map<std::array<long, 3>, mesh::NodeId> node_at;
  for (const auto& t : triangles) {
    std::vector<mesh::NodeId> ids;
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
      const double a = r(i, 0), b = r(i, 1);
      const Eigen::Vector3d x = place((1 - a - b) * corners[t[0]] + a * corners[t[1]] + b * corners[t[2]], r(i, 2));
      const std::array<long, 3> key{std::lround(x(0) * 1e9), std::lround(x(1) * 1e9), std::lround(x(2) * 1e9)};
      auto it = node_at.find(key);
      if (it == node_at.end()) it = node_at.emplace(key, m.add_node(x)).first;
      ids.push_back(it->second);
    }
    m.add_element(Shape::Prism, ids);
  }
  return m;
}

}  // namespace semimesh::ho
