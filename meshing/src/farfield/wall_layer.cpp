#include "wall_layer.hpp"

#include "semimesh/cad/labels.hpp"
#include "semimesh/farfield/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

namespace semimesh::farfield {
namespace {

using mesh::CadAttachment;
using mesh::NodeId;

bool bounds_surface(const cad::Model& model, int curve, int surface) {
  const auto& uses = model.surfaces_of_curve(curve);
  return std::any_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& u) { return u.surface == surface; });
}

// The largest lean of a far-field face from the wall's normal where they meet: its nodes are lifted
// along the normal and projected back onto it, so the layer's side prisms lean with the face (a
// box side cutting a fuselage whose radius changes there: 2 degrees); a face leaning more (a cone,
// a slanted box) would need its own lift direction.
constexpr double kMaxTilt = 0.1;

// The largest wall layer thickness times the wall's curvature: a concave wall (a duct) folds the
// layer's normals at 1, and the junction's halo, placed over the wall's tangent plane, is off by
// about half this fraction of the layer's thickness.
constexpr double kMaxWallTurn = 0.25;

// Over a curved wall, box nodes up to at least this many layer thicknesses above it are lifted.
constexpr double kCurvedWallLiftReach = 4.0;

// Re-attaches a moved node to its CAD entity (projection from its old parameters).
void place_on_entity(const cad::Model& model, mesh::Mesh& mesh, NodeId id, const Eigen::Vector3d& x,
                     CadAttachment cad) {
  if (cad.kind == CadAttachment::Surface) {
    const auto p = model.surface(cad.entity).project(x, cad::Vec2(cad.u, cad.v));
    cad.u = p.uv.x(), cad.v = p.uv.y();
    mesh.place_node_on_cad(id, p.point, cad);
  } else if (cad.kind == CadAttachment::Curve) {
    const auto p = model.curve(cad.entity).project(x, cad.u);
    cad.u = p.t;
    mesh.place_node_on_cad(id, p.point, cad);
  } else {
    mesh.place_node_on_cad(id, x, cad);
  }
}

// The CAD entity of a box node's top: the box surface of its bottom curve, or the box edge
// leaving its bottom vertex.
CadAttachment top_entity(const cad::Model& model, const CadAttachment& bottom, int wall) {
  if (bottom.kind == CadAttachment::Curve)
    for (const cad::SurfaceUse& u : model.surfaces_of_curve(bottom.entity))
      if (u.surface != wall) return {CadAttachment::Surface, u.surface, 0.0, 0.0};
  if (bottom.kind == CadAttachment::Vertex)
    for (int c : model.curves_of_vertex(bottom.entity))
      if (!bounds_surface(model, c, wall)) return {CadAttachment::Curve, c, 0.0, 0.0};
  return {};
}

// How far a far-field face leans from the wall's normal where it meets the wall (radians, the
// largest over samples of the curves it shares with the wall), or nothing when it does not meet
// the wall. A box side (plane) or a hemisphere cut at its equator: 0.
std::optional<double> tilt_at_the_wall(const cad::Model& model, int surface, int wall) {
  constexpr int kSamples = 8;
  std::optional<double> tilt;
  for (const cad::Loop& loop : model.loops(surface))
    for (const cad::CurveUse& use : loop.uses) {
      if (!bounds_surface(model, use.curve, wall) || model.curve(use.curve).is_degenerate()) continue;
      const cad::Curve& curve = model.curve(use.curve);
      const cad::Interval t = curve.bounds();
      for (int k = 0; k <= kSamples; ++k) {
        const cad::Vec3 x = curve.point(t.lo + t.length() * k / kSamples);
        const auto p = model.surface(surface).project(x);
        const Eigen::Vector3d normal = model.surface(wall).normal(model.surface(wall).project(x).uv);
        const double leaning = std::asin(std::min(1.0, std::abs(model.surface(surface).normal(p.uv).dot(normal))));
        tilt = std::max(tilt.value_or(0.0), leaning);
      }
    }
  return tilt;
}

