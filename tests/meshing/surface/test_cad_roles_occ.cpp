// Roles found without names through the occ backend: the OCC-built NACA wing (its faces carry the
// analytic names, which the detection never reads) and the shared NekMesh STEP wing, whose
// expected roles come from the file itself: its box faces are named L1, L2, L4 by the CATIA export
// and the body's Join.13, the wall is the one face with two loops (ADVANCED_FACE #736, #741), the
// wing stands 10 degrees off x, the units are mm.
#include "naca_wing_roles.hpp"
#include "semimesh/surface/cad_roles.hpp"

#include "semimesh/cad/labels.hpp"

#include "semimesh/occ/occ_backend.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace semimesh::surface {
namespace {

TEST(CadRolesOcc, OccBuiltWing) {
  const auto model = occ::load_occ(cad::Source{"", {{"naca.span", "2"}}});
  expect_blunt_naca_wing_roles(*model, detect_cad_roles(*model), 2.0, 1.0);
}

TEST(CadRolesOcc, NekMeshStepWing) {
  const std::string path = std::string(SEMIMESH_TESTDATA_DIR) + "/cad/nektar_3d_bl_wing_naca0012.stp";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "test CAD file " << path << " not found (see shared/testdata/cad/README.md)";
  const auto model = occ::load_occ(cad::Source{path, {}});
  const CadRoles roles = detect_cad_roles(*model);
  EXPECT_EQ(model->loops(roles.wall).size(), 2u);
  for (int s = 0; s < model->num_surfaces(); ++s) {
    if (s == roles.wall) continue;
    EXPECT_EQ(model->loops(s).size(), 1u) << "the wall is the only face with a hole";
  }
  for (int s : roles.farfield) EXPECT_EQ(model->surface(s).name().front(), 'L') << model->surface(s).name();
  for (int s : roles.body) EXPECT_EQ(model->surface(s).name().rfind("Join.13", 0), 0u) << model->surface(s).name();
  EXPECT_EQ(roles.farfield.size() + roles.body.size() + 1, static_cast<std::size_t>(model->num_surfaces()));
  // A blunt trailing edge and a revolved tip: one base (planar, at the downstream end) and one tip.
  ASSERT_TRUE(roles.te_base.has_value());
  EXPECT_TRUE(model->surface(*roles.te_base).is_planar());
  ASSERT_EQ(roles.tip.size(), 1u);
  EXPECT_FALSE(model->surface(roles.tip.front()).is_planar());
  // The NACA 0012 root section at 10 degrees: its streamwise extent is chord x cos(10 deg) up to the
  // base's thickness; a chord of 0.1..10 m in mm.
  EXPECT_GT(roles.chord, 100.0);
  EXPECT_LT(roles.chord, 10000.0);
}

// The ONERA M6 (a body-only file, the wall plane y = 0 and a box built at load): its sharp trailing
// edge is closed by two thin planar faces (cad-info of the file: faces of 4327 mm2 whose root curves,
// 4.6 mm long, run from the skins' ends to the trailing-edge point along the chord). Narrow, on the
// root at the downstream end, but along the stream: part of the skin, not a base; before, the lower
// one was taken for the base and the H-type swept its wake from a face nearly parallel to the stream.
TEST(CadRolesOcc, OneraM6ThinTrailingEdgeFacesAreNoBase) {
  const std::string path = std::string(SEMIMESH_TESTDATA_DIR) + "/cad/onera_m6_sharp_te.stp";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "test CAD file " << path << " not found (see shared/testdata/cad/README.md)";
  const auto model = occ::load_occ(cad::Source{
      path, {{"occ.wall_plane", "0,0,0,0,1,0"}, {"occ.farfield_box", "-8000,-8000,-8000,9000,9000,8000"}}});
  const CadRoles roles = detect_cad_roles(*model);
  int thin_planar = 0;
  for (int s : roles.body) thin_planar += model->surface(s).is_planar();
  EXPECT_EQ(thin_planar, 2) << "the two faces closing the trailing edge";
  EXPECT_FALSE(roles.te_base.has_value()) << cad::surface_label(*model, *roles.te_base);
}

}  // namespace
}  // namespace semimesh::surface
