// The fluid domain of a body-only CAD file: a wall plane and a far field given by the user, joined
// to the body with OCCT's Boolean operations (far field ∩ the wall's fluid side, minus the body).
// The wall face then holds the body's root loop as edges shared with the body's faces, and the
// body's face on the wall plane is gone: the result reads as any wing-on-a-wall-in-a-box file.
#pragma once

#include "body_cut.hpp"
#include "prepare_shape.hpp"

#include <TopoDS_Shape.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace semimesh::occ {

/// The plane the body stands on; `normal` points into the fluid.
struct WallPlane {
  gp_Pnt point;
  gp_Dir normal;
  std::string label;  ///< how the user wrote it, for messages
};

/// The outer boundary: exactly one of an axis-aligned box, a sphere, or a box `box_chords` root
/// chords (the body's streamwise extent) around the body's bounding box.
struct FarFieldShape {
  std::optional<std::array<double, 6>> box;  ///< xmin, ymin, zmin, xmax, ymax, zmax
  std::optional<std::array<double, 4>> sphere;  ///< centre x, y, z, radius
  std::optional<double> box_chords;
  std::string label;  ///< how the user wrote it, for messages
};

/// The body (a closed shell or solid) inside the far field, standing on the wall: the closed
/// boundary of the fluid, as one solid whose inside is the fluid. Named faces of the body keep
/// their names; the new faces are named "wall" and "farfield_<k>". `tolerance` is the distance
/// under which a point counts as on the plane. Throws cad::CadError(BadParameter) naming the
/// plane or the far field when the body does not stand on the plane (no face of it lies in the
/// plane), the plane cuts through the body, or the far field does not contain the body. An open
/// body's flat free loops (its root, a flat tip) are closed by planar faces, each said in `repairs`.
TopoDS_Shape fluid_domain(const TopoDS_Shape& body, const WallPlane& wall, const FarFieldShape& far,
                          const std::optional<CutPlane>& body_cut, double tolerance, FaceNames& names,
                          std::vector<std::string>& repairs);

/// The parts of an assembly to join (geometry.join): the body's and the wall's faces of the file,
/// each a face id ("#7", as `semimesh cad-info` numbers the file's faces) or a face name.
struct PartsToJoin {
  std::vector<std::string> body, wall;
};

/// The fluid domain of an assembly whose body (a wing) reaches into its wall (a fuselage, a hub)
/// without being joined to it, as OpenVSP exports one: the far field minus the union of the two
/// parts (each made a solid, flat open loops capped), every other face of the file left out. The
/// body's faces keep their names, the wall's become "wall" ("wall_<k>" when cut in several), the
/// far field's "farfield_<k>". Throws cad::CadError(BadParameter) naming the key when a face is
/// unknown or named twice, a part is not closed, the body does not reach into the wall, or the far
/// field does not hold the body; a far field of box_chords is refused (no root to measure yet).
/// `body_cut` as for fluid_domain; a free loop of the body pinched to zero thickness inside the wall
/// part is trimmed back inside it (the joined shape unchanged), said in `repairs`.
TopoDS_Shape fluid_domain_of_parts(const TopoDS_Shape& shape, const PartsToJoin& parts, const FarFieldShape& far,
                                   const std::optional<CutPlane>& body_cut, double tolerance, FaceNames& names,
                                   std::vector<std::string>& repairs);

}  // namespace semimesh::occ
