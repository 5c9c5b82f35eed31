// The C-type near field (paper, "medial halos"; docs/architecture.md): the O-type prism layer on the
// wing, lifted off the wall by a root strip, and a block of hexes in the corner between the wing
// and the wall along the root loop.
//
// Construction, per root node R_i (the body mesh's nodes on the wall, one loop):
//  - H_i, the medial halo point: at delta_wing (ShellParams::thickness) from the wing and
//    delta_wall (the wall layer's thickness) from the wall's tangent plane at R_i, in the direction
//    e_i of that plane that bisects the outward normals of the two root segments at R_i
//    (medial_halo);
//  - W_i, the top of the root strip: the foot of H_i on R_i's own wing surface (on the spanwise
//    curve leaving R_i when R_i is a CAD vertex), so H_i - W_i is the wing's normal at W_i; where
//    the wing leans over the fluid (angle > 90 degrees) that foot sinks below delta_wall, and W_i is
//    the point at the height delta_wall straight up the wing from R_i (its chordwise parameter);
//  - L_i = H_i - delta_wall n_wall, on the wall: the wing layer's footprint; where the wing leans
//    over the fluid that foot comes nearer than delta_wing to the root, and L_i is moved out along
//    e_i to delta_wing from R_i (the wall layer's prisms there lean to meet the halo).
// So the hex R-W-H-L keeps both strips (a sliver would be folded by the curved root at high order).
// At 90 degrees and below, W_i and L_i are the halo's feet.
// The wall may be curved (a fuselage, a hub): n_wall is then its normal under each point, heights
// are distances to its surface (detail::WallFrame), and L_i is projected onto it.
// The wing's surface mesh is lifted along the wing so that its root row lands on the W line (every
// node at height d < D above the wall moves to s + d (1 - s / D) along its CAD entity, by Newton in
// the entity's parameters: s the strip height, D the lowest point of the surfaces that do not stand
// on the wall, i.e. the tip's: a rounded tip turns level, where such a move would run across it; the
// body's top when every surface stands on the wall), and the O-type layer is built on it
// with the offsets of the W nodes pinned at H. One hex per root segment fills R-W-H-L (vertex
// order: near_field.hpp). The wall's
// own layer (prisms between the L loop and the box) is built by the far field on its wall mesh, its
// top nodes over the L loop being the halo points (NearField::footprint_top).
//
// Boundary orientation as for the O-type: "wing" holds the wing triangles and the hexes' R-W
// quads, "wall" the hexes' R-L quads, all facing out of the domain.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/near_field.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/params/table.hpp"
#include "semimesh/surface/model_surfaces.hpp"

namespace semimesh::nearfield {

/// Which body-wall curves are concave corners and the angles the junction supports. Keys, ranges
/// and meanings: junction_keys() (rows of the config's [nearfield] section).
struct JunctionParams {
  double concave_below_deg = 170;  ///< a body-wall curve whose dihedral angle seen from the fluid stays below this
  double min_angle_deg = 60;       ///< supported dihedral angles of the root curves
  double max_angle_deg = 150;
};

/// One row per key of JunctionParams (semimesh/params/table.hpp).
const params::Table<JunctionParams>& junction_keys();

/// Body surface meshes -> wing prism layer + junction hexes (order 1), the wall layer of thickness
/// `wall_thickness` (delta_wall > 0) to be built by the far field on the footprint. Throws
/// NearFieldError naming the parameter, or the curve/surface and the value, when the junction
/// cannot be built: a root curve outside the supported angles or not concave, a halo point or
/// strip top that cannot be placed, a strip too tall for the body, a junction hex that would be
/// inverted.
NearField build_c_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params, const JunctionParams& junction, double wall_thickness);

}  // namespace semimesh::nearfield
