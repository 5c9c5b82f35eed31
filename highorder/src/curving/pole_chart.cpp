#include "curving/pole_chart.hpp"

#include "curving/cad_classification.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace semimesh::ho::detail {

namespace {

/// Whether the surface has a tangent plane at its pole `at`: the derivatives along the radial
/// parameter there, taken at three angles, lie in one plane (a rounded nose, a hemisphere). At a
/// cone's apex they lie on the cone: there the polar parameters (straight meridians) are the
/// better chart, and a closest-point projection is not smooth.
bool has_tangent_plane(const cad::Surface& surface, const cad::Vec3& at) {
  const cad::Vec2 uv = surface.project(at).uv;
  const cad::SurfaceDerivatives d = surface.derivatives(uv);
  const int angle = d.du.norm() < d.dv.norm() ? 0 : 1;
  const cad::Interval range = surface.bounds()[angle];
  std::array<cad::Vec3, 3> radial;
  for (int k = 0; k < 3; ++k) {
    cad::Vec2 at_angle = uv;
    at_angle[angle] = range.lo + (0.2 + 0.3 * k) * range.length();
    const cad::SurfaceDerivatives dk = surface.derivatives(at_angle);
    radial[k] = angle == 0 ? dk.dv : dk.du;
  }
  const double scale = radial[0].norm() * radial[1].norm() * radial[2].norm();
  return std::abs(radial[0].cross(radial[1]).dot(radial[2])) <= 1e-6 * scale;
}

}  // namespace

std::vector<cad::Vec3> surface_poles(const cad::Model& model, int surface) {
  std::vector<cad::Vec3> poles;
  for (const cad::Loop& loop : model.loops(surface))
    for (const cad::CurveUse& use : loop.uses) {
      const cad::Curve& curve = model.curve(use.curve);
      if (!curve.is_degenerate()) continue;
      const cad::Vec3 at = curve.point(curve.bounds().lo);
      if (has_tangent_plane(model.surface(surface), at)) poles.push_back(at);
    }
  return poles;
}

bool near_pole(const std::vector<cad::Vec3>& poles, const std::vector<cad::Vec3>& vertices) {
  if (poles.empty()) return false;
  double side = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    side = std::max(side, (vertices[(i + 1) % vertices.size()] - vertices[i]).norm());
  for (const cad::Vec3& pole : poles)
    for (const cad::Vec3& v : vertices)
      if ((v - pole).norm() <= kPoleReach * side) return true;
  return false;
}

void place_by_projection(const cad::Surface& surface, const cad::Vec3& x, Eigen::Ref<Eigen::MatrixXd> uv,
                         Eigen::Ref<Eigen::MatrixXd> pts, int row) {
  const cad::SurfaceProjection p = surface.project(x, into_box(surface, uv.row(row).transpose()));
  uv.row(row) = p.uv.transpose();
  pts.row(row) = p.point.transpose();
}

}  // namespace semimesh::ho::detail
