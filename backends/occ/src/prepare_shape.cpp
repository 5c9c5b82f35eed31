#include "prepare_shape.hpp"

#include "semimesh/cad/error.hpp"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeFix_Wireframe.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

namespace semimesh::occ {
namespace {

/// Replaces each named face by its image; faces that vanished lose their name.
template <class Image>
void carry_names(FaceNames& names, Image image) {
  FaceNames carried;
  for (auto& [face, name] : names) {
    TopoDS_Shape next = image(face);
    if (next.IsNull()) continue;
    for (TopExp_Explorer f(next, TopAbs_FACE); f.More(); f.Next()) carried.emplace_back(f.Current(), name);
  }
  names = std::move(carried);
}

/// Healing rebuilds faces around their surfaces, and its history reports the rebuilt shell rather
/// than each face: names follow the (surface, location) a face lies on instead.
void carry_names_by_surface(FaceNames& names, const TopoDS_Shape& result) {
  FaceNames carried;
  for (auto& [face, name] : names) {
    TopLoc_Location location;
    const Handle(Geom_Surface)& surface = BRep_Tool::Surface(TopoDS::Face(face), location);
    for (TopExp_Explorer f(result, TopAbs_FACE); f.More(); f.Next()) {
      TopLoc_Location other_location;
      if (BRep_Tool::Surface(TopoDS::Face(f.Current()), other_location) == surface && other_location == location)
        carried.emplace_back(f.Current(), name);
    }
  }
  names = std::move(carried);
}

}  // namespace

TopoDS_Shape scale_shape(const TopoDS_Shape& shape, double factor, FaceNames& names) {
  if (factor == 1.0) return shape;
  gp_Trsf scale;
  scale.SetScale(gp::Origin(), factor);
  BRepBuilderAPI_Transform transform(shape, scale, /*copy=*/true);
  if (!transform.IsDone()) throw cad::CadError(cad::CadError::Kind::Geometry, "occ: scaling the shape failed");
  carry_names(names, [&](const TopoDS_Shape& face) { return transform.ModifiedShape(face); });
  return transform.Shape();
}

bool has_free_edges(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edge_faces.FindKey(i));
    const TopTools_ListOfShape& faces = edge_faces.FindFromIndex(i);
    if (BRep_Tool::Degenerated(edge) || faces.Extent() != 1) continue;
    if (!BRep_Tool::IsClosed(edge, TopoDS::Face(faces.First()))) return true;
  }
  return false;
}

namespace {

Sewn sew_at(const TopoDS_Shape& shape, double tolerance, FaceNames names_in, FaceNames& names_out) {
  BRepBuilderAPI_Sewing sewing(tolerance);
  sewing.Add(shape);
  sewing.Perform();
  carry_names(names_in, [&](const TopoDS_Shape& face) {
    return sewing.IsModifiedSubShape(face) ? sewing.ModifiedSubShape(face) : face;
  });
  names_out = std::move(names_in);
  return {sewing.SewedShape(), tolerance, sewing.NbContigousEdges(), sewing.NbFreeEdges()};
}

}  // namespace

Sewn sew_shape(const TopoDS_Shape& shape, double tolerance, double max_tolerance, FaceNames& names) {
  if (!has_free_edges(shape)) return {shape, tolerance, 0, 0};
  FaceNames best_names;
  Sewn best = sew_at(shape, tolerance, names, best_names);
  for (double t = 10.0 * tolerance; best.free > 0 && t <= max_tolerance * (1.0 + 1e-12); t *= 10.0) {
    FaceNames trial_names;
    Sewn trial = sew_at(shape, t, names, trial_names);
    if (trial.free >= best.free) break;
    best = std::move(trial);
    best_names = std::move(trial_names);
  }
  names = std::move(best_names);
  return best;
}

TopoDS_Shape heal_shape(const TopoDS_Shape& shape, double precision, FaceNames& names) {
  Handle(ShapeFix_Shape) fix = new ShapeFix_Shape(shape);
  fix->SetPrecision(precision);
  fix->SetMaxTolerance(100.0 * precision);
  fix->Perform();

  Handle(ShapeFix_Wireframe) wires = new ShapeFix_Wireframe(fix->Shape());
  wires->SetPrecision(precision);
  wires->SetMaxTolerance(100.0 * precision);
  wires->ModeDropSmallEdges() = Standard_True;
  wires->FixWireGaps();
  wires->FixSmallEdges();

  TopoDS_Shape healed = wires->Shape();
  BRepLib::BuildCurves3d(healed);
  carry_names_by_surface(names, healed);
  return healed;
}

}  // namespace semimesh::occ
