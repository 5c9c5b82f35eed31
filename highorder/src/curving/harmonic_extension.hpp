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

/// A prism's extension for the energy whose weight along its triangles (u, v) is `lateral` times its
/// weight across them (w): the reference Dirichlet energy of a prism as thin as the layer elements
/// are (lateral = 1: harmonic_extension's). Cached like it, per weight.
const HarmonicExtension& prism_extension(int order, NodeSet set, double lateral);

/// The weight for a prism whose vertices are rows 0-5 of x (canonical order: bottom triangle, then
/// top): the physical Dirichlet energy pulled back to the reference prism (triangle legs 1, height 2)
/// weighs (u, v) by (delta / 2L)^2 against w, delta the mean vertical edge, L the mean triangle edge.
/// The isotropic reference energy damps a curved triangle face within the first rows of nodes of a
/// thin prism (its bulge reaches the next row a third as much, which folds the prism at order >= 3
/// on a fuselage's wall layer); this one carries it through the layer. Rounded down to a power of 4
/// in [4^-5, 1], so that few extensions are built and the same prism always takes the same one.
double prism_lateral_weight(const Eigen::MatrixXd& x);

/// values: (num_nodes, k) with the boundary rows set; fills the interior rows.
void extend_harmonically(const HarmonicExtension& h, Eigen::MatrixXd& values);

}  // namespace semimesh::ho::detail
