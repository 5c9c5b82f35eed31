// A body-only file with a wall plane and a far field from the parameters (occ.wall_plane,
// occ.farfield_*): the fluid domain built by OCCT's Booleans, and the bad input it refuses.
#include "occ_test_support.hpp"
#include "semimesh/cad/error.hpp"
#include "semimesh/occ/occ_backend.hpp"
#include "temp_path.hpp"

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace semimesh::occ {
namespace {

// A 1 x 1 x 2 block standing on z = 0 (the body), written as a BREP file; its volume is 2.
std::string block_file() {
  const std::string path = semimesh::test::temp_path("block.brep").string();
  EXPECT_TRUE(BRepTools::Write(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 2)).Shape(), path.c_str()));
  return path;
}

std::unique_ptr<cad::Model> load(const std::vector<std::pair<std::string, std::string>>& params) {
  cad::Source source{block_file(), {}};
  for (const auto& [key, value] : params) source.params.set(key, value);
  return load_occ(source);
}

std::string error_of(const std::vector<std::pair<std::string, std::string>>& params) {
  try {
    load(params);
  } catch (const cad::CadError& e) {
    EXPECT_EQ(e.kind(), cad::CadError::Kind::BadParameter);
    return e.what();
  }
  ADD_FAILURE() << "no CadError";
  return {};
}

std::set<int> surfaces_named(const cad::Model& model, const std::string& prefix) {
  std::set<int> out;
  for (int s = 0; s < model.num_surfaces(); ++s)
    if (model.surface(s).name().rfind(prefix, 0) == 0) out.insert(s);
  return out;
}

TEST(OccFluidDomain, BoxOnTheWallMinusTheBody) {
  const auto model = load({{"occ.wall_plane", "0,0,0,0,0,1"}, {"occ.farfield_box", "-5,-5,-5,5,5,5"}});
  // The block's 5 faces above the wall, the wall, the box's 5 faces above the wall: the block's
  // bottom face is gone.
  ASSERT_EQ(model->num_surfaces(), 11);
  const std::set<int> wall = surfaces_named(*model, "wall"), far = surfaces_named(*model, "farfield_");
  ASSERT_EQ(wall.size(), 1u);
  EXPECT_EQ(far.size(), 5u);
  const int w = *wall.begin();
  ASSERT_EQ(model->loops(w).size(), 2u) << "the wall holds the root loop as a hole";
  // The root loop's curves are shared with the body's side faces: real topology, closed model.
  for (const cad::Loop& loop : model->loops(w))
    for (const cad::CurveUse& use : loop.uses) EXPECT_EQ(model->surfaces_of_curve(use.curve).size(), 2u);
  for (int c = 0; c < model->num_curves(); ++c) EXPECT_EQ(model->surfaces_of_curve(c).size(), 2u) << "curve " << c;
  // No face lies below the wall, and none but the wall lies in it with the body's root.
  for (int s = 0; s < model->num_surfaces(); ++s)
    for (const cad::Vec2& uv : test::inside_samples(model->surface(s), 5)) EXPECT_GE(model->surface(s).point(uv).z(), -1e-9);
  // The fluid is inside: the flux of x.n is -3 x (the half box minus the block) = -3 (500 - 2).
  EXPECT_NEAR(test::position_flux(*model), -3.0 * (500.0 - 2.0), 1e-6 * 1500.0);
}

TEST(OccFluidDomain, HalfSphereAndBoxOfChords) {
  const auto sphere = load({{"occ.wall_plane", "0,0,0,0,0,1"}, {"occ.farfield_sphere", "0.5,0.5,0,6"}});
  EXPECT_EQ(surfaces_named(*sphere, "wall").size(), 1u);
  const double half_ball = 2.0 / 3.0 * M_PI * 216.0;
  EXPECT_NEAR(test::position_flux(*sphere, 200), -3.0 * (half_ball - 2.0), 1e-3 * 3.0 * half_ball);
  // 3 root chords (the root's longest side, 1) around the block's box [0,1]x[0,1]x[0,2], cut at
  // z = 0: 7 x 7 x 5.
  const auto box = load({{"occ.wall_plane", "0,0,0,0,0,1"}, {"occ.farfield_box_chords", "3"}});
  EXPECT_NEAR(test::position_flux(*box), -3.0 * (7.0 * 7.0 * 5.0 - 2.0), 1e-6 * 735.0);
}

TEST(OccFluidDomain, ABodyOffThePlaneIsRefusedNamingThePlane) {
  const std::string e = error_of({{"occ.wall_plane", "0,0,-0.5,0,0,1"}, {"occ.farfield_box", "-5,-5,-5,5,5,5"}});
  EXPECT_NE(e.find("geometry.wall_plane = {point = [0, 0, -0.5], normal = [0, 0, 1]}"), std::string::npos) << e;
  EXPECT_NE(e.find("does not touch the plane"), std::string::npos) << e;
  EXPECT_NE(e.find("0.5 above it"), std::string::npos) << e;
  EXPECT_NE(e.find("block.brep"), std::string::npos) << "names the file: " << e;
}

TEST(OccFluidDomain, APlaneThroughTheBodyIsRefused) {
  const std::string e = error_of({{"occ.wall_plane", "0,0,1.5,0,0,1"}, {"occ.farfield_box", "-5,-5,-5,5,5,5"}});
  EXPECT_NE(e.find("geometry.wall_plane = {point = [0, 0, 1.5], normal = [0, 0, 1]}"), std::string::npos) << e;
  EXPECT_NE(e.find("cuts through the body"), std::string::npos) << e;
  EXPECT_NE(e.find("1.5 below it"), std::string::npos) << e;
  // The normal decides the fluid side: the block stands on z = 0 only seen from +z.
  const std::string flipped = error_of({{"occ.wall_plane", "0,0,0,0,0,-1"}, {"occ.farfield_box", "-5,-5,-5,5,5,5"}});
  EXPECT_NE(flipped.find("the body lies on the side the normal points away from"), std::string::npos) << flipped;
}

TEST(OccFluidDomain, AFarFieldNotHoldingTheBodyIsRefused) {
  std::string e = error_of({{"occ.wall_plane", "0,0,0,0,0,1"}, {"occ.farfield_box", "-5,-5,-5,5,5,1.5"}});
  EXPECT_NE(e.find("geometry.farfield = {box = [-5, -5, -5, 5, 5, 1.5]}"), std::string::npos) << e;
  EXPECT_NE(e.find("does not contain the body"), std::string::npos) << e;
  e = error_of({{"occ.wall_plane", "0,0,0,0,0,1"}, {"occ.farfield_box", "10,10,-5,20,20,5"}});
  EXPECT_NE(e.find("does not contain the body: the body lies outside it"), std::string::npos) << e;
  e = error_of({{"occ.wall_plane", "0,0,0,0,0,1"}, {"occ.farfield_sphere", "0,0,0,1"}});
  EXPECT_NE(e.find("geometry.farfield = {sphere = {centre = [0, 0, 0], radius = 1}}"), std::string::npos) << e;
  EXPECT_NE(e.find("does not contain the body"), std::string::npos) << e;
  e = error_of({{"occ.wall_plane", "0,0,0,0,0,1"}});
  EXPECT_NE(e.find("go together"), std::string::npos) << e;
}

}  // namespace
}  // namespace semimesh::occ
