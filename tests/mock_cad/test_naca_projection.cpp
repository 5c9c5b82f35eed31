// Closest-point queries: round trips on and off the surfaces, near the leading edge, against a
// brute-force search, and the trimmed faces (wall hole, tip outline).
#include "naca_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>
#include <vector>

namespace {

using semimesh::cad::Vec2;
using semimesh::cad::Vec3;
using semimesh::mock_cad::NacaWingParams;

NacaWingParams params(const std::string& code, double taper, double sweep) {
  NacaWingParams p;
  p.code = code;
  p.taper = taper;
  p.sweep_deg = sweep;
  return p;
}

// The projection returned a stationary point of the distance: residual orthogonal to the free tangents.
void expect_stationary(const semimesh::cad::Surface& s, const semimesh::cad::SurfaceProjection& pr, const Vec3& x,
                       const std::string& what) {
  const auto d = s.derivatives(pr.uv);
  const Vec3 r = d.p - x;
  const auto box = s.bounds();
  const bool interior_u = pr.uv.x() > box[0].lo && pr.uv.x() < box[0].hi;
  const bool interior_v = pr.uv.y() > box[1].lo && pr.uv.y() < box[1].hi;
  if (interior_u) {
    EXPECT_LT(std::abs(d.du.normalized().dot(r)), 1e-10) << what;
  }
  if (interior_v) {
    EXPECT_LT(std::abs(d.dv.normalized().dot(r)), 1e-10) << what;
  }
}

TEST(NacaProjection, RoundTripOnTheSkins) {
  for (const auto& p : {params("0012", 1.0, 0.0), params("2412", 0.5, 30.0), params("4415", 0.8, -20.0)}) {
    auto model = naca_test::wing(p);
    for (const char* name : {"upper", "lower"}) {
      const auto& s = model->surface(naca_test::surface_id(*model, name));
      for (double u : {0.0, 1e-4, 0.01, 0.1, 0.45, 0.7, 0.99, 1.0})
        for (double v : {0.0, 0.4, 1.7, 3.0}) {
          const Vec3 x = s.point(Vec2(u, v));
          const auto pr = s.project(x);
          const std::string at = p.code + " " + name + " (" + std::to_string(u) + ", " + std::to_string(v) + ")";
          EXPECT_TRUE(pr.converged) << at;
          EXPECT_TRUE(pr.inside) << at;
          EXPECT_LT(pr.distance, 1e-12) << at;
          EXPECT_NEAR(pr.uv.x(), u, 1e-9) << at;
          EXPECT_NEAR(pr.uv.y(), v, 1e-9) << at;
        }
    }
  }
}

TEST(NacaProjection, OffSurfaceAlongTheNormalRecoversTheFoot) {
  // NACA 0012, straight wing: convex skins, so x = S + d n has its foot at S for any d > 0.
  auto model = naca_test::wing(params("0012", 1.0, 0.0));
  for (const char* name : {"upper", "lower"}) {
    const auto& s = model->surface(naca_test::surface_id(*model, name));
    for (double u : {0.0, 0.02, 0.1, 0.3, 0.6, 0.9, 1.0})
      for (double d : {1e-6, 1e-3, 0.05, 0.3, 1.0}) {
        const Vec2 uv(u, 1.3);
        const Vec3 x = s.point(uv) + d * s.normal(uv);
        const auto pr = s.project(x);
        const std::string at = std::string(name) + " u=" + std::to_string(u) + " d=" + std::to_string(d);
        EXPECT_TRUE(pr.converged) << at;
        EXPECT_NEAR(pr.distance, d, 1e-12) << at;
        EXPECT_NEAR(pr.uv.x(), u, 1e-8) << at;
        EXPECT_NEAR(pr.uv.y(), 1.3, 1e-10) << at;
      }
  }
}

TEST(NacaProjection, OffSurfaceOnATaperedSweptCamberedWingIsStationary) {
  auto model = naca_test::wing(params("2412", 0.5, 30.0));
  for (const char* name : {"upper", "lower", "te_base"}) {
    const auto& s = model->surface(naca_test::surface_id(*model, name));
    const auto box = s.bounds();
    for (double a : {0.0, 0.05, 0.4, 0.8, 1.0})
      for (double b : {0.2, 0.5, 0.8})
        for (double d : {1e-4, 0.02, 0.2, 1.0}) {
          const Vec2 uv(box[0].lo + a * box[0].length(), box[1].lo + b * box[1].length());
          const Vec3 x = s.point(uv) + d * s.normal(uv);
          const auto pr = s.project(x);
          const std::string at = std::string(name) + " " + std::to_string(a) + "," + std::to_string(b) + " d=" + std::to_string(d);
          EXPECT_TRUE(pr.converged) << at;
          EXPECT_LE(pr.distance, d + 1e-12) << at;
          expect_stationary(s, pr, x, at);
        }
  }
}

TEST(NacaProjection, NearTheLeadingEdgeMatchesBruteForce) {
  // Points on circles around the leading edge; the straight wing's closest point is in the
  // section plane, found here by dense sampling of that section.
  auto model = naca_test::wing(params("2412", 1.0, 0.0));
  const double z = 1.0;
  for (const char* name : {"upper", "lower"}) {
    const auto& s = model->surface(naca_test::surface_id(*model, name));
    for (double r : {1e-4, 0.005, 0.05, 0.5})
      for (int k = 0; k < 16; ++k) {
        const double phi = 2 * M_PI * k / 16;
        const Vec3 x(0.01 + r * std::cos(phi), r * std::sin(phi), z);
        double best = std::numeric_limits<double>::max();
        constexpr int kSamples = 20000;
        for (int i = 0; i <= kSamples; ++i) best = std::min(best, (s.point(Vec2(double(i) / kSamples, z)) - x).norm());
        const auto pr = s.project(x);
        const std::string at = std::string(name) + " r=" + std::to_string(r) + " phi=" + std::to_string(phi);
        EXPECT_TRUE(pr.converged) << at;
        EXPECT_LE(pr.distance, best + 1e-9) << at;
        EXPECT_NEAR(pr.uv.y(), z, 1e-9) << at;
      }
  }
}

TEST(NacaProjection, ConvergesOnTheCamberCrease) {
  // The 4-digit construction offsets the thickness normal to a camber line whose curvature jumps
  // at x = p, so a cambered skin has a small tangent kink there. Seen from outside the kink, the
  // closest point is the crease itself, where no gradient vanishes.
  auto model = naca_test::wing(params("2412", 1.0, 0.0));
  const auto& upper = model->surface(naca_test::surface_id(*model, "upper"));
  const double x = 0.4, h = 1e-7;
  const auto at = naca_test::surface_point(0.02, 0.4, 0.12, x, true, false);
  const auto ahead = naca_test::surface_point(0.02, 0.4, 0.12, x - h, true, false);
  const auto behind = naca_test::surface_point(0.02, 0.4, 0.12, x + h, true, false);
  const double slope_ahead = std::atan2(at.y - ahead.y, at.x - ahead.x);
  const double slope_behind = std::atan2(behind.y - at.y, behind.x - at.x);
  EXPECT_GT(std::abs(slope_ahead - slope_behind), 1e-4);  // a real kink, not round-off
  const double bisector = 0.5 * (slope_ahead + slope_behind) + M_PI / 2;
  for (double d : {0.01, 0.2, 1.0}) {
    const Vec3 p(at.x + d * std::cos(bisector), at.y + d * std::sin(bisector), 1.0);
    const auto pr = upper.project(p);
    EXPECT_TRUE(pr.converged) << d;
    EXPECT_NEAR(pr.uv.x(), std::sqrt(0.4), 1e-12) << d;
    EXPECT_NEAR(pr.distance, d, 1e-12) << d;
  }
}

TEST(NacaProjection, SectionCurvesRoundTripAndFindTheClosestPoint) {
  auto model = naca_test::wing(params("2412", 0.5, 30.0));
  for (const char* name : {"root_upper", "root_lower", "tip_upper", "tip_lower"}) {
    const auto& c = model->curve(naca_test::curve_id(*model, name));
    for (double t : {0.0, 0.003, 0.2, 0.63, 1.0}) {
      const auto pr = c.project(c.point(t));
      EXPECT_TRUE(pr.converged) << name << " " << t;
      EXPECT_NEAR(pr.t, t, 1e-9) << name << " " << t;
      EXPECT_LT(pr.distance, 1e-12) << name << " " << t;
    }
    const Vec3 x = c.point(0.5) + Vec3(0.05, 0.2, 0.3);
    double best = std::numeric_limits<double>::max();
    for (int i = 0; i <= 20000; ++i) best = std::min(best, (c.point(i / 20000.0) - x).norm());
    const auto pr = c.project(x);
    EXPECT_LE(pr.distance, best + 1e-9) << name;
  }
}

TEST(NacaProjection, LinesAndPlanesAreExact) {
  auto model = naca_test::wing(params("0012", 0.5, 30.0));
  const auto& le = model->curve(naca_test::curve_id(*model, "leading_edge"));
  const auto pr = le.project(le.point(1.2) + Vec3(-0.3, 0.1, 0.0).cross(le.tangent(1.2)));
  EXPECT_NEAR(pr.t, 1.2, 1e-14);
  EXPECT_NEAR(le.length(), 3.0 / std::cos(30 * M_PI / 180), 1e-13);
  EXPECT_NEAR(le.parameter_at_length(0.0, le.length() / 2), 1.5, 1e-14);
  const auto& xmax = model->surface(naca_test::surface_id(*model, "box_xmax"));
  const auto pp = xmax.project(Vec3(3.0, 2.0, 4.0));
  EXPECT_NEAR(pp.distance, 8.0, 1e-14);
  EXPECT_LT((pp.point - Vec3(11.0, 2.0, 4.0)).norm(), 1e-14);
  EXPECT_TRUE(pp.inside);
}

TEST(NacaProjection, WallHoleIsTheRootSection) {
  auto model = naca_test::wing(params("2412", 1.0, 0.0));
  const auto& wall = model->surface(naca_test::surface_id(*model, "wall"));
  // Inside the root section: a foot on the untrimmed plane, reported outside the face.
  for (const Vec3& x : {Vec3(0.3, 0.02, 0.0), Vec3(0.3, 0.0, -0.2), Vec3(0.95, 0.0, 0.5), Vec3(0.001, 0.0, 0.0)}) {
    const auto pr = wall.project(x);
    EXPECT_FALSE(pr.inside) << x.transpose();
    EXPECT_NEAR(pr.distance, std::abs(x.z()), 1e-15);
  }
  // Outside the section (above, below, ahead, behind, far).
  for (const Vec3& x : {Vec3(0.3, 0.1, 0.0), Vec3(0.3, -0.06, 0.1), Vec3(-0.001, 0.0, 0.0), Vec3(1.01, 0.0, 0.0),
                        Vec3(-5, 7, 2)}) {
    const auto pr = wall.project(x);
    EXPECT_TRUE(pr.inside) << x.transpose();
  }
  // On the root outline: the boundary belongs to the face.
  const auto& root_upper = model->curve(naca_test::curve_id(*model, "root_upper"));
  const auto& root_lower = model->curve(naca_test::curve_id(*model, "root_lower"));
  for (double t : {0.0, 0.01, 0.3, 0.7, 1.0}) {
    EXPECT_TRUE(wall.project(root_upper.point(t)).inside) << t;
    EXPECT_TRUE(wall.project(root_lower.point(t)).inside) << t;
  }
  // Outside the box rectangle: clamped and not inside.
  EXPECT_FALSE(wall.contains(Vec2(12.0, 0.0)));
}

TEST(NacaProjection, TipKeepsTheInsideOfTheTipSection) {
  NacaWingParams p = params("2412", 0.5, 30.0);
  auto model = naca_test::wing(p);
  const auto& tip = model->surface(naca_test::surface_id(*model, "tip"));
  const double x_le = 3.0 * std::tan(30 * M_PI / 180), chord = 0.5;
  const auto ref = naca_test::surface_point(0.02, 0.4, 0.12, 0.3, true, false);
  EXPECT_TRUE(tip.project(Vec3(x_le + 0.3 * chord, 0.5 * ref.y * chord, 3.2)).inside);
  EXPECT_TRUE(tip.contains(Vec2(x_le + ref.x * chord, ref.y * chord)));  // on the outline
  EXPECT_FALSE(tip.contains(Vec2(x_le + ref.x * chord, ref.y * chord + 1e-6)));
  EXPECT_FALSE(tip.contains(Vec2(x_le - 1e-6, 0.0)));
  EXPECT_FALSE(tip.project(Vec3(x_le + 0.3 * chord, 0.1, 3.0)).inside);
}

TEST(NacaProjection, ConcurrentQueriesGiveTheSerialAnswers) {
  auto model = naca_test::wing(params("2412", 0.5, 30.0));
  ASSERT_TRUE(model->thread_safe());
  const auto& s = model->surface(naca_test::surface_id(*model, "upper"));
  std::vector<Vec3> points;
  for (int i = 0; i < 2000; ++i) points.push_back(s.point(Vec2((i % 97) / 96.0, 3.0 * (i % 89) / 88.0)) + Vec3(0.01, 0.02, -0.01) * (i % 7));
  std::vector<Vec2> serial, a(points.size()), b(points.size());
  for (const Vec3& x : points) serial.push_back(s.project(x).uv);
  auto run = [&](std::vector<Vec2>& out) {
    for (size_t i = 0; i < points.size(); ++i) out[i] = s.project(points[i]).uv;
  };
  std::thread ta(run, std::ref(a)), tb(run, std::ref(b));
  ta.join();
  tb.join();
  EXPECT_EQ(a, serial);
  EXPECT_EQ(b, serial);
}

}  // namespace
