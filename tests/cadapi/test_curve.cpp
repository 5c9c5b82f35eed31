// Generic Curve algorithms (projection, arc length and its inverse, curvature) on a line and a
// circle, whose answers are known in closed form.
#include "shapes.hpp"

#include <gtest/gtest.h>

using shapes::Circle;
using shapes::kPi;
using shapes::Line;
using shapes::Vec3;

TEST(Curve, ProjectOntoLineFindsFootOfPerpendicular) {
  Line line(0, Vec3(0, 0, 0), Vec3(2, 0, 0));
  auto p = line.project(Vec3(0.5, 3, 4));
  EXPECT_NEAR(p.t, 0.25, 1e-12);
  EXPECT_NEAR(p.distance, 5.0, 1e-12);
  EXPECT_TRUE(p.converged);
  EXPECT_TRUE(p.point.isApprox(Vec3(0.5, 0, 0), 1e-12));
}

TEST(Curve, ProjectBeyondEndClampsToEnd) {
  Line line(0, Vec3(0, 0, 0), Vec3(1, 0, 0));
  auto p = line.project(Vec3(3, 1, 0));
  EXPECT_DOUBLE_EQ(p.t, 1.0);
  EXPECT_NEAR(p.distance, std::sqrt(5.0), 1e-12);
}

TEST(Curve, ProjectOntoCircleRecoversAngleAndRadialDistance) {
  Circle circle(0, 2.0, {0, 2 * kPi});
  for (double angle : {0.3, 1.7, 3.0, 4.4, 6.0}) {
    Vec3 x(3.5 * std::cos(angle), 3.5 * std::sin(angle), 0.0);
    auto p = circle.project(x);
    EXPECT_NEAR(p.t, angle, 1e-10) << "angle " << angle;
    EXPECT_NEAR(p.distance, 1.5, 1e-12);
    EXPECT_TRUE(p.converged);
  }
}

TEST(Curve, ProjectWithGuessConvergesFromTheGuess) {
  Circle circle(0, 1.0, {0, 2 * kPi});
  auto p = circle.project(Vec3(std::cos(2.0), std::sin(2.0), 0.7), 1.8);
  EXPECT_NEAR(p.t, 2.0, 1e-10);
  EXPECT_NEAR(p.distance, 0.7, 1e-12);
  // On the axis every point of the circle is closest: the guess itself is the answer.
  auto q = circle.project(Vec3(0, 0, 0.5), 1.25);
  EXPECT_NEAR(q.t, 1.25, 1e-12);
  EXPECT_NEAR(q.distance, std::sqrt(1.25), 1e-12);
}

TEST(Curve, ArcLengthOfCircleIsRadiusTimesAngle) {
  Circle circle(0, 3.0, {0, 2 * kPi});
  EXPECT_NEAR(circle.arc_length(0.2, 1.4), 3.0 * 1.2, 1e-12);
  EXPECT_NEAR(circle.arc_length(1.4, 0.2), -3.0 * 1.2, 1e-12);
  EXPECT_DOUBLE_EQ(circle.arc_length(1.0, 1.0), 0.0);
  EXPECT_NEAR(circle.length(), 6 * kPi, 1e-11);
}

TEST(Curve, ArcLengthOfLineIsDistance) {
  Line line(0, Vec3(1, 2, 3), Vec3(4, 6, 3));
  EXPECT_NEAR(line.arc_length(0.0, 1.0), 5.0, 1e-13);
  EXPECT_NEAR(line.arc_length(0.2, 0.6), 2.0, 1e-13);
}

TEST(Curve, ParameterAtLengthInvertsArcLength) {
  Circle circle(0, 2.0, {0, 2 * kPi});
  EXPECT_NEAR(circle.parameter_at_length(0.5, 2.0), 1.5, 1e-11);   // s = r * dt
  EXPECT_NEAR(circle.parameter_at_length(3.0, -4.0), 1.0, 1e-11);  // backwards
  EXPECT_NEAR(circle.parameter_at_length(1.0, 0.0), 1.0, 1e-12);
}

