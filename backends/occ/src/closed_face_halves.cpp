#include "closed_face_halves.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Tool.hxx>
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

namespace semimesh::occ {
namespace {

bool has_own_seam(const TopoDS_Face& face) {
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
    if (BRep_Tool::IsClosed(TopoDS::Edge(e.Current()), face)) return true;
  return false;
}

// The pieces of `face` cut across its closed direction, each on its own surface handle; the face
// alone when OCCT does not cut it.
std::vector<TopoDS_Face> halves(const TopoDS_Face& face) {
  ShapeUpgrade_ShapeDivideClosed divide(face);
  divide.SetNbSplitPoints(1);
  std::vector<TopoDS_Face> out;
  if (divide.Perform())
    for (TopExp_Explorer f(divide.Result(), TopAbs_FACE); f.More(); f.Next())
      out.push_back(out.empty() ? TopoDS::Face(f.Current())
                                : TopoDS::Face(BRepBuilderAPI_Copy(f.Current(), /*copyGeom=*/true).Shape()));
  if (out.size() < 2) return {face};
  return out;
}

}  // namespace

TopoDS_Shape with_closed_faces_halved(const TopoDS_Shape& part, double tolerance, FaceNames& names,
                                      std::vector<std::string>& repairs) {
  BRepBuilderAPI_Sewing sewing(tolerance);
  const std::size_t named = names.size();
  int cut = 0;
  for (TopExp_Explorer f(part, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    const std::vector<TopoDS_Face> pieces = has_own_seam(face) ? halves(face) : std::vector<TopoDS_Face>{face};
    if (pieces.size() > 1) ++cut;
    for (const TopoDS_Face& piece : pieces) {
      sewing.Add(piece);
      if (pieces.size() == 1) continue;
      for (std::size_t i = 0; i < named; ++i)
        if (names[i].first.IsSame(face)) names.emplace_back(piece, names[i].second);
    }
  }
  if (cut == 0) return part;
  sewing.Perform();
  for (std::size_t i = 0, n = names.size(); i < n; ++i)
    if (sewing.IsModifiedSubShape(names[i].first)) names.emplace_back(sewing.ModifiedSubShape(names[i].first), names[i].second);
  repairs.push_back("cut " + std::to_string(cut) + " closed face(s) of the body in two across its seam before joining "
                    "it to the wall part (OCCT's Booleans split the halves, not the closed face)");
  return sewing.SewedShape();
}

}  // namespace semimesh::occ
