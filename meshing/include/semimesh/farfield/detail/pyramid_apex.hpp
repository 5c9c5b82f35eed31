// The apex of the pyramid that turns a quadrilateral skin face into triangles for TetGen.
#pragma once

#include <Eigen/Core>

#include <array>

namespace semimesh::farfield {

/// nearfield::pyramid_apex (semimesh/nearfield/pyramid_apex.hpp). Throws FarFieldError (with the
/// quad's centroid) when the quad has zero area or no height gives a valid pyramid.
Eigen::Vector3d pyramid_apex(const std::array<Eigen::Vector3d, 4>& quad);

}  // namespace semimesh::farfield
