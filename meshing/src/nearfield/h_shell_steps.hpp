// The H-type near field's steps (build_h_shell, h_shell.cpp) and what they hand each other: the
// trailing edge and the fan's legs at a sharp edge's root (h_shell.cpp, fan_wedge.cpp), the wake
// block's cut row, sections and sweep (wake_block.cpp), the fan's wedge (fan_wedge.cpp) and the
// skin handed to the far field (skin_faces.cpp).
#pragma once

#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/h_shell.hpp"

#include "junction_shell.hpp"
#include "translational_rims.hpp"

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace semimesh::nearfield::h_type {

using mesh::NodeId;
using Quad = std::array<NodeId, 4>;

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] inline void fail(const std::string& what) { throw NearFieldError("near field: " + what); }

/// "[x, y, z]": wake.direction as the messages name it.
std::string direction_label(const WakeParams& w);
/// "wake.widening = W with " when the block widens: a fold may be the widening's doing.
std::string widening_label(const WakeParams& w);
/// Is the linear element on these vertices valid (its Jacobian's sign)?
bool element_valid(const mesh::Mesh& m, ho::Shape shape, const std::vector<NodeId>& v);

// The trailing edge the wake is swept from: squared-off (its base surface, meshed with structured
// quads) or, with te_base "auto" and no base found, sharp (a curve between two body surfaces).
struct TrailingEdge {
  int base = -1;           ///< the base surface on the root; -1: sharp
  std::vector<int> faces;  ///< the base's faces (detail::trailing_edge_base), ascending; empty: sharp
  int crack = -1;          ///< the sharp edge's curve; -1: blunt
  std::set<int> flat;      ///< the base faces' flat corners (CAD vertices): swept as prisms
};

// A quad of the base's mesh and the base face it lies on.
struct BaseQuad {
  Quad q;
  int surface = -1;
};

// A sharp trailing edge's root (js.fan): its three legs, side 0, middle and side 1 (feet on the
// wall, tops at the halos). The junction gives the two sides'; the middle one, added here, stands
// on the bisector of the feet (whose legs from the root open by less than 180 degrees, downstream):
// the wedge between the two halos is filled in two halves (fill_fan_wedge). Its legs from the
// strip top may open by more than 180 degrees where the edge sweeps back. No fan: kNoNode.
struct FanLegs {
  std::array<NodeId, 3> foot{mesh::kNoNode, mesh::kNoNode, mesh::kNoNode}, top = foot;
};

/// The fan's middle leg added (FanLegs); none without a fan.
FanLegs add_fan_middle_leg(const cad::Model& model, int wall_surface, detail::JunctionShell& js);

// The cut row, the wake block's root: the lowest trailing-edge row at least `gap` above the wall
// layer's top (and above the root strip); the block is swept from the rows at or above it.
struct CutRow {
  detail::WallFrame wall;
  double height = 1e300, tolerance = 0.0;
  bool above(const Vec3& x) const { return wall.height(x) >= height - tolerance; }
};

/// The cut row among `te_nodes`. Throws NearFieldError when it would leave no row below the tip.
CutRow wake_cut_row(const detail::JunctionShell& js, const std::vector<NodeId>& te_nodes, double wall_thickness,
                    const WakeParams& wake);

// One piece of the wake's cross-section at the trailing edge: q0 -> q1 its body-side edge and
// q0 -> q3 its layer direction for a rear interface (`layer`); a base quad otherwise.
struct Section {
  std::array<NodeId, 4> q;
  bool layer = false;
  bool triangle = false;  ///< a base triangle (q[3] unused): swept into a prism
  int surface = -1;       ///< a base piece's base face; -1: a rear interface
};

struct WakeSections {
  std::vector<Section> swept;      ///< base pieces, then rear interfaces, above the cut
  std::vector<Quad> exposed_base;  ///< base quads below the cut: faced by the far field
};

/// The base quads above the cut (a flat corner's as two triangles), then the rear interfaces above
/// it; the base quads below it exposed. Throws NearFieldError when nothing is swept.
WakeSections wake_sections(const detail::JunctionShell& js, const TrailingEdge& te, const std::vector<BaseQuad>& base,
                           const CutRow& cut);

