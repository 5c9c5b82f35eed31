#include "naca_section.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::mock_cad::detail {
namespace {

// Thickness polynomial y_t = 5 t (a0 sqrt(x) + a1 x + a2 x^2 + a3 x^3 + a4 x^4) (NACA Report 460);
// a4 = -0.1015 leaves the classic 0.21% t squared-off trailing edge, -0.1036 closes it.
constexpr double kA1 = -0.1260;
constexpr double kA2 = -0.3516;
constexpr double kA3 = 0.2843;
constexpr double kA4Blunt = -0.1015;
constexpr double kA4Sharp = -0.1036;

// Sampling used once at construction to split each side into arcs monotone in X.
constexpr int kMonotonySamples = 400;
constexpr int kExtentSamples = 2000;
// Bounds the error of the sampled extents (Y'' h^2 / 8 with h = 1/kExtentSamples, in chords).
constexpr double kExtentMargin = 1e-6;

}  // namespace

NacaSection::NacaSection(const NacaDigits& digits, bool sharp_te)
    : digits_(digits), sharp_te_(sharp_te), a4_(sharp_te ? kA4Sharp : kA4Blunt) {
  if (digits.max_camber > 0.0) {
    const double p = digits.camber_position;
    crease_u_ = std::sqrt(p);
    while (crease_u_ * crease_u_ < p) crease_u_ = std::nextafter(crease_u_, 2.0);
    while (std::nextafter(crease_u_, 0.0) * std::nextafter(crease_u_, 0.0) >= p) crease_u_ = std::nextafter(crease_u_, 0.0);
  }
  for (Side side : {Side::Upper, Side::Lower}) {
    // Roots of dX/du split the side into monotone arcs (a cambered upper side first runs
    // forward of the leading edge point, then aft).
    std::vector<double> cuts{0.0};
    double u_prev = 0.0, d_prev = eval(side, 0.0).d1.x();
    for (int i = 1; i <= kMonotonySamples; ++i) {
      double u = static_cast<double>(i) / kMonotonySamples, d = eval(side, u).d1.x();
      if (d_prev * d < 0.0) {
        double lo = u_prev, hi = u;
        for (int it = 0; it < 60; ++it) {
          double mid = 0.5 * (lo + hi);
          if ((eval(side, mid).d1.x() < 0.0) == (d_prev < 0.0)) lo = mid; else hi = mid;
        }
        cuts.push_back(0.5 * (lo + hi));
      }
      u_prev = u;
      d_prev = d;
    }
    cuts.push_back(1.0);
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
      double x0 = point(side, cuts[k]).x(), x1 = point(side, cuts[k + 1]).x();
      pieces_.push_back(Piece{side, cuts[k], cuts[k + 1], std::min(x0, x1), std::max(x0, x1), x1 > x0});
    }
  }

  extent_lo_ = Vec2::Constant(1e300);
  extent_hi_ = Vec2::Constant(-1e300);
  for (Side side : {Side::Upper, Side::Lower})
    for (int i = 0; i <= kExtentSamples; ++i) {
      Vec2 p = point(side, static_cast<double>(i) / kExtentSamples);
      extent_lo_ = extent_lo_.cwiseMin(p);
      extent_hi_ = extent_hi_.cwiseMax(p);
    }
  for (const Piece& piece : pieces_) {
    extent_lo_.x() = std::min(extent_lo_.x(), piece.x_lo);
    extent_hi_.x() = std::max(extent_hi_.x(), piece.x_hi);
  }
}

NacaSection::Camber NacaSection::camber(double x) const {
  const double m = digits_.max_camber, p = digits_.camber_position;
  if (m == 0.0) return {0.0, 0.0, 0.0};
  // Two parabolic arcs meeting at the maximum camber x = p (Abbott & von Doenhoff eq. 6.4).
  if (x < p) {
    double k = m / (p * p);
    return {k * (2.0 * p * x - x * x), 2.0 * k * (p - x), -2.0 * k};
  }
  double k = m / ((1.0 - p) * (1.0 - p));
  return {k * (1.0 - 2.0 * p + 2.0 * p * x - x * x), 2.0 * k * (p - x), -2.0 * k};
}

double NacaSection::half_thickness(double x) const {
  const double u = std::sqrt(x);
  const double x2 = x * x;
  return 5.0 * digits_.thickness * (kA0 * u + kA1 * x + kA2 * x2 + kA3 * x2 * x + a4_ * x2 * x2);
}

ScalarPoint NacaSection::half_thickness_in_u(double u) const {
  // Thickness as a polynomial in u (x = u^2 turns sqrt(x) into u).
  const double u2 = u * u, u3 = u2 * u, u4 = u2 * u2, u5 = u4 * u, u6 = u4 * u2, u7 = u6 * u, u8 = u4 * u4;
  const double tt = 5.0 * digits_.thickness;
  return {tt * (kA0 * u + kA1 * u2 + kA2 * u4 + kA3 * u6 + a4_ * u8),
          tt * (kA0 + 2.0 * kA1 * u + 4.0 * kA2 * u3 + 6.0 * kA3 * u5 + 8.0 * a4_ * u7),
          tt * (2.0 * kA1 + 12.0 * kA2 * u2 + 30.0 * kA3 * u4 + 56.0 * a4_ * u6)};
}

