// Discrete harmonic extension on a reference element: the interior node values that minimise the
// Dirichlet energy (integral of |grad u|^2 over the reference element) of the Lagrange interpolant
// with the boundary node values fixed. Affine and multilinear maps are harmonic, so a straight-sided
// element is reproduced exactly; a curved boundary is blended smoothly into the interior.
#pragma once

#include "semimesh/ho/element_type.hpp"

#include <Eigen/Core>

#include <vector>

namespace semimesh::ho::detail {

struct HarmonicExtension {
  std::vector<int> interior;   ///< canonical indices of the nodes inside (3D: volume; 2D: face)
  std::vector<int> boundary;   ///< all other canonical indices
  Eigen::MatrixXd extension;   ///< (interior, boundary): interior values = extension * boundary values
};

/// Built once per (shape, order, set) and cached; thread-safe. Shapes: triangle, quadrilateral and
/// every 3D shape (the pyramid's rational basis is integrated approximately).
const HarmonicExtension& harmonic_extension(Shape shape, int order, NodeSet set);

/// values: (num_nodes, k) with the boundary rows set; fills the interior rows.
void extend_harmonically(const HarmonicExtension& h, Eigen::MatrixXd& values);

}  // namespace semimesh::ho::detail
