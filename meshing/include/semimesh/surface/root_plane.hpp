// The plane a body-only CAD file's wing stands on, found from the body itself (issue: your own
// wing CAD as it comes), so `init --cad` can write geometry.wall_plane for a file that holds no
// wall:
//  - an open root: the body's free curves form one loop lying in a plane (the root section left
//    open, as wing CAD is often exported): that plane;
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

/// The root plane, or nothing when the body has neither a planar free loop nor a planar cap (free
/// curves that are not one planar loop: nothing either, the caller names them).
std::optional<RootPlane> find_root_plane(const cad::Model& model);

}  // namespace semimesh::surface
