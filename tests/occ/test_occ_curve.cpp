// The occ backend's curves: where their tangent breaks (a B-spline's C0 knots, as on the leading
// edge of a wing lofted linearly between its sections) and the arc length integrated between them.
#include "occ_curve.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Circ.hxx>
#include <gtest/gtest.h>

#include <cmath>

namespace semimesh::occ {
namespace {

// A degree-1 B-spline through (0,0,0), (1,0,0), (1,2,0), (4,2,0) with knots 0, 0.3, 0.35, 1: a
// polyline of lengths 1, 2, 3 whose corners are its inner knots.
TopoDS_Edge polyline_edge() {
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = gp_Pnt(0, 0, 0);
  poles(2) = gp_Pnt(1, 0, 0);
  poles(3) = gp_Pnt(1, 2, 0);
  poles(4) = gp_Pnt(4, 2, 0);
  TColStd_Array1OfReal knots(1, 4);
  knots(1) = 0.0;
  knots(2) = 0.3;
  knots(3) = 0.35;
  knots(4) = 1.0;
  TColStd_Array1OfInteger multiplicities(1, 4);
  multiplicities(1) = 2;
  multiplicities(2) = 1;
  multiplicities(3) = 1;
  multiplicities(4) = 2;
  return BRepBuilderAPI_MakeEdge(new Geom_BSplineCurve(poles, knots, multiplicities, 1)).Edge();
}

TEST(OccCurve, APolylinesCornersAreItsTangentBreaksAndItsLengthIsExact) {
  const OccCurve curve(0, "polyline", polyline_edge());
  ASSERT_EQ(curve.tangent_breaks().size(), 2u);
  EXPECT_NEAR(curve.tangent_breaks()[0], 0.3, 1e-15);
  EXPECT_NEAR(curve.tangent_breaks()[1], 0.35, 1e-15);
  EXPECT_NEAR(curve.length(), 6.0, 1e-12);
  EXPECT_NEAR(curve.arc_length(0.15, 0.7), 0.5 + 2.0 + (0.7 - 0.35) / 0.65 * 3.0, 1e-12);  // uniform speed per span
}

TEST(OccCurve, ASmoothCurveHasNoTangentBreak) {
  const OccCurve circle(0, "circle", BRepBuilderAPI_MakeEdge(gp_Circ(gp::XOY(), 2.0)).Edge());
  EXPECT_TRUE(circle.tangent_breaks().empty());
  EXPECT_NEAR(circle.length(), 4 * M_PI, 1e-12);
}

}  // namespace
}  // namespace semimesh::occ
