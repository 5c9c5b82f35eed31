#include "revolution_entities.hpp"
#include "constants.hpp"

#include "newton_projection.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::mock_cad::detail {

RevolutionBody::RevolutionBody(int id, std::string name, std::shared_ptr<const NacaSection> section, double chord,
                               double tol)
    : cad::Surface(id, std::move(name), -1), section_(std::move(section)), chord_(chord), tol_(tol) {}

std::array<cad::Interval, 2> RevolutionBody::bounds() const { return {cad::Interval{0.0, 1.0}, cad::Interval{0.0, kTwoPi}}; }

cad::SurfaceDerivatives RevolutionBody::derivatives(const Vec2& uv) const {
  const ProfilePoint e = section_->eval(Side::Upper, uv.x());
  const double c = chord_, cw = std::cos(uv.y()), sw = std::sin(uv.y());
  const double X = e.p.x(), Y = e.p.y(), X1 = e.d1.x(), Y1 = e.d1.y(), X2 = e.d2.x(), Y2 = e.d2.y();
  cad::SurfaceDerivatives d;
  d.p = c * cad::Vec3(X, Y * cw, Y * sw);
  d.du = c * cad::Vec3(X1, Y1 * cw, Y1 * sw);
  d.dv = c * cad::Vec3(0.0, -Y * sw, Y * cw);
  d.duu = c * cad::Vec3(X2, Y2 * cw, Y2 * sw);
  d.duv = c * cad::Vec3(0.0, -Y1 * sw, Y1 * cw);
  d.dvv = c * cad::Vec3(0.0, -Y * cw, -Y * sw);
  return d;
}

bool RevolutionBody::contains(const Vec2& uv) const {
  const auto box = bounds();
  return box[0].contains(uv.x(), tol_) && box[1].contains(uv.y(), tol_);
}

cad::SurfaceProjection RevolutionBody::project(const cad::Vec3& x, std::optional<Vec2> guess) const {
  Vec2 start;
  if (guess) {
    start = *guess;
  } else {
    double w = std::atan2(x.z(), x.y());
    if (w < 0.0) w += kTwoPi;
    start = Vec2(std::sqrt(std::clamp(x.x() / chord_, 0.0, 1.0)), w);
  }
  // w wraps round (the seam is no boundary): the solver may walk a period either way, the answer
  // comes back into [0, 2 pi).
  auto box = bounds();
  box[1] = {-kTwoPi, 2.0 * kTwoPi};
  const auto solve = [&](const Vec2& from) {
    cad::SurfaceProjection p = newton_project_surface([this](const Vec2& uv) { return derivatives(uv); },
                                                      [this](const Vec2& uv) { return derivatives(uv).p; }, x, from,
                                                      box, tol_, chord_, kNoCrease);
    p.uv.y() -= std::floor(p.uv.y() / kTwoPi) * kTwoPi;
    return p;
  };
  cad::SurfaceProjection out = cad::leave_pole(*this, solve(start), solve);
  out.inside = contains(out.uv);
  return out;
}

std::optional<double> RevolutionBody::period(int direction) const {
  cad::Surface::period(direction);  // checks the direction
  if (direction == 1) return kTwoPi;
  return std::nullopt;
}

MeridianCurve::MeridianCurve(int id, std::string name, std::shared_ptr<const NacaSection> section, double chord)
    : cad::Curve(id, std::move(name)), section_(std::move(section)), chord_(chord) {}

cad::CurveDerivatives MeridianCurve::derivatives(double t) const {
  const ProfilePoint e = section_->eval(Side::Upper, t);
  return {chord_ * cad::Vec3(e.p.x(), e.p.y(), 0.0), chord_ * cad::Vec3(e.d1.x(), e.d1.y(), 0.0),
          chord_ * cad::Vec3(e.d2.x(), e.d2.y(), 0.0)};
}

cad::CurveProjection PoleCurve::project(const cad::Vec3& x, std::optional<double> guess) const {
  const double t = bounds().clamp(guess.value_or(0.5 * (range_.lo + range_.hi)));
  return {t, at_, (x - at_).norm(), true};
}

}  // namespace semimesh::mock_cad::detail
