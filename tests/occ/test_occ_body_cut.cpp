// geometry.body_cut (body_cut.hpp): a body's part beyond a plane taken away. Solids and faces the
// plane crosses obliquely go through OCCT's splitter; a face whose iso-parameter line the plane is
// (a loft's section) is cut in its parameters. Names follow the faces; a plane that misses the body
// or leaves nothing of it is refused by its label.
#include "body_cut.hpp"
#include "fluid_domain.hpp"
#include "shape_measures.hpp"

#include "semimesh/cad/error.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GeomConvert.hxx>
#include <GeomFill_Generator.hxx>
#include <Geom_Ellipse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Precision.hxx>
#include <GProp_GProps.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <gtest/gtest.h>

#include <cmath>

namespace semimesh::occ {
namespace {

Bnd_Box box_of(const TopoDS_Shape& shape) {
  Bnd_Box b;
  BRepBndLib::AddOptimal(shape, b, false, false);
  return b;
}

int faces_of(const TopoDS_Shape& shape) {
  int n = 0;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) ++n;
  return n;
}

// The shell of a solid's faces, each named "side_<k>".
TopoDS_Shell named_shell(const TopoDS_Shape& solid, FaceNames& names) {
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  int k = 0;
  for (TopExp_Explorer f(solid, TopAbs_FACE); f.More(); f.Next()) {
    builder.Add(shell, f.Current());
    names.emplace_back(f.Current(), "side_" + std::to_string(k++));
  }
  return shell;
}

TEST(OccBodyCut, ASolidKeepsItsPartOnTheNearSideClosedByTheCut) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(2, 1, 1)).Solid();
  FaceNames names;
  const TopoDS_Shape left = cut_beyond(box, CutPlane{gp_Pnt(0.5, 0, 0), gp_Dir(1, 1, 0), "cut"}, 1e-7, names);
  // x + y <= 0.5 of the box: a right triangle of legs 0.5, one deep.
  EXPECT_NEAR(test::volume_of(left), 0.125, 1e-9);
  EXPECT_TRUE(TopExp_Explorer(left, TopAbs_SOLID).More());
}

TEST(OccBodyCut, AShellCutObliquelyStaysOpenAlongTheCutAndKeepsItsNames) {
  // A cylinder's faces (side, two discs) cut by a plane across its axis at a slant.
  FaceNames names;
  const TopoDS_Shell shell = named_shell(BRepPrimAPI_MakeCylinder(gp_Ax2(gp::Origin(), gp::DZ()), 1.0, 2.0).Solid(), names);
  const CutPlane cut{gp_Pnt(0, 0, 1), gp_Dir(0.2, 0, 1), "cut"};
  const TopoDS_Shape left = cut_beyond(shell, cut, 1e-7, names);
  ASSERT_EQ(faces_of(left), 2);  // the side's lower part and the bottom disc
  // Nothing beyond the plane: every corner of the result's tight box on the near side, but for
  // the slant's reach.
  const Bnd_Box b = box_of(left);
  EXPECT_NEAR(b.CornerMax().Z(), 1.2, 1e-6);
  EXPECT_NEAR(b.CornerMin().Z(), 0.0, 1e-6);
  // The side left: 2 pi r times the mean height 1 (the slant averages out round the axis).
  double side = 0.0;
  for (TopExp_Explorer f(left, TopAbs_FACE); f.More(); f.Next())
    if (std::abs(test::area_of(f.Current()) - M_PI) > 1e-6) side = test::area_of(f.Current());
  EXPECT_NEAR(side, 2.0 * M_PI, 1e-6);
  // One free loop, along the cut; the kept faces named as the ones they come from.
  ShapeAnalysis_FreeBounds bounds(left, 1e-6, false, false);
  int loops = 0;
  for (TopExp_Explorer w(bounds.GetClosedWires(), TopAbs_WIRE); w.More(); w.Next()) ++loops;
  EXPECT_EQ(loops, 1);
  for (TopExp_Explorer f(left, TopAbs_FACE); f.More(); f.Next()) {
    bool named = false;
    for (const auto& [face, name] : names) named = named || (face.IsSame(f.Current()) && name.rfind("side_", 0) == 0);
    EXPECT_TRUE(named);
  }
}

// A loft through sections at constant z (an OpenVSP wing's way): every iso-line across the sections
// lies in a plane z = const, and the cut at one is made in the face's parameters, exactly.
TopoDS_Shape lofted_half_cylinder() {
  BRepOffsetAPI_ThruSections loft(false, false, 1e-9);
  for (const double z : {0.0, 0.4, 1.0, 1.5, 2.0}) {
    const double r = 1.0 + 0.1 * z;
    const Handle(Geom_TrimmedCurve) arc = GC_MakeArcOfCircle(gp_Pnt(r, 0, z), gp_Pnt(0, r, z), gp_Pnt(-r, 0, z)).Value();
    loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(arc).Edge()).Wire());
  }
  loft.Build();
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  for (TopExp_Explorer f(loft.Shape(), TopAbs_FACE); f.More(); f.Next()) builder.Add(shell, f.Current());
  return shell;
}

