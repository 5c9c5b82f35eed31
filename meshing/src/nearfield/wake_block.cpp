// The H-type's wake block: its root (the cut row), its cross-section at the trailing edge, the
// sweep downstream into hexes, and what the split and the checks read of it.
#include "semimesh/ho/element_type.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"
#include "semimesh/nearfield/pyramid_apex.hpp"

#include "h_shell_steps.hpp"
#include "labels.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace semimesh::nearfield {

namespace detail {

std::vector<double> wake_stations(const WakeParams& wake) {
  std::vector<double> s(wake.layers + 1, 0.0);
  double h = 1.0;
  for (int k = 1; k <= wake.layers; ++k, h *= wake.growth) s[k] = s[k - 1] + h;
  for (double& x : s) x *= wake.length / s.back();
  return s;
}

std::vector<double> wake_stations_to(const WakeParams& wake, double distance) {
  std::vector<double> s = wake_stations(wake);
  if (!(distance > wake.length)) {
    for (double& x : s) x *= distance / wake.length;
    return s;
  }
  const double longest = wake.outlet_cell > 0.0 ? wake.outlet_cell : distance;
  std::vector<double> further;
  double cell = s.back() - s[s.size() - 2], covered = 0.0;
  while (covered < distance - wake.length) {
    cell = std::min(cell * wake.growth, longest);
    further.push_back(cell);
    covered += cell;
  }
  const double scale = (distance - wake.length) / covered;
  for (double c : further) s.push_back(s.back() + scale * c);
  s.back() = distance;
  return s;
}

}  // namespace detail

