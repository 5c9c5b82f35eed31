// Nodal (Lagrange) bases on the reference elements of element_type.hpp.
//
// Polynomial spaces: segment P_P; triangle and tetrahedron P_P (total degree); quadrilateral and
// hexahedron Q_P (degree P in each variable); prism P_P(x, y) x P_P(z); pyramid: the rational space of
// Bergot, Cohen & Durufle (2010), the one Gmsh uses, which contains P_P and has (P+1)(P+2)(2P+3)/6
// functions (see modal_basis.cpp for its orthogonal basis and how the apex is handled).
// Node i of the basis is row i of reference_nodes(shape, order, set) (canonical Gmsh order) and
// function i is 1 at node i and 0 at every other node.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

#include <array>
#include <memory>
#include <vector>

namespace semimesh::ho {

class LagrangeBasis {
 public:
  /// Throws std::invalid_argument for an order outside [1, kMaxOrder]. Bases are built once per
  /// (shape, order, set) and shared; construction is thread-safe and copies are cheap.
  LagrangeBasis(Shape shape, int order, NodeSet set = NodeSet::Equispaced);

  Shape shape() const;
  int order() const;
  NodeSet node_set() const;
  int size() const;                        ///< number of nodes = number of functions
  const Eigen::MatrixX3d& nodes() const;  ///< (size, 3) reference nodes, canonical order

  /// Values of every function at reference points (npoints, 3): (npoints, size). Quadrilaterals,
  /// hexahedra and prisms as products of their factors' values (segments, triangle).
  Eigen::MatrixXd values(const Eigen::MatrixX3d& points) const;
  /// The same through the modal basis and the inverse Vandermonde matrix, for every shape: the
  /// reference the product path is tested against.
  Eigen::MatrixXd values_by_modes(const Eigen::MatrixX3d& points) const;
  /// d/dxi_k of every function, k = 0, 1, 2; each (npoints, size). Unused directions are 0.
  std::array<Eigen::MatrixXd, 3> gradients(const Eigen::MatrixX3d& points) const;

  struct Data;  // shared, immutable

 private:
  std::shared_ptr<const Data> data_;
};

/// Matrix (to.size(), from.size()) taking node values of `from` to node values of `to` (same shape).
Eigen::MatrixXd interpolation_matrix(const LagrangeBasis& from, const LagrangeBasis& to);

/// The element map chi at reference points: element_nodes (size, 3) physical coordinates in canonical
/// order, ref_points (npoints, 3); returns (npoints, 3).
Eigen::MatrixX3d map_points(const LagrangeBasis& basis, const Eigen::MatrixX3d& element_nodes,
                            const Eigen::MatrixX3d& ref_points);

/// Jacobian matrices d chi_i / d xi_j of the element map at reference points. For 1D/2D shapes the
/// columns of the unused reference directions are 0 (the matrix is then singular by construction).
std::vector<Eigen::Matrix3d> jacobians(const LagrangeBasis& basis, const Eigen::MatrixX3d& element_nodes,
                                       const Eigen::MatrixX3d& ref_points);

/// 2-norm condition number of the Vandermonde matrix (orthonormal modal basis at the nodes): a measure
/// of how well a node set interpolates (GLL is far better than equispaced at high order).
double vandermonde_condition_number(Shape shape, int order, NodeSet set);

}  // namespace semimesh::ho
