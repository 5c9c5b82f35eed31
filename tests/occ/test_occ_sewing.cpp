// Sewing at load (prepare_shape.hpp): faces exported one by one leave gaps of their CAD tool's
// tolerance, wider than a millionth of the model; sew_shape raises its tolerance tenfold while
// that closes more gaps, and an open body's flat loops are closed by planar faces (fluid_domain),
// each said as a repair.
#include "fluid_domain.hpp"
#include "prepare_shape.hpp"
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gtest/gtest.h>

#include <cmath>

namespace semimesh::occ {
namespace {

mock_cad::NacaWingParams body_only() {
  mock_cad::NacaWingParams p;
  p.farfield = false;
  p.span = 1.0;
  return p;
}

double diagonal(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return std::sqrt(box.SquareExtent());
}

// The wing's faces (upper, lower, te_base, tip), each moved by its own 1e-5 chord.
TopoDS_Shape faces_with_gaps() {
  TopoDS_Compound out;
  BRep_Builder builder;
  builder.MakeCompound(out);
  int i = 0;
  for (TopExp_Explorer f(make_naca_wing_shape(body_only()), TopAbs_FACE); f.More(); f.Next()) {
    const double a = 1.3 * ++i;
    gp_Trsf move;
    move.SetTranslation(gp_Vec(std::cos(a), std::sin(a), 0.5 * std::cos(2 * a)).Normalized() * 1e-5);
    builder.Add(out, BRepBuilderAPI_Transform(f.Current(), move, /*copy=*/true).Shape());
  }
  return out;
}

TEST(OccSewing, GapsOfAHundredThousandthChordCloseAsTheToleranceRises) {
  const TopoDS_Shape faces = faces_with_gaps();
  const double d = diagonal(faces);
  FaceNames names;
  // At a millionth of the model only: the gaps stay open (more free edges than the root's three).
  const Sewn strict = sew_shape(faces, 1e-6 * d, 1e-6 * d, names);
  EXPECT_GT(strict.free, 3);
  EXPECT_DOUBLE_EQ(strict.tolerance, 1e-6 * d);
  // Raised up to a ten-thousandth: every gap closes, the open root's three edges stay free.
  const Sewn raised = sew_shape(faces, 1e-6 * d, 1e-4 * d, names);
  EXPECT_EQ(raised.free, 3);
  EXPECT_GT(raised.tolerance, 1e-6 * d);
  EXPECT_LE(raised.tolerance, 1e-4 * d * (1 + 1e-12));
  EXPECT_GT(raised.joined, strict.joined);
}

TEST(OccSewing, ShapeWithoutFreeEdgesIsReturnedAsItIs) {
  mock_cad::NacaWingParams p = body_only();
  p.farfield = true;  // the wing on its wall in a box: closed
  const TopoDS_Shape closed = make_naca_wing_shape(p);
  FaceNames names;
  const Sewn sewn = sew_shape(closed, 1e-6, 1e-4, names);
  EXPECT_TRUE(sewn.shape.IsSame(closed));
  EXPECT_EQ(sewn.joined, 0);
  EXPECT_EQ(sewn.free, 0);
}

TEST(OccSewing, OpenRootAndOpenTipAreClosedByPlanarFacesAndSaidSo) {
  // The skin without its tip face: the root and the tip are open, both flat.
  BRepBuilderAPI_Sewing skin(1e-7);
  int index = 0;
  for (TopExp_Explorer f(make_naca_wing_shape(body_only()), TopAbs_FACE); f.More(); f.Next(), ++index)
    if (index != 3) skin.Add(f.Current());  // upper, lower, te_base; not the tip
  skin.Perform();
  FaceNames names;
  std::vector<std::string> repairs;
  const WallPlane wall{gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1), "geometry.wall_plane"};
  FarFieldShape far;
  far.box_chords = 3.0;
  far.label = "geometry.farfield";
  const TopoDS_Shape domain = fluid_domain(skin.SewedShape(), wall, far, std::nullopt, 1e-6, names, repairs);
  EXPECT_FALSE(domain.IsNull());
  ASSERT_EQ(repairs.size(), 2u);
  for (const std::string& r : repairs) EXPECT_NE(r.find("closed an open flat loop of 3 free edge(s)"), std::string::npos) << r;
}

}  // namespace
}  // namespace semimesh::occ
