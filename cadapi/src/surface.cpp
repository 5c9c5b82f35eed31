#include "semimesh/cad/surface.hpp"

#include "semimesh/cad/error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace semimesh::cad {

std::optional<double> Surface::period(int direction) const {
  if (direction != 0 && direction != 1)
    throw CadError(CadError::Kind::BadParameter, "surface " + std::to_string(id_) + " ('" + name_ +
                                                     "'): period of parameter direction " + std::to_string(direction) +
                                                     " asked for; directions are 0 (u) and 1 (v)");
  return std::nullopt;
}

Vec3 Surface::normal(const Vec2& uv) const {
  SurfaceDerivatives d = derivatives(uv);
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

SurfaceProjection Surface::project(const Vec3& x, std::optional<Vec2> guess) const {
  const auto box = bounds();
  auto clamp = [&](Vec2 uv) { return Vec2(box[0].clamp(uv.x()), box[1].clamp(uv.y())); };
  Vec2 uv;
  if (guess) {
    uv = clamp(*guess);
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
  // Newton on the gradient of |S - x|^2 / 2, Gauss-Newton when the Hessian is indefinite,
  // with a halving line search so the distance never grows.
  bool converged = false;
  const double scale = std::max({1.0, box[0].length(), box[1].length()});
  for (int it = 0; it < 60; ++it) {
    SurfaceDerivatives d = derivatives(uv);
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
    for (int ls = 0; ls < 30 && (point(next) - x).squaredNorm() > f0; ++ls) next = clamp(uv + (step *= 0.5));
    double moved = (next - uv).norm();
    uv = next;
    if (moved <= 1e-14 * scale) { converged = true; break; }
  }
  SurfaceProjection out;
  out.uv = uv;
  out.point = point(uv);
  out.distance = (out.point - x).norm();
  out.converged = converged;
  out.inside = contains(uv);
  return out;
}

}  // namespace semimesh::cad
