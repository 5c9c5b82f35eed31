// The C-type junction shell's steps (build_junction_shell, c_shell.cpp) and what they hand each
// other: the junction's cross-section at every root node and its hexes (junction_block.cpp), the
// body lifted onto the root strip (root_lift.cpp), the wing layer on it: cracked, pinned at the
// halos, offset and meshed (wing_layer.cpp).
#pragma once

#include "semimesh/mesh/directed_edge_index.hpp"
#include "semimesh/nearfield/body_mesh.hpp"

#include "junction_shell.hpp"
#include "shell_common.hpp"

#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace semimesh::nearfield::c_type {

using mesh::CadAttachment;
using mesh::NodeId;
using Frame = detail::WallFrame;

struct JunctionNode {
  Vec3 root, halo, strip_top, wall_foot;
  CadAttachment strip_top_cad, wall_foot_cad;
};

// The body's triangles by their directed edges, for the root segments a -> b along the loop: which
// triangle stands on each, its surface, and the segment's outward direction in the wall plane.
class RootSegments {
 public:
  RootSegments(const BodyMesh& body, const Frame& wall);

  /// The triangle with the directed edge a -> b (the last one given, where two have it); throws
  /// std::out_of_range if none has.
  int triangle(int a, int b) const;
  Vec3 outward(int a, int b) const;
  int surface(int a, int b) const { return body_.triangle_surface[triangle(a, b)]; }

 private:
  const BodyMesh& body_;
  const Frame& wall_;
  mesh::DirectedEdgeIndex triangle_of_edge_;
};

// The root curve a root node lies on (of its vertex: the first curve on the wall).
int root_curve_of(const cad::Model& model, const CadAttachment& root, int wall);

// The junction's cross-section at every root node (root, halo, strip top, wall foot); at the fan
// node one per side, each over its own root segment's outward direction (side 0: the segment into
// it, side 1: the one out of it).
struct JunctionNodes {
  std::vector<JunctionNode> at;            ///< [loop]; the fan node's side 0
  int fan = -1;                            ///< loop index of the fan node, -1: none
  JunctionNode fan_side1;                  ///< the fan node's side 1
  std::array<int, 2> fan_surface{-1, -1};  ///< [sides] the surface of the fan node's root segment on each side
};

/// Halo, strip top and wall foot of every root node, each over the bisector of its two root
/// segments' outward directions (the fan node's sides over their own, kept off the sharp edge's
/// rear interfaces). A strip top raised from its root along the wing (where the halo's foot lies
/// below delta_wall) gets its halo, and the halo its foot, over it rather than over the root: on a
/// swept wing it stands downstream of the root (not at a sharp trailing edge's root, whose halos
/// are placed against the rear interfaces). Throws NearFieldError where a strip top falls off its
/// face or has no height.
JunctionNodes place_junction_nodes(const cad::Model& model, const BodyRoles& roles,
                                   const std::map<int, int>& root_surface, const BodyMesh& body,
                                   const std::vector<int>& loop, const RootSegments& segments, int crack_curve,
                                   const Frame& wall, double delta_wing, double delta_wall);

// The strip tops along the bare surfaces' root (the H-type's trailing-edge base) raised to one height,
// the highest of them. Nothing stands on that root row but the junction, whose W-H faces there face
// the far field and carry pyramids: on a swept, cambered base the two corners' strip tops (the
// halos projected onto the trailing-edge curves) differ in height by several times the base's
// thickness, which twists those quads until no pyramid apex is valid above them (a NACA 2412 swept
// 28.6 degrees: the short edge of the quad stood at 60 degrees to the long one).
void level_bare_strip_tops(const cad::Model& model, const Frame& wall, const BodyMesh& body,
                           const std::vector<int>& loop, const std::set<int>& bare_surfaces,
                           const RootSegments& segments, std::vector<JunctionNode>& nodes);

// Lifts the body mesh off the wall so its root row lands on the strip tops (lift_node), fading out
// at the lowest CAD vertex of the body off the wall (the tip's corners on an ordinary wing; on a
// revolved tip the trailing edge's top, below the tip's crown: a node on the tip's faces must not
// be lifted past the end of the face below it); throws when the strip is too tall for the body or
// a triangle would fold. The lift also dies out below every surface that does not stand on the
// wall (lift_top). Returns the strip height and the body's top height.
std::pair<double, double> lift_onto_strip(const cad::Model& model, const Frame& wall, const std::vector<int>& loop,
                                          const std::vector<JunctionNode>& nodes, double delta_wall, BodyMesh& body);

