#include "faces_replaced.hpp"

#include <BRepBuilderAPI_Sewing.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace semimesh::occ {

FacesReplaced with_faces_replaced(const TopoDS_Shape& part, double tolerance, FaceNames& names,
                                  const FacePieces& pieces_of) {
  BRepBuilderAPI_Sewing sewing(tolerance);
  const std::size_t named = names.size();
  int replaced = 0;
  for (TopExp_Explorer f(part, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    const std::vector<TopoDS_Face> pieces = pieces_of(face);
    if (pieces.size() < 2) {
      sewing.Add(face);
      continue;
    }
    ++replaced;
    for (const TopoDS_Face& piece : pieces) {
      sewing.Add(piece);
      for (std::size_t i = 0; i < named; ++i)
        if (names[i].first.IsSame(face)) names.emplace_back(piece, names[i].second);
    }
  }
  if (replaced == 0) return {part, 0};
  sewing.Perform();
  for (std::size_t i = 0, n = names.size(); i < n; ++i)
    if (sewing.IsModifiedSubShape(names[i].first)) names.emplace_back(sewing.ModifiedSubShape(names[i].first), names[i].second);
  return {sewing.SewedShape(), replaced};
}

}  // namespace semimesh::occ
