// The apex of the linear pyramid that stands on a quadrilateral skin face (the far field's pyramids
// between the near field's quads and TetGen's triangles). In the near field because the H-type's
// wake block checks its own outer faces with it before the far field stands on them.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

namespace semimesh::nearfield {

/// Apex over the quad a,b,c,d (counter-clockwise seen from the side the pyramid goes to): the
/// centroid plus h times the unit (Newell) normal, h = 0.3 times its narrowest width (twice the
/// centroid's distance to the nearest edge line: a rectangle's shorter side), halved (down to
/// 1/64) then doubled (up to 4 times: a warped quad needs a taller apex), then 0.3 to 1 times the
/// mean edge (a twisted trapezoid with one short edge), until the linear pyramid (a,b,c,d,apex) has
/// a certified positive Jacobian; none when the quad has zero area or no such height gives a valid
/// pyramid (the quad is folded or far from planar).
std::optional<Eigen::Vector3d> pyramid_apex(const std::array<Eigen::Vector3d, 4>& quad);

}  // namespace semimesh::nearfield
