#include "semimesh/nearfield/h_shell.hpp"

#include "semimesh/ho/element_type.hpp"
#include "semimesh/ho/validity.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/pyramid_apex.hpp"

#include "junction_shell.hpp"
#include "labels.hpp"
#include "translational_rims.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace semimesh::nearfield {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

namespace detail {

int sharp_trailing_edge(const cad::Model& model, const BodyRoles& roles, const Vec3& d) {
  auto is_body = [&](int s) { return std::count(roles.body_surfaces.begin(), roles.body_surfaces.end(), s) > 0; };
  auto on_wall = [&](int vertex) {
    for (int c : model.curves_of_vertex(vertex))
      for (const cad::SurfaceUse& u : model.surfaces_of_curve(c))
        if (u.surface == roles.wall_surface) return true;
    return false;
  };
  int best = -1;
  double farthest = -1e300;
  for (int c = 0; c < model.num_curves(); ++c) {
    const auto& uses = model.surfaces_of_curve(c);
    if (uses.size() != 2 || !is_body(uses[0].surface) || !is_body(uses[1].surface) || uses[0].surface == uses[1].surface)
      continue;
    for (int v : model.curve_vertices(c))
      if (on_wall(v) && model.vertex(v).point.dot(d) > farthest) farthest = model.vertex(v).point.dot(d), best = c;
  }
  return best;
}

std::set<int> flat_base_corners(const cad::Model& model, int base) {
  constexpr double kFlatCorner = 150.0;  // degrees
  std::set<int> flat;
  for (const cad::Loop& loop : model.loops(base))
    for (std::size_t k = 0; k < loop.uses.size(); ++k) {
      const cad::CurveUse& in = loop.uses[k];
      const cad::CurveUse& out = loop.uses[(k + 1) % loop.uses.size()];
      const cad::Curve& a = model.curve(in.curve);
      const cad::Curve& b = model.curve(out.curve);
      if (a.is_degenerate() || b.is_degenerate()) continue;
      // Tangents leaving the shared vertex along each curve.
      const Vec3 back = in.forward ? Vec3(-a.derivatives(a.bounds().hi).d1) : Vec3(a.derivatives(a.bounds().lo).d1);
      const Vec3 ahead = out.forward ? Vec3(b.derivatives(b.bounds().lo).d1) : Vec3(-b.derivatives(b.bounds().hi).d1);
      const double cosine = back.normalized().dot(ahead.normalized());
      if (cosine < std::cos(kFlatCorner * kPi / 180.0)) {
        const auto ends = model.curve_vertices(out.curve);
        flat.insert(out.forward ? ends[0] : ends[1]);
      }
    }
  return flat;
}

std::vector<double> wake_stations(const WakeParams& wake) {
  std::vector<double> s(wake.layers + 1, 0.0);
  double h = 1.0;
  for (int k = 1; k <= wake.layers; ++k, h *= wake.growth) s[k] = s[k - 1] + h;
  for (double& x : s) x *= wake.length / s.back();
  return s;
}

}  // namespace detail

