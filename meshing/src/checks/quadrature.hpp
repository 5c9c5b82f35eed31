// Gauss quadrature on Gmsh's reference elements (element_type.hpp): tensor Gauss-Legendre rules,
// collapsed (Duffy) onto simplices and the pyramid, so one 1D rule serves every shape.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

namespace semimesh::checks::detail {

struct QuadratureRule {
  Eigen::MatrixX3d points;  ///< (n, 3) reference coordinates
  Eigen::VectorXd weights;  ///< (n) weights; they sum to the reference measure
};

/// Gauss-Legendre rule of n points on [0, 1] (exact for polynomials of degree 2n - 1); points in x.
QuadratureRule gauss_legendre_01(int n);

/// Rule on the reference volume of a 3D shape with n points per collapsed direction.
QuadratureRule volume_rule(ho::Shape shape, int n);

/// Rule on the reference triangle (0,0) (1,0) (0,1) (points in x, y) or on the unit square [0,1]^2.
QuadratureRule unit_triangle_rule(int n);
QuadratureRule unit_square_rule(int n);

}  // namespace semimesh::checks::detail
