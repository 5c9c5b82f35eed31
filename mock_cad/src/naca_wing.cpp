#include "naca_wing.hpp"
#include "constants.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::mock_cad::detail {

NacaWing::NacaWing(const NacaSection& section, double chord, double span, double taper, double sweep_deg,
                   double dihedral_deg)
    : section_(section),
      chord_(chord),
      span_(span),
      dchord_(-chord * (1.0 - taper) / span),
      tan_sweep_(std::tan(sweep_deg * kPi / 180.0)),
      tan_dihedral_(std::tan(dihedral_deg * kPi / 180.0)) {}

// The dihedral's terms are added only when there is one: adding 0 turns a -0 into +0, and a wing
// without dihedral keeps every bit it had before the key existed.
double NacaWing::shifted_y(double y, double v) const { return tan_dihedral_ == 0.0 ? y : leading_edge_y(v) + y; }

SurfaceDerivatives NacaWing::eval(Side side, double u, double v) const {
  const ProfilePoint e = section_.eval(side, u);
  const double c = chord_at(v);
  SurfaceDerivatives d;
  d.p = Vec3(leading_edge_x(v) + c * e.p.x(), shifted_y(c * e.p.y(), v), v);
  d.du = Vec3(c * e.d1.x(), c * e.d1.y(), 0.0);
  d.dv = Vec3(tan_sweep_ + dchord_ * e.p.x(), tan_dihedral_ == 0.0 ? dchord_ * e.p.y() : tan_dihedral_ + dchord_ * e.p.y(), 1.0);
  d.duu = Vec3(c * e.d2.x(), c * e.d2.y(), 0.0);
  d.duv = Vec3(dchord_ * e.d1.x(), dchord_ * e.d1.y(), 0.0);
  d.dvv = Vec3::Zero();
  return d;
}

SurfaceDerivatives NacaWing::eval_base(double s, double v) const {
  const SurfaceDerivatives lower = eval(Side::Lower, 1.0, v), upper = eval(Side::Upper, 1.0, v);
  SurfaceDerivatives d;
  d.p = lower.p + s * (upper.p - lower.p);
  d.du = upper.p - lower.p;
  d.dv = lower.dv + s * (upper.dv - lower.dv);
  d.duu = Vec3::Zero();
  d.duv = upper.dv - lower.dv;
  d.dvv = Vec3::Zero();  // the trailing-edge lines are straight
  return d;
}

Vec3 NacaWing::point(Side side, double u, double v) const {
  const Vec2 p = section_.point(side, u);
  const double c = chord_at(v);
  return Vec3(leading_edge_x(v) + c * p.x(), shifted_y(c * p.y(), v), v);
}

Vec2 NacaWing::to_section(const Vec3& x, double v) const {
  const double c = chord_at(v);
  return Vec2((x.x() - leading_edge_x(v)) / c, (tan_dihedral_ == 0.0 ? x.y() : x.y() - leading_edge_y(v)) / c);
}

std::array<double, 2> NacaWing::start_candidates(Side side, const Vec2& q) const {
  return {std::sqrt(std::clamp(q.x(), 0.0, 1.0)),
          std::clamp(sign_of(side) * q.y() / section_.leading_edge_slope(), 0.0, 1.0)};
}

double NacaWing::initial_u(Side side, const Vec2& q) const {
  const auto [from_station, from_thickness] = start_candidates(side, q);
  const double d_station = (section_.point(side, from_station) - q).squaredNorm();
  const double d_thickness = (section_.point(side, from_thickness) - q).squaredNorm();
  return d_station <= d_thickness ? from_station : from_thickness;
}

Vec2 NacaWing::initial_guess(Side side, const Vec3& x) const {
  const double v = std::clamp(x.z(), 0.0, span_);
  return Vec2(initial_u(side, to_section(x, v)), v);
}

}  // namespace semimesh::mock_cad::detail
