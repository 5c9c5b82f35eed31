// The linear near field: one layer of prisms (and hexes in C/H topologies) around the body, and
// the skin it offers to the far field. This is the contract between the shell builder, the far
// field, the high-order stages and the checks.
//
// Element convention (relied on by isoparametric splitting): every layer prism has its vertices
// 0,1,2 on the body (or wall) and 3,4,5 on the outer skin, 3+i being the offset of i, so its
// wall-normal direction is reference zeta and its body face is face 0. The body triangle 0,1,2 is
// counter-clockwise seen from the fluid, so the element has positive volume (Gmsh's reference prism).
// A junction hex (C-type) lies in the corner between the wing and the wall: its cross-section is
// R-W-H-L (R on the root curve, W on the wing, L on the wall, H on the medial halo), vertices
// (Gmsh order) R_a R_b W_b W_a L_a L_b H_b H_a: xi runs along the root, zeta is the wing-normal
// direction (R->L, W->H; face R-W on the wing) and eta the wall-normal one (R->W, L->H; face R-L
// on the wall). The near field records every such stack (LayerStack), so no later stage re-derives
// which element is a layer, in which direction, from element shapes or indices.
#pragma once

#include "semimesh/ho/splitting/precut_faces.hpp"
#include "semimesh/mesh/mesh.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace semimesh::nearfield {

/// A face of the near field's outer skin: 3 or 4 node ids, ordered so that the right-hand normal
/// points OUT of the near field, into the region the far field fills.
struct SkinFace {
  std::array<mesh::NodeId, 4> nodes{};
  int count = 3;
};

/// Which boundary layer a split direction belongs to: its number of layers and growth ratio.
enum class LayerFamily { Wing, Wall };

/// One wall-normal direction of a layer element: the reference axis (0 xi, 1 eta, 2 zeta) along
/// which it is split, and whose layers (the first, thinnest one touches the face at -1 of that axis).
struct LayerDirection {
  int axis = 2;
  LayerFamily family = LayerFamily::Wing;
};

/// A layer element of the near field and its wall-normal direction(s), in the order they are split
/// (wing family first, then wall family). Prisms have one direction, junction hexes two.
struct LayerStack {
  std::size_t element = 0;
  std::vector<LayerDirection> directions;
};

/// A warning about a place where the builder had to depart from what was asked (e.g. a locally
/// reduced thickness), with the place so a user can find it.
struct Warning {
  std::string message;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
};

/// H-type: the wake block swept from the trailing edge (h_shell.hpp), for the ratio along it and
/// the report. Empty (length 0) for the other topologies.
struct WakeBlock {
  std::vector<Eigen::Vector3d> origins;                  ///< trailing-edge nodes the block is swept from,
                                                         ///< sorted by their coordinate along span_axis
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< unit
  Eigen::Vector3d span_axis = Eigen::Vector3d::UnitZ();  ///< unit, across `direction` (the wall normal's part)
  double length = 0.0;  ///< wake.length: the ratio along the block changes over it
  double reach = 0.0;   ///< the block's whole length: `length`, or more when it runs to the far field's face
  int streamwise_cells = 0;
  int hexes = 0;   ///< wake elements: hexes, and prisms behind a base's flat corners (h_shell.hpp)
  double gap = 0.0;  ///< measured: lowest wake node's height above the wall layer's top
};

/// Distance downstream of the trailing edge as a fraction of the wake's length, in [0, 1]: along
/// the direction from the origin whose line (origin + s direction) passes nearest to x (0 upstream).
double wake_fraction(const WakeBlock& wake, const Eigen::Vector3d& x);

struct NearField {
  mesh::Mesh mesh{1};                       ///< order 1; boundary groups "wing" and "wall"
  std::vector<SkinFace> skin;               ///< [faces] outer skin facing the far field
  std::vector<mesh::NodeId> footprint;      ///< closed loop (first != last) where the skin meets the wall
                                            ///< plane, counter-clockwise seen from the fluid side of the wall
  std::vector<mesh::NodeId> footprint_top;  ///< [footprint] C-type: the node at the wall-layer thickness above
                                            ///< each footprint node (its halo point); empty for O-type
  std::vector<mesh::NodeId> outlet;         ///< H-type with wake.to_outlet: the outline of the wake's outflow
                                            ///< face (a closed loop, first != last, on the far field's
                                            ///< downstream face, cut where the split cuts it); empty otherwise
  std::vector<LayerStack> stacks;           ///< every layer element of the mesh, with its direction(s) (the
                                            ///< far field appends its wall-layer prisms)
  std::vector<int> element_surface;         ///< [elements the shell built] CAD surface id of each one's body
                                            ///< face (junction hexes: the wing surface of their R-W face)
  int junction_hexes = 0;                   ///< C-type: hexes along the root loop(s)
  WakeBlock wake;                           ///< H-type
  std::vector<ho::PrecutFace> precut_faces;  ///< H-type, a sharp trailing edge: the junction hexes' faces
                                            ///< R-L-H-W the fan shares cut at the wing layer's interfaces
                                            ///< (ho::follow_precut_faces puts the cuts on the curved faces)
  double thickness_min = 0.0;               ///< smallest layer thickness used (after local reduction)
  double thickness_max = 0.0;               ///< largest layer thickness used
  std::vector<Warning> warnings;
};

}  // namespace semimesh::nearfield
