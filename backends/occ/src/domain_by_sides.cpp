#include "domain_by_sides.hpp"

#include "semimesh/cad/error.hpp"

#include <BOPTools_AlgoTools3D.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IntTools_Context.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include <sstream>
#include <string>
#include <vector>

namespace semimesh::occ {
namespace {

[[noreturn]] void refuse_join(const std::string& what) { throw cad::CadError(cad::CadError::Kind::BadParameter, what); }

std::string place_text(const gp_Pnt& p) {
  std::ostringstream text;
  text << "(" << p.X() << ", " << p.Y() << ", " << p.Z() << ")";
  return text.str();
}

enum class Input { FarField, Body, Wall };

// Where a point inside `piece` lies with respect to `solid` (IN, OUT or ON its boundary).
TopAbs_State side_of(const TopoDS_Face& piece, const TopoDS_Shape& solid, double tolerance,
                     const Handle(IntTools_Context)& context, const std::string& what) {
  gp_Pnt p;
  gp_Pnt2d uv;
  if (BOPTools_AlgoTools3D::PointInFace(piece, p, uv, context) != 0)
    refuse_join("geometry.join: no point inside a piece of " + what + " cut by the other parts (OCCT's PointInFace)");
  return BRepClass3d_SolidClassifier(solid, p, tolerance).State();
}

// The kept faces grouped by shared edges: each group must be closed (every edge between two of its
// faces, a seam twice in one), or the domain has a hole there.
std::vector<TopoDS_Shell> closed_shells(const std::vector<TopoDS_Face>& faces) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (const TopoDS_Face& f : faces) builder.Add(all, f);
  TopTools_IndexedDataMapOfShapeListOfShape faces_of_edge;
  TopExp::MapShapesAndAncestors(all, TopAbs_EDGE, TopAbs_FACE, faces_of_edge);
  TopTools_IndexedMapOfShape face_ids;
  for (const TopoDS_Face& f : faces) face_ids.Add(f);

  std::vector<int> group(faces.size(), -1);
  std::vector<TopoDS_Shell> shells;
  for (std::size_t seed = 0; seed < faces.size(); ++seed) {
    if (group[seed] >= 0) continue;
    const int g = static_cast<int>(shells.size());
    shells.emplace_back();
    builder.MakeShell(shells.back());
    std::vector<std::size_t> to_visit{seed};
    group[seed] = g;
    while (!to_visit.empty()) {
      const TopoDS_Face& face = faces[to_visit.back()];
      to_visit.pop_back();
      builder.Add(shells.back(), face);
      for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        if (BRep_Tool::Degenerated(edge)) continue;
        const TopTools_ListOfShape& around = faces_of_edge.FindFromKey(edge);
        if (around.Extent() != 2) {
          const gp_Pnt p = BRep_Tool::Pnt(TopExp::FirstVertex(edge));
          refuse_join("geometry.join: the fluid domain's boundary is not closed: an edge near " + place_text(p) + " bounds " +
                 std::to_string(around.Extent()) + " of its faces (the body and the wall part meet there in a way the "
                 "Boolean operations do not resolve)");
        }
        for (const TopoDS_Shape& other : around) {
          const std::size_t k = static_cast<std::size_t>(face_ids.FindIndex(other) - 1);
          if (group[k] < 0) {
            group[k] = g;
            to_visit.push_back(k);
          }
        }
      }
    }
  }
  return shells;
}

}  // namespace

TopTools_ListOfShape DomainBySides::pieces(const TopoDS_Shape& face) const {
  TopTools_ListOfShape out = fuse->Modified(face);
  if (out.IsEmpty() && !fuse->IsDeleted(face)) out.Append(face);
  return out;
}

DomainBySides domain_by_sides(const TopoDS_Shape& far_field, const TopoDS_Shape& body, const TopoDS_Shape& wall,
                              double fuzzy) {
  DomainBySides domain;
  domain.fuse = std::make_shared<BRepAlgoAPI_BuilderAlgo>();
  TopTools_ListOfShape arguments;
  arguments.Append(far_field);
  arguments.Append(body);
  arguments.Append(wall);
  domain.fuse->SetArguments(arguments);
  domain.fuse->SetFuzzyValue(fuzzy);
  domain.fuse->SetRunParallel(false);  // the same pieces in the same order whatever the thread count
  domain.fuse->Build();
  if (!domain.fuse->IsDone() || domain.fuse->HasErrors()) {
    std::ostringstream report;
    domain.fuse->DumpErrors(report);
    refuse_join("geometry.join: OCCT's general fuse of the far field, the body and the wall failed: " + report.str());
  }

  // A piece's side of the other inputs decides: kept when outside the parts it must be outside of
  // and inside the far field (for the parts' pieces). ON counts as neither.
  const Handle(IntTools_Context) context = new IntTools_Context;
  const double tolerance = std::max(fuzzy, 1e-7);
  std::vector<TopoDS_Face> kept;
  TopTools_IndexedMapOfShape seen;
  const auto keep_pieces = [&](const TopoDS_Shape& input, Input which) {
    for (TopExp_Explorer f(input, TopAbs_FACE); f.More(); f.Next())
      for (const TopoDS_Shape& shape : domain.pieces(f.Current())) {
        if (seen.Contains(shape)) continue;  // a piece shared by two inputs (coincident faces) is met once
        seen.Add(shape);
        const TopoDS_Face piece = TopoDS::Face(shape);
        const auto outside = [&](const TopoDS_Shape& solid, const char* what) {
          return side_of(piece, solid, tolerance, context, what) == TopAbs_OUT;
        };
        const auto inside = [&](const TopoDS_Shape& solid, const char* what) {
          return side_of(piece, solid, tolerance, context, what) == TopAbs_IN;
        };
        switch (which) {
          case Input::FarField:
            if (outside(body, "the far field") && outside(wall, "the far field")) kept.push_back(piece);
            break;
          case Input::Body:
            if (outside(wall, "the body") && inside(far_field, "the body")) {
              kept.push_back(TopoDS::Face(piece.Reversed()));  // the fluid on its other side
              domain.from_body.Add(piece);
            }
            break;
          case Input::Wall:
            if (outside(body, "the wall") && inside(far_field, "the wall")) {
              kept.push_back(TopoDS::Face(piece.Reversed()));
              domain.from_wall.Add(piece);
            }
            break;
        }
      }
  };
  keep_pieces(far_field, Input::FarField);
  keep_pieces(body, Input::Body);
  keep_pieces(wall, Input::Wall);
  if (kept.empty()) refuse_join("geometry.join: no face of the far field lies outside the body and the wall");

  TopoDS_Compound solids;
  BRep_Builder builder;
  builder.MakeCompound(solids);
  for (TopoDS_Shell& shell : closed_shells(kept)) {
    shell.Closed(true);
    TopoDS_Solid solid;
    builder.MakeSolid(solid);
    builder.Add(solid, shell);
    BRepLib::OrientClosedSolid(solid);  // the finite side inside
    builder.Add(solids, solid);
  }
  domain.solids = solids;
  return domain;
}

}  // namespace semimesh::occ