namespace {

using mesh::NodeId;
using Quad = std::array<NodeId, 4>;

[[noreturn]] void fail(const std::string& what) { throw NearFieldError("near field: " + what); }

// The smallest share of wake.gap the block may keep above the wall layer downstream of its root.
constexpr double kLeastGapFraction = 0.5;

std::string direction_label(const WakeParams& w) {
  return "[" + number_label(w.direction[0]) + ", " + number_label(w.direction[1]) + ", " + number_label(w.direction[2]) + "]";
}

// "wake.widening = W with " when the block widens: a fold may be the widening's doing.
std::string widening_label(const WakeParams& w) {
  return w.widening_deg > 0.0 ? "wake.widening = " + number_label(w.widening_deg) + " with " : std::string();
}

// The [wake] keys in range and the sweep direction: unit, downstream (the wall is checked once the
// junction has found it).
Vec3 wake_direction(const WakeParams& wake) {
  if (const auto bad = params::violation(wake, wake_keys(), "wake")) fail(*bad);
  const Vec3 d0(wake.direction[0], wake.direction[1], wake.direction[2]);
  if (!(d0.norm() > 0.0)) fail("wake.direction = " + direction_label(wake) + ": expected a non-zero vector");
  const Vec3 d = d0.normalized();
  if (!(d.x() > 0.0)) fail("wake.direction = " + direction_label(wake) + " points upstream (x <= 0)");
  return d;
}

// The trailing edge the wake is swept from: squared-off (its base surface, meshed with structured
// quads) or, with te_base "auto" and no base found, sharp (a curve between two body surfaces).
struct TrailingEdge {
  int base = -1;       ///< the base surface; -1: sharp
  int crack = -1;      ///< the sharp edge's curve; -1: blunt
  std::set<int> flat;  ///< the base's flat corners (CAD vertices): swept as prisms
};

TrailingEdge find_trailing_edge(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                                const WakeParams& wake, const Vec3& d) {
  const auto found = model.find_surface(wake.te_base);
  const bool blunt = found && std::count(roles.body_surfaces.begin(), roles.body_surfaces.end(), *found) > 0;
  TrailingEdge te;
  te.base = blunt ? *found : -1;
  te.crack = !blunt && wake.te_base == "auto" ? detail::sharp_trailing_edge(model, roles, d) : -1;
  if (!blunt && te.crack < 0)
    fail("wake.te_base = \"" + wake.te_base +
         "\": no such trailing-edge base among the body surfaces" +
         (wake.te_base == "auto" ? " and no sharp trailing edge (a curve between two body surfaces leaving the wall)"
                                 : "") +
         "; the H-type near field sweeps the wake from the trailing edge");
  if (blunt) {
    te.flat = detail::flat_base_corners(model, te.base);
    const surface::SurfaceMesh& base_mesh = meshes.surfaces.at(te.base);
    if (base_mesh.quads.empty() || !base_mesh.triangles.empty())
      fail("the trailing-edge base " + surface_label(model, te.base) + " must be meshed with structured quads only");
  }
  return te;
}

// The surface meshes with the base's quads as triangle pairs (q0 q1 q2, q0 q2 q3), so the junction
// machinery sees one triangulated body; quad i becomes triangles 2i and 2i + 1 of the base. A quad
// at a flat corner is turned to start there, so its diagonal leaves the corner and halves its angle.
surface::SurfaceMeshes base_as_triangles(const surface::SurfaceMeshes& meshes, int te, const std::set<int>& flat) {
  surface::SurfaceMeshes out = meshes;
  surface::SurfaceMesh& m = out.surfaces.at(te);
  for (auto q : m.quads) {
    for (int k = 0; k < 4 && !flat.count(m.origin[q[0]].vertex); ++k) std::rotate(q.begin(), q.begin() + 1, q.end());
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  m.quads.clear();
  return out;
}

// The C-type wing layer and junction with the base bare (lifted, no prisms) or the layer cracked
// open along the sharp edge.
detail::JunctionShell junction_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes,
                                     const BodyRoles& roles, const ShellParams& params, const JunctionParams& junction,
                                     double wall_thickness, const TrailingEdge& te) {
  return detail::build_junction_shell(model, te.base >= 0 ? base_as_triangles(meshes, te.base, te.flat) : meshes, roles,
                                      params, junction, wall_thickness, te.base, te.crack);
}

// A sharp trailing edge's root (js.fan): its three legs, side 0, middle and side 1 (feet on the
// wall, tops at the halos). The junction gives the two sides'; the middle one, added here, stands
// on the bisector of the feet (whose legs from the root open by less than 180 degrees, downstream):
// the wedge between the two halos is filled in two halves (fill_fan_wedge). Its legs from the
// strip top may open by more than 180 degrees where the edge sweeps back. No fan: kNoNode.
struct FanLegs {
  std::array<NodeId, 3> foot{mesh::kNoNode, mesh::kNoNode, mesh::kNoNode}, top = foot;
};

FanLegs add_fan_middle_leg(const cad::Model& model, int wall_surface, detail::JunctionShell& js) {
  FanLegs legs;
  if (js.fan.index < 0) return legs;
  mesh::Mesh& m = js.field.mesh;
  const Vec3 r = m.node(js.root_id[js.fan.index]);
  const Vec3 a = m.node(js.fan.foot[0]) - r, b = m.node(js.fan.foot[1]) - r;
  const auto foot = model.surface(wall_surface).project(r + 0.5 * (a.norm() + b.norm()) * (a.normalized() + b.normalized()).normalized());
  legs.foot = {js.fan.foot[0],
               m.add_node(foot.point, {mesh::CadAttachment::Surface, wall_surface, foot.uv.x(), foot.uv.y()}),
               js.fan.foot[1]};
  const Vec3 rise = 0.5 * (m.node(js.fan.top[0]) - m.node(js.fan.foot[0]) + m.node(js.fan.top[1]) - m.node(js.fan.foot[1]));
  legs.top = {js.fan.top[0], m.add_node(foot.point + rise), js.fan.top[1]};
  return legs;
}

// The footprint (wall feet) and its tops (strip tops' offsets, the halos) along the root loop, the
// fan's three legs in place of its root's one.
void record_footprint(const detail::JunctionShell& js, const FanLegs& fan, NearField& field) {
  for (std::size_t i = 0; i < js.chain.size(); ++i) {
    const bool at_fan = static_cast<int>(i) == js.fan.index;
    field.footprint.push_back(js.foot_id[i]);
    field.footprint_top.push_back(at_fan ? js.fan.top[0] : static_cast<NodeId>(js.chain[i]) + js.offset);
    if (at_fan)
      for (int leg : {1, 2}) field.footprint.push_back(fan.foot[leg]), field.footprint_top.push_back(fan.top[leg]);
  }
}

// The base's quads (body node ids, lifted), rebuilt from the triangle pairs of base_as_triangles;
// none for a sharp trailing edge.
std::vector<Quad> base_quads(const detail::JunctionShell& js, int base) {
  std::vector<Quad> quads;
  std::vector<std::array<int, 3>> pair;
  for (std::size_t t = 0; t < js.body.triangles.size(); ++t) {
    if (js.body.triangle_surface[t] != base) continue;
    const auto& v = js.body.triangles[t];
    if (pair.empty()) {
      pair.push_back(v);
    } else {
      quads.push_back({static_cast<NodeId>(pair[0][0]), static_cast<NodeId>(pair[0][1]),
                       static_cast<NodeId>(pair[0][2]), static_cast<NodeId>(v[2])});
      pair.clear();
    }
  }
  return quads;
}

// The trailing-edge nodes: the base's, or the sharp trailing edge's inner ones.
std::vector<NodeId> trailing_edge_nodes(const detail::JunctionShell& js, const std::vector<Quad>& base) {
  std::vector<NodeId> nodes;
  for (const auto& q : base) nodes.insert(nodes.end(), q.begin(), q.end());
  for (int v = 0; v < js.body.num_nodes(); ++v)
    if (js.crack[v]) nodes.push_back(static_cast<NodeId>(v));
  return nodes;
}

// The cut row, the wake block's root: the lowest trailing-edge row at least `gap` above the wall
// layer's top (and above the root strip); the block is swept from the rows at or above it.
struct CutRow {
  detail::WallFrame wall;
  double height = 1e300, tolerance = 0.0;
  bool above(const Vec3& x) const { return wall.height(x) >= height - tolerance; }
};

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

// One piece of the wake's cross-section at the trailing edge: q0 -> q1 its body-side edge and
// q0 -> q3 its layer direction for a rear interface (`layer`); a base quad otherwise.
struct Section {
  std::array<NodeId, 4> q;
  bool layer = false;
  bool triangle = false;  ///< a base triangle (q[3] unused): swept into a prism
};

struct WakeSections {
  std::vector<Section> swept;        ///< base pieces, then rear interfaces, above the cut
  std::vector<Quad> exposed_base;    ///< base quads below the cut: faced by the far field
};

// The base quads above the cut as sections; a quad at a flat corner as two triangles split from
// the corner (a hex there would have a vanishing Jacobian at the corner once curved).
void add_base_sections(const mesh::Mesh& m, const std::vector<Quad>& base, const std::set<int>& flat,
                       const CutRow& cut, WakeSections& out) {
  auto at_flat_corner = [&](const Quad& q) {
    return std::any_of(q.begin(), q.end(), [&](NodeId v) {
      const mesh::CadAttachment& a = m.cad_attachment(v);
      return a.kind == mesh::CadAttachment::Vertex && flat.count(a.entity) > 0;
    });
  };
  for (const auto& q : base) {
    if (!std::all_of(q.begin(), q.end(), [&](NodeId v) { return cut.above(m.node(v)); })) {
      out.exposed_base.push_back(q);
    } else if (at_flat_corner(q)) {  // q starts at its flat corner (base_as_triangles)
      out.swept.push_back({{q[0], q[1], q[2], mesh::kNoNode}, false, true});
      out.swept.push_back({{q[0], q[2], q[3], mesh::kNoNode}, false, true});
    } else {
      out.swept.push_back({q, false});
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

WakeSections wake_sections(const detail::JunctionShell& js, const TrailingEdge& te, const std::vector<Quad>& base,
                           const CutRow& cut) {
  WakeSections sections;
  add_base_sections(js.field.mesh, base, te.flat, cut, sections);
  add_rear_interface_sections(js, te.crack >= 0, cut, sections);
  if (sections.swept.empty()) fail("no trailing edge found: the wing layer has no rear interface above the cut");
  return sections;
}

// The wake's nodes: node p at station k is p + s_k d, the layer offsets also moved away from the
// sheet by tan(widening) per unit length across d, within the trailing edge's cross-section (across
// the streamwise axis x, as the base and the rear interfaces): moved across d instead, at
// incidence the two sides' offsets (and the tip corners') would leave that plane by opposite
// amounts, warping the block's outflow and tip faces until they fold. A node's stations are made
// when first asked for, so node ids follow the order the elements use them.
class WakeSweep {
 public:
  WakeSweep(mesh::Mesh& m, const WakeParams& wake, const Vec3& d, const std::vector<Section>& sections,
            const cad::BBox& box)
      : m_(m), wake_(wake), d_(d), s_(detail::wake_stations(wake)), spread_(std::tan(wake.widening_deg * kPi / 180.0)),
        inner_(box.lo + 1e-3 * (box.hi - box.lo)), outer_(box.hi - 1e-3 * (box.hi - box.lo)) {
    for (const Section& c : sections)
      if (c.layer)
        for (int k : {0, 1}) {
          Vec3 across = m.node(c.q[3 - k]) - m.node(c.q[k]);
          across = (across - across.x() * Vec3::UnitX()).normalized();
          away_[c.q[3 - k]] = across / (across - across.dot(d) * d).norm();
        }
  }

  /// [stations] p's node at each station, p itself first.
  const std::vector<NodeId>& nodes(NodeId p) {
    auto it = swept_.find(p);
    if (it != swept_.end()) return it->second;
    std::vector<NodeId> ids{p};
    const Vec3 x0 = m_.node(p);
    const auto a = away_.find(p);
    for (std::size_t k = 1; k < s_.size(); ++k) {
      Vec3 x = x0 + s_[k] * d_;
      if (a != away_.end()) x += s_[k] * spread_ * a->second;
      if ((x.array() < inner_.array()).any() || (x.array() > outer_.array()).any())
        fail("wake.length = " + number_label(wake_.length) + " with wake.direction = " + direction_label(wake_) +
             ": the wake block leaves the far-field box at " + point_label(x) + "; use a shorter wake or a larger box");
      ids.push_back(m_.add_node(x));
    }
    return swept_.emplace(p, std::move(ids)).first->second;
  }

  std::size_t stations() const { return s_.size(); }
  /// trailing-edge node -> its nodes at every station
  const std::map<NodeId, std::vector<NodeId>>& swept() const { return swept_; }

 private:
  mesh::Mesh& m_;
  const WakeParams& wake_;
  Vec3 d_;
  std::vector<double> s_;
  double spread_;
  Vec3 inner_, outer_;          ///< the far-field box, a little inside
  std::map<NodeId, Vec3> away_;  ///< offset node -> direction in the cross-section, of unit part across d
  std::map<NodeId, std::vector<NodeId>> swept_;
};

bool element_valid(const mesh::Mesh& m, ho::Shape shape, const std::vector<NodeId>& v) {
  Eigen::MatrixX3d x(v.size(), 3);
  for (std::size_t k = 0; k < v.size(); ++k) x.row(k) = m.node(v[k]).transpose();
  return ho::certify_jacobian(shape, 1, ho::NodeSet::Equispaced, x).valid;
}

// The wake block's elements, station by station behind each section (hexes; prisms behind a flat
// corner's triangles), turned to sweep along d; the base's pieces faced as wing boundary. Hexes
// over rear interfaces continue their wing layer (a stack of the wing family); the base's are not
// split.
void add_wake_elements(NearField& field, WakeSweep& sweep, const std::vector<Section>& sections,
                       const WakeParams& wake, const Vec3& d, int base) {
  mesh::Mesh& m = field.mesh;
  const int wake_region = m.region_index("wake");
  for (Section c : sections) {
    const int corners = c.triangle ? 3 : 4;
    const Vec3 n = (m.node(c.q[1]) - m.node(c.q[0])).cross(m.node(c.q[corners - 1]) - m.node(c.q[0]));
    int axis = 1;  // the layer direction q0 -> q3
    if (n.dot(d) < 0.0) std::swap(c.q[1], c.q[corners - 1]), axis = 0;
    if (c.triangle) m.add_boundary_face("wing", ho::Shape::Triangle, {c.q[0], c.q[2], c.q[1]});
    else if (!c.layer) m.add_boundary_face("wing", ho::Shape::Quadrilateral, {c.q[0], c.q[3], c.q[2], c.q[1]});
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
      field.element_surface.push_back(base);  // -1 for a sharp trailing edge: no base
      ++field.wake.hexes;
    }
  }
}

// The body faces no element stands on: the base quads below the cut, the bare triangles at a sharp
// edge's tip end (wing boundary, facing into the body as the layer's).
void add_exposed_body_faces(mesh::Mesh& m, const std::vector<Quad>& exposed_base,
                            const std::vector<std::array<int, 3>>& bare) {
  for (const auto& q : exposed_base) m.add_boundary_face("wing", ho::Shape::Quadrilateral, {q[0], q[3], q[2], q[1]});
  for (const auto& t : bare)
    m.add_boundary_face("wing", ho::Shape::Triangle,
                        {static_cast<NodeId>(t[0]), static_cast<NodeId>(t[2]), static_cast<NodeId>(t[1])});
}

// The WakeBlock the split's ratio along the wake reads: its direction, length, measured gap and the
// trailing-edge nodes it is swept from, sorted along the span axis. A sharp edge's nodes below the
// cut and its root R count too: the ratio there is the trailing edge's own (r), at R and W alike.
// The junction hexes beside the fan interpolate their layer interfaces between R's and W's along
// R-W, the fan's pieces (cut in advance, straight from R's cut to W's) only match that when both
// are the same.
void describe_wake_block(const detail::JunctionShell& js, const WakeSweep& sweep, const std::vector<Section>& sections,
                         const WakeParams& wake, const Vec3& d, double wall_thickness, WakeBlock& w) {
  const mesh::Mesh& m = js.field.mesh;
  w.direction = d;
  w.length = wake.length;
  w.streamwise_cells = wake.layers;
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

// The split's interface nodes placed ahead of it on layer edges: (bottom vertex, top vertex, k) ->
// node (a sharp trailing edge's nodes have two layer edges, one per side).
using InterfaceNodes = std::map<std::tuple<NodeId, NodeId, int>, NodeId>;

// The fan's legs cut at the split's interfaces: per leg (side 0, middle, side 1) the nodes from
// the root R to the foot (`low`) and from the strip top W to the halo (`high`).
struct FanRows {
  std::array<std::vector<NodeId>, 3> low, high;
};

FanRows cut_fan_legs(mesh::Mesh& m, NodeId r, NodeId top, const FanLegs& legs, const std::vector<double>& at_root,
                     const std::vector<double>& at_top, InterfaceNodes& interface_node) {
  FanRows rows;
  for (int leg : {0, 1, 2}) {
    const NodeId foot = legs.foot[leg], halo = legs.top[leg];
    rows.low[leg] = {r}, rows.high[leg] = {top};
    for (std::size_t k = 1; k + 1 < at_root.size(); ++k) {
      rows.low[leg].push_back(m.add_node(m.node(r) + at_root[k] * (m.node(foot) - m.node(r))));
      rows.high[leg].push_back(m.add_node(m.node(top) + at_top[k] * (m.node(halo) - m.node(top))));
      interface_node[{r, foot, static_cast<int>(k)}] = rows.low[leg].back();
      interface_node[{top, halo, static_cast<int>(k)}] = rows.high[leg].back();
    }
    rows.low[leg].push_back(foot), rows.high[leg].push_back(halo);
  }
  return rows;
}

// One piece of the fan's wedge (a prism of the junction standing on the wall, split with the wall
// layer along R-W), its vertices in the order that makes it valid.
void add_fan_piece(NearField& field, int wall_surface, NodeId r, ho::Shape shape, std::vector<NodeId> v) {
  mesh::Mesh& m = field.mesh;
  const int half = static_cast<int>(v.size()) / 2;
  if (!element_valid(m, shape, v)) {  // the other way round
    std::reverse(v.begin() + 1, v.begin() + half);
    std::reverse(v.begin() + half + 1, v.end());
    if (!element_valid(m, shape, v))
      fail("the junction's wedge at the sharp trailing edge's root " + point_label(m.node(r)) + " would be inverted");
  }
  field.stacks.push_back({field.element_surface.size(), {LayerDirection{2, LayerFamily::Wall}}});
  field.element_surface.push_back(wall_surface);
  m.add_element(shape, v, m.region_index("junction"));
  if (shape == ho::Shape::Prism) m.add_boundary_face("wall", ho::Shape::Triangle, {v[0], v[2], v[1]});
  else m.add_boundary_face("wall", ho::Shape::Quadrilateral, {v[0], v[3], v[2], v[1]});
}

// A sharp trailing edge's root: the wedge between its two halos (root R, strip top W, feet L_0
// L_1, halos H_0 H_1) is a prism R L_0 L_1 / W H_0 H_1 standing on the wall, split by the wall
// layer's split along R-W (a stack of the wall family), in two halves about the middle leg.
// Across, the junction hexes beside it split their faces R-W-H-L at the wing layer's interfaces,
// a fan from R the split cannot make: the prisms are given here already cut there (an inner
// prism and bands of prisms around it, at the interfaces the split will use: `fractions`), and
// the weld after the split joins their nodes to the hexes' (as the far field's pre-cut skin quads).
// Returns the nodes on each face R-W-H-L the fan shares with a junction hex (none without a fan).
std::vector<std::set<NodeId>> fill_fan_wedge(NearField& field, const detail::JunctionShell& js, const FanLegs& legs,
                                             int wall_surface, const LayerFractions& fractions,
                                             InterfaceNodes& interface_node) {
  if (js.fan.index < 0) return {};
  mesh::Mesh& m = field.mesh;
  const NodeId r = js.root_id[js.fan.index], top = static_cast<NodeId>(js.chain[js.fan.index]);
  std::vector<double> at_root{0.0, 1.0}, at_top{0.0, 1.0};
  if (fractions) at_root = fractions(m.node(r), field.wake), at_top = fractions(m.node(top), field.wake);
  for (std::size_t k = 0; k < at_root.size(); ++k)
    if (std::abs(at_root[k] - at_top[k]) > 1e-12)
      fail("the wing layer's ratio differs between the sharp trailing edge's root " + point_label(m.node(r)) +
           " and the top of its root strip " + point_label(m.node(top)) +
           " (a boundary_layer.ratio_line?): the junction's wedge there takes one ratio; make it the same at both");
  const FanRows rows = cut_fan_legs(m, r, top, legs, at_root, at_top, interface_node);
  std::vector<std::set<NodeId>> planes;
  for (int leg : {0, 2}) {  // the middle leg's plane is inside the fan
    planes.emplace_back(rows.low[leg].begin(), rows.low[leg].end());
    planes.back().insert(rows.high[leg].begin(), rows.high[leg].end());
  }
  // Each band between two interfaces as two prisms (its diagonal from side 0's inner corner):
  // the fan opens by nearly 180 degrees, so a band is a sliver whose top, a quad, would carry a
  // pyramid leaning over the rear interfaces beside it; triangles take tetrahedra.
  const auto& low = rows.low;
  const auto& high = rows.high;
  for (const auto& [p, q] : {std::pair{0, 1}, std::pair{1, 2}}) {  // the two halves
    add_fan_piece(field, wall_surface, r, ho::Shape::Prism, {r, low[p][1], low[q][1], top, high[p][1], high[q][1]});
    for (std::size_t k = 1; k + 1 < low[p].size(); ++k) {
      add_fan_piece(field, wall_surface, r, ho::Shape::Prism,
                    {low[p][k], low[p][k + 1], low[q][k + 1], high[p][k], high[p][k + 1], high[q][k + 1]});
      add_fan_piece(field, wall_surface, r, ho::Shape::Prism,
                    {low[p][k], low[q][k + 1], low[q][k], high[p][k], high[q][k + 1], high[q][k]});
    }
  }
  return planes;
}

// Every face by its sorted vertices: how many elements use it (a boundary face counts twice, so it
// is never skin) and the last element face seen with its vertices in that element's order.
std::map<std::vector<NodeId>, std::pair<int, SkinFace>> face_uses(const mesh::Mesh& m) {
  std::map<std::vector<NodeId>, std::pair<int, SkinFace>> uses;
  auto key = [](std::vector<NodeId> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  for (const mesh::Element& e : m.elements())
    for (const std::vector<int>& f : ho::faces(e.shape)) {
      SkinFace face;
      face.count = static_cast<int>(f.size());
      std::vector<NodeId> v;
      for (int k = 0; k < face.count; ++k) v.push_back(face.nodes[k] = e.vertices[f[k]]);
      if (face.count == 3) face.nodes[3] = mesh::kNoNode;
      auto& slot = uses[key(v)];
      ++slot.first, slot.second = face;
    }
  for (const mesh::BoundaryFace& b : m.boundary_faces()) {
    const int count = b.shape == ho::Shape::Triangle ? 3 : 4;
    uses[key(std::vector<NodeId>(b.vertices.begin(), b.vertices.begin() + count))].first += 2;
  }
  return uses;
}

// The skin: faces used by one element that are not body or wall faces and do not stand on the
// footprint (those the wall layer's prisms share) or on a face the fan shares with a junction
// hex, plus the exposed body faces.
std::vector<SkinFace> skin_faces(const NearField& field, const std::vector<std::set<NodeId>>& fan_planes,
                                 const std::vector<Quad>& exposed_base, const std::vector<std::array<int, 3>>& bare) {
  std::set<NodeId> on_footprint(field.footprint.begin(), field.footprint.end());
  on_footprint.insert(field.footprint_top.begin(), field.footprint_top.end());
  auto all_in = [](const std::vector<NodeId>& face, const std::set<NodeId>& nodes) {
    return std::all_of(face.begin(), face.end(), [&](NodeId v) { return nodes.count(v) > 0; });
  };
  std::vector<SkinFace> skin;
  for (const auto& [k, use] : face_uses(field.mesh))
    if (use.first == 1 && !all_in(k, on_footprint) &&
        std::none_of(fan_planes.begin(), fan_planes.end(), [&](const std::set<NodeId>& plane) { return all_in(k, plane); }))
      skin.push_back(use.second);
  for (const auto& q : exposed_base) skin.push_back({{q[0], q[1], q[2], q[3]}, 4});
  for (const auto& t : bare)
    skin.push_back({{static_cast<NodeId>(t[0]), static_cast<NodeId>(t[1]), static_cast<NodeId>(t[2]), mesh::kNoNode}, 3});
  return skin;
}

// Vertex pairs (bottom, top) along reference axis 0, 1, 2 of a hexahedron (Gmsh order).
constexpr int kHexAxisEdges[3][4][2] = {{{0, 1}, {3, 2}, {4, 5}, {7, 6}},
                                        {{0, 3}, {1, 2}, {4, 7}, {5, 6}},
                                        {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// Every layer edge of the near field's stacks by its sorted ends: (bottom vertex, top vertex, family).
using LayerEdges = std::map<std::pair<NodeId, NodeId>, std::tuple<NodeId, NodeId, LayerFamily>>;

LayerEdges layer_edges(const NearField& f) {
  LayerEdges edges;
  for (const LayerStack& s : f.stacks) {
    const mesh::Element& e = f.mesh.elements()[s.element];
    for (const LayerDirection& d : s.directions) {
      auto add = [&](int a, int b) {
        const NodeId u = e.vertices[a], w = e.vertices[b];
        edges[{std::min(u, w), std::max(u, w)}] = {u, w, d.family};
      };
      if (e.shape == ho::Shape::Prism)
        for (int i = 0; i < 3; ++i) add(i, i + 3);
      else
        for (const auto& pair : kHexAxisEdges[d.axis]) add(pair[0], pair[1]);
    }
  }
  return edges;
}

// The split's interfaces on the wing layer's edges as nodes, made once and shared by every skin
// quad on an edge.
class LayerEdgeCuts {
 public:
  LayerEdgeCuts(NearField& field, const LayerFractions& fractions, InterfaceNodes& made)
      : field_(field), fractions_(fractions), edges_(layer_edges(field)), made_(made) {}

  bool is_layer_edge(NodeId a, NodeId b) const { return edges_.count({std::min(a, b), std::max(a, b)}) > 0; }

  /// [interfaces] the nodes from -> to on a layer edge.
  std::vector<NodeId> along(NodeId from, NodeId to) {
    mesh::Mesh& m = field_.mesh;
    const auto& [bottom, top, family] = edges_.at({std::min(from, to), std::max(from, to)});
    if (family != LayerFamily::Wing)
      fail("the skin quad at " + point_label(m.node(from)) + " is cut by the wall layer's split (not supported)");
    const std::vector<double> f = fractions_(m.node(bottom), field_.wake);
    std::vector<NodeId> ids;
    for (std::size_t k = 0; k < f.size(); ++k) {
      NodeId id = k == 0 ? bottom : k + 1 == f.size() ? top : mesh::kNoNode;
      if (id == mesh::kNoNode) {
        auto [it, fresh] = made_.emplace(std::make_tuple(bottom, top, static_cast<int>(k)), mesh::kNoNode);
        if (fresh) it->second = m.add_node(m.node(bottom) + f[k] * (m.node(top) - m.node(bottom)));
        id = it->second;
      }
      ids.push_back(id);
    }
    if (bottom != from) std::reverse(ids.begin(), ids.end());
    return ids;
  }

 private:
  NearField& field_;
  const LayerFractions& fractions_;
  LayerEdges edges_;
  InterfaceNodes& made_;
};

// Skin quads the split will cut (two opposite layer edges), cut already at its interfaces so the
// far field's pyramids and tetrahedra match the split elements' faces once welded; the others as
// they are. No fractions: the layer is not split.
void cut_skin_at_split_interfaces(NearField& field, const std::vector<SkinFace>& skin, const LayerFractions& fractions,
                                  InterfaceNodes& interface_node) {
  LayerEdgeCuts cuts(field, fractions, interface_node);
  field.skin.clear();
  for (SkinFace f : skin) {
    if (f.count == 4 && fractions && !cuts.is_layer_edge(f.nodes[0], f.nodes[3]) && cuts.is_layer_edge(f.nodes[0], f.nodes[1]))
      f.nodes = {f.nodes[1], f.nodes[2], f.nodes[3], f.nodes[0]};
    if (f.count != 4 || !fractions || !cuts.is_layer_edge(f.nodes[0], f.nodes[3]) ||
        !cuts.is_layer_edge(f.nodes[1], f.nodes[2])) {
      field.skin.push_back(f);
      continue;
    }
    const std::vector<NodeId> left = cuts.along(f.nodes[0], f.nodes[3]), right = cuts.along(f.nodes[1], f.nodes[2]);
    for (std::size_t k = 0; k + 1 < left.size(); ++k)
      field.skin.push_back({{left[k], right[k], right[k + 1], left[k + 1]}, 4});
  }
}

// The block's outer faces must stay flat enough to carry the far field's pyramids.
void check_wake_faces_carry_pyramids(const NearField& field, const WakeSweep& sweep, const WakeParams& wake) {
  const mesh::Mesh& m = field.mesh;
  std::set<NodeId> in_wake;
  for (const auto& [p, ids] : sweep.swept()) in_wake.insert(ids.begin() + 1, ids.end());
  for (const SkinFace& f : field.skin) {
    if (f.count != 4 || std::none_of(f.nodes.begin(), f.nodes.end(), [&](NodeId v) { return in_wake.count(v) > 0; }))
      continue;
    if (!pyramid_apex({m.node(f.nodes[0]), m.node(f.nodes[1]), m.node(f.nodes[2]), m.node(f.nodes[3])}))
      fail(widening_label(wake) + "wake.direction = " + direction_label(wake) + ": the wake block folds: its outer face at " +
           point_label(m.node(f.nodes[0])) + " is too warped to carry a pyramid; use a smaller widening or a "
           "direction closer to the chord");
  }
}

}  // namespace

double wake_fraction(const WakeBlock& wake, const Eigen::Vector3d& x) {
  if (wake.origins.empty() || !(wake.length > 0.0)) return 0.0;
  // The distance across `direction` is at least the one along span_axis: search outwards from x's
  // place in the sorted origins and stop where that bound exceeds the best distance found.
  const double key = x.dot(wake.span_axis);
  const auto& o = wake.origins;
  const auto start = std::lower_bound(o.begin(), o.end(), key, [&](const Eigen::Vector3d& p, double k) {
                       return p.dot(wake.span_axis) < k;
                     }) - o.begin();
  double best = 1e300, s = 0.0;
  auto visit = [&](long i) {
    const double gap = o[i].dot(wake.span_axis) - key;
    if (gap * gap > best) return false;
    const double along = (x - o[i]).dot(wake.direction);
    const double across = (x - o[i] - along * wake.direction).squaredNorm();
    if (across < best) best = across, s = along;
    return true;
  };
  for (long i = start; i < static_cast<long>(o.size()) && visit(i); ++i) {}
  for (long i = start - 1; i >= 0 && visit(i); --i) {}
  return std::clamp(s / wake.length, 0.0, 1.0);
}

const params::Table<WakeParams>& wake_keys() {
  static const params::Table<WakeParams> table = {
      params::reals("direction", &WakeParams::direction, "",
                    "H: the wake block's sweep direction (the freestream), x > 0 and not into the wall"),
      params::real("length", &WakeParams::length, "> 0", "H: the wake block's length behind the trailing edge, model units"),
      params::integer("layers", &WakeParams::layers, "[1, 1000]", "H: streamwise cells of the wake block"),
      params::real("growth", &WakeParams::growth, "[1, 3]", "H: each streamwise cell this times the previous one"),
      params::real("widening", &WakeParams::widening_deg, "[0, 45)",
                   "H: angle (degrees) by which the block's cross-flow thickness grows downstream"),
      params::real("gap", &WakeParams::gap, "> 0", "H: height of the wake block's root above the wall layer's top"),
      params::real("ratio_end", &WakeParams::ratio_end, ">= 1",
                   "H: the layer ratio at the wake's far end (r at the trailing edge, linear in between)"),
      params::string("te_base", &WakeParams::te_base, "non-empty", "H: the squared-off trailing edge's surface, by name or \"#id\"; \"auto\": the narrow body face at the root's downstream end, or a sharp trailing edge"),
  };
  return table;
}

// The method's steps (h_shell.hpp): the trailing edge, the C-type layer and junction around a bare
// base or a cracked sharp edge, the wake block swept from the cut row, a sharp edge's fan, and the
// skin handed to the far field, pre-cut where the split will cut it.
NearField build_h_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params, const JunctionParams& junction, double wall_thickness,
                        const WakeParams& wake, const cad::BBox& box, const LayerFractions& fractions) {
  const Vec3 d = wake_direction(wake);
  const TrailingEdge te = find_trailing_edge(model, meshes, roles, wake, d);
  detail::JunctionShell js = junction_shell(model, meshes, roles, params, junction, wall_thickness, te);
  if (wake.translational_rear_interfaces) detail::make_rear_interfaces_translational(js);
  if (d.dot(js.wall.normal) < -1e-12) fail("wake.direction = " + direction_label(wake) + " points into the wall");
  NearField& field = js.field;
  const FanLegs fan = add_fan_middle_leg(model, roles.wall_surface, js);
  record_footprint(js, fan, field);

  const std::vector<Quad> base = base_quads(js, te.base);
  const CutRow cut = wake_cut_row(js, trailing_edge_nodes(js, base), wall_thickness, wake);
  const WakeSections sections = wake_sections(js, te, base, cut);
  WakeSweep sweep(field.mesh, wake, d, sections.swept, box);
  add_wake_elements(field, sweep, sections.swept, wake, d, te.base);
  add_exposed_body_faces(field.mesh, sections.exposed_base, js.bare);
  describe_wake_block(js, sweep, sections.swept, wake, d, wall_thickness, field.wake);
  // A curved wall may rise under the block downstream (a fuselage widening): the gap must hold
  // along the whole block, not only at its root.
  if (!(field.wake.gap > kLeastGapFraction * wake.gap))
    fail("the wall rises under the wake block: it comes within " + number_label(field.wake.gap) +
         " of the wall layer's top (wake.gap = " + number_label(wake.gap) + " at the trailing edge); use a larger "
         "wake.gap, a shorter wake.length or a wake.direction that follows the wall");

  InterfaceNodes interface_node;
  const auto fan_planes = fill_fan_wedge(field, js, fan, roles.wall_surface, fractions, interface_node);
  cut_skin_at_split_interfaces(field, skin_faces(field, fan_planes, sections.exposed_base, js.bare), fractions,
                               interface_node);
  check_wake_faces_carry_pyramids(field, sweep, wake);
  return std::move(field);
}

}  // namespace semimesh::nearfield
