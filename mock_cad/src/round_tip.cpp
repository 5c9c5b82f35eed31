#include "round_tip.hpp"

#include <cmath>

namespace semimesh::mock_cad::detail {

SurfaceDerivatives RoundTipMap::eval(double u, double phi) const {
  const NacaWing& w = *wing_;
  const double span = w.span(), c = w.chord_at(span), dc = w.chord_slope();
  // C = mid of the two sides, c y_t N = half their difference: both with exact u-derivatives.
  const ProfilePoint up = w.section().eval(Side::Upper, u), lo = w.section().eval(Side::Lower, u);
  auto lift = [](const Vec2& p) { return Vec3(p.x(), p.y(), 0.0); };
  const Vec3 C = Vec3(w.leading_edge_x(span), 0.0, span) + 0.5 * c * lift(up.p + lo.p);
  const Vec3 C1 = 0.5 * c * lift(up.d1 + lo.d1), C2 = 0.5 * c * lift(up.d2 + lo.d2);
  Vec3 B = 0.5 * c * lift(up.p - lo.p);
  const Vec3 B1 = 0.5 * c * lift(up.d1 - lo.d1), B2 = 0.5 * c * lift(up.d2 - lo.d2);
  const double yc = 0.5 * (up.p.y() + lo.p.y()), yc1 = 0.5 * (up.d1.y() + lo.d1.y()), yc2 = 0.5 * (up.d2.y() + lo.d2.y());
  ScalarPoint yt = w.section().half_thickness_in_u(u);
  // A closed trailing edge has y_t(1) = 0 exactly; the polynomial's round-off (1e-17) would leave a
  // circle there whose curvature (1e17) the callers would take for the surface's: make it the pole.
  if (w.section().sharp_te() && u >= 1.0) B = Vec3::Zero(), yt.f = 0.0;
  const Vec3 W(w.tan_sweep() + dc * u * u, dc * yc, 1.0), W1(2.0 * dc * u, dc * yc1, 0.0), W2(2.0 * dc, dc * yc2, 0.0);
  const Vec3 D = c * yt.f * W, D1 = c * (yt.d1 * W + yt.f * W1), D2 = c * (yt.d2 * W + 2.0 * yt.d1 * W1 + yt.f * W2);
  const double cs = std::cos(phi), sn = std::sin(phi);
  SurfaceDerivatives d;
  d.p = C + cs * B + sn * D;
  d.du = C1 + cs * B1 + sn * D1;
  d.dv = -sn * B + cs * D;
  d.duu = C2 + cs * B2 + sn * D2;
  d.duv = -sn * B1 + cs * D1;
  d.dvv = -cs * B - sn * D;
  return d;
}

Vec3 RoundTipMap::base_origin() const {
  const NacaWing& w = *wing_;
  const Vec2 up = w.section().point(Side::Upper, 1.0), lo = w.section().point(Side::Lower, 1.0);
  const Vec2 mid = 0.5 * w.root_chord() * (up + lo);
  return Vec3(mid.x(), mid.y(), 0.0);
}

Vec3 RoundTipMap::base_across() const {
  const NacaWing& w = *wing_;
  const Vec2 gap = w.section().point(Side::Upper, 1.0) - w.section().point(Side::Lower, 1.0);
  if (gap.norm() == 0.0) return Vec3(0.0, 1.0, 0.0);  // sharp: no base; N(1) of a symmetric section
  const Vec2 n = gap.normalized();
  return Vec3(n.x(), n.y(), 0.0);
}

Vec3 RoundTipMap::base_along() const {
  const NacaWing& w = *wing_;
  const Vec2 up = w.section().point(Side::Upper, 1.0), lo = w.section().point(Side::Lower, 1.0);
  const Vec2 mid = 0.5 * (up + lo);
  return Vec3(w.tan_sweep() + w.chord_slope() * mid.x(), w.chord_slope() * mid.y(), 1.0);
}

double RoundTipMap::trailing_edge_half_thickness() const { return wing_->section().half_thickness_in_u(1.0).f; }

}  // namespace semimesh::mock_cad::detail
