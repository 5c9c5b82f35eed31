#include "semimesh/cad/surface.hpp"

#include "semimesh/cad/error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <functional>
#include <limits>

namespace semimesh::cad {

std::optional<double> Surface::period(int direction) const {
  if (direction != 0 && direction != 1)
    throw CadError(CadError::Kind::BadParameter, "surface " + std::to_string(id_) + " ('" + name_ +
                                                     "'): period of parameter direction " + std::to_string(direction) +
                                                     " asked for; directions are 0 (u) and 1 (v)");
  return std::nullopt;
}

Vec3 Surface::normal(const Vec2& uv) const { return normal(derivatives(uv)); }

Vec3 Surface::normal(const SurfaceDerivatives& d) const {
  Vec3 n = d.du.cross(d.dv);
  double len = n.norm();
  if (len == 0.0) return Vec3::Zero();  // degenerate point (pole): no normal
  return (orientation_ / len) * n;
}

PrincipalCurvatures Surface::curvatures(const Vec2& uv) const {
  SurfaceDerivatives d = derivatives(uv);
  Vec3 n = d.du.cross(d.dv);
  PrincipalCurvatures out;
  if (n.norm() == 0.0) return out;
  n = (orientation_ / n.norm()) * n;
  // First (I) and second (II) fundamental forms; shape operator W = I^-1 II. Against the fluid
  // normal a convex solid bends away from n, so II is negative there: curvatures are -eig(W).
  Eigen::Matrix2d I, II;
  I << d.du.dot(d.du), d.du.dot(d.dv), d.du.dot(d.dv), d.dv.dot(d.dv);
  II << d.duu.dot(n), d.duv.dot(n), d.duv.dot(n), d.dvv.dot(n);
  // Symmetric form: with I = L L^T, eig(I^-1 II) = eig(L^-1 II L^-T).
  Eigen::LLT<Eigen::Matrix2d> llt(I);
  Eigen::Matrix2d L = llt.matrixL();
  Eigen::Matrix2d Linv = L.inverse();
  Eigen::Matrix2d S = -(Linv * II * Linv.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(S);
  out.k_min = eig.eigenvalues()(0);
  out.k_max = eig.eigenvalues()(1);
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector2d ab = Linv.transpose() * eig.eigenvectors().col(k);  // back to (du, dv) coordinates
    Vec3 dir = (ab(0) * d.du + ab(1) * d.dv).normalized();
    (k == 0 ? out.dir_min : out.dir_max) = dir;
  }
  return out;
}

namespace {

/// Newton on the gradient of |S - x|^2 / 2 from uv, Gauss-Newton when the Hessian is indefinite,
/// with a halving line search so the distance never grows; uv stays in the parameter box.
/// A parameter whose box spans a whole period wraps round instead of stopping at the box (a seam
/// is no boundary); the result is moved back into the box.
SurfaceProjection newton_projection(const Surface& s, const Vec3& x, Vec2 uv) {
  const auto box = s.bounds();
  std::array<std::optional<double>, 2> wraps;
  for (int d = 0; d < 2; ++d)
    if (const auto period = s.period(d); period && box[d].length() >= *period * (1.0 - 1e-9)) wraps[d] = period;
  auto clamp = [&](Vec2 p) {
    for (int d = 0; d < 2; ++d)
      if (!wraps[d]) p[d] = box[d].clamp(p[d]);
    return p;
  };
  uv = clamp(uv);
  bool converged = false;
  const double scale = std::max({1.0, box[0].length(), box[1].length()});
  for (int it = 0; it < 60; ++it) {
    SurfaceDerivatives d = s.derivatives(uv);
    Vec3 r = d.p - x;
    Eigen::Vector2d g(d.du.dot(r), d.dv.dot(r));
    Eigen::Matrix2d H;
    H << d.du.dot(d.du) + d.duu.dot(r), d.du.dot(d.dv) + d.duv.dot(r), d.du.dot(d.dv) + d.duv.dot(r),
        d.dv.dot(d.dv) + d.dvv.dot(r);
    Eigen::LLT<Eigen::Matrix2d> llt(H);
    Eigen::Vector2d step;
    if (llt.info() == Eigen::Success) {
      step = -llt.solve(g);
    } else {
      Eigen::Matrix2d JTJ;
      JTJ << d.du.dot(d.du), d.du.dot(d.dv), d.du.dot(d.dv), d.dv.dot(d.dv);
      step = -JTJ.completeOrthogonalDecomposition().solve(g);
    }
    double f0 = r.squaredNorm();
    Vec2 next = clamp(uv + step);
    for (int ls = 0; ls < 30 && (s.point(next) - x).squaredNorm() > f0; ++ls) next = clamp(uv + (step *= 0.5));
    double moved = (next - uv).norm();
    uv = next;
    if (moved <= 1e-14 * scale) { converged = true; break; }
  }
  for (int d = 0; d < 2; ++d)
    if (wraps[d]) uv[d] -= std::floor((uv[d] - box[d].lo) / *wraps[d]) * *wraps[d];
  SurfaceProjection out;
  out.uv = uv;
  out.point = s.point(uv);
  out.distance = (out.point - x).norm();
  out.converged = converged;
  return out;
}

/// The parameter direction along which the surface does not move at uv (a pole), or -1.
int degenerate_direction(const SurfaceDerivatives& d) {
  if (d.du.norm() <= 1e-9 * d.dv.norm()) return 0;
  if (d.dv.norm() <= 1e-9 * d.du.norm()) return 1;
  return -1;
}

}  // namespace

SurfaceProjection leave_pole(const Surface& s, SurfaceProjection found,
                             const std::function<SurfaceProjection(const Vec2&)>& solve) {
  const SurfaceDerivatives d = s.derivatives(found.uv);
  const int angle = degenerate_direction(d);
  if (angle < 0 || !(found.distance > 0.0)) return found;
  const auto box = s.bounds();
  const int radial = 1 - angle;
  const Interval along = box[radial];
  const double speed = (radial == 0 ? d.du : d.dv).norm();
  const double offset = std::min(0.5 * along.length(), found.distance / std::max(speed, 1e-300));
  const double inward = found.uv[radial] - along.lo <= along.hi - found.uv[radial] ? offset : -offset;
  constexpr int kAngles = 8;
  for (int k = 0; k < kAngles; ++k) {
    Vec2 start = found.uv;
    start[angle] = box[angle].lo + (k + 0.5) / kAngles * box[angle].length();
    start[radial] += inward;
    SurfaceProjection p = solve(start);
    if (p.distance < found.distance) found = p;
  }
  return found;
}

SurfaceProjection Surface::local_projection(const Vec3& x, const Vec2& guess) const {
  return leave_pole(*this, newton_projection(*this, x, guess),
                    [&](const Vec2& start) { return newton_projection(*this, x, start); });
}

SurfaceProjection Surface::project_near(const Vec3& x, const Vec2& guess) const {
  SurfaceProjection out = project(x, guess);
  out.inside = false;
  return out;
}

SurfaceProjection Surface::project(const Vec3& x, std::optional<Vec2> guess) const {
  const auto box = bounds();
  Vec2 uv(box[0].lo, box[1].lo);  // the sampling below always improves on it
  if (guess) {
    uv = *guess;
  } else {
    constexpr int kSamples = 24;
    double best = std::numeric_limits<double>::max();
    for (int i = 0; i <= kSamples; ++i)
      for (int j = 0; j <= kSamples; ++j) {
        Vec2 s(box[0].lo + box[0].length() * i / kSamples, box[1].lo + box[1].length() * j / kSamples);
        double d = (point(s) - x).squaredNorm();
        if (d < best) { best = d; uv = s; }
      }
  }
  SurfaceProjection out = local_projection(x, uv);
  out.inside = contains(out.uv);
  return out;
}

}  // namespace semimesh::cad
