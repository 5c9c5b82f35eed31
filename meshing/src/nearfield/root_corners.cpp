// For PyFR (output.target = "pyfr"): the trailing edge's root corners, where each side's lowest rear
// interface meets the junction. Its layer edge there is the strip top's halo, which bisects the
// side's and the base's outward normals (or, at a sharp edge's root, is kept off the rear
// interfaces): not the side's one vector, so the interface is no parallelogram and PyFR refuses the
// far field's pyramids on it. The junction gave such a corner one halo per side (the fan, or
// JunctionShell::corners); the side's is moved onto the side's layer edge here, the wedge between
// the two filled later (fan_wedge.cpp).
#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"

#include "h_shell_steps.hpp"
#include "labels.hpp"

#include <algorithm>
#include <set>

namespace semimesh::nearfield::h_type {
namespace {

// The wall foot paired with `halo` at a root corner and that corner's root node, or kNoNode when the
// halo is no corner's (the junction did not split it).
std::pair<NodeId, NodeId> corner_foot(const detail::JunctionShell& js, NodeId halo) {
  for (int side : {0, 1})
    if (js.fan.index >= 0 && js.fan.top[side] == halo) return {js.fan.foot[side], js.root_id[js.fan.index]};
  for (const detail::JunctionShell::Corner& c : js.corners)
    if (c.top[1 - c.bare] == halo) return {c.foot[1 - c.bare], js.root_id[c.index]};
  return {mesh::kNoNode, mesh::kNoNode};
}

// Every element using a moved node valid (first order), else the corner is named.
void check_elements_at(const mesh::Mesh& m, const std::set<NodeId>& moved, const Vec3& corner) {
  for (const mesh::Element& e : m.elements()) {
    const int n = ho::num_vertices(e.shape);
    if (std::none_of(e.vertices.begin(), e.vertices.begin() + n, [&](NodeId v) { return moved.count(v) > 0; }))
      continue;
    if (!element_valid(m, e.shape, std::vector<NodeId>(e.vertices.begin(), e.vertices.begin() + n)))
      fail("output.target = \"pyfr\": the junction at the trailing edge's root corner " + point_label(corner) +
           " folds once its halo is moved onto the side's rear-interface layer edge (PyFR's parallelogram rule); "
           "use a thinner nearfield.thickness or wall_layer.thickness");
  }
}

}  // namespace

void open_root_corners(const cad::Model& model, int wall_surface, double delta_wing, double delta_wall,
                       const detail::TranslationalRims& rims, detail::JunctionShell& js) {
  mesh::Mesh& m = js.field.mesh;
  const cad::Surface& face = model.surface(wall_surface);
  // The wedge's pieces are cut in advance on straight legs; the junction hexes beside it are cut
  // after curving, on their curved faces: on a curved wall the two miss each other (the sharp
  // edge's fan does too), which would leave the mesh open there.
  if (js.wall.curved && !rims.root_corner.empty())
    fail("output.target = \"pyfr\": the trailing edge's root corner " +
         point_label(m.node(js.layer_body[rims.root_corner.begin()->first])) + " stands on the curved wall " +
         surface_label(model, wall_surface) +
         ", where the junction's wedge between its two halos is not cut like the junction beside it yet; for PyFR "
         "use nearfield.topology = \"C\" on a curved wall");
  for (const auto& [layer_node, side] : rims.root_corner) {
    const NodeId halo = static_cast<NodeId>(layer_node) + js.offset;
    const auto [foot, root] = corner_foot(js, halo);
    const auto edge = rims.side_edge.find(side);
    if (foot == mesh::kNoNode || edge == rims.side_edge.end()) continue;  // left for the pyfr stage to name
    const Vec3 w = m.node(js.layer_body[layer_node]);
    const Vec3 h = w + edge->second;
    // The foot below the halo, the wall strip at least delta_wing wide (as the junction's feet).
    const Vec3 normal = js.wall.normal_at(w);
    const Vec3 below = h - delta_wall * normal;
    Vec3 outward = edge->second - edge->second.dot(normal) * normal;
    outward.normalize();
    const double out = (below - m.node(root)).dot(outward);
    const Vec3 above_foot = below + std::max(0.0, delta_wing - out) * outward;
    const auto p = js.wall.curved ? face.project(above_foot, js.wall.root_uv) : face.project(above_foot);
    m.place_node(halo, h);
    m.place_node_on_cad(foot, p.point, {mesh::CadAttachment::Surface, wall_surface, p.uv.x(), p.uv.y()});
    check_elements_at(m, {halo, foot}, w);
  }
}

}  // namespace semimesh::nearfield::h_type