// Heights above the wall and its normal into the fluid, where the wall layer needs them: on a plane
// the signed distance and the one normal; on a curved wall (a fuselage) the distance to the
// surface and the normal at the foot, found from a point's own wall parameters when it has them.
class WallHeights {
 public:
  WallHeights(const cad::Model& model, int wall) : wall_(model.surface(wall)), id_(wall), planar_(wall_.is_planar()) {
    const auto b = wall_.bounds();
    const cad::Vec2 mid(0.5 * (b[0].lo + b[0].hi), 0.5 * (b[1].lo + b[1].hi));
    normal_ = wall_.normal(mid);
    origin_ = wall_.point(mid);
  }
  bool planar() const { return planar_; }
  /// One normal for every point of a planar wall (the one used for all of them).
  const Eigen::Vector3d& plane_normal() const { return normal_; }

  double height(const Eigen::Vector3d& x) const {
    if (planar_) return (x - origin_).dot(normal_);
    const cad::SurfaceProjection p = wall_.project(x);
    return (x - p.point).dot(wall_.normal(p.uv));
  }
  /// The normal under x; `cad` its attachment (the wall's parameters, when on the wall surface).
  Eigen::Vector3d normal_under(const Eigen::Vector3d& x, const CadAttachment& cad) const {
    if (planar_) return normal_;
    if (cad.kind == CadAttachment::Surface && cad.entity == id_) return wall_.normal(cad::Vec2(cad.u, cad.v));
    return wall_.normal(wall_.project(x).uv);
  }

 private:
  const cad::Surface& wall_;
  int id_;
  bool planar_;
  Eigen::Vector3d normal_, origin_;
};

// Refuses a curved wall that turns too fast for the layer's thickness somewhere under it (a
// fuselage whose radius nears the thickness, a tight fillet), naming the place and the key.
void require_gentle_wall(const cad::Model& model, int wall_surface, double thickness, const std::vector<Triangle>& wall,
                         const mesh::Mesh& mesh) {
  const cad::Surface& face = model.surface(wall_surface);
  std::set<NodeId> nodes;
  for (const Triangle& t : wall) nodes.insert(t.begin(), t.end());
  for (NodeId v : nodes) {
    const CadAttachment cad = mesh.cad_attachment(v);
    const cad::Vec2 uv = cad.kind == CadAttachment::Surface && cad.entity == wall_surface
                             ? cad::Vec2(cad.u, cad.v)
                             : face.project(mesh.node(v)).uv;
    const cad::PrincipalCurvatures k = face.curvatures(uv);
    const double kappa = std::max(std::abs(k.k_min), std::abs(k.k_max));
    if (thickness * kappa > kMaxWallTurn) {
      const Eigen::Vector3d& x = mesh.node(v);
      throw FarFieldError(fmt::format(
          "far field: the wall {} turns with a radius of {:.4g} at ({:.6g}, {:.6g}, {:.6g}), too tight for the wall "
          "layer's thickness {:.4g} (at most {:.3g} of the radius); use a thinner wall_layer.thickness",
          cad::surface_label(model, wall_surface), 1.0 / kappa, x.x(), x.y(), x.z(), thickness, kMaxWallTurn));
    }
  }
}

// The height under which box nodes are lifted: on a plane the box's whole height (the lift fades
// to nothing at its top); on a curved wall the reach of the box triangles touching the wall, and at
// least a few layer thicknesses (so a node lifted by nearly the thickness keeps its triangle's
// height), nodes further away, whose foot on the wall may not be the nearest point of its trimmed
// face, staying.
double lift_reach(const WallHeights& wall, const std::vector<Triangle>& box, const mesh::Mesh& mesh, double thickness,
                  double tolerance) {
  double reach = 0.0;
  for (const Triangle& t : box) {
    double low = std::numeric_limits<double>::infinity(), high = 0.0;
    for (NodeId v : t) {
      const double d = wall.height(mesh.node(v));
      low = std::min(low, d);
      high = std::max(high, d);
    }
    if (wall.planar() || low <= tolerance) reach = std::max(reach, high);
  }
  return wall.planar() ? reach : std::max(reach, kCurvedWallLiftReach * thickness);
}

}  // namespace

