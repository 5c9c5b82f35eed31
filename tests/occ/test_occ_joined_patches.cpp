// Untrimmed B-spline patches of one smooth skin joined into one face (joined_patches.hpp), and
// patches that only touch, or meet at a crease, left as they are.
#include "joined_patches.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace semimesh::occ {
namespace {

TopoDS_Face trimmed_patch(const Handle(Geom_Surface)& surface, double u0, double u1, double v0, double v1) {
  const Handle(Geom_RectangularTrimmedSurface) piece = new Geom_RectangularTrimmedSurface(surface, u0, u1, v0, v1);
  return BRepBuilderAPI_MakeFace(GeomConvert::SurfaceToBSplineSurface(piece), Precision::Confusion()).Face();
}

TopoDS_Shell sewn_patches(const std::vector<TopoDS_Face>& faces) {
  BRepBuilderAPI_Sewing sewing(1e-7);
  for (const TopoDS_Face& f : faces) sewing.Add(f);
  sewing.Perform();
  TopExp_Explorer shell(sewing.SewedShape(), TopAbs_SHELL);
  EXPECT_TRUE(shell.More());
  return TopoDS::Shell(shell.Current());
}

std::vector<TopoDS_Face> patch_faces(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Face> out;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) out.push_back(TopoDS::Face(f.Current()));
  return out;
}

// A cylinder of radius 2 about the x axis, 3 long, in 4 quarters round and 3 pieces along, the
// faces in `order`: one closed face on the cylinder, whatever the order.
TEST(JoinedPatches, AGridOfPatchesRoundACylinderBecomesOneClosedFace) {
  const Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(gp_Ax3(gp::Origin(), gp::DX()), 2.0);
  std::vector<TopoDS_Face> grid;
  for (int along = 0; along < 3; ++along)
    for (int round = 0; round < 4; ++round)
      grid.push_back(trimmed_patch(cylinder, round * M_PI / 2, (round + 1) * M_PI / 2, along, along + 1.0));
  std::vector<std::vector<TopoDS_Face>> orders{grid, {grid.rbegin(), grid.rend()}};
  std::vector<TopoDS_Face> along_first;  // along, then round
  for (int round = 0; round < 4; ++round)
    for (int along = 0; along < 3; ++along) along_first.push_back(grid[static_cast<std::size_t>(along * 4 + round)]);
  orders.push_back(along_first);
  for (std::size_t k = 0; k < orders.size(); ++k) {
    std::vector<std::string> repairs;
    const TopoDS_Shape joined = with_patches_joined(sewn_patches(orders[k]), 1e-7, repairs);
    const std::vector<TopoDS_Face> faces = patch_faces(joined);
    ASSERT_EQ(faces.size(), 1u) << "order " << k;
    ASSERT_EQ(repairs.size(), 1u);
    EXPECT_NE(repairs[0].find("joined 12 patches of the wall part into 1 face(s)"), std::string::npos) << repairs[0];
    const auto surface = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(faces[0]));
    ASSERT_FALSE(surface.IsNull());
    EXPECT_TRUE(surface->IsUClosed() || surface->IsVClosed()) << "round the cylinder";
    double u0, u1, v0, v1, worst = 0.0;
    surface->Bounds(u0, u1, v0, v1);
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const gp_Pnt p = surface->Value(u0 + (u1 - u0) * i / 20, v0 + (v1 - v0) * j / 20);
        worst = std::max(worst, std::abs(std::hypot(p.Y(), p.Z()) - 2.0));
      }
    EXPECT_LT(worst, 1e-12) << "the patches' control points, exactly";
  }
}

// Two planar patches at a right angle share a side but not a tangent plane: left as they are (the
// same shape, nothing said). A patch alone is left too.
TEST(JoinedPatches, ACreaseIsNotJoined) {
  const Handle(Geom_Plane) floor = new Geom_Plane(gp_Ax3(gp::Origin(), gp::DZ()));
  const Handle(Geom_Plane) side = new Geom_Plane(gp_Ax3(gp::Origin(), gp::DY(), gp::DX()));
  const TopoDS_Shell l_shape = sewn_patches({trimmed_patch(floor, 0, 1, 0, 1), trimmed_patch(side, 0, 1, 0, 1)});
  std::vector<std::string> repairs;
  EXPECT_TRUE(with_patches_joined(l_shape, 1e-7, repairs).IsSame(l_shape));
  EXPECT_TRUE(repairs.empty());
  // The same two patches flattened into one plane are joined.
  const TopoDS_Shell flat = sewn_patches({trimmed_patch(floor, 0, 1, 0, 1), trimmed_patch(floor, 1, 2, 0, 1)});
  EXPECT_EQ(patch_faces(with_patches_joined(flat, 1e-7, repairs)).size(), 1u);
}

}  // namespace
}  // namespace semimesh::occ
