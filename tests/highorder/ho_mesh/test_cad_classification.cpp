// Parameters of nodes on a periodic face less than a period wide (highorder/src/curving/
// cad_classification.hpp): a fuselage cut at its plane of symmetry is half a cylinder, whose
// parameter box is half the period. A parameter brought into the box must land on the same point
// of the face, never a period past the box's other end (the far side of the fuselage).
#include "curving/cad_classification.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace semimesh::ho::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// S(u, v) = (v, cos u, sin u): the unit cylinder about x, trimmed to u in [lo, lo + pi], v in [0, 1].
class HalfCylinder : public cad::Surface {
 public:
  explicit HalfCylinder(double lo) : cad::Surface(0, "half_cylinder"), lo_(lo) {}
  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Cylinder; }
  std::array<cad::Interval, 2> bounds() const override { return {cad::Interval{lo_, lo_ + kPi}, cad::Interval{0, 1}}; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override {
    const double c = std::cos(uv.x()), s = std::sin(uv.x());
    return {cad::Vec3(uv.y(), c, s), cad::Vec3(0, -s, c), cad::Vec3(1, 0, 0),
            cad::Vec3(0, -c, -s),    cad::Vec3::Zero(),   cad::Vec3::Zero()};
  }
  std::optional<double> period(int direction) const override {
    if (direction == 0) return 2 * kPi;
    return std::nullopt;
  }
  bool contains(const cad::Vec2& uv) const override { return bounds()[0].contains(uv.x()) && bounds()[1].contains(uv.y()); }

 private:
  double lo_;
};

TEST(IntoBox, AParameterARoundOffShortOfAPeriodPastTheLowEndLandsOnTheLowEnd) {
  const HalfCylinder face(kPi / 2);
  // The box's low end seen a period on, a hair short of it: the floor of its offset is 0.
  const double u = std::nextafter(kPi / 2 + 2 * kPi, 0.0);
  ASSERT_EQ(std::floor((u - kPi / 2) / (2 * kPi)), 0.0);
  const cad::Vec2 in = into_box(face, cad::Vec2(u, 0.5));
  EXPECT_NEAR(in.x(), kPi / 2, 1e-12);
  EXPECT_NEAR((face.point(in) - face.point(cad::Vec2(u, 0.5))).norm(), 0.0, 1e-12);
}

TEST(IntoBox, ParametersInsideStayAndOthersComeInByWholePeriods) {
  const HalfCylinder face(kPi / 2);
  for (const double u : {kPi / 2, kPi, 1.5 * kPi}) {
    EXPECT_EQ(into_box(face, cad::Vec2(u, 0.25)).x(), u);
    EXPECT_NEAR(into_box(face, cad::Vec2(u - 2 * kPi, 0.25)).x(), u, 1e-12);
    EXPECT_NEAR(into_box(face, cad::Vec2(u + 4 * kPi, 0.25)).x(), u, 1e-12);
  }
  EXPECT_EQ(into_box(face, cad::Vec2(1.0, 0.75)).y(), 0.75);  // v is not periodic: left alone
}

TEST(IntoBox, OutsideTheBoxTheNearestImageWins) {
  const HalfCylinder face(kPi / 2);
  // 0.1 past the box's high end and 0.1 short of its low end are images of points off the face:
  // each goes to the image nearest the box, not a period away.
  EXPECT_NEAR(into_box(face, cad::Vec2(1.5 * kPi + 0.1, 0)).x(), 1.5 * kPi + 0.1, 1e-12);
  EXPECT_NEAR(into_box(face, cad::Vec2(kPi / 2 - 0.1, 0)).x(), kPi / 2 - 0.1, 1e-12);
}

}  // namespace
}  // namespace semimesh::ho::detail