ProfilePoint NacaSection::eval(Side side, double u) const {
  const double sg = sign_of(side);
  const double u2 = u * u;
  const double x = u2;

  const ScalarPoint thickness = half_thickness_in_u(u);
  const double yt = thickness.f, yt_u = thickness.d1, yt_uu = thickness.d2;

  // sin and cos of the camber-line angle theta = atan(s) and their x-derivatives
  // (s'' = 0 on each parabolic arc): with c = 1/sqrt(1+s^2), sin = s c, (sin)' = s' c^3,
  // (sin)'' = -3 s s'^2 c^5, (cos)' = -s s' c^3, (cos)'' = s'^2 c^3 (3 s^2 c^2 - 1).
  const Camber cm = camber(x);
  const double s = cm.slope, k = cm.curvature;
  const double cs = 1.0 / std::sqrt(1.0 + s * s), cs2 = cs * cs, cs3 = cs2 * cs, cs5 = cs3 * cs2;
  const double sn = s * cs;
  const double sn_x = k * cs3, sn_xx = -3.0 * s * k * k * cs5;
  const double cs_x = -s * k * cs3, cs_xx = k * k * cs3 * (3.0 * s * s * cs2 - 1.0);

  // Chain rule through x = u^2: f_u = 2u f_x, f_uu = 4u^2 f_xx + 2 f_x.
  const double yc_u = 2.0 * u * s, yc_uu = 4.0 * u2 * k + 2.0 * s;
  const double sn_u = 2.0 * u * sn_x, sn_uu = 4.0 * u2 * sn_xx + 2.0 * sn_x;
  const double cs_u = 2.0 * u * cs_x, cs_uu = 4.0 * u2 * cs_xx + 2.0 * cs_x;

  ProfilePoint out;
  out.p = Vec2(x - sg * yt * sn, cm.y + sg * yt * cs);
  out.d1 = Vec2(2.0 * u - sg * (yt_u * sn + yt * sn_u), yc_u + sg * (yt_u * cs + yt * cs_u));
  out.d2 = Vec2(2.0 - sg * (yt_uu * sn + 2.0 * yt_u * sn_u + yt * sn_uu),
                yc_uu + sg * (yt_uu * cs + 2.0 * yt_u * cs_u + yt * cs_uu));
  return out;
}

Vec2 NacaSection::point(Side side, double u) const {
  const double sg = sign_of(side);
  const double u2 = u * u, u4 = u2 * u2;
  const double yt = 5.0 * digits_.thickness * (kA0 * u + kA1 * u2 + kA2 * u4 + kA3 * u4 * u2 + a4_ * u4 * u4);
  const Camber cm = camber(u2);
  const double cs = 1.0 / std::sqrt(1.0 + cm.slope * cm.slope);
  return Vec2(u2 - sg * yt * cm.slope * cs, cm.y + sg * yt * cs);
}

double NacaSection::solve_for_x(const Piece& piece, double x) const {
  // Safeguarded Newton on X(u) = x inside the bracket [u_lo, u_hi] where X is monotone.
  double lo = piece.u_lo, hi = piece.u_hi;
  double u = std::clamp(std::sqrt(std::max(x, 0.0)), lo, hi);
  for (int it = 0; it < 100; ++it) {
    ProfilePoint e = eval(piece.side, u);
    double f = e.p.x() - x;
    if (f == 0.0) return u;
    if ((f > 0.0) == piece.increasing) hi = u; else lo = u;
    double next = e.d1.x() != 0.0 ? u - f / e.d1.x() : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - u) <= 1e-16) return next;
    u = next;
  }
  return u;
}

double NacaSection::foot_distance(const Piece& piece, double u, const Vec2& q) const {
  // A few Newton steps on the foot-point condition X'(u).(X(u) - q) = 0 from the vertical foot,
  // keeping the closest point met: enough to decide "within tol of the outline".
  double best = (point(piece.side, u) - q).norm();
  for (int it = 0; it < 8; ++it) {
    ProfilePoint e = eval(piece.side, u);
    Vec2 r = e.p - q;
    double g = e.d1.dot(r), h = e.d1.squaredNorm() + e.d2.dot(r);
    if (h <= 0.0) h = e.d1.squaredNorm();
    if (h == 0.0) break;
    double next = std::clamp(u - g / h, piece.u_lo, piece.u_hi);
    if (next == u) break;
    u = next;
    best = std::min(best, (point(piece.side, u) - q).norm());
  }
  return best;
}

OutlineSide NacaSection::classify(const Vec2& q, double tol) const {
  // Even-odd rule along the ray from q towards +Y. Each arc covers a half-open X range
  // [x_lo, x_hi) so that a vertex shared by two arcs is counted once where the outline passes
  // through it and twice (or not at all) where it only touches the ray.
  if ((q.array() < extent_lo_.array() - kExtentMargin - tol).any() || (q.array() > extent_hi_.array() + kExtentMargin + tol).any())
    return OutlineSide::Outside;
  int crossings = 0;
  bool on_boundary = false;
  for (const Piece& piece : pieces_) {
    if (q.x() < piece.x_lo - tol || q.x() > piece.x_hi + tol) continue;
    double u = solve_for_x(piece, std::clamp(q.x(), piece.x_lo, piece.x_hi));
    if (q.x() >= piece.x_lo && q.x() < piece.x_hi && point(piece.side, u).y() > q.y()) ++crossings;
    if (!on_boundary) on_boundary = foot_distance(piece, u, q) <= tol;
  }
  if (!sharp_te_) {  // the straight trailing-edge base from the upper to the lower side
    const Vec2 a = point(Side::Upper, 1.0), b = point(Side::Lower, 1.0), ab = b - a;
    const double lo = std::min(a.x(), b.x()), hi = std::max(a.x(), b.x());
    if (q.x() >= lo && q.x() < hi && a.y() + ab.y() * (q.x() - a.x()) / ab.x() > q.y()) ++crossings;
    const double s = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    if ((a + s * ab - q).norm() <= tol) on_boundary = true;
  }
  if (on_boundary) return OutlineSide::OnBoundary;
  return crossings % 2 == 1 ? OutlineSide::Inside : OutlineSide::Outside;
}

}  // namespace semimesh::mock_cad::detail
