#include "semimesh/surface/root_plane.hpp"

#include "semimesh/surface/cad_roles.hpp"

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

// How far a point of a flat loop may stray from its plane: round-off of the model's size, or the
// model's own tolerance where faces were sewn across gaps wider than that.
double flatness_tolerance(const cad::Model& model) { return std::max(kFlatness * model_size(model), model.tolerance()); }

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

// The free curves (bounding one surface, not a seam nor a point), grouped into loops: the curves
// that share vertices, transitively.
std::vector<std::vector<int>> free_loops(const cad::Model& model) {
  std::vector<int> parent(static_cast<std::size_t>(model.num_vertices()));
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<int> free;
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto& uses = model.surfaces_of_curve(c);
    if (uses.size() != 1 || model.curve(c).is_degenerate() || model.is_seam(uses[0].surface, c)) continue;
    free.push_back(c);
    const auto ends = model.curve_vertices(c);
    parent[root(ends[0])] = root(ends[1]);
  }
  std::vector<std::vector<int>> loops;
  std::vector<int> loop_of_root(parent.size(), -1);
  for (int c : free) {
    int& loop = loop_of_root[root(model.curve_vertices(c)[0])];
    if (loop < 0) loop = static_cast<int>(loops.size()), loops.emplace_back();
    loops[loop].push_back(c);
  }
  return loops;
}

// The loop's plane, the normal towards the body; a CadRoleError naming the loop when it is not
// flat or its plane cuts the body (the root of a body standing on a plane is neither).
RootPlane plane_of_loop(const cad::Model& model, const std::vector<int>& loop) {
  const std::vector<cad::Vec3> points = curve_samples(model, loop);
  cad::Vec3 centre = cad::Vec3::Zero();
  for (const cad::Vec3& p : points) centre += p / static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const cad::Vec3& p : points) scatter += (p - centre) * (p - centre).transpose();
  cad::Vec3 normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
  const double tolerance = flatness_tolerance(model);
  double off = 0.0;
  for (const cad::Vec3& p : points) off = std::max(off, std::abs((p - centre).dot(normal)));
  const std::string where = fmt::format("the body is open along a loop of {} free curve(s) (curve {} ...) around ({:.6g}, "
                                        "{:.6g}, {:.6g})",
                                        loop.size(), loop.front(), centre.x(), centre.y(), centre.z());
  if (off > tolerance)
    throw CadRoleError(fmt::format("CAD roles: {} that lies in no plane (it strays {:.3g} from its best plane, more than "
                                   "{:.3g}): no open root or flat tip; faces not sewn together (a gap: set "
                                   "geometry.sew_tolerance above it) or an opening to close in a CAD tool",
                                   where, off, tolerance));
  if (!body_on_one_side(model, centre, normal, tolerance)) normal = -normal;
  if (!body_on_one_side(model, centre, normal, tolerance))
    throw CadRoleError(fmt::format("CAD roles: {} whose plane cuts through the body: the body cannot stand on it (set "
                                   "geometry.wall_plane to the plane it stands on)",
                                   where));
  return RootPlane{centre, normal, ""};
}

double loop_length(const cad::Model& model, const std::vector<int>& loop) {
  double length = 0.0;
  for (int c : loop) length += model.curve(c).length();
  return length;
}

// An open root: of the body's free loops, those lying in one plane with the body on one side; the
// longest (a tapered wing's root), of loops within 1 % of the same length (a straight wing's open
// root and open tip) the one nearer the origin. Nothing when a free loop is not flat: the body is
// then open where no plane can close it (unsewn faces, a gap), which the caller reports.
std::optional<RootPlane> plane_of_free_loop(const cad::Model& model) {
  const std::vector<std::vector<int>> loops = free_loops(model);
  struct Candidate {
    std::size_t loop;
    double length;
    RootPlane plane;
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    candidates.push_back({i, loop_length(model, loops[i]), plane_of_loop(model, loops[i])});
  }
  if (candidates.empty()) return std::nullopt;
  const auto before = [](const Candidate& a, const Candidate& b) {
    if (std::abs(a.length - b.length) > 0.01 * std::max(a.length, b.length)) return a.length > b.length;
    return std::abs(a.plane.point.dot(a.plane.normal)) < std::abs(b.plane.point.dot(b.plane.normal));
  };
  const Candidate best = *std::min_element(candidates.begin(), candidates.end(), before);
  RootPlane out = best.plane;
  const std::vector<int>& loop = loops[best.loop];
  // No curve id: the file's ids are not those of the model built around the body at load.
  out.why = fmt::format("the plane of the body's open root: of its {} open loop(s) of free curves, each in a plane, the "
                        "longest or nearest the origin of equal ones ({} curve(s))",
                        loops.size(), loop.size());
  return out;
}

// A closed body's planar caps, the largest (ties: nearer the origin).
std::optional<RootPlane> plane_of_cap(const cad::Model& model) {
  const double tolerance = flatness_tolerance(model);
  struct Cap {
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
    caps.push_back({surface.exact_area().value_or(0.0), {point, above ? n : cad::Vec3(-n), ""}});
  }
  if (caps.empty()) return std::nullopt;
  const auto before = [](const Cap& a, const Cap& b) {
    const double scale = std::max(a.area, b.area);
    if (std::abs(a.area - b.area) > 0.01 * scale) return a.area > b.area;
    return std::abs(a.plane.point.dot(a.plane.normal)) < std::abs(b.plane.point.dot(b.plane.normal));
  };
  const Cap best = *std::min_element(caps.begin(), caps.end(), before);
  RootPlane out = best.plane;
  // No face id: the file's ids are not those of the model built around the body at load, where
  // the wall takes the cap's place.
  out.why = fmt::format("the plane of the body's root cap: of its {} planar cap(s) (faces with all of the body on one "
                        "side) the largest, or nearest the origin of equal ones, of area {:.6g}",
                        caps.size(), best.area);
  return out;
}

}  // namespace

std::optional<RootPlane> find_root_plane(const cad::Model& model) {
  if (!model.is_closed()) return plane_of_free_loop(model);
  return plane_of_cap(model);
}

}  // namespace semimesh::surface
