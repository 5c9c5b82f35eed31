// The medial halo against its closed form on a wing plane leaning at any dihedral angle over the
// wall z = 0: the wing half-plane through the x axis in direction w = (0, cos a, sin a), the fluid in
// the wedge between it and the wall's half-plane y > 0. The point at distance d1 from the wing
// plane and d2 from the wall, straight out from the root along e = (0, 1, 0), is
// (0, (d1 + d2 cos a) / sin a, d2): in front of the root and with its foot on the wing's face when
// -d1 cos a <= d2 < d1 / -cos a (no bound for a <= 90 degrees).
#include "semimesh/cad/model.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/junction_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

namespace semimesh::nearfield {
namespace {

using cad::Interval;
using cad::Vec2;

class Segment final : public cad::Curve {
 public:
  Segment(int id, Vec3 a, Vec3 b) : Curve(id, "segment"), a_(a), b_(b) {}
  cad::CurveKind kind() const override { return cad::CurveKind::Line; }
  Interval bounds() const override { return {0.0, 1.0}; }
  cad::CurveDerivatives derivatives(double t) const override { return {a_ + t * (b_ - a_), b_ - a_, Vec3::Zero()}; }

 private:
  Vec3 a_, b_;
};

// S(u, v) = u x + v w on [-1, 1] x [0, 1]; du x dv = x cross w points into the solid (orientation -1).
class LeaningPlane final : public cad::Surface {
 public:
  LeaningPlane(int id, Vec3 w) : Surface(id, "wing", -1), w_(w) {}
  cad::SurfaceKind kind() const override { return cad::SurfaceKind::Plane; }
  std::array<Interval, 2> bounds() const override { return {Interval{-1.0, 1.0}, Interval{0.0, 1.0}}; }
  cad::SurfaceDerivatives derivatives(const Vec2& uv) const override {
    return {uv.x() * Vec3::UnitX() + uv.y() * w_, Vec3::UnitX(), w_, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  }
  bool contains(const Vec2& uv) const override {
    return uv.x() >= -1.0 && uv.x() <= 1.0 && uv.y() >= 0.0 && uv.y() <= 1.0;
  }

 private:
  Vec3 w_;
};

std::unique_ptr<cad::Model> leaning_wing(double angle_deg) {
  const double a = angle_deg * std::acos(-1.0) / 180.0;
  const Vec3 w(0.0, std::cos(a), std::sin(a));
  auto model = std::make_unique<cad::Model>("test");
  const Vec3 corners[4] = {-Vec3::UnitX(), Vec3::UnitX(), Vec3::UnitX() + w, -Vec3::UnitX() + w};
  int vertex[4];
  for (int k = 0; k < 4; ++k) vertex[k] = model->add_vertex(corners[k]);
  cad::Loop loop;
  for (int k = 0; k < 4; ++k) {
    const int c = model->add_curve(std::make_unique<Segment>(k, corners[k], corners[(k + 1) % 4]), vertex[k],
                                   vertex[(k + 1) % 4]);
    loop.uses.push_back({c, true});
  }
  model->add_surface(std::make_unique<LeaningPlane>(0, w), {loop});
  model->finalize();
  return model;
}

TEST(MedialHalo, MatchesTheClosedFormAtEverySupportedAngle) {
  const double d1 = 0.1, d2 = 0.105;  // inside the window of every angle below
  for (double angle : {60.0, 75.0, 90.0, 120.0, 150.0}) {
    const auto model = leaning_wing(angle);
    const double a = angle * std::acos(-1.0) / 180.0;
    const Vec3 expected(0.25, (d1 + d2 * std::cos(a)) / std::sin(a), d2);
    const Vec3 halo = medial_halo(*model, {0}, Vec3(0.25, 0, 0), Vec3::UnitY(), Vec3::UnitZ(), d1, d2);
    EXPECT_LT((halo - expected).norm(), 1e-9) << angle << " degrees: " << halo.transpose();
  }
}

TEST(MedialHalo, NoPointBeyondTheWingIsAnErrorNamingThePlace) {
  // So open an angle with a wall layer this thick: the point at both distances from the planes lies
  // behind the root, inside the body; none in front of it.
  const auto model = leaning_wing(175.0);
  EXPECT_THROW(medial_halo(*model, {0}, Vec3(0.25, 0, 0), Vec3::UnitY(), Vec3::UnitZ(), 0.1, 0.5), NearFieldError);
}

std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// At 120 degrees the wing leans away from the wall's normal: the point d2 up the normal is
// d2 |cos a| from the wing plane. The closed form's window d2 < d1 / -cos a is the wall thickness
// that fits, d2 |cos a| the shell thickness that does; the message names both, and both work.
TEST(MedialHalo, ABodyLeaningAwayNamesTheThicknessesThatFitAndTheyDo) {
  const auto model = leaning_wing(120.0);
  const double d1 = 0.1, d2 = 0.5;  // the point 0.5 up is 0.25 from the wing
  const Vec3 root(0.25, 0, 0);
  const auto fit = thicknesses_that_fit(*model, {0}, root, Vec3::UnitY(), Vec3::UnitZ(), d1, d2);
  ASSERT_TRUE(fit.has_value());
  EXPECT_LE(fit->wall_below, 0.2);
  EXPECT_GT(fit->wall_below, 0.2 - 1e-3);
  EXPECT_GE(fit->shell_at_least, 0.25);
  EXPECT_LT(fit->shell_at_least, 0.25 + 1e-3);
  try {
    medial_halo(*model, {0}, root, Vec3::UnitY(), Vec3::UnitZ(), d1, d2);
    FAIL() << "no halo point expected";
  } catch (const NearFieldError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("below " + number(fit->wall_below) + " (wall_layer.thickness;"), std::string::npos) << message;
    EXPECT_NE(message.find("at least " + number(fit->shell_at_least) + " (nearfield.thickness;"), std::string::npos)
        << message;
  }
  EXPECT_NO_THROW(medial_halo(*model, {0}, root, Vec3::UnitY(), Vec3::UnitZ(), d1, fit->wall_below));
  EXPECT_NO_THROW(medial_halo(*model, {0}, root, Vec3::UnitY(), Vec3::UnitZ(), fit->shell_at_least, d2));
  // Leaning towards the normal (60 degrees), the point up it lies beyond the wing: no lean to name.
  EXPECT_FALSE(thicknesses_that_fit(*leaning_wing(60.0), {0}, root, Vec3::UnitY(), Vec3::UnitZ(), d1, d2).has_value());
}

}  // namespace
}  // namespace semimesh::nearfield
