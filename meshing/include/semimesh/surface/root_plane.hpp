// The plane a body-only CAD file's wing stands on, found from the body itself (issue: your own
// wing CAD as it comes), so `init --cad` can write geometry.wall_plane for a file that holds no
// wall:
//  - an open root: the body's free curves form loops, each lying in a plane (the root section left
//    open, as wing CAD is often exported, and perhaps an open flat tip): the longest loop's plane,
//    of loops of the same length (within 1 %) the one nearer the origin;
//  - a closed body: the planar faces with the whole body on one side (its caps: root, and a flat
//    tip): the largest, and of caps within 1 % of the same area (a straight wing's root and tip)
//    the one nearer the origin, where CAD puts a wing's root.
// The normal points into the fluid: from the plane towards the body.
#pragma once

#include "semimesh/cad/model.hpp"

#include <optional>
#include <string>

namespace semimesh::surface {

struct RootPlane {
  cad::Vec3 point = cad::Vec3::Zero();
  cad::Vec3 normal = cad::Vec3::UnitZ();  ///< unit, towards the body
  std::string why;                         ///< how it was found, naming the curves or the face
};

/// The root plane, or nothing when a closed body has no planar cap. An open body whose free loops
/// are not each flat with the body on one side (unsewn faces, a root plane through the body):
/// CadRoleError naming the loop, how far off it is and the key to set.
std::optional<RootPlane> find_root_plane(const cad::Model& model);

}  // namespace semimesh::surface