// A sharp trailing edge `curve`: its inner nodes (on the curve, the strip top on the root loop
// included: the junction gives it one halo per side) and its end node (the tip vertex).
struct CrackNodes {
  std::vector<char> inner, end;  // [body nodes]
};

// The layer cracked open along the crack's inner nodes: each gets a copy (appended after the body's
// nodes) used by the triangles of the larger of its two surfaces, so each side has its own normal
// and offset there. copy_of[k]: the body node of layer node (body node count + k).
struct CrackedLayer {
  BodyMesh layer;
  std::vector<int> copy_of;
};

// The body the wing layer stands on: without the bare triangles (whose own nodes get no offset:
// pinned where they are), cracked open along the crack curve; the two sides of the crack count as
// neighbours, as they still crowd each other.
struct WingLayer {
  CrackNodes crack;
  std::vector<char> bare;  ///< [body triangles]
  CrackedLayer cracked;
  std::vector<std::vector<int>> neighbours;  ///< [layer nodes]
};

/// The wing layer on `body` (WingLayer): the bare triangles left out, cracked along `crack_curve`.
WingLayer wing_layer(const cad::Model& model, const BodyMesh& body, const std::vector<int>& loop,
                     const std::set<int>& bare_surfaces, int crack_curve);

// Where the layer's offsets start from and which stay: node normals ([layer nodes]); isolated nodes
// pinned where they are, the strip tops (and the fan node's two layer nodes) pinned at their halos,
// their normals towards them.
struct LayerStart {
  std::vector<Vec3> normals;
  detail::OffsetConstraints constraints;
  std::array<int, 2> fan_layer{-1, -1};  ///< the fan node's layer node on each side
};

LayerStart pin_layer_at_the_halos(const WingLayer& w, const BodyMesh& body, const std::vector<int>& loop,
                                  const JunctionNodes& j, const ShellParams& params);

// The wing layer's offsets at the strip tops are pinned at the halo: where the layer cannot be
// built next to them even at its thinnest, the root loop is too short (too few segments, too tight
// a turn) for the thickness and the wall layer's thickness: said so, naming the root curve.
detail::LayerOffsets offsets_meeting_the_halo(const cad::Model& model, const BodyMesh& layer,
                                              const std::vector<std::vector<int>>& neighbours,
                                              const std::vector<Vec3>& normals,
                                              const detail::OffsetConstraints& constraints, const ShellParams& params,
                                              const std::vector<int>& loop, const std::vector<CadAttachment>& root_cad,
                                              int wall, double delta_wall);

// The wing layer's prisms (region wing_layer): body node i is mesh node i, layer node i's offset
// mesh node i + offset; each prism's body face a wing boundary face, its outer face skin. The
// bare triangles off the bare surfaces are listed (the crack's ends).
void add_wing_layer(const BodyMesh& body, const WingLayer& w, const detail::LayerOffsets& offsets,
                    const std::set<int>& bare_surfaces, detail::JunctionShell& shell);

// The junction's wall nodes: the root R and the wall foot L of every root node, and the fan node's
// second foot (side 1).
void add_junction_wall_nodes(const std::vector<int>& loop, const std::vector<CadAttachment>& root_cad,
                             const JunctionNodes& j, detail::JunctionShell& shell);

// output.target = "pyfr": the bare surfaces' root corners (JunctionShell::corners), where one root
// segment is on a bare surface and the other is not (not where two bare faces meet); each corner's
// bare side gets a copy of the wall foot and of the halo (the strip top's layer node), at the same
// places.
void split_bare_root_corners(const std::vector<int>& loop, const std::set<int>& bare_surfaces,
                             const RootSegments& segments, detail::JunctionShell& shell);

// Junction hexes R_a R_b W_b W_a L_a L_b H_b H_a on every root segment (region junction, stacks
// of both families); a -> b along the loop or against it, whichever gives a positive volume. At
// the fan node and the split corners each segment takes its own side's foot and halo.
void add_junction_hexes(const cad::Model& model, const BodyMesh& body, const std::vector<int>& loop,
                        const JunctionNodes& j, const std::array<int, 2>& fan_layer, double delta_wing,
                        double delta_wall, detail::JunctionShell& shell);

// The layer's thinnest and thickest offset after reduction, over the nodes that have neighbours
// (the bare surface's own nodes get no offset).
void record_thickness_range(const detail::LayerOffsets& offsets, const std::vector<std::vector<int>>& neighbours,
                            double thickness, NearField& field);

}  // namespace semimesh::nearfield::c_type
