// The apex of the pyramid that turns a quadrilateral skin face into triangles for TetGen.
#pragma once

#include <Eigen/Core>

#include <array>

namespace semimesh::farfield {

/// Apex over the quad a,b,c,d (counter-clockwise seen from the side the pyramid goes to): the
/// centroid plus h times the unit (Newell) normal, h = 0.3 times the shortest edge, halved (down to
/// 1/64) then doubled (up to 4 times: a warped quad needs a taller apex) until the linear pyramid
/// (a,b,c,d,apex) has a certified positive Jacobian. Throws FarFieldError (with the quad's
/// centroid) when no such height gives a valid pyramid.
Eigen::Vector3d pyramid_apex(const std::array<Eigen::Vector3d, 4>& quad);

}  // namespace semimesh::farfield
