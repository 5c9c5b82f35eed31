// A sharp trailing edge's root: the fan of the junction between its two halos, filled with
// prisms on the wall, cut in advance at the split's interfaces; for PyFR a blunt edge's root
// corners' wedges the same way (JunctionShell::corners).
#include "semimesh/ho/element_type.hpp"

#include "h_shell_steps.hpp"
#include "labels.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace semimesh::nearfield::h_type {
namespace {

// A wedge of the junction standing on the wall between halos of one strip top: its root R, strip
// top W and legs in the order they open (feet on the wall, tops at the halos); `where` names it.
struct Wedge {
  NodeId r, top;
  std::vector<NodeId> foot, halo;
  std::string where;
};

// The wedge's legs cut at the split's interfaces: per leg the nodes from the root R to the foot
// (`low`) and from the strip top W to the halo (`high`).
struct FanRows {
  std::vector<std::vector<NodeId>> low, high;
};

// The cut of a leg on the wall at `x` (on its chord): on a curved wall, the wall's point under it,
// on the CAD, so that curving bends the wedge's wall faces with the wall (a node off the CAD keeps
// them on the chord, up to the wall's sag under the leg).
NodeId wall_cut(mesh::Mesh& m, const detail::WallFrame& wall, int wall_surface, const Vec3& x) {
  if (!wall.curved) return m.add_node(x);
  const cad::SurfaceProjection p = wall.curved->project(x, wall.root_uv);
  return m.add_node(p.point, {mesh::CadAttachment::Surface, wall_surface, p.uv.x(), p.uv.y()});
}

FanRows cut_fan_legs(mesh::Mesh& m, const Wedge& w, const detail::WallFrame& wall, int wall_surface,
                     const std::vector<double>& at_root, const std::vector<double>& at_top,
                     InterfaceNodes& interface_node) {
  FanRows rows;
  rows.low.resize(w.foot.size()), rows.high.resize(w.foot.size());
  for (std::size_t leg = 0; leg < w.foot.size(); ++leg) {
    const NodeId foot = w.foot[leg], halo = w.halo[leg];
    rows.low[leg] = {w.r}, rows.high[leg] = {w.top};
    for (std::size_t k = 1; k + 1 < at_root.size(); ++k) {
      const Vec3 on_chord = m.node(w.r) + at_root[k] * (m.node(foot) - m.node(w.r));
      rows.low[leg].push_back(wall_cut(m, wall, wall_surface, on_chord));
      rows.high[leg].push_back(m.add_node(m.node(w.top) + at_top[k] * (m.node(halo) - m.node(w.top))));
      interface_node[{w.r, foot, static_cast<int>(k)}] = rows.low[leg].back();
      interface_node[{w.top, halo, static_cast<int>(k)}] = rows.high[leg].back();
    }
    rows.low[leg].push_back(foot), rows.high[leg].push_back(halo);
  }
  return rows;
}

// One piece of the wedge (a prism of the junction standing on the wall, split with the wall
// layer along R-W), its vertices in the order that makes it valid.
void add_fan_piece(NearField& field, int wall_surface, const Wedge& w, ho::Shape shape, std::vector<NodeId> v) {
  mesh::Mesh& m = field.mesh;
  const int half = static_cast<int>(v.size()) / 2;
  if (!element_valid(m, shape, v)) {  // the other way round
    std::reverse(v.begin() + 1, v.begin() + half);
    std::reverse(v.begin() + half + 1, v.end());
    if (!element_valid(m, shape, v))
      fail("the junction's wedge at " + w.where + " " + point_label(m.node(w.r)) + " would be inverted");
  }
  field.stacks.push_back({field.element_surface.size(), {LayerDirection{2, LayerFamily::Wall}}});
  field.element_surface.push_back(wall_surface);
  m.add_element(shape, v, m.region_index("junction"));
  if (shape == ho::Shape::Prism)
    m.add_boundary_face("wall", ho::Shape::Triangle, {v[0], v[2], v[1]});
  else
    m.add_boundary_face("wall", ho::Shape::Quadrilateral, {v[0], v[3], v[2], v[1]});
}

// The wedge (R, the feet / W, the halos) as prisms on the wall, cut in advance at the wing layer's
// interfaces (`fractions`); the nodes on its two outer legs' faces R-W-H-L, which it shares with
// junction hexes.
std::vector<std::set<NodeId>> fill_wedge(NearField& field, const Wedge& w, const detail::WallFrame& wall,
                                         int wall_surface, const LayerFractions& fractions,
                                         InterfaceNodes& interface_node) {
  mesh::Mesh& m = field.mesh;
  std::vector<double> at_root{0.0, 1.0}, at_top{0.0, 1.0};
  if (fractions) at_root = fractions(m.node(w.r), field.wake), at_top = fractions(m.node(w.top), field.wake);
  for (std::size_t k = 0; k < at_root.size(); ++k)
    if (std::abs(at_root[k] - at_top[k]) > 1e-12)
      fail("the wing layer's ratio differs between " + w.where + " " + point_label(m.node(w.r)) +
           " and the top of its root strip " + point_label(m.node(w.top)) +
           " (a boundary_layer.ratio_line?): the junction's wedge there takes one ratio; make it the same at both");
  const FanRows rows = cut_fan_legs(m, w, wall, wall_surface, at_root, at_top, interface_node);
  std::vector<std::set<NodeId>> planes;
  for (std::size_t leg : {std::size_t{0}, w.foot.size() - 1}) {  // the inner legs' planes are inside the wedge
    planes.emplace_back(rows.low[leg].begin(), rows.low[leg].end());
    planes.back().insert(rows.high[leg].begin(), rows.high[leg].end());
    if (fractions) field.precut_faces.push_back({rows.low[leg], rows.high[leg], at_root});
  }
  // Each band between two interfaces as two prisms (its diagonal from the first leg's inner
  // corner): the sharp edge's fan opens by nearly 180 degrees, so a band is a sliver whose top, a
  // quad, would carry a pyramid leaning over the rear interfaces beside it; triangles take
  // tetrahedra (and a quad there would be a trapezoid, which PyFR's pyramids refuse).
  const auto& low = rows.low;
  const auto& high = rows.high;
  for (std::size_t p = 0, q = 1; q < w.foot.size(); ++p, ++q) {  // the wedge's parts between two legs
    add_fan_piece(field, wall_surface, w, ho::Shape::Prism,
                  {w.r, low[p][1], low[q][1], w.top, high[p][1], high[q][1]});
    for (std::size_t k = 1; k + 1 < low[p].size(); ++k) {
      add_fan_piece(field, wall_surface, w, ho::Shape::Prism,
                    {low[p][k], low[p][k + 1], low[q][k + 1], high[p][k], high[p][k + 1], high[q][k + 1]});
      add_fan_piece(field, wall_surface, w, ho::Shape::Prism,
                    {low[p][k], low[q][k + 1], low[q][k], high[p][k], high[q][k + 1], high[q][k]});
    }
  }
  return planes;
}

}  // namespace

