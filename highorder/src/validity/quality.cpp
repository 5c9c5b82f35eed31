#include "semimesh/ho/quality.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::ho {

double scaled_jacobian(const JacobianBounds& bounds) {
  // Dividing by the larger magnitude keeps the ratio in [-1, 1] and makes a fully inverted element
  // (both bounds negative) come out as -1 instead of a misleading positive ratio.
  const double scale = std::max(std::abs(bounds.max_upper), std::abs(bounds.min_lower));
  if (scale == 0.0) return -1.0;  // det J identically zero: a flat element
  return bounds.min_lower / scale;
}

bool acceptable(const JacobianBounds& bounds, double min_scaled_jacobian) {
  return bounds.valid && (min_scaled_jacobian <= 0.0 || scaled_jacobian(bounds) >= min_scaled_jacobian);
}

ElementQuality element_quality(Shape shape, int order, NodeSet set, const Eigen::MatrixX3d& element_nodes,
                               int max_depth, double floor_ratio) {
  ElementQuality quality;
  quality.bounds = certify_jacobian(shape, order, set, element_nodes, max_depth, floor_ratio);
  quality.scaled_jacobian = scaled_jacobian(quality.bounds);
  return quality;
}

}  // namespace semimesh::ho
