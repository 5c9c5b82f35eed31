// Element quality from the certified Jacobian bounds of validity.hpp.
//
// Scaled Jacobian of a high-order element: min det J / max det J over the whole element (docs/architecture.md
// section 4). It is computed from the certified bounds, min_lower / max_upper, so it never
// overstates the quality: the true ratio lies between this value and min_upper / max_upper.
// Values: in (0, 1] for a valid element (1: constant det J, e.g. any affine element), <= 0 when the
// element is, or cannot be proven not to be, inverted somewhere; -1 when inverted everywhere.
#pragma once

#include "semimesh/ho/validity.hpp"

namespace semimesh::ho {

struct ElementQuality {
  JacobianBounds bounds;
  double scaled_jacobian = 0.0;  // scaled_jacobian(bounds)
};

/// Whether an element counts as valid with a floor on its scaled Jacobian: proven valid and
/// scaled_jacobian(bounds) >= min_scaled_jacobian (bounds certified with that floor_ratio, so a
/// loose bound does not fail a good element). A floor of 0 is plain validity.
bool acceptable(const JacobianBounds& bounds, double min_scaled_jacobian);

/// Certifies one element and derives its scaled Jacobian; same arguments as certify_jacobian.
ElementQuality element_quality(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                               int max_depth = 8, double floor_ratio = 0.0);

}  // namespace semimesh::ho