FanLegs add_fan_middle_leg(const cad::Model& model, int wall_surface, detail::JunctionShell& js) {
  FanLegs legs;
  if (js.fan.index < 0) return legs;
  mesh::Mesh& m = js.field.mesh;
  const Vec3 r = m.node(js.root_id[js.fan.index]);
  const Vec3 a = m.node(js.fan.foot[0]) - r, b = m.node(js.fan.foot[1]) - r;
  const auto foot = model.surface(wall_surface)
                        .project(r + 0.5 * (a.norm() + b.norm()) * (a.normalized() + b.normalized()).normalized());
  legs.foot = {js.fan.foot[0],
               m.add_node(foot.point, {mesh::CadAttachment::Surface, wall_surface, foot.uv.x(), foot.uv.y()}),
               js.fan.foot[1]};
  const Vec3 rise =
      0.5 * (m.node(js.fan.top[0]) - m.node(js.fan.foot[0]) + m.node(js.fan.top[1]) - m.node(js.fan.foot[1]));
  legs.top = {js.fan.top[0], m.add_node(foot.point + rise), js.fan.top[1]};
  return legs;
}

std::vector<std::set<NodeId>> fill_fan_wedge(NearField& field, const detail::JunctionShell& js, const FanLegs& legs,
                                             int wall_surface, const LayerFractions& fractions,
                                             InterfaceNodes& interface_node) {
  if (js.fan.index < 0) return {};
  const Wedge w{js.root_id[js.fan.index], static_cast<NodeId>(js.chain[js.fan.index]),
                {legs.foot.begin(), legs.foot.end()}, {legs.top.begin(), legs.top.end()},
                "the sharp trailing edge's root"};
  return fill_wedge(field, w, js.wall, wall_surface, fractions, interface_node);
}

std::vector<std::set<NodeId>> fill_corner_wedges(NearField& field, const detail::JunctionShell& js, int wall_surface,
                                                 const LayerFractions& fractions, InterfaceNodes& interface_node) {
  std::vector<std::set<NodeId>> planes;
  for (const detail::JunctionShell::Corner& c : js.corners) {
    const Wedge w{js.root_id[c.index], static_cast<NodeId>(js.chain[c.index]), {c.foot[0], c.foot[1]},
                  {c.top[0], c.top[1]}, "the trailing edge's root corner"};
    for (auto& plane : fill_wedge(field, w, js.wall, wall_surface, fractions, interface_node))
      planes.push_back(std::move(plane));
  }
  return planes;
}

}  // namespace semimesh::nearfield::h_type
