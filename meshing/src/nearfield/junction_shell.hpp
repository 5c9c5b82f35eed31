// What the C-type and H-type near fields share: the wing layer lifted off the wall by the root strip
// and the junction hexes along the root loop (c_shell.hpp describes the construction). The H-type
// builds it with its trailing-edge base bare: the base is lifted and carries junction hexes along
// its root like the rest of the wing, but no prisms, and the layer ends at it with its own normals.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/body_mesh.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/near_field.hpp"

#include <array>
#include <set>
#include <vector>

namespace semimesh::nearfield::detail {

/// The wall under the junction: a plane (its normal into the fluid and a point of it), or a curved
/// surface (a fuselage, a hub) with `normal` and `origin` taken at the root's centroid. Heights on a
/// curved wall are distances to its surface along the normal at the foot, found by Newton from the
/// root's parameters (the near field lies over the root; an unguided projection onto the trimmed
/// face would avoid the root's hole and land on the far side of a fuselage).
struct WallFrame {
  Vec3 normal;
  Vec3 origin;
  const cad::Surface* curved = nullptr;  ///< the wall's surface when it is not planar
  cad::Vec2 root_uv = cad::Vec2::Zero();  ///< curved: the wall's parameters at `origin`

  /// x's height above the wall and the wall's normal into the fluid under it (one projection).
  struct Above {
    double height;
    Vec3 normal;
  };
  Above above(const Vec3& x) const {
    if (!curved) return {(x - origin).dot(normal), normal};
    const cad::SurfaceProjection p = curved->project(x, root_uv);
    const Vec3 n = curved->normal(p.uv);
    return {(x - p.point).dot(n), n};
  }
  double height(const Vec3& x) const { return above(x).height; }
  Vec3 normal_at(const Vec3& x) const { return curved ? above(x).normal : normal; }
};

/// The frame of `wall_surface` under the root loop `root_points` (see WallFrame).
WallFrame wall_frame(const cad::Model& model, int wall_surface, const std::vector<Vec3>& root_points);

struct JunctionShell {
  NearField field;                   ///< wing prisms, junction hexes, their boundary faces and stacks; no footprint
  BodyMesh body;                     ///< the layer's body mesh, lifted onto the strip
  BodyMesh layer;                    ///< the prisms' triangles (no bare ones), cracked along the crack curve
  std::vector<mesh::NodeId> layer_body;  ///< [layer nodes] the body (mesh) node of each: i, or a crack copy's original
  std::vector<char> crack;           ///< [body nodes] 1: inside the crack curve (one offset per side)
  std::vector<std::array<int, 3>> bare;  ///< body triangles off the bare surface left without prisms (crack ends)
  mesh::NodeId offset = 0;           ///< body node i is mesh node i; layer node i's offset is mesh node i + offset
  std::vector<int> chain;            ///< body nodes of the root row (strip tops W), in loop order
  std::vector<mesh::NodeId> root_id; ///< [chain] the root node R on the wall below each
  std::vector<mesh::NodeId> foot_id; ///< [chain] the wall foot L of each halo
  /// A sharp trailing edge's root (chain[index], -1: none): one wall foot and halo per side, side 0
  /// that of the root segment into it along the chain, side 1 the one out of it; the junction
  /// leaves the wedge between them open (see fan_wedge.cpp).
  struct Fan {
    int index = -1;
    std::array<mesh::NodeId, 2> foot{mesh::kNoNode, mesh::kNoNode}, top{mesh::kNoNode, mesh::kNoNode};
  } fan;
  /// output.target = "pyfr" (split_bare_corners): a bare surface's root corner (chain[index], where
  /// one root segment is on the bare surface, the blunt trailing edge's base): one wall foot and
  /// halo per side, as the fan's (side 0 the root segment into it along the chain). The side with
  /// the wing layer keeps the strip top's layer node and foot_id, the bare side gets copies of
  /// them, so the layer side's halo can move onto its rear interfaces' layer edge (one vector, a
  /// parallelogram for PyFR) and a wedge between the two halos fill the gap (fan_wedge.cpp).
  struct Corner {
    int index = -1;
    int bare = 0;  ///< the side whose root segment lies on the bare surface
    std::array<mesh::NodeId, 2> foot{mesh::kNoNode, mesh::kNoNode}, top{mesh::kNoNode, mesh::kNoNode};
  };
  std::vector<Corner> corners;
  WallFrame wall;
  double strip = 0.0, tip = 0.0;     ///< the lift's strip height; the body's top height
};

/// The wing layer and junction on `roles.body_surfaces` (as build_c_shell), no prisms on the
/// triangles of `bare_surfaces` (none: empty; the trailing-edge base's faces), whose nodes off the
/// other surfaces get no offset and do not count in the thickness figures. Along `crack_curve` (-1: none; a sharp trailing edge) the
/// layer is cracked open: the curve's inner nodes get one offset per side, each along its own
/// side's normal, so the layer ends there with two rear interfaces; the triangles touching the
/// curve's tip end stay bare (JunctionShell::bare), so the crack ends on the layer's edge instead of
/// closing to a zero-angle wedge; at its root the junction gets two halos (JunctionShell::fan).
/// With `split_bare_corners` the bare surfaces' root corners get two halos too, both where the
/// one would be (JunctionShell::corners). Throws NearFieldError.
JunctionShell build_junction_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                                   const ShellParams& params, const JunctionParams& junction, double wall_thickness,
                                   const std::set<int>& bare_surfaces, int crack_curve, bool split_bare_corners = false);

/// x moved along its CAD entity (a surface or curve) to `target` height above the wall, along the
/// entity's steepest ascent; updates the attachment.
Vec3 move_to_height(const cad::Model& model, const WallFrame& wall, const Vec3& x, mesh::CadAttachment& cad,
                    double target);

/// The lift of a wing node at height d along its CAD entity to height strip + d (1 - strip / ceiling),
/// updating its attachment; nodes at or above the ceiling and CAD vertices stay.
Vec3 lift_node(const cad::Model& model, const WallFrame& wall, double strip, double ceiling, const Vec3& x,
               mesh::CadAttachment& cad);

}  // namespace semimesh::nearfield::detail
