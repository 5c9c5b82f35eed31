// A body face closed round its sections with its seam on a sharp edge (OpenVSP's one-face wing, the
// seam its trailing edge) is split into two halves of the same surface (crease_seam.hpp); a face
// whose seam is smooth (a cylinder) is kept whole.
#include "crease_seam.hpp"
#include "shape_measures.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <cmath>

namespace semimesh::occ {
namespace {

// A NACA 0012 section as one curve starting and ending at its sharp trailing edge x = 1, lofted
// from z = 0 to 2: one face closed round, its seam on the sharp edge.
TopoDS_Shape lens_skin() {
  BRepOffsetAPI_ThruSections loft(false, false, 1e-9);
  for (const double z : {0.0, 1.0, 2.0}) {
    const int n = 41;
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, n);
    for (int j = 1; j <= n; ++j) {
      const double a = 2.0 * M_PI * (j - 1.0) / (n - 1.0);
      const double x = 0.5 * (1.0 + std::cos(a));
      const double t = 0.6 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
      points->SetValue(j, gp_Pnt(x, (a < M_PI ? 1.0 : -1.0) * t * (1.0 - 0.1 * z), z));
    }
    GeomAPI_Interpolate curve(points, false, 1e-12);
    curve.Perform();
    loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve.Curve()).Edge()).Wire());
  }
  loft.Build();
  return loft.Shape();
}

int count_faces(const TopoDS_Shape& shape) {
  int n = 0;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) ++n;
  return n;
}

TEST(OccCreaseSeam, AFaceClosedRoundASharpEdgeIsSplitIntoTwoHalvesOfTheSameSurface) {
  const TopoDS_Shape skin = lens_skin();
  ASSERT_EQ(count_faces(skin), 1);
  FaceNames names{{TopExp_Explorer(skin, TopAbs_FACE).Current(), "skin"}};
  std::vector<std::string> repairs;
  const TopoDS_Shape split = with_crease_seams_split(skin, 1e-7, names, repairs);
  ASSERT_EQ(count_faces(split), 2);
  EXPECT_NEAR(test::area_of(split), test::area_of(skin), 1e-9 * test::area_of(skin));
  ASSERT_EQ(repairs.size(), 1u);
  // No seam left, and two edges (the sharp edge and the split line) each between the two faces.
  TopTools_IndexedDataMapOfShapeListOfShape faces_of_edge;
  TopExp::MapShapesAndAncestors(split, TopAbs_EDGE, TopAbs_FACE, faces_of_edge);
  int shared = 0;
  for (int i = 1; i <= faces_of_edge.Extent(); ++i) {
    const TopTools_ListOfShape& faces = faces_of_edge(i);
    if (faces.Extent() == 2 && !faces.First().IsSame(faces.Last())) ++shared;
    for (const TopoDS_Shape& f : faces) {
      const TopoDS_Edge& e = TopoDS::Edge(faces_of_edge.FindKey(i));
      double a, b;
      const Handle(Geom_Curve) c = BRep_Tool::Curve(e, a, b);
      EXPECT_FALSE(BRep_Tool::IsClosed(e, TopoDS::Face(f)))
          << "a seam from (" << c->Value(a).X() << ", " << c->Value(a).Y() << ", " << c->Value(a).Z() << ")";
    }
  }
  EXPECT_EQ(shared, 2);
  // Both halves named as the face they come from.
  for (TopExp_Explorer f(split, TopAbs_FACE); f.More(); f.Next()) {
    bool named = false;
    for (const auto& [face, name] : names) named = named || (face.IsSame(f.Current()) && name == "skin");
    EXPECT_TRUE(named);
  }
}

TEST(OccCreaseSeam, AFaceWhoseSeamIsSmoothIsKeptWhole) {
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape();
  FaceNames names;
  std::vector<std::string> repairs;
  const TopoDS_Shape same = with_crease_seams_split(cylinder, 1e-7, names, repairs);
  EXPECT_TRUE(same.IsSame(cylinder));
  EXPECT_TRUE(repairs.empty());
}

}  // namespace
}  // namespace semimesh::occ
