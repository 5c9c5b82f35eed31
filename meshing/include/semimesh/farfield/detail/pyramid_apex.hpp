// The apex of the pyramid that turns a quadrilateral skin face into triangles for TetGen.
#pragma once

#include <Eigen/Core>

#include <array>

namespace semimesh::farfield {

/// nearfield::pyramid_apex (semimesh/nearfield/pyramid_apex.hpp), with its per-edge slope caps, or
/// without them when no capped height is valid. Throws FarFieldError (with the
/// quad's centroid) when the quad has zero area or no height gives a valid pyramid.
Eigen::Vector3d pyramid_apex(const std::array<Eigen::Vector3d, 4>& quad,
                             const std::array<double, 4>& max_slope = {1e300, 1e300, 1e300, 1e300});

}  // namespace semimesh::farfield
