#include "semimesh/surface/root_plane.hpp"

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace semimesh::surface {
namespace {

constexpr int kSamplesPerCurve = 16;
constexpr double kFlatness = 1e-6;  // of the model's size: how far a point may stray from the plane

double model_size(const cad::Model& model) { return (model.bbox().hi - model.bbox().lo).norm(); }

// Points spread along every curve, ends included.
std::vector<cad::Vec3> curve_samples(const cad::Model& model, const std::vector<int>& curves) {
  std::vector<cad::Vec3> points;
  for (int c : curves) {
    const cad::Interval t = model.curve(c).bounds();
    for (int k = 0; k <= kSamplesPerCurve; ++k) points.push_back(model.curve(c).point(t.lo + t.length() * k / kSamplesPerCurve));
  }
  return points;
}

// Every vertex lies on the side the normal points to, within `tolerance`.
bool body_on_one_side(const cad::Model& model, const cad::Vec3& point, const cad::Vec3& normal, double tolerance) {
  for (int v = 0; v < model.num_vertices(); ++v)
    if ((model.vertex(v).point - point).dot(normal) < -tolerance) return false;
  for (int c = 0; c < model.num_curves(); ++c)
    for (const cad::Vec3& p : curve_samples(model, {c}))
      if ((p - point).dot(normal) < -tolerance) return false;
  return true;
}

// An open root: the free curves (bounding one surface, not a seam nor a point), all in one plane.
std::optional<RootPlane> plane_of_free_loop(const cad::Model& model) {
  std::vector<int> free;
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto& uses = model.surfaces_of_curve(c);
    if (uses.size() == 1 && !model.curve(c).is_degenerate() && !model.is_seam(uses[0].surface, c)) free.push_back(c);
  }
  if (free.size() < 2) return std::nullopt;
  const std::vector<cad::Vec3> points = curve_samples(model, free);
  cad::Vec3 centre = cad::Vec3::Zero();
  for (const cad::Vec3& p : points) centre += p / static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const cad::Vec3& p : points) scatter += (p - centre) * (p - centre).transpose();
  cad::Vec3 normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
  const double tolerance = kFlatness * model_size(model);
  for (const cad::Vec3& p : points)
    if (std::abs((p - centre).dot(normal)) > tolerance) return std::nullopt;
  if (!body_on_one_side(model, centre, normal, tolerance)) normal = -normal;
  if (!body_on_one_side(model, centre, normal, tolerance)) return std::nullopt;  // the plane cuts the body
  return RootPlane{centre, normal,
                   fmt::format("the plane of the body's open root: its {} free curve(s) (curve {} ...) lie in one plane",
                               free.size(), free.front())};
}

// A closed body's planar caps, the largest (ties: nearer the origin).
std::optional<RootPlane> plane_of_cap(const cad::Model& model) {
  const double tolerance = kFlatness * model_size(model);
  struct Cap {
    int surface;
    double area;
    RootPlane plane;
  };
  std::vector<Cap> caps;
  for (int s = 0; s < model.num_surfaces(); ++s) {
    const cad::Surface& surface = model.surface(s);
    if (!surface.is_planar()) continue;
    const auto box = surface.bounds();
    const cad::Vec2 mid(box[0].lo + 0.5 * box[0].length(), box[1].lo + 0.5 * box[1].length());
    // Whichever side the body is on (a body-only file has no fluid side its normals could know).
    const cad::Vec3 point = surface.point(mid), n = surface.normal(mid);
    const bool above = body_on_one_side(model, point, n, tolerance);
    if (!above && !body_on_one_side(model, point, -n, tolerance)) continue;
    caps.push_back({s, surface.exact_area().value_or(0.0), {point, above ? n : cad::Vec3(-n), ""}});
  }
  if (caps.empty()) return std::nullopt;
  const auto before = [](const Cap& a, const Cap& b) {
    const double scale = std::max(a.area, b.area);
    if (std::abs(a.area - b.area) > 0.01 * scale) return a.area > b.area;
    return std::abs(a.plane.point.dot(a.plane.normal)) < std::abs(b.plane.point.dot(b.plane.normal));
  };
  const Cap best = *std::min_element(caps.begin(), caps.end(), before);
  RootPlane out = best.plane;
  out.why = fmt::format("the plane of surface {} ('{}'): of the body's {} planar cap(s) (faces with all of the body on "
                        "one side) the largest, or nearest the origin of equal ones",
                        best.surface, model.surface(best.surface).name(), caps.size());
  return out;
}

}  // namespace

std::optional<RootPlane> find_root_plane(const cad::Model& model) {
  if (!model.is_closed()) return plane_of_free_loop(model);
  return plane_of_cap(model);
}

}  // namespace semimesh::surface
