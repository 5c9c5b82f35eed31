// The body mesh lifted off the wall onto the root strip, so the wing layer starts at the strip
// tops; nodes move along their CAD entities.
#include "semimesh/nearfield/error.hpp"

#include "c_shell_steps.hpp"
#include "labels.hpp"

#include <algorithm>
#include <set>

namespace semimesh::nearfield {

namespace c_type {
namespace {

// Smallest ratio of a lifted triangle's area to its own before the lift (projected on its normal).
constexpr double kFlattest = 1e-6;

// The lowest node of the body's surfaces that do not stand on the wall (no triangle at the root
// loop: a tip cap, flat or rounded, its sliver faces), or the body's top when every surface stands
// on the wall. A tip cap turns level: a node on it (or on its edge) moved to a slightly greater
// height would run far across it (the height's gradient along the surface vanishes), so the cap
// stays where it is and the lift dies out below it (the ONERA M6: a node on the rounded tip's
// nearly level edge was lifted along it to its end and folded a triangle).
double lift_top(const BodyMesh& body, const Frame& wall, const std::vector<int>& loop) {
  const std::set<int> root(loop.begin(), loop.end());
  std::set<int> standing;
  for (std::size_t t = 0; t < body.triangles.size(); ++t)
    for (int v : body.triangles[t])
      if (root.count(v)) standing.insert(body.triangle_surface[t]);
  double top = 0.0, cap = 1e300;
  for (const Vec3& x : body.points) top = std::max(top, wall.height(x));
  for (std::size_t t = 0; t < body.triangles.size(); ++t)
    if (!standing.count(body.triangle_surface[t]))
      for (int v : body.triangles[t]) cap = std::min(cap, wall.height(body.points[v]));
  return std::min(top, cap);
}

}  // namespace

std::pair<double, double> lift_onto_strip(const cad::Model& model, const Frame& wall, const std::vector<int>& loop,
                                          const std::vector<JunctionNode>& nodes, double delta_wall, BodyMesh& body) {
  double tip = 0.0, strip = 0.0;
  for (const Vec3& x : body.points) tip = std::max(tip, wall.height(x));
  for (const JunctionNode& j : nodes) strip = std::max(strip, wall.height(j.strip_top));
  std::vector<char> on_root(body.num_nodes(), 0);
  for (int r : loop) on_root[r] = 1;
  // Off the wall by topology, not height: a root sewn across gaps has its corners a gap's width off.
  double ceiling = std::min(tip, lift_top(body, wall, loop));
  for (int v = 0; v < body.num_nodes(); ++v)
    if (body.cad[v].kind == CadAttachment::Vertex && !on_root[v])
      ceiling = std::min(ceiling, wall.height(body.points[v]));
  if (!(strip < 0.5 * ceiling))
    throw NearFieldError("near field: the root strip (height " + number_label(strip) +
                         ") for the wall layer thickness " + number_label(delta_wall) +
                         " takes more than half of the body's height " + number_label(ceiling) +
                         " above the wall (up to its lowest corner off the wall); use a thinner wall layer");
  const std::vector<Vec3> unlifted = body.points;
  // Each node on its own (its point and attachment only), on every thread where the CAD allows.
#pragma omp parallel for schedule(dynamic, 64) if (model.thread_safe())
  for (int v = 0; v < body.num_nodes(); ++v)
    if (!on_root[v]) body.points[v] = detail::lift_node(model, wall, strip, ceiling, body.points[v], body.cad[v]);
  for (std::size_t i = 0; i < loop.size(); ++i)
    body.points[loop[i]] = nodes[i].strip_top, body.cad[loop[i]] = nodes[i].strip_top_cad;
  for (const auto& t : body.triangles) {
    const Vec3 before = (unlifted[t[1]] - unlifted[t[0]]).cross(unlifted[t[2]] - unlifted[t[0]]);
    const Vec3 after = (body.points[t[1]] - body.points[t[0]]).cross(body.points[t[2]] - body.points[t[0]]);
    // Relative: a triangle flattened onto a line (e.g. all three nodes on a CAD edge) keeps a
    // round-off area of either sign.
    if (!(before.dot(after) > kFlattest * before.squaredNorm()))
      throw NearFieldError(
          "near field: lifting the wing mesh onto the root strip (height " + number_label(strip) +
          ") folds or flattens a triangle at " + point_label(body.points[t[0]]) + " on " +
          surface_label(model, body.node_surface[t[0]]) +
          "; the root loop is too short for the sizes: use a thinner wall layer or a finer surface mesh");
  }
  return {strip, tip};
}

}  // namespace c_type

namespace detail {

using mesh::CadAttachment;

Vec3 move_to_height(const cad::Model& model, const WallFrame& wall, const Vec3& x, CadAttachment& cad, double target) {
  // Newton on the height along its gradient in the entity's parameters: on a lofted wing the
  // chordwise parameter stays (the height grows with the spanwise one), so a node near a swept
  // leading edge keeps its place along the section. A move in space projected back (vertical or
  // steepest ascent on the surface) drifts to the closest point, onto the edge itself.
  Vec3 p = x;
  for (int iteration = 0; iteration < 12; ++iteration) {
    const detail::WallFrame::Above here = wall.above(p);
    const double missing = target - here.height;
    const Vec3& normal = here.normal;
    if (cad.kind == CadAttachment::Surface) {
      const cad::Surface& face = model.surface(cad.entity);
      const cad::SurfaceDerivatives d = face.derivatives(cad::Vec2(cad.u, cad.v));
      const cad::Vec2 gradient(d.du.dot(normal), d.dv.dot(normal));
      if (!(gradient.squaredNorm() > 0.0)) break;
      const auto bounds = face.bounds();
      const cad::Vec2 uv(
          std::clamp(cad.u + missing * gradient.x() / gradient.squaredNorm(), bounds[0].lo, bounds[0].hi),
          std::clamp(cad.v + missing * gradient.y() / gradient.squaredNorm(), bounds[1].lo, bounds[1].hi));
      cad.u = uv.x(), cad.v = uv.y();
      p = face.point(uv);
    } else {
      const cad::Curve& curve = model.curve(cad.entity);
      const double slope = curve.derivatives(cad.u).d1.dot(normal);
      if (slope == 0.0) break;
      const auto bounds = curve.bounds();
      cad.u = std::clamp(cad.u + missing / slope, bounds.lo, bounds.hi);
      p = curve.derivatives(cad.u).p;
    }
  }
  return p;
}

Vec3 lift_node(const cad::Model& model, const WallFrame& wall, double strip, double ceiling, const Vec3& x,
               CadAttachment& cad) {
  const double d = wall.height(x);
  if (d >= ceiling * (1.0 - 1e-9) || cad.kind == CadAttachment::Vertex || cad.kind == CadAttachment::None) return x;
  return move_to_height(model, wall, x, cad, strip + d * (1.0 - strip / ceiling));
}

}  // namespace detail
}  // namespace semimesh::nearfield
