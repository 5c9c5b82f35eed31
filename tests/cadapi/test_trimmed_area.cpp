// trimmed_area (cad-info's face areas) on faces whose area is known in closed form.
#include "semimesh/cad/trimmed_area.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace {

namespace cad = semimesh::cad;

// Plane z = 0 with (u, v) = (x, y) on a box, trimmed by `inside`.
class TrimmedPlane : public cad::Surface {
 public:
  TrimmedPlane(std::array<cad::Interval, 2> box, std::function<bool(const cad::Vec2&)> inside)
      : Surface(0, "plane"), box_(box), inside_(std::move(inside)) {}
  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Plane; }
  std::array<cad::Interval, 2> bounds() const override { return box_; }
  bool contains(const cad::Vec2& uv) const override { return inside_(uv); }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override {
    return {cad::Vec3(uv.x(), uv.y(), 0), cad::Vec3(1, 0, 0), cad::Vec3(0, 1, 0), cad::Vec3::Zero(), cad::Vec3::Zero(),
            cad::Vec3::Zero()};
  }

 private:
  std::array<cad::Interval, 2> box_;
  std::function<bool(const cad::Vec2&)> inside_;
};

// Sphere of radius r, (u, v) = (longitude, latitude), untrimmed.
class SphereBand : public cad::Surface {
 public:
  explicit SphereBand(double r) : Surface(0, "sphere"), r_(r) {}
  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Sphere; }
  std::array<cad::Interval, 2> bounds() const override { return {cad::Interval{0, 2.0}, cad::Interval{-0.5, 1.0}}; }
  bool contains(const cad::Vec2&) const override { return true; }
  cad::SurfaceDerivatives derivatives(const cad::Vec2& uv) const override {
    double cu = std::cos(uv.x()), su = std::sin(uv.x()), cv = std::cos(uv.y()), sv = std::sin(uv.y());
    cad::SurfaceDerivatives d;
    d.p = r_ * cad::Vec3(cv * cu, cv * su, sv);
    d.du = r_ * cad::Vec3(-cv * su, cv * cu, 0);
    d.dv = r_ * cad::Vec3(-sv * cu, -sv * su, cv);
    d.duu = d.duv = d.dvv = cad::Vec3::Zero();  // not used by the area
    return d;
  }

 private:
  double r_;
};

}  // namespace

TEST(TrimmedArea, UntrimmedSphereBandIsExactToQuadrature) {
  // r^2 * (u1 - u0) * (sin v1 - sin v0)
  const double expected = 4.0 * 2.0 * (std::sin(1.0) - std::sin(-0.5));
  auto a = cad::trimmed_area(SphereBand(2.0));
  EXPECT_NEAR(a.area, expected, 1e-8 * expected);
  EXPECT_LE(a.error_estimate, 2e-6 * expected);
}

TEST(TrimmedArea, DiscIsWithinItsErrorEstimate) {
  TrimmedPlane disc({cad::Interval{-1.5, 1.5}, cad::Interval{-1.5, 1.5}}, [](const cad::Vec2& uv) { return uv.squaredNorm() <= 1.0; });
  auto a = cad::trimmed_area(disc);
  EXPECT_NEAR(a.area, M_PI, 3 * a.error_estimate);
  EXPECT_LE(a.error_estimate, 3e-3 * M_PI);
  EXPECT_NEAR(a.area, M_PI, 1e-3 * M_PI);
}

TEST(TrimmedArea, SquareWithRoundHole) {
  TrimmedPlane plate({cad::Interval{0, 4}, cad::Interval{0, 4}},
                     [](const cad::Vec2& uv) { return (uv - cad::Vec2(2.2, 1.9)).norm() >= 0.5; });
  const double expected = 16.0 - M_PI * 0.25;
  auto a = cad::trimmed_area(plate);
  EXPECT_NEAR(a.area, expected, 3 * a.error_estimate);
  EXPECT_NEAR(a.area, expected, 1e-4 * expected);
}

TEST(TrimmedArea, LooseToleranceStopsEarlier) {
  TrimmedPlane disc({cad::Interval{-1, 1}, cad::Interval{-1, 1}}, [](const cad::Vec2& uv) { return uv.squaredNorm() <= 1.0; });
  auto loose = cad::trimmed_area(disc, 3e-2);
  auto tight = cad::trimmed_area(disc);
  EXPECT_LT(tight.error_estimate, loose.error_estimate);
  EXPECT_NEAR(loose.area, M_PI, 3e-2 * M_PI);
  EXPECT_NEAR(tight.area, M_PI, 1e-3 * M_PI);
}
