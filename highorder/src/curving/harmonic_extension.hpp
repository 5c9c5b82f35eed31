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

/// The extension curve_mesh gives a face off the CAD and a volume (and extend_inward): transfinite
/// for the quadrilateral (Coons: the blend of its opposite edges less the bilinear blend of its
/// corners) and the prism (the Boolean sum of the linear blend of its two triangles across zeta and
/// the triangle's harmonic extension of each level's ring of boundary nodes), harmonic for the other
/// shapes. A layer prism is thin across zeta: the harmonic extension in its reference element took
/// its curved base's bulge out within about a base's width of reference zeta (a slope ~pi/2 times
/// the bulge at the base, against 1/2 for the linear blend), so its first split sub-layer lost a
/// tenth of the bulge and folded on a wall curved across wide triangles. Both reproduce affine and
/// bilinear maps as the harmonic extension does.
const HarmonicExtension& inner_extension(Shape shape, int order, NodeSet set);

/// values: (num_nodes, k) with the boundary rows set; fills the interior rows.
void extend_harmonically(const HarmonicExtension& h, Eigen::MatrixXd& values);

}  // namespace semimesh::ho::detail
