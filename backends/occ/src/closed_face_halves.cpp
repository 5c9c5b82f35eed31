#include "closed_face_halves.hpp"

#include "crease_seam.hpp"
#include "faces_replaced.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <ShapeUpgrade_ShapeDivideClosed.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

namespace semimesh::occ {
namespace {

// The pieces of `face` cut across its closed direction, each on its own surface handle; one or
// none when OCCT does not cut it (the face is then kept).
std::vector<TopoDS_Face> halves(const TopoDS_Face& face) {
  ShapeUpgrade_ShapeDivideClosed divide(face);
  divide.SetNbSplitPoints(1);
  std::vector<TopoDS_Face> out;
  if (divide.Perform())
    for (TopExp_Explorer f(divide.Result(), TopAbs_FACE); f.More(); f.Next())
      out.push_back(out.empty() ? TopoDS::Face(f.Current())
                                : TopoDS::Face(BRepBuilderAPI_Copy(f.Current(), /*copyGeom=*/true).Shape()));
  return out;
}

}  // namespace

TopoDS_Shape with_closed_faces_halved(const TopoDS_Shape& part, double tolerance, FaceNames& names,
                                      std::vector<std::string>& repairs) {
  const FacesReplaced cut = with_faces_replaced(part, tolerance, names, [](const TopoDS_Face& face) {
    return has_seam(face) ? halves(face) : std::vector<TopoDS_Face>{};
  });
  if (cut.replaced > 0)
    repairs.push_back("cut " + std::to_string(cut.replaced) + " closed face(s) of the body in two across its seam before "
                      "joining it to the wall part (OCCT's Booleans split the halves, not the closed face)");
  return cut.shape;
}

}  // namespace semimesh::occ
