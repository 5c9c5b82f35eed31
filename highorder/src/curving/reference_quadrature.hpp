// Gauss quadrature on the reference elements of element_type.hpp.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

namespace semimesh::ho::detail {

struct Quadrature {
  Eigen::MatrixX3d points;  ///< (npoints, 3) reference coordinates
  Eigen::VectorXd weights;  ///< (npoints) summing to the reference measure
};

/// n Gauss-Legendre points per direction; simplices and the pyramid through the collapsed
/// (Duffy) map, whose Jacobian is folded into the weights, so a polynomial of degree <= 2n - 3 in
/// each collapsed direction is integrated exactly (Karniadakis & Sherwin, "Spectral/hp element
/// methods", section 4.1). n >= 1.
Quadrature reference_quadrature(Shape shape, int n);

}  // namespace semimesh::ho::detail
