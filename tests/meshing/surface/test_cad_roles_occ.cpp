// Roles found without names through the occ backend: the OCC-built NACA wing (its faces carry the
// analytic names, which the detection never reads) and the shared NekMesh STEP wing, whose
// expected roles come from the file itself: its box faces are named L1, L2, L4 by the CATIA export
// and the body's Join.13, the wall is the one face with two loops (ADVANCED_FACE #736, #741), the
// wing stands 10 degrees off x, the units are mm.
#include "naca_wing_roles.hpp"
#include "semimesh/surface/cad_roles.hpp"

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

}  // namespace
}  // namespace semimesh::surface
