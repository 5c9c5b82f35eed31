// The H-type near field (paper, section 3 "H-type", "wake block", "wake gap"; DESIGN.md section 5):
// the C-type near field whose wing layer ends at the squared-off trailing edge, and a block of hexes
// swept from the trailing edge downstream, standing a gap above the wall layer.
//
// Construction:
//  - the C-type wing layer and root junction (c_shell.hpp) with the trailing-edge base bare: the base
//    (one face, or several forming one strip from the root to the tip: detail::trailing_edge_base,
//    e.g. a lower and an upper half, or one per panel of a cranked wing; each meshed with
//    structured quads, conforming across their shared curves) is lifted and carries junction hexes along its root like the
//    rest of the wing, but no prisms; the upper and lower layers end at the trailing edge with
//    their own normals (no rounding around it). Each has a rear interface, the quads (a, b, b', a')
//    over its trailing-edge edges a-b up to its outer edge a'-b' (the tip's layer likewise over the
//    tip's trailing-edge edge);
//  - a sharp trailing edge (te_base "auto" and no base: the body-body curve leaving the wall
//    farthest downstream): the layer is cracked open along the curve, each side's nodes inside it
//    offset along that side's own normal, so the upper and lower rear interfaces meet on the curve
//    and their sweeps share the wake sheet (the curve swept). A crack cannot close inside the layer
//    (the two interfaces would meet at a zero angle along one edge: no element fills that, no
//    pyramid stands in it), so it ends on the layer's edge: at the tip the triangles touching the
//    tip vertex stay bare, faced by the far field (the block stops one trailing-edge cell below the
//    tip); at the root the junction gives the strip top one halo per side, none upstream of its
//    side's rear interface (the plane of the curve's tangent and the side's normal: where the edge
//    sweeps back, a halo placed from the root is moved into it, so the rear interface stays flat
//    down to the wall layer), and fills the wedge between them with prisms standing on the wall, cut in advance at the wing layer's split
//    interfaces (the split cannot fan a prism from its root) and welded to the junction hexes'
//    split nodes;
//  - the wake block: the base quads and the rear interfaces above the cut row (the lowest
//    trailing-edge row at least `gap` above the wall layer's top) are swept along `direction` in
//    `layers` streamwise cells growing by `growth` up to `length`, the layer offsets moving away
//    from the wake sheet by tan(widening) per unit length. Hexes over rear interfaces continue their
//    wing layer (a LayerStack of the wing family), hexes over the base are not split. A base quad
//    at a flat corner of the base (its two curves meeting at over 150 degrees, e.g. where a
//    revolved tip's rounded trailing edge continues the base's sides tangentially) is swept as two
//    prisms, its triangles split from that corner: a hex there has two edges on one tangent line
//    and, curved, a Jacobian that vanishes at the corner;
//  - the skin: every near-field face used once that is neither body, wall nor on the footprint,
//    plus the base quads below the cut. A skin quad that the wing layer's split will cut (the rear
//    interfaces below the cut, the junction's faces behind the base, the wake's root and outflow
//    faces) is given to the far field already cut, at the split's interfaces along its straight
//    layer edges, so the pyramids and tetrahedra match the split elements' faces once the split
//    nodes are welded to these (the paper's pyramids on "(split) quadrilaterals").
//  - for PyFR (WakeParams::translational_rear_interfaces, output.target = "pyfr"): each side's layer
//    edges over the trailing edge made one vector before the wake is swept (translational_rims.hpp),
//    so its rear interfaces and the wake's outflow face are parallelograms once split; the
//    trailing edge's root corners too, each with one halo per side (a wedge between them, as a
//    sharp edge's fan; root_corners.cpp), save on a curved wall; not yet the tip's trailing-edge
//    corners (docs/solvers.md).
// Boundary orientation as for the C-type; the base quads are in group "wing".
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/c_shell.hpp"
#include "semimesh/nearfield/near_field.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/params/table.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace semimesh::nearfield {

/// Keys, ranges and meanings: wake_keys() (the config's [wake] section).
struct WakeParams {
  std::array<double, 3> direction{1.0, 0.0, 0.0};
  double length = 2.0;
  int layers = 12;
  double growth = 1.15;
  double widening_deg = 0.0;
  double gap = 0.1;
  double ratio_end = 1.0;
  std::string te_base = "auto";  ///< the pipeline resolves "auto" (cad_roles) to the detected base's name
  /// Not a key: output.target = "pyfr" sets it. The layer edges over each side's trailing edge made
  /// one vector (translates), the root corners' halos included (the junction split in two halos
  /// there), so the rear interfaces below the cut and the wake's outflow face are parallelograms
  /// once split (PyFR's pyramid rule; docs/solvers.md says what is left).
  bool translational_rear_interfaces = false;
  /// Not keys: output.target = "pyfr" sets them. The block runs on past `length` to the far
  /// field's downstream face (a plane across `direction`), its cells still growing by `growth` but
  /// none longer than `outlet_cell`, so its outflow face is part of the domain's boundary: the
  /// quads there cannot all be parallelograms (the layer's cross-section turns round the tip), and
  /// PyFR refuses a pyramid on one that is not (docs/solvers.md).
  bool to_outlet = false;
  double outlet_cell = 0.0;
};

/// One row per key of WakeParams (semimesh/params/table.hpp).
const params::Table<WakeParams>& wake_keys();

/// The wing layer's split as the near field must foresee it on the skin: the split's interfaces
/// (fractions 0 = f_0 < ... < f_N = 1 from the body side) along a layer edge whose body-side vertex
/// is at x, given the wake block (for the ratio along it). Empty: the layer is not split.
using LayerFractions = std::function<std::vector<double>(const Eigen::Vector3d& x, const WakeBlock& wake)>;

/// Body surface meshes (the trailing-edge base `wake.te_base` and the faces going on with it to the
/// tip meshed with structured quads, the rest with triangles) -> wing prisms, junction hexes and wake hexes (order 1). `box` bounds the
/// domain (the far field's box); `fractions` the wing layer's split (see LayerFractions). Throws NearFieldError naming the key and value, or the surface,
/// when: no trailing-edge base is found among the body surfaces (nor, for te_base "auto", a sharp
/// trailing edge), the trailing edge goes on past the base's faces or the sharp curve (naming the
/// faces and the one it goes on into, or the curves), the direction points upstream
/// (x <= 0) or into the wall, the gap leaves no trailing-edge row below the tip, the wake leaves
/// the box, a wake hex would be inverted (widening or direction), or the C-type junction fails.
NearField build_h_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params, const JunctionParams& junction, double wall_thickness,
                        const WakeParams& wake, const cad::BBox& box, const LayerFractions& fractions);

}  // namespace semimesh::nearfield
