// Far-field elements that stand on the body itself (the bare triangles at a sharp trailing edge's
// tip end) bent with the body's curved faces. curve_mesh moves only the nodes on the CAD: an edge
// on a curved face then leaves its end at the CAD's tangent, which tilts it by about kappa L / 2
// from its chord, while a far-field edge from that end to a node a thin first layer h above the
// face's next vertex stays straight; once h < kappa L^2 / 2 that node lies below the tangent plane
// and the element folds (pyramids on the pre-cut rims and tets on the bare triangles, at every
// order >= 2). The far field near such a face takes the face's own bulge instead: each node off the
// CAD and off the near field moves by the bulge at its foot on the face, fading out over one face
// size, so next to the face the far field bends exactly as the layer's split prisms do.
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <cstddef>
#include <string>

namespace semimesh::ho {

struct ExposedBodyStats {
  std::size_t faces = 0;  ///< curved body faces that a far-field element stands on
  std::size_t nodes = 0;  ///< far-field nodes moved
};

/// In `curved` (order >= 2, vertices where the linear mesh had them): the nodes of elements of
/// region `region` within one face size of a curved triangle of boundary group `body_group` that
/// one of those elements stands on, moved to their straight position plus that triangle's bulge at
/// their closest point on it, weighted (1 - d / size)^2. Nodes on the CAD or on any boundary face,
/// nodes of elements of other regions and the base vertices of pyramids (the near field's pre-cut
/// rims, which the weld matches by position) stay. Nothing happens when the region or group is
/// absent or no such face is curved. The far-field vertices among the moved nodes (pyramid apexes,
/// TetGen's own points) keep no straight copy: `moved_before` says a first pass moved them, so a
/// second one (after a stage that re-extended the far field's inner nodes, the H-type weld) finds
/// their straight places again instead of moving them twice.
ExposedBodyStats follow_exposed_body(mesh::Mesh& curved, const std::string& body_group, const std::string& region,
                                     bool moved_before = false);

}  // namespace semimesh::ho
