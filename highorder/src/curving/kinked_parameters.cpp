#include "curving/kinked_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace semimesh::ho::detail {
namespace {

constexpr int kSpacings = 256, kEndSpacingsLeftOut = 3;

// The kinks of speed(t), t in [0, 1] (see kink_chart), each with the ratio of the speeds after
// and before it, mapped onto `range`.
template <class Speed>
KinkChart chart_of(const Speed& speed, cad::Interval range) {
  std::vector<double> at, ratios;
  double previous = -1.0;
  for (int k = kEndSpacingsLeftOut; k <= kSpacings - kEndSpacingsLeftOut; ++k) {
    const double now = speed(static_cast<double>(k) / kSpacings);
    if (previous > 0.0 && now > 0.0 && std::max(now, previous) > kKinkRatio * std::min(now, previous)) {
      double a = static_cast<double>(k - 1) / kSpacings, b = static_cast<double>(k) / kSpacings;
      double left = previous, right = now;
      for (int step = 0; step < 50; ++step) {
        const double m = 0.5 * (a + b), middle = speed(m);
        if (std::abs(std::log(middle / left)) < std::abs(std::log(middle / right)))
          a = m, left = middle;
        else
          b = m, right = middle;
      }
      at.push_back(range.lo + 0.5 * (a + b) * range.length());
      ratios.push_back(right / left);
    }
    previous = now;
  }
  return KinkChart(std::move(at), ratios);
}

}  // namespace

KinkChart::KinkChart(std::vector<double> kinks, const std::vector<double>& ratios) : kinks_(std::move(kinks)) {
  slopes_.push_back(1.0);
  for (std::size_t i = 0; i < kinks_.size(); ++i) {
    at_.push_back(i == 0 ? kinks_[0] : at_[i - 1] + slopes_[i] * (kinks_[i] - kinks_[i - 1]));
    slopes_.push_back(slopes_[i] * ratios[i]);
  }
}

double KinkChart::to_chart(double t) const {
  const std::size_t i = std::upper_bound(kinks_.begin(), kinks_.end(), t) - kinks_.begin();
  return i == 0 ? t : at_[i - 1] + slopes_[i] * (t - kinks_[i - 1]);
}

double KinkChart::from_chart(double s) const {
  const std::size_t i = std::upper_bound(at_.begin(), at_.end(), s) - at_.begin();
  return i == 0 ? s : kinks_[i - 1] + (s - at_[i - 1]) / slopes_[i];
}

KinkChart kink_chart(const cad::Surface& surface, int along) {
  const std::array<cad::Interval, 2> box = surface.bounds();
  cad::Vec2 uv;
  uv[1 - along] = box[1 - along].lo + 0.5 * box[1 - along].length();
  const auto speed = [&](double fraction) {
    uv[along] = box[along].lo + fraction * box[along].length();
    const cad::SurfaceDerivatives d = surface.derivatives(uv);
    return (along == 0 ? d.du : d.dv).norm();
  };
  return chart_of(speed, box[along]);
}

KinkChart kink_chart(const cad::Curve& curve) {
  if (curve.kind() == cad::CurveKind::Line || curve.is_degenerate()) return {};
  const cad::Interval range = curve.bounds();
  return chart_of([&](double fraction) { return curve.derivatives(range.lo + fraction * range.length()).d1.norm(); },
                  range);
}

}  // namespace semimesh::ho::detail
