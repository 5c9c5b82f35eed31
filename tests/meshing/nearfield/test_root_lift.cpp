// The lift onto the root strip (meshing/src/nearfield/root_lift.cpp), on the analytic NACA wing
// (wall z = 0, the skin's parameters (chord fraction, z)):
//  - move_to_height moves a node along its CAD entity to a height above the wall, keeping its
//    chordwise parameter on a swept, tapered wing (not drifting to the closest point);
//  - lift_node takes height d to strip + d (1 - strip / ceiling) and leaves the nodes at or above
//    the ceiling, CAD vertices and unattached nodes where they are.
#include "semimesh/cad/model.hpp"

#include "junction_shell.hpp"
#include "wing_case.hpp"

#include <gtest/gtest.h>

namespace semimesh::nearfield {
namespace {

using cad::Vec3;
using mesh::CadAttachment;
using testing::curve_named;
using testing::naca;

// The wall z = 0, its normal into the fluid (the wing stands on it, z up to the span).
const detail::WallFrame kWall{Vec3::UnitZ(), Vec3::Zero()};

TEST(MoveToHeight, SurfaceNodeReachesTheHeightKeepingItsPlaceAlongTheSection) {
  const auto model = mock_cad::make_naca_wing(naca("2412", false, /*taper=*/0.5, /*sweep=*/30.0));
  const int upper = model->find_surface("upper").value();
  const cad::Surface& face = model->surface(upper);
  for (double u : {0.02, 0.3, 0.8})
    for (double target : {0.1, 0.6}) {
      CadAttachment at{CadAttachment::Surface, upper, u, 0.35};
      const Vec3 moved = detail::move_to_height(*model, kWall, face.point({u, 0.35}), at, target);
      // The skin's point at the same chord fraction and the target's z, from the CAD itself.
      EXPECT_LT((moved - face.point({u, target})).norm(), 1e-9) << "u " << u << ", target " << target;
      EXPECT_NEAR(at.u, u, 1e-12);
      EXPECT_LT((moved - face.point({at.u, at.v})).norm(), 1e-12) << "the attachment follows the node";
    }
}

TEST(MoveToHeight, CurveNodeReachesTheHeightOnItsCurve) {
  const auto model = mock_cad::make_naca_wing(naca("0012", false, 0.5, 30.0));
  const int edge = curve_named(*model, "leading_edge");
  ASSERT_GE(edge, 0);
  const cad::Curve& curve = model->curve(edge);
  const double t0 = curve.project(Vec3(0.1, 0.0, 0.2)).t;
  CadAttachment at{CadAttachment::Curve, edge, t0, 0.0};
  const Vec3 moved = detail::move_to_height(*model, kWall, curve.derivatives(t0).p, at, 0.9);
  EXPECT_NEAR(moved.z(), 0.9, 1e-9);
  EXPECT_LT((moved - curve.derivatives(at.u).p).norm(), 1e-12);
  EXPECT_LT((moved - curve.project(moved).point).norm(), 1e-9) << "off the curve";
}

TEST(LiftNode, TakesHeightDToTheStripPlusDScaledAndLeavesWhatItMust) {
  const auto model = mock_cad::make_naca_wing(naca("0012", false));
  const int upper = model->find_surface("upper").value();
  const cad::Surface& face = model->surface(upper);
  const double strip = 0.1, ceiling = 1.0;
  // 0.4 above the wall: 0.1 + 0.4 (1 - 0.1 / 1) = 0.46, at the same chord fraction.
  CadAttachment at{CadAttachment::Surface, upper, 0.4, 0.4};
  const Vec3 lifted = detail::lift_node(*model, kWall, strip, ceiling, face.point({0.4, 0.4}), at);
  EXPECT_LT((lifted - face.point({0.4, 0.46})).norm(), 1e-9);
  // At or above the ceiling, a CAD vertex, an unattached node: where they are.
  CadAttachment high{CadAttachment::Surface, upper, 0.4, 1.2};
  const Vec3 above = face.point({0.4, 1.2});
  EXPECT_EQ(detail::lift_node(*model, kWall, strip, ceiling, above, high), above);
  EXPECT_EQ(high.v, 1.2);
  CadAttachment vertex{CadAttachment::Vertex, 0, 0.0, 0.0};
  const Vec3 x(0.2, 0.05, 0.3);
  EXPECT_EQ(detail::lift_node(*model, kWall, strip, ceiling, x, vertex), x);
  CadAttachment none;
  EXPECT_EQ(detail::lift_node(*model, kWall, strip, ceiling, x, none), x);
}

}  // namespace
}  // namespace semimesh::nearfield