TEST(OccBodyCut, AFaceWhoseSectionThePlaneIsIsCutAlongThatSection) {
  FaceNames names;
  const TopoDS_Shape loft = lofted_half_cylinder();
  const double whole = test::area_of(loft);
  const TopoDS_Shape left = cut_beyond(loft, CutPlane{gp_Pnt(0, 0, 1.2), gp_Dir(0, 0, 1), "cut"}, 1e-7, names);
  ASSERT_EQ(faces_of(left), 1);
  const Bnd_Box b = box_of(left);
  EXPECT_NEAR(b.CornerMax().Z(), 1.2, 1e-6);  // the box grows by the edges' tolerance
  EXPECT_NEAR(b.CornerMin().Z(), 0.0, 1e-6);
  // The half cylinder's side between z = 0 and 1.2 of radius 1 + 0.1 z (a cone's side, near enough:
  // the loft runs smoothly through the sections, within half a percent).
  EXPECT_NEAR(test::area_of(left), M_PI * 1.2 * (1.0 + 0.06), 0.02);
  EXPECT_LT(test::area_of(left), whole);
  // Its boundary's curves have 3D curves (the capping's plane finders need them).
  for (TopExp_Explorer e(left, TopAbs_EDGE); e.More(); e.Next()) {
    double first, last;
    EXPECT_FALSE(BRep_Tool::Curve(TopoDS::Edge(e.Current()), first, last).IsNull());
  }
}

TEST(OccBodyCut, APlaneThatMissesTheBodyOrLeavesNothingIsRefusedByItsLabel) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 1)).Solid();
  FaceNames names;
  const auto message = [&](const gp_Pnt& p, const gp_Dir& n) {
    try {
      cut_beyond(box, CutPlane{p, n, "geometry.body_cut = {...}"}, 1e-7, names);
    } catch (const cad::CadError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(gp_Pnt(0, 0, 2), gp::DZ()).find("geometry.body_cut = {...}: the plane misses the body"),
            std::string::npos);
  EXPECT_NE(message(gp_Pnt(0, 0, -1), gp::DZ()).find("geometry.body_cut = {...}: the plane leaves nothing"),
            std::string::npos);
}

// A body-only "wing" lofted from an elliptic root section on z = 0 to a tip section flattened to a
// line (an ellipse of minor radius 1e-9) at z = 2, its loops left open: the root is capped, the tip
// loop encloses no area and is refused naming geometry.body_cut; cut at z = 1.8 it closes, and the
// fluid domain is the box's upper half minus the wing below the cut.
TEST(OccBodyCut, APinchedTipIsRefusedNamingTheKeyAndMeshesCutBlunt) {
  GeomFill_Generator loft;
  for (const auto& [z, minor] : {std::pair{0.0, 0.1}, std::pair{2.0, 1e-9}})
    loft.AddCurve(GeomConvert::CurveToBSplineCurve(new Geom_Ellipse(gp_Ax2(gp_Pnt(0.5, 0, z), gp::DZ(), gp::DX()), 0.5, minor)));
  loft.Perform(Precision::Confusion());
  const TopoDS_Face skin = BRepBuilderAPI_MakeFace(loft.Surface(), Precision::Confusion()).Face();
  const WallPlane wall{gp_Pnt(0, 0, 0), gp::DZ(), "geometry.wall_plane"};
  FarFieldShape far;
  far.box = std::array<double, 6>{-4, -4, -4, 4, 4, 4};
  far.label = "box";
  FaceNames names;
  std::vector<std::string> repairs;
  try {
    fluid_domain(skin, wall, far, std::nullopt, 1e-6, names, repairs);
    ADD_FAILURE() << "no CadError";
  } catch (const cad::CadError& e) {
    EXPECT_NE(std::string(e.what()).find("encloses no area"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("geometry.body_cut"), std::string::npos) << e.what();
  }
  repairs.clear();
  const TopoDS_Shape domain =
      fluid_domain(skin, wall, far, CutPlane{gp_Pnt(0, 0, 1.8), gp::DZ(), "cut"}, 1e-6, names, repairs);
  // The wing's sections have half-axes 0.5 and 0.1 (1 - z / 2), linear in z: its volume below 1.8
  // is pi 0.05 times the integral of (1 - z / 2) from 0 to 1.8 (1.8 - 0.81).
  EXPECT_NEAR(test::volume_of(domain), 4.0 * 8.0 * 8.0 - M_PI * 0.05 * (1.8 - 0.81), 1e-4);
  EXPECT_NE(repairs.front().find("cut the body at cut"), std::string::npos) << repairs.front();
}

}  // namespace
}  // namespace semimesh::occ
