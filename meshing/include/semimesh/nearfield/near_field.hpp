// The linear near field: one layer of prisms (and hexes in C/H topologies) around the body, and
// the skin it offers to the far field. This is the contract between the shell builder, the far
// field, the high-order stages and the checks.
//
// Element convention (relied on by isoparametric splitting): every near-field prism has its
// vertices 0,1,2 on the body (or wall) and 3,4,5 on the outer skin, 3+i being the offset of i; a
// hex likewise has 0..3 on the body and 4..7 on the skin. The layer direction is therefore the
// reference zeta direction of each element. The body triangle 0,1,2 is counter-clockwise seen from
// the fluid, so the element has positive volume (Gmsh's reference prism).
#pragma once

#include "semimesh/mesh/mesh.hpp"

#include <array>
#include <string>
#include <vector>

namespace semimesh::nearfield {

/// A face of the near field's outer skin: 3 or 4 node ids, ordered so that the right-hand normal
/// points OUT of the near field, into the region the far field fills.
struct SkinFace {
  std::array<mesh::NodeId, 4> nodes{};
  int count = 3;
};

/// A warning about a place where the builder had to depart from what was asked (e.g. a locally
/// reduced thickness), with the place so a user can find it.
struct Warning {
  std::string message;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
};

struct NearField {
  mesh::Mesh mesh{1};                       ///< order 1; boundary groups "wing" and "wall"
  std::vector<SkinFace> skin;               ///< [faces] outer skin facing the far field
  std::vector<mesh::NodeId> footprint;      ///< closed loop (first != last) where the skin meets the wall
                                            ///< plane, counter-clockwise seen from the fluid side of the wall
  std::vector<int> element_surface;         ///< [elements] CAD surface id of each element's body face
  double thickness_min = 0.0;               ///< smallest layer thickness used (after local reduction)
  double thickness_max = 0.0;               ///< largest layer thickness used
  std::vector<Warning> warnings;
};

}  // namespace semimesh::nearfield