// wake.to_outlet (output.target = "pyfr"): the far field's downstream face, the box's face across
// d (which must be one of its axes), as its coordinate along d, and its distance from the block's
// outer edge at the trailing edge (the rear interfaces' layer nodes, which must lie in one plane
// across d within `tolerance`: the block's outer faces then meet that face on one line-up of
// nodes). Throws NearFieldError naming the key otherwise, or with a widening (the cells must be
// translates) or a box that does not reach past the trailing edge.
struct Outlet {
  double along = 0.0;
  double distance = 0.0;
};
Outlet find_outlet(const mesh::Mesh& m, const std::vector<Section>& sections, const WakeParams& wake, const Vec3& d,
                   const cad::BBox& box, double tolerance);

// The wake's nodes: node p at station k is p + s_k d, the layer offsets also moved away from the
// sheet by tan(widening) per unit length across d, within the trailing edge's cross-section (across
// the streamwise axis x, as the base and the rear interfaces): moved across d instead, at
// incidence the two sides' offsets (and the tip corners') would leave that plane by opposite
// amounts, warping the block's outflow and tip faces until they fold. A node's stations are made
// when first asked for, so node ids follow the order the elements use them.
class WakeSweep {
 public:
  /// `stations`: 0 = s_0 < ... < s_K, the distances downstream (detail::wake_stations); `outlet`:
  /// the coordinate along d of a plane the last station is laid on (each node moved along d).
  WakeSweep(mesh::Mesh& m, const WakeParams& wake, const Vec3& d, const std::vector<Section>& sections,
            const cad::BBox& box, std::vector<double> stations, std::optional<double> outlet = std::nullopt);

  /// [stations] p's node at each station, p itself first. Throws NearFieldError when a station
  /// leaves the far field's box.
  const std::vector<NodeId>& nodes(NodeId p);

  std::size_t stations() const { return s_.size(); }
  /// the last station's distance downstream (of the block's outer edge)
  double reach() const { return s_.back(); }
  bool to_outlet() const { return outlet_.has_value(); }
  /// trailing-edge node -> its nodes at every station
  const std::map<NodeId, std::vector<NodeId>>& swept() const { return swept_; }

 private:
  mesh::Mesh& m_;
  const WakeParams& wake_;
  Vec3 d_;
  std::vector<double> s_;
  std::optional<double> outlet_;
  double spread_;
  Vec3 inner_, outer_;           ///< the far-field box, a little inside
  std::map<NodeId, Vec3> away_;  ///< offset node -> direction in the cross-section, of unit part across d
  std::map<NodeId, std::vector<NodeId>> swept_;
};

// The wake block's elements, station by station behind each section (hexes; prisms behind a flat
// corner's triangles), turned to sweep along d; the base's pieces faced as wing boundary. Hexes
// over rear interfaces continue their wing layer (a stack of the wing family); the base's are not
// split. Each element's body surface: its base piece's face, else `base` (the root's base face).
/// Returns the block's outflow faces when it runs to the far field's downstream face
/// (wake.to_outlet), made "farfield" boundary faces, wound out of the domain; empty otherwise.
std::vector<std::vector<NodeId>> add_wake_elements(NearField& field, WakeSweep& sweep,
                                                   const std::vector<Section>& sections, const WakeParams& wake,
                                                   const Vec3& d, int base);

// The body faces no element stands on: the base quads below the cut, the bare triangles at a sharp
// edge's tip end (wing boundary, facing into the body as the layer's).
void add_exposed_body_faces(mesh::Mesh& m, const std::vector<Quad>& exposed_base,
                            const std::vector<std::array<int, 3>>& bare);

// The WakeBlock the split's ratio along the wake reads: its direction, length, measured gap and the
// trailing-edge nodes it is swept from, sorted along the span axis. A sharp edge's nodes below the
// cut and its root R count too: the ratio there is the trailing edge's own (r), at R and W alike.
// The junction hexes beside the fan interpolate their layer interfaces between R's and W's along
// R-W, the fan's pieces (cut in advance, straight from R's cut to W's) only match that when both
// are the same.
void describe_wake_block(const detail::JunctionShell& js, const WakeSweep& sweep, const std::vector<Section>& sections,
                         const WakeParams& wake, const Vec3& d, double wall_thickness, WakeBlock& w);

