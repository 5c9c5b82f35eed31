// Edge naming of the generated NACA wing by the pair of faces each edge joins: sewing merges the
// faces' edges, so the pair (found after sewing and scaling) is what identifies an edge's role.
#include "naca_edge_names.hpp"

#include "semimesh/cad/error.hpp"

#include <BRep_Tool.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace semimesh::occ {
namespace {

/// Wing curves keyed by their two face names in alphabetical order.
const std::map<std::pair<std::string, std::string>, std::string>& wing_curve_names() {
  static const std::map<std::pair<std::string, std::string>, std::string> names = {
      {{"lower", "upper"}, "leading_edge"}, {{"te_base", "upper"}, "te_upper"}, {{"lower", "te_base"}, "te_lower"},
      {{"tip", "upper"}, "tip_upper"},      {{"lower", "tip"}, "tip_lower"},    {{"te_base", "tip"}, "tip_te"},
      {{"upper", "wall"}, "root_upper"},    {{"lower", "wall"}, "root_lower"},  {{"te_base", "wall"}, "root_te"}};
  return names;
}

/// "xmin" for box_xmin, "zmin" for the wall (the box's z = zmin side), "" for a wing face.
std::string box_side(const std::string& face) {
  if (face == "wall") return "zmin";
  return face.rfind("box_", 0) == 0 ? face.substr(4) : std::string();
}

std::string curve_name(std::string a, std::string b) {
  if (b < a) std::swap(a, b);
  const auto wing = wing_curve_names().find({a, b});
  if (wing != wing_curve_names().end()) return wing->second;
  std::string side_a = box_side(a), side_b = box_side(b);
  if (side_a.empty() || side_b.empty() || side_a[0] == side_b[0])
    throw cad::CadError(cad::CadError::Kind::Geometry,
                        "occ: the NACA wing has an edge between faces '" + a + "' and '" + b + "', which no analytic curve joins");
  if (side_b < side_a) std::swap(side_a, side_b);  // axis order: x before y before z
  return "box_" + side_a + "_" + side_b;
}

double mean_x_of_ends(const TopoDS_Edge& edge) {
  TopoDS_Vertex first, last;
  TopExp::Vertices(edge, first, last);
  return 0.5 * (BRep_Tool::Pnt(first).X() + BRep_Tool::Pnt(last).X());
}

}  // namespace

std::vector<std::pair<TopoDS_Shape, std::string>> naca_wing_edge_names(
    const TopoDS_Shape& shape, const std::vector<std::pair<TopoDS_Shape, std::string>>& face_names) {
  NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher> name_of_face;
  for (const auto& [face, name] : face_names) name_of_face.Bind(face, name);

  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<std::pair<TopoDS_Shape, std::string>> out;
  std::vector<size_t> leading_edges;  // indices in `out`; two when the TE is sharp
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    std::vector<std::string> faces;
    for (const TopoDS_Shape& face : edge_faces.FindFromIndex(i))
      faces.push_back(name_of_face.IsBound(face) ? name_of_face.Find(face) : std::string("unnamed"));
    if (faces.size() == 1) faces.push_back("wall");  // no far field: the root edges bound one face
    if (faces.size() != 2)
      throw cad::CadError(cad::CadError::Kind::Geometry,
                          "occ: NACA wing edge " + std::to_string(i) + " bounds " + std::to_string(faces.size()) + " faces, expected 2");
    const std::string name = curve_name(faces[0], faces[1]);
    if (name == "leading_edge") leading_edges.push_back(out.size());
    out.emplace_back(edge_faces.FindKey(i), name);
  }
  if (leading_edges.size() == 2) {  // sharp TE: upper and lower also meet at the trailing edge
    const auto x = [&](size_t k) { return mean_x_of_ends(TopoDS::Edge(out[k].first)); };
    out[x(leading_edges[0]) > x(leading_edges[1]) ? leading_edges[0] : leading_edges[1]].second = "trailing_edge";
  }
  return out;
}

}  // namespace semimesh::occ
