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

// The reach (CurvingParams::pole_reach = 3 sides), measured by bench/ho_mesh/bench_pole_reach on
// the NekMesh STEP wing's revolved tip at order 4 (sizes 4.7 and 2.35 mm near the pole, a 20 mm
// shell split into 6 layers): max geometric error and min scaled Jacobian of the prisms within 12
// sides of the pole, for reach 0..5, 8 and everywhere.
//  - Projection is the better chart only in the pole's fan: off it, its error is 7-60 times that of
//    the parameters (1 side out: 4.7e-4 against 6.3e-5 mm at 4.7 mm; 8-12 sides out: 5.4e-5 against
//    9.0e-7; on an analytic ellipsoid away from its pole 45-50 times at P = 4, both converging at
//    P + 1). So the reach is the smallest that gives the fan's faces and their sides one chart.
//  - Where a face was projected while one of its sides took the parameters (the reach's edge), the
//    prisms had 5-10 times the error of either side (reach 3: 2.7e-3 mm at 4.7 mm, 6.3e-4 at 2.35)
//    and the split layers' lowest scaled Jacobian (0.46); hence face_near_pole: 5.7e-4 and 1.5e-4 mm,
//    min scaled Jacobian of the layers 0.66.
//  - With that, reach 2 or less leaves the fan's outer faces on the parameters (error 1.1e-3 mm,
//    layers' min scaled Jacobian 0.03 at 4.7 mm); reach 3, 4, 5 give the same figures within 20%
//    (max error 4.7e-4..5.7e-4 and 1.5e-4 mm, min scaled Jacobian of the layers 0.66). In the
//    whole order-4 example the max geometric error fell from 1.7e-6 to 4.3e-7 chord (it was there).
//  - Not solved: a reach counted in element sides leaves the elements just beyond it spanning a
//    fixed angle at the pole in the polar parameters, so their error falls like h^2 whatever P
//    (test_curve_periodic.cpp, five rings round an ellipsoid's pole: rate 2.0; projecting every
//    face there: rate ~6). P + 1 near a pole needs a reach of a fixed length (e.g. the surface's
//    radius of curvature at the pole), beyond which an element's angle at the pole shrinks with h.
bool near_pole(const std::vector<cad::Vec3>& poles, const cad::Vec3& a, const cad::Vec3& b, double reach) {
  const double side = (b - a).norm();
  for (const cad::Vec3& pole : poles)
    if ((a - pole).norm() <= reach * side || (b - pole).norm() <= reach * side) return true;
  return false;
}

bool face_near_pole(const std::vector<cad::Vec3>& poles, const std::vector<cad::Vec3>& vertices, double reach) {
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!near_pole(poles, vertices[i], vertices[(i + 1) % vertices.size()], reach)) return false;
  return !vertices.empty();
}

void place_by_projection(const cad::Surface& surface, const cad::Vec3& x, Eigen::Ref<Eigen::MatrixXd> uv,
                         Eigen::Ref<Eigen::MatrixXd> pts, int row) {
  const cad::SurfaceProjection p = surface.project(x, into_box(surface, uv.row(row).transpose()));
  uv.row(row) = p.uv.transpose();
  pts.row(row) = p.point.transpose();
}

}  // namespace semimesh::ho::detail
