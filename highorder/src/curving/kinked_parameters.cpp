#include "curving/kinked_parameters.hpp"

#include <algorithm>

namespace semimesh::ho::detail {
namespace {

constexpr int kSpacings = 256, kEndSpacingsLeftOut = 3;

// Whether speed(t) at t = k / kSpacings (k away from both ends) jumps between neighbours.
template <class Speed>
bool speed_jumps(const Speed& speed) {
  double previous = -1.0;
  for (int k = kEndSpacingsLeftOut; k <= kSpacings - kEndSpacingsLeftOut; ++k) {
    const double now = speed(static_cast<double>(k) / kSpacings);
    if (previous > 0.0 && now > 0.0 && std::max(now, previous) > kKinkRatio * std::min(now, previous)) return true;
    previous = now;
  }
  return false;
}

}  // namespace

bool has_kinked_parameters(const cad::Surface& surface) {
  constexpr int kLines = 9;
  const std::array<cad::Interval, 2> box = surface.bounds();
  for (int along = 0; along < 2; ++along)
    for (int line = 0; line < kLines; ++line) {
      cad::Vec2 uv;
      uv[1 - along] = box[1 - along].lo + (line + 0.5) / kLines * box[1 - along].length();
      const bool kinked = speed_jumps([&](double fraction) {
        uv[along] = box[along].lo + fraction * box[along].length();
        const cad::SurfaceDerivatives d = surface.derivatives(uv);
        return (along == 0 ? d.du : d.dv).norm();
      });
      if (kinked) return true;
    }
  return false;
}

bool has_kinked_parameters(const cad::Curve& curve) {
  if (curve.kind() == cad::CurveKind::Line || curve.is_degenerate()) return false;
  const cad::Interval range = curve.bounds();
  return speed_jumps([&](double fraction) { return curve.derivatives(range.lo + fraction * range.length()).d1.norm(); });
}

}  // namespace semimesh::ho::detail
