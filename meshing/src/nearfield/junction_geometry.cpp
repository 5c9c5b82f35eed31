#include "semimesh/nearfield/junction_geometry.hpp"

#include "semimesh/nearfield/error.hpp"

#include "labels.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace semimesh::nearfield {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Dihedral angle at a point of a curve between a face (fluid normal n_face, the direction `into`
// leading from the curve into the face) and the wall (fluid normal n_wall), seen from the fluid.
double dihedral_deg(const Vec3& n_face, const Vec3& into, const Vec3& n_wall) {
  const double opening = std::acos(std::clamp(-n_wall.dot(n_face), -1.0, 1.0)) * 180.0 / kPi;
  return into.dot(n_wall) >= 0.0 ? opening : 360.0 - opening;
}

// The share of a limit thickness the message suggests: at the limit itself the halo stands
// straight over the root and the skins cross there (a sharp tapered NACA 0006 root: 90 % of the
// wall layer's limit and 110 % of the shell's ran, 99.8 % and 103 % did not).
constexpr double kMargin = 0.9;

// `value` rounded to 4 significant digits, down or up: a suggested bound that is safe as printed.
double rounded(double value, bool up) {
  if (!(value > 0.0)) return value;
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 3);
  return (up ? std::ceil(value / unit) : std::floor(value / unit)) * unit;
}

}  // namespace

std::optional<ThicknessesThatFit> thicknesses_that_fit(const cad::Model& model, const std::vector<int>& body_surfaces,
                                                       const Vec3& root, const Vec3& e, const Vec3& n_wall,
                                                       double wing_offset, double wall_offset) {
  const auto distance_at = [&](double height) {
    return nearest_on_surfaces(model, body_surfaces, root + height * n_wall).distance;
  };
  const Vec3 top_point = root + wall_offset * n_wall;
  const NearestPoint top_foot = nearest_on_surfaces(model, body_surfaces, top_point);
  const double top = top_foot.distance;
  // A lean away: the point is too far from the body on the fluid's side (away from it along e);
  // on the other side it lies over a body leaning towards the wall, where medial_halo finds its point.
  if (top_foot.surface < 0 || !(top > wing_offset) || !((top_point - top_foot.point).dot(e) > 0.0)) return std::nullopt;
  // From the root (distance 0) up to wall_offset the distance passes wing_offset: bisection.
  double lo = 0.0, hi = wall_offset;
  for (int i = 0; i < 60 && hi - lo > 1e-12 * wall_offset; ++i) {
    const double mid = 0.5 * (lo + hi);
    (distance_at(mid) > wing_offset ? hi : lo) = mid;
  }
  return ThicknessesThatFit{rounded(lo, false), rounded(top, true)};
}

std::vector<WallCurve> wall_curves(const cad::Model& model, const std::vector<int>& body_surfaces, int wall,
                                   int samples) {
  std::vector<WallCurve> found;
  const cad::Surface& wall_face = model.surface(wall);
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto& uses = model.surfaces_of_curve(c);
    const bool on_wall =
        std::any_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& u) { return u.surface == wall; });
    if (!on_wall) continue;
    for (const cad::SurfaceUse& use : uses) {
      if (!std::count(body_surfaces.begin(), body_surfaces.end(), use.surface)) continue;
      const cad::Curve& curve = model.curve(c);
      const cad::Surface& face = model.surface(use.surface);
      WallCurve w{c, use.surface, 360.0, 0.0, Vec3::Zero(), Vec3::Zero()};
      const auto bounds = curve.bounds();
      for (int k = 0; k < samples; ++k) {
        // Ends included: a swept wing leans most at its leading-edge vertex.
        const double t = bounds.lo + static_cast<double>(k) / (samples - 1) * bounds.length();
        const cad::CurveDerivatives d = curve.derivatives(t);
        const Vec3 n_face = face.normal(face.project(d.p).uv);
        const Vec3 n_wall = wall_face.normal(wall_face.project(d.p).uv);
        // The face lies on the left of its loop's walking direction seen from the fluid.
        const Vec3 walk = (use.forward ? 1.0 : -1.0) * d.d1.normalized();
        const double angle = dihedral_deg(n_face, n_face.cross(walk), n_wall);
        if (angle < w.min_angle_deg) w.min_angle_deg = angle, w.min_at = d.p;
        if (angle > w.max_angle_deg) w.max_angle_deg = angle, w.max_at = d.p;
      }
      found.push_back(w);
    }
  }
  return found;
}

std::vector<WallCurve> concave_wall_curves(const cad::Model& model, const std::vector<int>& body_surfaces, int wall,
                                           double concave_below_deg) {
  std::vector<WallCurve> concave;
  for (const WallCurve& w : wall_curves(model, body_surfaces, wall))
    if (w.max_angle_deg < concave_below_deg) concave.push_back(w);
  return concave;
}

NearestPoint nearest_on_surfaces(const cad::Model& model, const std::vector<int>& surfaces, const Vec3& x) {
  NearestPoint best;
  for (int s : surfaces) {
    const cad::SurfaceProjection p = model.surface(s).project(x);
    if (p.inside && p.distance < best.distance) best = {p.distance, p.point, s};
  }
  return best;
}

Vec3 medial_halo(const cad::Model& model, const std::vector<int>& body_surfaces, const Vec3& root, const Vec3& e,
                 const Vec3& n_wall, double wing_offset, double wall_offset) {
  const Vec3 base = root + wall_offset * n_wall;
  const double tolerance = 1e-13 * std::max(1.0, wing_offset);
  double a = wing_offset;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const Vec3 h = base + a * e;
    const NearestPoint foot = nearest_on_surfaces(model, body_surfaces, h);
    if (foot.surface < 0) break;
    const double residual = foot.distance - wing_offset;
    // The projections' own accuracy bounds what the last iterations can gain.
    if (std::abs(residual) < (iteration < 40 ? tolerance : 1e3 * tolerance)) return h;
    // d(distance)/da = (unit gradient of the distance) . e; damped when the gradient turns away.
    const double slope = (h - foot.point).normalized().dot(e);
    if (!(slope > 0.05)) break;
    a = std::clamp(a - residual / slope, 0.5 * a, 2.0 * a);
  }
  const std::string where = "near field: no medial halo point at " + number_label(wing_offset) + " from the body and " +
                            number_label(wall_offset) + " from the wall above the root point " + point_label(root);
  if (const auto fit = thicknesses_that_fit(model, body_surfaces, root, e, n_wall, wing_offset, wall_offset))
    throw NearFieldError(where + ": the body leans away from the wall's normal there, so the point " +
                         number_label(wall_offset) + " above the root is already " + number_label(fit->shell_at_least) +
                         " from the body; use a wall layer thickness below " + number_label(fit->wall_below) +
                         " (wall_layer.thickness; e.g. " + number_label(rounded(kMargin * fit->wall_below, false)) +
                         ") or a shell thickness of at least " + number_label(fit->shell_at_least) +
                         " (nearfield.thickness; e.g. " + number_label(rounded(fit->shell_at_least / kMargin, true)) +
                         "): at the limit the halo stands straight over the root and the layer folds there");
  throw NearFieldError(where + "; the wing and the wall meet at too sharp or too open an angle there");
}

}  // namespace semimesh::nearfield
