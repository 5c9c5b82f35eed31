#include "cylinder_root.hpp"

#include <cmath>

namespace semimesh::mock_cad::detail {
namespace {

// Newton converges quadratically from the untapered closed form (exact when untapered); it stops
// when the step is at the round-off of z, so a handful of iterations.
constexpr int kRootIterations = 30;
constexpr double kRootStep = 1e-15;  // relative to |z|

// y(z) = y_le(z) + c(z) Y: the ordinate at height z of the surface point whose section ordinate is Y.
double ordinate_at(const NacaWing& wing, double z, double Y) { return wing.tan_dihedral() * z + wing.chord_at(z) * Y; }

// y(z)^2 + z (z + 2R) = 0 for z near 0, from the closed form with the chord at z = 0.
double solve_root_z(const NacaWing& wing, double radius, double Y) {
  const double y0 = wing.root_chord() * Y;
  double z = -y0 * y0 / (radius + std::sqrt(radius * radius - y0 * y0));
  for (int it = 0; it < kRootIterations; ++it) {
    const double y = ordinate_at(wing, z, Y);
    const double f = y * y + z * (z + 2.0 * radius);
    const double fz = 2.0 * (y * (wing.tan_dihedral() + wing.chord_slope() * Y) + z + radius);
    const double step = f / fz;
    z -= step;
    if (!(std::abs(step) > kRootStep * std::abs(z))) break;
  }
  return z;
}

}  // namespace

CylinderRoot::CylinderRoot(std::shared_ptr<const NacaWing> wing, double radius)
    : wing_(std::move(wing)),
      radius_(radius),
      base_lower_(wing_->section().point(Side::Lower, 1.0).y()),
      base_upper_(wing_->section().point(Side::Upper, 1.0).y()) {}

ScalarPoint CylinderRoot::height(const ScalarPoint& Y) const {
  const double z = solve_root_z(*wing_, radius_, Y.f);
  // Partial derivatives of F(s, z) = y(s, z)^2 + z (z + 2R), y = y_le(z) + c(z) Y(s), linear in z.
  const double c = wing_->chord_at(z), y = ordinate_at(*wing_, z, Y.f);
  const double y_s = c * Y.d1, y_z = wing_->tan_dihedral() + wing_->chord_slope() * Y.f;
  const double y_ss = c * Y.d2, y_sz = wing_->chord_slope() * Y.d1;
  const double f_z = 2.0 * (y * y_z + z + radius_);
  const double f_s = 2.0 * y * y_s;
  const double f_ss = 2.0 * (y_s * y_s + y * y_ss);
  const double f_sz = 2.0 * (y_z * y_s + y * y_sz);
  const double f_zz = 2.0 * (y_z * y_z + 1.0);
  ScalarPoint out;
  out.f = z;
  out.d1 = -f_s / f_z;
  out.d2 = -(f_ss + 2.0 * f_sz * out.d1 + f_zz * out.d1 * out.d1) / f_z;
  return out;
}

ScalarPoint CylinderRoot::ordinate(RootPart part, double s) const {
  if (part == RootPart::Base) return ScalarPoint{base_lower_ + s * (base_upper_ - base_lower_), base_upper_ - base_lower_, 0.0};
  const ProfilePoint e = wing_->section().eval(part == RootPart::Upper ? Side::Upper : Side::Lower, s);
  return ScalarPoint{e.p.y(), e.d1.y(), e.d2.y()};
}

ScalarPoint CylinderRoot::root_height(RootPart part, double s) const { return height(ordinate(part, s)); }

SurfaceDerivatives CylinderRoot::unlifted(RootPart part, double s, double z) const {
  if (part == RootPart::Base) return wing_->eval_base(s, z);
  return wing_->eval(part == RootPart::Upper ? Side::Upper : Side::Lower, s, z);
}

SurfaceDerivatives CylinderRoot::eval(RootPart part, double s, double v) const {
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

Vec3 CylinderRoot::point(RootPart part, double s, double v) const {
  if (part == RootPart::Base) return eval(part, s, v).p;
  const Side side = part == RootPart::Upper ? Side::Upper : Side::Lower;
  const double z = height_at(solve_root_z(*wing_, radius_, wing_->section().point(side, s).y()), v);
  return wing_->point(side, s, z);
}

}  // namespace semimesh::mock_cad::detail