TEST(Curve, ParameterAtLengthClampsToBounds) {
  Circle circle(0, 1.0, {0, kPi});
  EXPECT_DOUBLE_EQ(circle.parameter_at_length(1.0, 100.0), kPi);
  EXPECT_DOUBLE_EQ(circle.parameter_at_length(1.0, -100.0), 0.0);
}

TEST(Curve, CurvatureAndTangent) {
  Circle circle(0, 4.0, {0, 2 * kPi});
  EXPECT_NEAR(circle.curvature(0.9), 0.25, 1e-14);
  EXPECT_TRUE(circle.tangent(kPi / 2).isApprox(Vec3(-1, 0, 0), 1e-14));
  Line line(0, Vec3(0, 0, 0), Vec3(0, 0, 2));
  EXPECT_DOUBLE_EQ(line.curvature(0.5), 0.0);
  EXPECT_TRUE(line.tangent(0.5).isApprox(Vec3(0, 0, 1)));
}

namespace {

// A polyline t -> (t, 0, 0) on [0, 0.31], then along y at speed 50 to t = 0.77, then along x at
// speed 0.02 to t = 2: corners at parameters no bisection of [0, 2] lands on, as a loft linear
// between its sections has them. `declared`: whether it says where its tangent breaks.
class Polyline : public semimesh::cad::Curve {
 public:
  explicit Polyline(bool declared) : Curve(0, "polyline") {
    if (declared) breaks_ = {0.31, 0.77};
  }
  semimesh::cad::CurveKind kind() const override { return semimesh::cad::CurveKind::Other; }
  semimesh::cad::Interval bounds() const override { return {0.0, 2.0}; }
  semimesh::cad::CurveDerivatives derivatives(double t) const override {
    if (t <= 0.31) return {Vec3(t, 0, 0), Vec3(1, 0, 0), Vec3::Zero()};
    if (t <= 0.77) return {Vec3(0.31, 50 * (t - 0.31), 0), Vec3(0, 50, 0), Vec3::Zero()};
    return {Vec3(0.31 + 0.02 * (t - 0.77), 23, 0), Vec3(0.02, 0, 0), Vec3::Zero()};
  }
  const std::vector<double>& tangent_breaks() const override { return breaks_; }

 private:
  std::vector<double> breaks_;
};

constexpr double kPolylineLength = 0.31 + 0.46 * 50 + 1.23 * 0.02;

}  // namespace

// Across the corners the arc length is integrated piecewise, exact to round-off; the same curve
// without its breaks (the slow path's reference: Gauss across a kink) is off by far more, which is
// what ran a thousand-step discretisation out of length before its end.
TEST(Curve, ArcLengthAcrossTangentBreaksIsIntegratedPiecewise) {
  const Polyline declared(true), undeclared(false);
  EXPECT_NEAR(declared.length(), kPolylineLength, 1e-12);
  EXPECT_NEAR(declared.arc_length(0.2, 1.5), (0.31 - 0.2) + 0.46 * 50 + (1.5 - 0.77) * 0.02, 1e-12);
  EXPECT_NEAR(declared.arc_length(0.5, 0.6), 0.1 * 50, 1e-12) << "no break inside: one piece";
  EXPECT_GT(std::abs(undeclared.length() - kPolylineLength), 1e-9) << "the reference shows the error it fixes";
}

// Stepping equal lengths from the start, as the curve mesher does: every step advances and the
// last one ends at the curve's end to round-off.
TEST(Curve, EqualStepsAlongABrokenCurveEndAtItsEnd) {
  const Polyline curve(true);
  const int n = 2000;
  double t = 0.0;
  for (int i = 1; i < n; ++i) {
    const double next = curve.parameter_at_length(t, kPolylineLength / n);
    ASSERT_GT(next, t) << "step " << i;
    t = next;
  }
  EXPECT_NEAR(curve.arc_length(t, 2.0), kPolylineLength / n, 1e-10);
}
