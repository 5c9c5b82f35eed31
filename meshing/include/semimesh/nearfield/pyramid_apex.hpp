// The apex of the linear pyramid that stands on a quadrilateral skin face (the far field's pyramids
// between the near field's quads and TetGen's triangles). In the near field because the H-type's
// wake block checks its own outer faces with it before the far field stands on them.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

namespace semimesh::nearfield {

inline constexpr std::array<double, 4> kNoSlopeCap{1e300, 1e300, 1e300, 1e300};

/// Apex over the quad a,b,c,d (counter-clockwise seen from the side the pyramid goes to): the
/// centroid plus h times the unit (Newell) normal, h = 0.3 times the shortest edge, halved (down to
/// 1/64) then doubled (up to 4 times: a warped quad needs a taller apex), then 0.3 to 1 times the
/// mean edge (a twisted trapezoid with one short edge), until the linear pyramid (a,b,c,d,apex) has
/// a certified positive Jacobian; none when the quad has zero area or no such height gives a valid
/// pyramid (the quad is folded or far from planar).
/// `max_slope[k]`: the largest tan of the angle at which the pyramid's side over edge k (quad[k] ->
/// quad[k+1]) may rise from the quad, where a neighbouring face closes in (the far field's concave
/// corners); heights above any edge's cap are not tried.
std::optional<Eigen::Vector3d> pyramid_apex(const std::array<Eigen::Vector3d, 4>& quad,
                                            const std::array<double, 4>& max_slope = kNoSlopeCap);

}  // namespace semimesh::nearfield
