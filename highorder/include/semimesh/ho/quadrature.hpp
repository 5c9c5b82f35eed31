// Gauss quadrature on the reference elements of element_type.hpp (Gmsh's): one 1D Gauss-Legendre
// rule, tensorised, and collapsed (Duffy) onto simplices and the pyramid with the collapse's
// Jacobian folded into the weights (Karniadakis & Sherwin, "Spectral/hp element methods", 4.1).
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

namespace semimesh::ho {

struct Quadrature {
  Eigen::MatrixX3d points;  ///< (npoints, 3) reference coordinates (unused coordinates 0)
  Eigen::VectorXd weights;  ///< (npoints) summing to the reference measure
};

/// n Gauss-Legendre points per direction (n^dim points): exact for polynomials of degree <= 2n - 1
/// per direction on segments, quads and hexes, and of degree <= 2n - 3 per collapsed direction on
/// triangles, tets, prisms and pyramids. Throws std::invalid_argument for n < 1.
Quadrature reference_quadrature(Shape shape, int n);

}  // namespace semimesh::ho