WallLayer build_wall_layer(const cad::Model& model, int wall_surface, const std::vector<int>& box_surfaces,
                           double thickness, const std::vector<Triangle>& wall, const nearfield::NearField& near,
                           std::vector<Triangle>& box, const std::vector<NodeId>& box_outline, mesh::Mesh& mesh) {
  if (near.footprint_top.size() != near.footprint.size())
    throw FarFieldError("far field: a wall layer needs the near field's halo above its footprint (C-type near field)");
  const WallHeights wall_heights(model, wall_surface);
  auto height = [&](const Eigen::Vector3d& x) { return wall_heights.height(x); };
  auto normal_under = [&](NodeId v) { return wall_heights.normal_under(mesh.node(v), mesh.cad_attachment(v)); };
  const double tolerance = std::max(model.tolerance(), 1e-9 * model.bbox().diagonal());

  for (int s : box_surfaces)
    if (const std::optional<double> tilt = tilt_at_the_wall(model, s, wall_surface); tilt && *tilt > kMaxTilt)
      throw FarFieldError(fmt::format("far field: {} meets the wall at {:.3g} degrees from the wall's normal; the "
                                      "wall layer stands its sides on the far field's faces, which must rise "
                                      "perpendicular to the wall (within {:.3g} degrees) where they meet it",
                                      cad::surface_label(model, s), *tilt * 180 / M_PI, kMaxTilt * 180 / M_PI));

  // Lift the box: nodes on the wall get a top node, the others move up.
  std::set<NodeId> box_nodes;
  for (const Triangle& t : box) box_nodes.insert(t.begin(), t.end());
  box_nodes.insert(box_outline.begin(), box_outline.end());
  const double box_height = lift_reach(wall_heights, box, mesh, thickness, tolerance);
  if (!(thickness < 0.5 * box_height))
    throw FarFieldError("far field: the wall layer's thickness " + std::to_string(thickness) + " is not below half " +
                        (wall_heights.planar() ? "the box height " : "the height of the box triangles on the wall ") +
                        std::to_string(box_height));
  WallLayer layer;
  std::unordered_map<NodeId, NodeId>& top_of = layer.top_of;
  for (std::size_t i = 0; i < near.footprint.size(); ++i) top_of[near.footprint[i]] = near.footprint_top[i];
  for (NodeId v : box_nodes) {
    const Eigen::Vector3d x = mesh.node(v);
    const double d = height(x);
    if (d >= box_height - tolerance) continue;
    const Eigen::Vector3d normal = normal_under(v);
    if (d <= tolerance) {
      const NodeId top = mesh.add_node(x + thickness * normal);
      place_on_entity(model, mesh, top, x + thickness * normal,
                      top_entity(model, mesh.cad_attachment(v), wall_surface));
      top_of[v] = top;
      continue;
    }
    place_on_entity(model, mesh, v, x + (thickness + d * (1.0 - thickness / box_height) - d) * normal,
                    mesh.cad_attachment(v));
  }
  for (Triangle& t : box)
    for (NodeId& v : t)
      if (const auto it = top_of.find(v); it != top_of.end()) v = it->second;

  if (!wall_heights.planar()) require_gentle_wall(model, wall_surface, thickness, wall, mesh);

  // Prisms on the wall triangles (stored facing into the wall: (A, C, B) for the prism's (A, B, C)).
  const int region = mesh.region_index("wall_layer");
  std::map<std::pair<NodeId, NodeId>, int> edge_uses;
  for (const Triangle& t : wall)
    for (int k = 0; k < 3; ++k) ++edge_uses[std::minmax(t[k], t[(k + 1) % 3])];
  for (const Triangle& t : wall) {
    const std::array<NodeId, 3> bottom{t[0], t[2], t[1]};
    std::array<NodeId, 3> top;
    for (int k = 0; k < 3; ++k) {
      auto [it, added] = top_of.try_emplace(bottom[k], mesh::kNoNode);
      if (added) it->second = mesh.add_node(mesh.node(bottom[k]) + thickness * normal_under(bottom[k]));
      top[k] = it->second;
    }
    layer.stacks.push_back({mesh.elements().size(), {nearfield::LayerDirection{2, nearfield::LayerFamily::Wall}}});
    mesh.add_element(ho::Shape::Prism, {bottom[0], bottom[1], bottom[2], top[0], top[1], top[2]}, region);
    layer.tops.push_back(top);
    // Where the layer meets the box: the side quad (A, B, B', A') faces out of the domain.
    for (int k = 0; k < 3; ++k) {
      const NodeId a = bottom[k], c = bottom[(k + 1) % 3];
      if (edge_uses[std::minmax(a, c)] == 1 && box_nodes.count(a) && box_nodes.count(c))
        mesh.add_boundary_face("farfield", ho::Shape::Quadrilateral, {a, c, top[(k + 1) % 3], top[k]});
    }
  }
  return layer;
}

}  // namespace semimesh::farfield
