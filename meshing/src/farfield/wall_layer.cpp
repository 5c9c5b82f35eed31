#include "wall_layer.hpp"

#include "semimesh/cad/labels.hpp"
#include "semimesh/farfield/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

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
// along the normal and projected back onto it, which keeps the layer's side quads on the face
// when it rises perpendicular; a face leaning more (a cone, a slanted box) would need its own
// lift direction.
constexpr double kMaxTilt = 1e-3;

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
std::optional<double> tilt_at_the_wall(const cad::Model& model, int surface, int wall, const Eigen::Vector3d& normal) {
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
        const double leaning = std::asin(std::min(1.0, std::abs(model.surface(surface).normal(p.uv).dot(normal))));
        tilt = std::max(tilt.value_or(0.0), leaning);
      }
    }
  return tilt;
}

}  // namespace

WallLayer build_wall_layer(const cad::Model& model, int wall_surface, const std::vector<int>& box_surfaces,
                           double thickness, const std::vector<Triangle>& wall, const nearfield::NearField& near,
                           std::vector<Triangle>& box, mesh::Mesh& mesh) {
  if (near.footprint_top.size() != near.footprint.size())
    throw FarFieldError("far field: a wall layer needs the near field's halo above its footprint (C-type near field)");
  const cad::Surface& wall_face = model.surface(wall_surface);
  const auto b = wall_face.bounds();
  const cad::Vec2 mid(0.5 * (b[0].lo + b[0].hi), 0.5 * (b[1].lo + b[1].hi));
  const Eigen::Vector3d normal = wall_face.normal(mid), origin = wall_face.point(mid);
  auto height = [&](const Eigen::Vector3d& x) { return (x - origin).dot(normal); };
  const double tolerance = std::max(model.tolerance(), 1e-9 * model.bbox().diagonal());

  for (int s : box_surfaces)
    if (const std::optional<double> tilt = tilt_at_the_wall(model, s, wall_surface, normal); tilt && *tilt > kMaxTilt)
      throw FarFieldError(fmt::format("far field: {} meets the wall at {:.3g} degrees from the wall's normal; the "
                                      "wall layer stands its sides on the far field's faces, which must rise "
                                      "perpendicular to the wall (within {:.3g} degrees) where they meet it",
                                      cad::surface_label(model, s), *tilt * 180 / M_PI, kMaxTilt * 180 / M_PI));

  // Lift the box: nodes on the wall get a top node, the others move up.
  std::set<NodeId> box_nodes;
  for (const Triangle& t : box) box_nodes.insert(t.begin(), t.end());
  double box_height = 0.0;
  for (NodeId v : box_nodes) box_height = std::max(box_height, height(mesh.node(v)));
  if (!(thickness < 0.5 * box_height))
    throw FarFieldError("far field: the wall layer's thickness " + std::to_string(thickness) +
                        " is not below half the box height " + std::to_string(box_height));
  std::unordered_map<NodeId, NodeId> top_of;
  for (std::size_t i = 0; i < near.footprint.size(); ++i) top_of[near.footprint[i]] = near.footprint_top[i];
  for (NodeId v : box_nodes) {
    const Eigen::Vector3d x = mesh.node(v);
    const double d = height(x);
    if (d >= box_height - tolerance) continue;
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

  // Prisms on the wall triangles (stored facing into the wall: (A, C, B) for the prism's (A, B, C)).
  WallLayer layer;
  const int region = mesh.region_index("wall_layer");
  std::map<std::pair<NodeId, NodeId>, int> edge_uses;
  for (const Triangle& t : wall)
    for (int k = 0; k < 3; ++k) ++edge_uses[std::minmax(t[k], t[(k + 1) % 3])];
  for (const Triangle& t : wall) {
    const std::array<NodeId, 3> bottom{t[0], t[2], t[1]};
    std::array<NodeId, 3> top;
    for (int k = 0; k < 3; ++k) {
      auto [it, added] = top_of.try_emplace(bottom[k], mesh::kNoNode);
      if (added) it->second = mesh.add_node(mesh.node(bottom[k]) + thickness * normal);
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
