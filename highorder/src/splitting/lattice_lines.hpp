// The element map at the split pieces' nodes, from the few nodes that matter.
//
// A piece's node keeps its coarse node's reference coordinates in every direction but the split
// ones (one or two). On the line (one split direction) or plane (two) of the node lattice through
// that node, every basis function of a node off it is 0, and the others are products of the 1D
// Lagrange polynomials through the nodes' coordinates along the split directions: a hexahedron's
// space is Q_P, a prism's (split along zeta only) P_P(xi, eta) x P_P(zeta), both over a tensor node
// lattice. So chi there sums (P + 1) or (P + 1)^2 terms of 1D products, where the full basis
// (LagrangeBasis::values, the reference this is tested against) costs a (points, nodes) matrix.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace semimesh::ho::detail {

struct LatticeLines {
  int order = 1;
  int count = 1;                         ///< split directions: 1 or 2
  std::array<int, 2> directions{-1, -1};
  int stride = 0;                        ///< (P + 1)^count nodes per line or plane
  /// [node][m_b (P + 1)][m_a (P + 1)]: the canonical index of the node at lattice coordinate m_a
  /// along directions[0] (m_b along directions[1]) on node's line or plane.
  std::vector<int> nodes;
  /// [node][direction slot][m]: the reference coordinate of those nodes along that direction (a
  /// lattice line's nodes share it across the line: the node set is a tensor one).
  std::vector<double> coordinates;
};

/// The lines of a hexahedron (any one or two distinct directions) or a prism (direction 2 alone)
/// of order P and node set `set`; std::invalid_argument otherwise.
LatticeLines lattice_lines(Shape shape, int order, NodeSet set, const std::array<int, 2>& directions);

/// chi at points on the lines: row r of `points` (rows, 3) keeps node (r mod num_nodes)'s
/// reference coordinates but along the lines' directions; element_nodes (num_nodes, 3).
/// Returns (rows, 3).
Eigen::MatrixX3d map_along_lines(const LatticeLines& lines, const Eigen::MatrixX3d& element_nodes,
                                 const Eigen::MatrixX3d& points);

/// chi at one point on node `node`'s line or plane, given by its coordinates along the lines'
/// directions (`along`[slot]).
Eigen::Vector3d map_along_line(const LatticeLines& lines, const Eigen::MatrixX3d& element_nodes, int node,
                               const std::array<double, 2>& along);

/// The order-1 basis of a hexahedron or prism (Gmsh's vertex order) at reference point r, without
/// a matrix: the weights of its vertices; entries past num_vertices(shape) are 0.
std::array<double, 8> linear_weights(Shape shape, const Eigen::RowVector3d& r);

}  // namespace semimesh::ho::detail
