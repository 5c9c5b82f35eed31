// The wall's boundary layer (C-type near field): prisms of thickness delta on the far field's wall
// triangles, their tops over the near field's footprint being its halo points, and the box faces
// lifted so that they start on the layer's top (the box's side faces perpendicular to the wall).
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/near_field.hpp"

#include <array>
#include <unordered_map>
#include <vector>

namespace semimesh::farfield {

using Triangle = std::array<mesh::NodeId, 3>;

struct WallLayer {
  std::vector<Triangle> tops;                 ///< [prisms] the layer's top faces, normal away from the wall
  std::vector<nearfield::LayerStack> stacks;  ///< [prisms] each prism, split along zeta in the wall's layers
  std::unordered_map<mesh::NodeId, mesh::NodeId> top_of;  ///< node on the wall -> its top
};

/// Adds to `mesh` the wall-layer prisms (region "wall_layer") on `wall` (triangles facing out of
/// the domain, i.e. into the wall), each node's top delta along the wall's normal under it (one
/// normal on a plane, the CAD's at the node on a curved wall), their tops over the near field's
/// footprint being near.footprint_top, the "farfield" quads where the layer meets the box (its
/// triangles', and the outline `box_outline` of a box face meshed after the lift), and
/// lifts the box nodes: a node at height d above the wall moves to delta + d (1 - delta / D) on its
/// CAD entity (D: the box's height over a plane; over a curved wall the height of the box triangles
/// touching it, nodes higher up staying); `box` triangles referring to nodes on the wall then
/// refer to their tops. Throws
/// FarFieldError naming the surface when a far-field face (a box side, a hemisphere) does not rise
/// perpendicular to the wall where it meets it,
/// or the footprint has no halo (near.footprint_top).
WallLayer build_wall_layer(const cad::Model& model, int wall_surface, const std::vector<int>& box_surfaces,
                           double thickness, const std::vector<Triangle>& wall, const nearfield::NearField& near,
                           std::vector<Triangle>& box, const std::vector<mesh::NodeId>& box_outline, mesh::Mesh& mesh);

}  // namespace semimesh::farfield
