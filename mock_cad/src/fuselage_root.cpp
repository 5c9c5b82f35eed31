#include "fuselage_root.hpp"

#include <cmath>

namespace semimesh::mock_cad::detail {
namespace {

// Newton converges quadratically from the closed form at the section's point at z = 0 (exact when
// the section does not move with height: untapered, unswept, no dihedral); it stops when the step
// is at the round-off of z.
constexpr int kRootIterations = 30;
constexpr double kRootStep = 1e-15;  // relative to |z|

}  // namespace

FuselageRoot::FuselageRoot(std::shared_ptr<const NacaWing> wing, double radius, double slope)
    : wing_(std::move(wing)),
      radius_(radius),
      slope_(slope),
      base_lower_(wing_->section().point(Side::Lower, 1.0)),
      base_upper_(wing_->section().point(Side::Upper, 1.0)) {}

// F(z) = y^2 + z (z + 2R) - k x (2R + k x) = 0 for z near the crest, at the section point q.
double FuselageRoot::solve(const Vec2& q) const {
  const NacaWing& w = *wing_;
  const double R = radius_, k = slope_;
  // Start: the section at z = 0 held fixed, z = sqrt(r^2 - y^2) - R in its cancellation-free form.
  const double x0 = w.root_chord() * q.x(), y0 = w.root_chord() * q.y(), r0 = R + k * x0;
  double z = (k * x0 * (2.0 * R + k * x0) - y0 * y0) / (std::sqrt(r0 * r0 - y0 * y0) + R);
  for (int it = 0; it < kRootIterations; ++it) {
    const double c = w.chord_at(z);
    const double x = w.leading_edge_x(z) + c * q.x(), y = w.leading_edge_y(z) + c * q.y();
    const double x_z = w.tan_sweep() + w.chord_slope() * q.x(), y_z = w.tan_dihedral() + w.chord_slope() * q.y();
    const double f = y * y + z * (z + 2.0 * R) - k * x * (2.0 * R + k * x);
    const double f_z = 2.0 * (y * y_z + z + R - k * (R + k * x) * x_z);
    const double step = f / f_z;
    z -= step;
    if (!(std::abs(step) > kRootStep * std::abs(z))) break;
  }
  return z;
}

ScalarPoint FuselageRoot::height(const ProfilePoint& q) const {
  const NacaWing& w = *wing_;
  const double R = radius_, k = slope_, z = solve(q.p);
  // Partial derivatives of F(s, z); x and y are linear in z (x_zz = y_zz = 0).
  const double c = w.chord_at(z), dc = w.chord_slope();
  const double x = w.leading_edge_x(z) + c * q.p.x(), y = w.leading_edge_y(z) + c * q.p.y(), r = R + k * x;
  const double x_s = c * q.d1.x(), x_z = w.tan_sweep() + dc * q.p.x(), x_ss = c * q.d2.x(), x_sz = dc * q.d1.x();
  const double y_s = c * q.d1.y(), y_z = w.tan_dihedral() + dc * q.p.y(), y_ss = c * q.d2.y(), y_sz = dc * q.d1.y();
  const double f_z = 2.0 * (y * y_z + z + R - k * r * x_z);
  const double f_s = 2.0 * (y * y_s - k * r * x_s);
  const double f_ss = 2.0 * (y_s * y_s + y * y_ss - k * k * x_s * x_s - k * r * x_ss);
  const double f_sz = 2.0 * (y_z * y_s + y * y_sz - k * k * x_s * x_z - k * r * x_sz);
  const double f_zz = 2.0 * (y_z * y_z + 1.0 - k * k * x_z * x_z);
  ScalarPoint out;
  out.f = z;
  out.d1 = -f_s / f_z;
  out.d2 = -(f_ss + 2.0 * f_sz * out.d1 + f_zz * out.d1 * out.d1) / f_z;
  return out;
}

ProfilePoint FuselageRoot::section_point(RootPart part, double s) const {
  if (part == RootPart::Base)
    return ProfilePoint{base_lower_ + s * (base_upper_ - base_lower_), base_upper_ - base_lower_, Vec2::Zero()};
  return wing_->section().eval(part == RootPart::Upper ? Side::Upper : Side::Lower, s);
}

ScalarPoint FuselageRoot::root_height(RootPart part, double s) const { return height(section_point(part, s)); }

SurfaceDerivatives FuselageRoot::unlifted(RootPart part, double s, double z) const {
  if (part == RootPart::Base) return wing_->eval_base(s, z);
  return wing_->eval(part == RootPart::Upper ? Side::Upper : Side::Lower, s, z);
}

SurfaceDerivatives FuselageRoot::eval(RootPart part, double s, double v) const {
  const ScalarPoint zr = root_height(part, s);
  const double span = wing_->span(), w = 1.0 - v / span;
  const SurfaceDerivatives S = unlifted(part, s, height_at(zr.f, v));
  // Chain rule through z(s, v) = v + z_r(s) w: z_s = z_r' w, z_v = 1 - z_r / span,
  // z_ss = z_r'' w, z_sv = -z_r' / span, z_vv = 0.
  const double zs = zr.d1 * w, zv = 1.0 - zr.f / span, zss = zr.d2 * w, zsv = -zr.d1 / span;
  SurfaceDerivatives d;
  d.p = S.p;
  d.du = S.du + zs * S.dv;
  d.dv = zv * S.dv;
  d.duu = S.duu + 2.0 * zs * S.duv + zs * zs * S.dvv + zss * S.dv;
  d.duv = zv * (S.duv + zs * S.dvv) + zsv * S.dv;
  d.dvv = zv * zv * S.dvv;
  return d;
}

Vec3 FuselageRoot::point(RootPart part, double s, double v) const {
  if (part == RootPart::Base) return eval(part, s, v).p;
  const Side side = part == RootPart::Upper ? Side::Upper : Side::Lower;
  return wing_->point(side, s, height_at(solve(wing_->section().point(side, s)), v));
}

}  // namespace semimesh::mock_cad::detail
