// Exact first and second derivatives against central finite differences, on every entity of a
// cambered, tapered, swept wing; and normals pointing into the fluid.
#include "central_differences.hpp"
#include "naca_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using semimesh::cad::Vec2;
using semimesh::cad::Vec3;
using semimesh::mock_cad::NacaWingParams;

NacaWingParams cambered_tapered_swept(bool sharp) {
  NacaWingParams p;
  p.code = "2412";
  p.chord = 1.5;
  p.span = 2.0;
  p.taper = 0.6;
  p.sweep_deg = 25.0;
  p.sharp_te = sharp;
  return p;
}

constexpr double kStep = 1e-5;

TEST(NacaDerivatives, SurfacesMatchCentralDifferences) {
  for (bool sharp : {false, true}) {
    auto model = naca_test::wing(cambered_tapered_swept(sharp));
    for (int s = 0; s < model->num_surfaces(); ++s) {
      const auto& surf = model->surface(s);
      const auto box = surf.bounds();
      // Interior stations; u^2 avoids the camber kink at x = p = 0.4 (S_uu jumps there).
      for (double a : {0.03, 0.31, 0.5, 0.72, 0.97})
        for (double b : {0.1, 0.5, 0.9}) {
          const Vec2 uv(box[0].lo + a * box[0].length(), box[1].lo + b * box[1].length());
          const double hu = kStep * box[0].length(), hv = kStep * box[1].length();
          const std::string at = surf.name() + " at (" + std::to_string(uv.x()) + ", " + std::to_string(uv.y()) + ")";
          naca_test::expect_surface_derivatives_match_differences(surf, uv, hu, hv, at);
        }
    }
  }
}

TEST(NacaDerivatives, SkinsAreSmoothAtTheLeadingEdge) {
  // u = sqrt(x) removes the sqrt singularity: one-sided differences at u = 0 agree with du.
  auto model = naca_test::wing(cambered_tapered_swept(false));
  for (const char* name : {"upper", "lower"}) {
    const auto& surf = model->surface(naca_test::surface_id(*model, name));
    const auto d = surf.derivatives(Vec2(0.0, 1.0));
    const Vec3 fd = (-3 * surf.point(Vec2(0, 1)) + 4 * surf.point(Vec2(kStep, 1)) - surf.point(Vec2(2 * kStep, 1))) / (2 * kStep);
    naca_test::expect_close(d.du, fd, 1e-8, name);
    EXPECT_GT(d.du.norm(), 0.1);  // regular: no vanishing tangent at the leading edge
  }
}

TEST(NacaDerivatives, CurvesMatchCentralDifferences) {
  for (bool sharp : {false, true}) {
    auto model = naca_test::wing(cambered_tapered_swept(sharp));
    for (int c = 0; c < model->num_curves(); ++c) {
      const auto& curve = model->curve(c);
      const auto range = curve.bounds();
      for (double a : {0.02, 0.37, 0.8, 0.99}) {
        const double t = range.lo + a * range.length(), h = kStep * range.length();
        const auto d = curve.derivatives(t), p = curve.derivatives(t + h), m = curve.derivatives(t - h);
        const std::string at = curve.name() + " at " + std::to_string(t);
        EXPECT_LT((d.p - curve.point(t)).norm(), 1e-14) << at;
        naca_test::expect_close(d.d1, (p.p - m.p) / (2 * h), 1e-8, "d1 " + at);
        naca_test::expect_close(d.d2, (p.d1 - m.d1) / (2 * h), 1e-6, "d2 " + at);
      }
    }
  }
}

TEST(NacaDerivatives, CurvesLieOnTheSurfacesTheyBound) {
  auto model = naca_test::wing(cambered_tapered_swept(false));
  for (int c = 0; c < model->num_curves(); ++c) {
    const auto& curve = model->curve(c);
    for (const auto& use : model->surfaces_of_curve(c)) {
      const auto& surf = model->surface(use.surface);
      for (double a : {0.0, 0.25, 0.5, 1.0}) {
        const Vec3 x = curve.point(curve.bounds().lo + a * curve.bounds().length());
        const auto proj = surf.project(x);
        EXPECT_LT(proj.distance, 1e-12) << curve.name() << " on " << surf.name() << " at " << a;
        EXPECT_TRUE(proj.inside) << curve.name() << " on " << surf.name() << " at " << a;
      }
    }
  }
}

TEST(NacaDerivatives, NormalsPointIntoTheFluid) {
  auto model = naca_test::wing(cambered_tapered_swept(false));
  auto normal = [&](const char* name, Vec2 uv) { return model->surface(naca_test::surface_id(*model, name)).normal(uv); };
  EXPECT_GT(normal("upper", Vec2(std::sqrt(0.5), 1.0)).y(), 0.99);
  EXPECT_LT(normal("lower", Vec2(std::sqrt(0.5), 1.0)).y(), -0.99);
  EXPECT_LT(normal("upper", Vec2(0.0, 1.0)).x(), -0.8);  // upstream at the leading edge
  EXPECT_LT(normal("lower", Vec2(0.0, 1.0)).x(), -0.8);
  EXPECT_GT(normal("te_base", Vec2(0.5, 1.0)).x(), 0.95);  // tilted by the TE camber slope and sweep
  EXPECT_GT(normal("tip", Vec2(0.8, 0.0)).z(), 0.999);
  EXPECT_GT(normal("wall", Vec2(-3.0, 0.0)).z(), 0.999);
  // Box faces: towards the box centre.
  const auto& b = cambered_tapered_swept(false).box;
  const Vec3 centre(0.5 * (b[0] + b[3]), 0.5 * (b[1] + b[4]), 0.5 * (b[2] + b[5]));
  for (const char* name : {"box_xmin", "box_xmax", "box_ymin", "box_ymax", "box_zmax"}) {
    const auto& s = model->surface(naca_test::surface_id(*model, name));
    const auto box = s.bounds();
    const Vec2 mid(0.5 * (box[0].lo + box[0].hi), 0.5 * (box[1].lo + box[1].hi));
    EXPECT_GT(s.normal(mid).dot((centre - s.point(mid)).normalized()), 0.99) << name;
  }
  // Upper and lower normals agree at the leading edge (the outline is tangent-continuous there).
  EXPECT_LT((normal("upper", Vec2(0, 0.7)) - normal("lower", Vec2(0, 0.7))).norm(), 1e-12);
}

}  // namespace
