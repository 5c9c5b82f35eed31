// Which surfaces of a CAD model play which role, found from its topology and geometry alone (no
// names), so a file made elsewhere runs without naming its faces:
//  - the wall: a face, planar or curved (a fuselage, a hub), holding the body's root loop as an
//    inner loop (a hole), whose curves other faces also use;
//  - the body: the faces reached from that root loop across shared curves without crossing the wall;
//  - the far field: every other face (the outer shell);
//  - the trailing-edge base: the body face on the root loop that is narrow (its root curves
//    shorter than a tenth of the root chord), runs across the stream (its root curves reach along
//    it by less than half their length: not one of the thin faces closing a sharp trailing edge)
//    and lies at the body's downstream end (+x, projected onto the wall plane);
//  - the tip: the body faces, other than the base, that do not touch the root, reach the far end
//    of the span and are flat across it (their extent along the span below a quarter of their
//    extent along the chord).
// The span direction is the wall's normal (into the fluid) under the root's centroid: nothing
// assumes an axis for it.
#pragma once

#include "semimesh/cad/model.hpp"
#include "semimesh/error.hpp"

#include <optional>
#include <string>
#include <vector>

namespace semimesh::surface {

class CadRoleError : public InputError {
 public:
  using InputError::InputError;
};

struct CadRoles {
  std::vector<int> body;      ///< ascending ids
  int wall = -1;
  std::vector<int> farfield;  ///< ascending ids
  std::optional<int> te_base;
  std::vector<int> tip;       ///< ascending ids
  cad::Vec3 span_direction = cad::Vec3::Zero();  ///< the wall's normal under the root, into the fluid
  double span = 0.0;          ///< the body's height above the wall (at the root, along span_direction)
  double chord = 0.0;         ///< the root loop's extent along the streamwise direction
};

/// Finds the roles. `wall` (a surface id) fixes the wall instead of searching for it. Throws
/// CadRoleError saying what is missing or ambiguous (no face with a root loop, several, a body
/// that reaches behind the wall, no face left for the far field).
CadRoles detect_cad_roles(const cad::Model& model, std::optional<int> wall = std::nullopt);

/// Two parts of a model that share no curve but overlap (their bounding boxes share a box of some
/// thickness along every axis): the smaller taken for the body, the other for its wall part.
struct OverlappingParts {
  std::vector<int> body, wall;  ///< surface ids, ascending
  cad::BBox body_box, wall_box;
  int count = 0;                ///< how many parts the model falls apart into
};

/// The first two overlapping parts of a model that falls apart into several (faces joined through
/// shared curves), or nothing.
std::optional<OverlappingParts> find_overlapping_parts(const cad::Model& model);

/// Throws CadRoleError when the model falls apart into parts (faces joined through shared curves)
/// of which two overlap (their bounding boxes share a box of some thickness along every axis): an
/// assembly whose wing stands in a fuselage without being joined to it (an OpenVSP export). The
/// message names both parts and the remedies. Parts apart (two wings side by side) pass.
void refuse_overlapping_parts(const cad::Model& model);

/// Throws CadRoleError when a periodic face's seam runs into a body's root (a fuselage exported with
/// its seam along its crest): the root is then no hole of the wall, and neither the wall nor the
/// body-only route (a root plane) can be found; the message names the face, the seam and the remedy.
void refuse_seam_through_root(const cad::Model& model);

/// Whether some face holds a body's root loop as an inner loop (detect_cad_roles can find a
/// wall); false for a file that holds the body alone.
bool has_wall_with_root_loop(const cad::Model& model);

/// One line per role, e.g. "wall      surface 4 ('wall')", for cad-info and messages.
std::string describe_cad_roles(const cad::Model& model, const CadRoles& roles);

}  // namespace semimesh::surface
