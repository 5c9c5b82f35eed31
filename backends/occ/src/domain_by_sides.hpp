// The fluid domain around two overlapping solids (a body reaching into the wall part it stands on:
// a wing into a fuselage) inside a far-field solid, from one general fuse of the three: every face
// is split along every intersection curve, then each piece is kept or dropped by where a point inside
// it lies. Why not OCCT's Fuse then Cut: on an OpenVSP delta wing (trelau/AFEM's GT_supersonic_delta)
// they split the faces right but classified the pieces wrong (Common(wing, fuselage) came out empty,
// the union smaller than the fuselage), while OCCT's point classification of each piece is right.
#pragma once

#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include <memory>

namespace semimesh::occ {

/// The closed boundary of the fluid and where its faces come from.
struct DomainBySides {
  /// The far field minus both parts, as one compound of solids (several when the domain falls apart).
  TopoDS_Shape solids;
  /// The kept pieces of the body's and of the wall's faces.
  TopTools_IndexedMapOfShape from_body, from_wall;
  /// The pieces of a face of any of the three inputs (itself when no curve crossed it).
  TopTools_ListOfShape pieces(const TopoDS_Shape& face) const;

  std::shared_ptr<BRepAlgoAPI_BuilderAlgo> fuse;  // holds the pieces' history
};

/// The far field's pieces outside both parts, the body's outside the wall and inside the far field,
/// the wall's outside the body and inside the far field (a piece on another input's boundary, as a
/// wall's cap on a far-field face of symmetry, is inside neither: dropped), oriented with the fluid
/// on their inside and grouped into closed shells, one solid each. `fuzzy` is OCCT's fuzzy value.
/// Throws cad::CadError(BadParameter) when OCCT's general fuse fails or the kept pieces do not close.
DomainBySides domain_by_sides(const TopoDS_Shape& far_field, const TopoDS_Shape& body, const TopoDS_Shape& wall,
                              double fuzzy);

}  // namespace semimesh::occ