// The split's interface nodes placed ahead of it on layer edges: (bottom vertex, top vertex, k) ->
// node (a sharp trailing edge's nodes have two layer edges, one per side).
using InterfaceNodes = std::map<std::tuple<NodeId, NodeId, int>, NodeId>;

// A sharp trailing edge's root: the wedge between its two halos (root R, strip top W, feet L_0
// L_1, halos H_0 H_1) is a prism R L_0 L_1 / W H_0 H_1 standing on the wall, split by the wall
// layer's split along R-W (a stack of the wall family), in two halves about the middle leg.
// Across, the junction hexes beside it split their faces R-W-H-L at the wing layer's interfaces,
// a fan from R the split cannot make: the prisms are given here already cut there (an inner
// prism and bands of prisms around it, at the interfaces the split will use: `fractions`), and
// the weld after the split joins their nodes to the hexes' (as the far field's pre-cut skin quads).
// On a curved wall the legs' cuts on the wall are the wall's points (on the CAD), and the hexes'
// faces R-L-H-W cut for the fan go to field.precut_faces: the hexes' faces are curved or straight
// once the order is raised, and the cuts must follow them then (ho::follow_precut_faces).
// Returns the nodes on each face R-W-H-L the fan shares with a junction hex (none without a fan).
std::vector<std::set<NodeId>> fill_fan_wedge(NearField& field, const detail::JunctionShell& js, const FanLegs& legs,
                                             int wall_surface, const LayerFractions& fractions,
                                             InterfaceNodes& interface_node);

// output.target = "pyfr": the wedge at each of a blunt trailing edge's root corners (between the
// corner's two halos, JunctionShell::corners) filled as the sharp edge's fan (fill_fan_wedge),
// in one part. Returns the nodes on each face R-W-H-L a wedge shares with a junction hex.
std::vector<std::set<NodeId>> fill_corner_wedges(NearField& field, const detail::JunctionShell& js, int wall_surface,
                                                 const LayerFractions& fractions, InterfaceNodes& interface_node);

// output.target = "pyfr": the halo of each trailing-edge root corner (a blunt edge's corners, a
// sharp edge's fan sides: TranslationalRims::root_corner) moved onto its side's rear-interface layer
// edge and its wall foot below it, keeping the wall strip's width delta_wing, so the lowest rear
// interface of each side is a parallelogram too (docs/solvers.md, PyFR). Throws NearFieldError,
// naming the corner, if an element using a moved node would fold.
void open_root_corners(const cad::Model& model, int wall_surface, double delta_wing, double delta_wall,
                       const detail::TranslationalRims& rims, detail::JunctionShell& js);

// The skin: faces used by one element that are not body or wall faces and do not stand on the
// footprint (those the wall layer's prisms share) or on a face the fan shares with a junction
// hex, plus the exposed body faces.
std::vector<SkinFace> skin_faces(const NearField& field, const std::vector<std::set<NodeId>>& fan_planes,
                                 const std::vector<Quad>& exposed_base, const std::vector<std::array<int, 3>>& bare);

// Skin quads the split will cut (two opposite layer edges), cut already at its interfaces so the
// far field's pyramids and tetrahedra match the split elements' faces once welded; the others as
// they are. No fractions: the layer is not split.
void cut_skin_at_split_interfaces(NearField& field, const std::vector<SkinFace>& skin, const LayerFractions& fractions,
                                  InterfaceNodes& interface_node);

// The outline of the wake's outflow face (add_wake_elements' faces, wake.to_outlet), a closed loop
// cut at the split's interfaces as the skin is: the hole the far field leaves in its downstream face.
// Empty when there are no outflow faces. Throws NearFieldError when the faces are not bounded by one loop.
std::vector<NodeId> outlet_outline(NearField& field, const std::vector<std::vector<NodeId>>& outflow,
                                   const LayerFractions& fractions, InterfaceNodes& interface_node);

// The block's outer faces must stay flat enough to carry the far field's pyramids.
void check_wake_faces_carry_pyramids(const NearField& field, const WakeSweep& sweep, const WakeParams& wake);

}  // namespace semimesh::nearfield::h_type
