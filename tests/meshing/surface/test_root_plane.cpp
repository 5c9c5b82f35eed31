// find_root_plane on the analytic wing without its wall and box (the body alone, as wing CAD is
// often exported): the root section is a loop of free curves in z = 0, the body above it.
#include "semimesh/surface/root_plane.hpp"

#include "semimesh/mock_cad/naca.hpp"

#include <gtest/gtest.h>

namespace semimesh::surface {
namespace {

TEST(RootPlane, OpenRootOfASweptTaperedWingIsTheWallPlaneFacingTheBody) {
  for (bool sharp : {false, true}) {
    mock_cad::NacaWingParams p;
    p.farfield = false;
    p.sharp_te = sharp;
    p.sweep_deg = 25.0;
    p.taper = 0.5;
    const auto body = mock_cad::make_naca_wing(p);
    ASSERT_FALSE(body->is_closed());
    const std::optional<RootPlane> root = find_root_plane(*body);
    ASSERT_TRUE(root.has_value());
    EXPECT_NEAR(root->point.z(), 0.0, 1e-12);
    EXPECT_NEAR(root->normal.dot(cad::Vec3::UnitZ()), 1.0, 1e-12) << root->normal.transpose();
    EXPECT_NE(root->why.find("open root"), std::string::npos) << root->why;
  }
}

TEST(RootPlane, ClosedBodyWithoutAPlanarCapHasNone) {
  // A body of revolution closed by poles: no free curve, no planar face.
  const auto body_of_revolution = mock_cad::load_naca(
      cad::Source{"", {{"naca.shape", "revolution"}, {"naca.te", "sharp"}, {"naca.farfield", "false"}}});
  EXPECT_FALSE(find_root_plane(*body_of_revolution).has_value());  // closed, no planar cap
}

}  // namespace
}  // namespace semimesh::surface