namespace h_type {
namespace {

// The base quads above the cut as sections; a quad at a flat corner as two triangles split from
// the corner (a hex there would have a vanishing Jacobian at the corner once curved).
void add_base_sections(const mesh::Mesh& m, const std::vector<BaseQuad>& base, const std::set<int>& flat,
                       const CutRow& cut, WakeSections& out) {
  auto at_flat_corner = [&](const Quad& q) {
    return std::any_of(q.begin(), q.end(), [&](NodeId v) {
      const mesh::CadAttachment& a = m.cad_attachment(v);
      return a.kind == mesh::CadAttachment::Vertex && flat.count(a.entity) > 0;
    });
  };
  for (const auto& [q, face] : base) {
    if (!std::all_of(q.begin(), q.end(), [&](NodeId v) { return cut.above(m.node(v)); })) {
      out.exposed_base.push_back(q);
    } else if (at_flat_corner(q)) {  // q starts at its flat corner (base_as_triangles)
      out.swept.push_back({{q[0], q[1], q[2], mesh::kNoNode}, false, true, face});
      out.swept.push_back({{q[0], q[2], q[3], mesh::kNoNode}, false, true, face});
    } else {
      out.swept.push_back({q, false, false, face});
    }
  }
}

// The rear interfaces above the cut: the quads (a, b, b', a') over the layer's open edges a-b that
// are not on the root row over the junction (for a sharp edge: those on the crack, not the rims of
// the bare triangles).
void add_rear_interface_sections(const detail::JunctionShell& js, bool sharp, const CutRow& cut, WakeSections& out) {
  const mesh::Mesh& m = js.field.mesh;
  const std::set<int> chain(js.chain.begin(), js.chain.end());
  for (const auto& [a, b] : open_edges(js.layer)) {
    const NodeId na = js.layer_body[a], nb = js.layer_body[b];
    if (chain.count(static_cast<int>(na)) && chain.count(static_cast<int>(nb))) continue;
    if (sharp && !(js.crack[na] && js.crack[nb])) continue;
    if (cut.above(m.node(na)) && cut.above(m.node(nb)))
      out.swept.push_back({{na, nb, static_cast<NodeId>(b) + js.offset, static_cast<NodeId>(a) + js.offset}, true});
  }
}

}  // namespace

CutRow wake_cut_row(const detail::JunctionShell& js, const std::vector<NodeId>& te_nodes, double wall_thickness,
                    const WakeParams& wake) {
  CutRow cut{js.wall, 1e300, 1e-6 * std::max(1.0, js.tip)};
  const double wanted = wall_thickness + wake.gap;
  for (NodeId v : te_nodes) {
    const double h = js.wall.height(js.field.mesh.node(v));
    if (h >= wanted - cut.tolerance && h > js.strip + cut.tolerance) cut.height = std::min(cut.height, h);
  }
  if (!(cut.height < js.tip - cut.tolerance))
    fail("wake.gap = " + number_label(wake.gap) + ": the wake block's root would stand at " + number_label(wanted) +
         " above the wall, leaving no trailing-edge row below the wing's tip (" + number_label(js.tip) +
         "); use a smaller gap");
  return cut;
}

WakeSections wake_sections(const detail::JunctionShell& js, const TrailingEdge& te, const std::vector<BaseQuad>& base,
                           const CutRow& cut) {
  WakeSections sections;
  add_base_sections(js.field.mesh, base, te.flat, cut, sections);
  add_rear_interface_sections(js, te.crack >= 0, cut, sections);
  if (sections.swept.empty()) fail("no trailing edge found: the wing layer has no rear interface above the cut");
  return sections;
}

Outlet find_outlet(const mesh::Mesh& m, const std::vector<Section>& sections, const WakeParams& wake, const Vec3& d,
                   const cad::BBox& box, double tolerance) {
  const std::string why = "output.target = \"pyfr\" runs the wake block to the far field's downstream face (no "
                          "pyramid on its outflow face: PyFR's parallelogram rule, docs/solvers.md)";
  int axis = 0;
  d.cwiseAbs().maxCoeff(&axis);
  if (!(std::abs(d[axis]) > 1.0 - 1e-12))
    fail(why + ", a face of the box across wake.direction, but wake.direction = " + direction_label(wake) +
         " is not along an axis of the box; use an axis, or nearfield.topology = \"C\" for PyFR");
  if (wake.widening_deg != 0.0)
    fail(widening_label(wake) + why + ", which needs its cells to be translates: use wake.widening = 0");
  double lo = 1e300, hi = -1e300, last = -1e300;
  for (const Section& c : sections)
    for (int k = 0; k < (c.triangle ? 3 : 4); ++k) {
      const double along = m.node(c.q[k]).dot(d);
      last = std::max(last, along);
      if (c.layer && k >= 2) lo = std::min(lo, along), hi = std::max(hi, along);  // the block's outer edge
    }
  if (hi - lo > tolerance)
    fail(why + "; the block's outer edge at the trailing edge must then lie in one plane across wake.direction, "
         "but it spans " + number_label(hi - lo) + " along it (a swept, tapered or twisted trailing edge); for "
         "PyFR use nearfield.topology = \"C\"");
  Outlet outlet;
  outlet.along = d[axis] > 0 ? box.hi[axis] : -box.lo[axis];
  outlet.distance = outlet.along - hi;
  if (!(outlet.along - last > tolerance))
    fail(why + ", but the trailing edge reaches that face; use a larger farfield box");
  return outlet;
}

WakeSweep::WakeSweep(mesh::Mesh& m, const WakeParams& wake, const Vec3& d, const std::vector<Section>& sections,
                     const cad::BBox& box, std::vector<double> stations, std::optional<double> outlet)
    : m_(m),
      wake_(wake),
      d_(d),
      s_(std::move(stations)),
      outlet_(outlet),
      spread_(std::tan(wake.widening_deg * kPi / 180.0)),
      inner_(box.lo + 1e-3 * (box.hi - box.lo)),
      outer_(box.hi - 1e-3 * (box.hi - box.lo)) {
  for (const Section& c : sections)
    if (c.layer)
      for (int k : {0, 1}) {
        Vec3 across = m.node(c.q[3 - k]) - m.node(c.q[k]);
        across = (across - across.x() * Vec3::UnitX()).normalized();
        away_[c.q[3 - k]] = across / (across - across.dot(d) * d).norm();
      }
}

const std::vector<NodeId>& WakeSweep::nodes(NodeId p) {
  auto it = swept_.find(p);
  if (it != swept_.end()) return it->second;
  std::vector<NodeId> ids{p};
  const Vec3 x0 = m_.node(p);
  const auto a = away_.find(p);
  for (std::size_t k = 1; k < s_.size(); ++k) {
    const bool on_outlet = outlet_ && k + 1 == s_.size();  // the box's face: checked one station up
    Vec3 x = x0 + s_[k] * d_;
    if (a != away_.end()) x += s_[k] * spread_ * a->second;
    if (on_outlet) x += (*outlet_ - x.dot(d_)) * d_;
    if (!on_outlet && ((x.array() < inner_.array()).any() || (x.array() > outer_.array()).any()))
      fail("wake.length = " + number_label(wake_.length) + " with wake.direction = " + direction_label(wake_) +
           ": the wake block leaves the far-field box at " + point_label(x) + "; use a shorter wake or a larger box");
    ids.push_back(m_.add_node(x));
  }
  return swept_.emplace(p, std::move(ids)).first->second;
}

std::vector<std::vector<NodeId>> add_wake_elements(NearField& field, WakeSweep& sweep,
                                                   const std::vector<Section>& sections, const WakeParams& wake,
                                                   const Vec3& d, int base) {
  std::vector<std::vector<NodeId>> outflow;
  mesh::Mesh& m = field.mesh;
  const int wake_region = m.region_index("wake");
  for (Section c : sections) {
    const int corners = c.triangle ? 3 : 4;
    const Vec3 n = (m.node(c.q[1]) - m.node(c.q[0])).cross(m.node(c.q[corners - 1]) - m.node(c.q[0]));
    int axis = 1;  // the layer direction q0 -> q3
    if (n.dot(d) < 0.0) std::swap(c.q[1], c.q[corners - 1]), axis = 0;
    if (c.triangle)
      m.add_boundary_face("wing", ho::Shape::Triangle, {c.q[0], c.q[2], c.q[1]});
    else if (!c.layer)
      m.add_boundary_face("wing", ho::Shape::Quadrilateral, {c.q[0], c.q[3], c.q[2], c.q[1]});
    const ho::Shape shape = c.triangle ? ho::Shape::Prism : ho::Shape::Hexahedron;
    for (std::size_t k = 0; k + 1 < sweep.stations(); ++k) {
      std::vector<NodeId> h(2 * corners);
      for (int v = 0; v < corners; ++v) h[v] = sweep.nodes(c.q[v])[k], h[v + corners] = sweep.nodes(c.q[v])[k + 1];
      if (!element_valid(m, shape, h))
        fail(widening_label(wake) + "wake.direction = " + direction_label(wake) + ": the wake hex behind " +
             point_label(m.node(c.q[0])) + " at station " + std::to_string(k) +
             " would be inverted (the block folds); use a smaller widening or a direction closer to the chord");
      m.add_element(shape, h, wake_region);
      if (c.layer) field.stacks.push_back({field.element_surface.size(), {LayerDirection{axis, LayerFamily::Wing}}});
      field.element_surface.push_back(c.surface >= 0 ? c.surface : base);  // -1 for a sharp trailing edge: no base
      ++field.wake.hexes;
      if (sweep.to_outlet() && k + 2 == sweep.stations()) {  // the downstream face, wound along d: out of the domain
        outflow.emplace_back(h.begin() + corners, h.end());
        m.add_boundary_face("farfield", c.triangle ? ho::Shape::Triangle : ho::Shape::Quadrilateral, outflow.back());
      }
    }
  }
  return outflow;
}

void add_exposed_body_faces(mesh::Mesh& m, const std::vector<Quad>& exposed_base,
                            const std::vector<std::array<int, 3>>& bare) {
  for (const auto& q : exposed_base) m.add_boundary_face("wing", ho::Shape::Quadrilateral, {q[0], q[3], q[2], q[1]});
  for (const auto& t : bare)
    m.add_boundary_face("wing", ho::Shape::Triangle,
                        {static_cast<NodeId>(t[0]), static_cast<NodeId>(t[2]), static_cast<NodeId>(t[1])});
}

void describe_wake_block(const detail::JunctionShell& js, const WakeSweep& sweep, const std::vector<Section>& sections,
                         const WakeParams& wake, const Vec3& d, double wall_thickness, WakeBlock& w) {
  const mesh::Mesh& m = js.field.mesh;
  w.direction = d;
  w.length = wake.length;
  w.reach = sweep.reach();
  w.streamwise_cells = static_cast<int>(sweep.stations()) - 1;
  double lowest = 1e300;
  for (const auto& [p, ids] : sweep.swept())
    for (NodeId v : ids) lowest = std::min(lowest, js.wall.height(m.node(v)));
  w.gap = lowest - wall_thickness;
  for (const Section& c : sections)  // the trailing-edge nodes: rear interfaces' body side, base pieces
    for (int k = 0; k < (c.layer ? 2 : c.triangle ? 3 : 4); ++k) w.origins.push_back(m.node(c.q[k]));
  if (js.fan.index >= 0) {
    w.origins.push_back(m.node(js.root_id[js.fan.index]));
    for (int v = 0; v < js.body.num_nodes(); ++v)
      if (js.crack[v]) w.origins.push_back(m.node(static_cast<NodeId>(v)));
  }
  const Vec3 span = js.wall.normal - js.wall.normal.dot(d) * d;
  w.span_axis = span.norm() > 1e-6 ? Vec3(span.normalized()) : d.unitOrthogonal();
  std::sort(w.origins.begin(), w.origins.end(),
            [&](const Vec3& p, const Vec3& q) { return p.dot(w.span_axis) < q.dot(w.span_axis); });
}

void check_wake_faces_carry_pyramids(const NearField& field, const WakeSweep& sweep, const WakeParams& wake) {
  const mesh::Mesh& m = field.mesh;
  std::set<NodeId> in_wake;
  for (const auto& [p, ids] : sweep.swept()) in_wake.insert(ids.begin() + 1, ids.end());
  for (const SkinFace& f : field.skin) {
    if (f.count != 4 || std::none_of(f.nodes.begin(), f.nodes.end(), [&](NodeId v) { return in_wake.count(v) > 0; }))
      continue;
    if (!pyramid_apex({m.node(f.nodes[0]), m.node(f.nodes[1]), m.node(f.nodes[2]), m.node(f.nodes[3])}))
      fail(widening_label(wake) + "wake.direction = " + direction_label(wake) +
           ": the wake block folds: its outer face at " + point_label(m.node(f.nodes[0])) +
           " is too warped to carry a pyramid; use a smaller widening or a "
           "direction closer to the chord");
  }
}

}  // namespace h_type

double wake_fraction(const WakeBlock& wake, const Eigen::Vector3d& x) {
  if (wake.origins.empty() || !(wake.length > 0.0)) return 0.0;
  // The distance across `direction` is at least the one along span_axis: search outwards from x's
  // place in the sorted origins and stop where that bound exceeds the best distance found.
  const double key = x.dot(wake.span_axis);
  const auto& o = wake.origins;
  const auto start = std::lower_bound(o.begin(), o.end(), key,
                                      [&](const Eigen::Vector3d& p, double k) { return p.dot(wake.span_axis) < k; }) -
                     o.begin();
  double best = 1e300, s = 0.0;
  auto visit = [&](long i) {
    const double gap = o[i].dot(wake.span_axis) - key;
    if (gap * gap > best) return false;
    const double along = (x - o[i]).dot(wake.direction);
    const double across = (x - o[i] - along * wake.direction).squaredNorm();
    if (across < best) best = across, s = along;
    return true;
  };
  for (long i = start; i < static_cast<long>(o.size()) && visit(i); ++i) {
  }
  for (long i = start - 1; i >= 0 && visit(i); --i) {
  }
  return std::clamp(s / wake.length, 0.0, 1.0);
}

}  // namespace semimesh::nearfield
