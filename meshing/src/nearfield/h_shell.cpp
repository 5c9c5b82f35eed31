#include "semimesh/nearfield/h_shell.hpp"

#include "semimesh/ho/validity.hpp"
#include "semimesh/nearfield/detail/trailing_edge.hpp"

#include "h_shell_steps.hpp"
#include "labels.hpp"
#include "translational_rims.hpp"

#include <algorithm>
#include <cmath>

namespace semimesh::nearfield {

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

namespace {

// Faces whose longest curve, and curves, under this share of the base's longest curve or the
// crack's length are slivers, not panels (the ONERA M6's tip faces at its trailing edge).
constexpr double kSliver = 0.1;

bool is_body(const BodyRoles& roles, int s) {
  return std::count(roles.body_surfaces.begin(), roles.body_surfaces.end(), s) > 0;
}

// The body surfaces across the curves of `s` (other than s).
std::set<int> body_neighbours(const cad::Model& model, const BodyRoles& roles, int s) {
  std::set<int> out;
  for (const cad::Loop& loop : model.loops(s))
    for (const cad::CurveUse& use : loop.uses)
      for (const cad::SurfaceUse& u : model.surfaces_of_curve(use.curve))
        if (u.surface != s && is_body(roles, u.surface)) out.insert(u.surface);
  return out;
}

double longest_curve(const cad::Model& model, int s) {
  double longest = 0.0;
  for (const cad::Loop& loop : model.loops(s))
    for (const cad::CurveUse& use : loop.uses) longest = std::max(longest, model.curve(use.curve).length());
  return longest;
}

bool borders_any(const cad::Model& model, const BodyRoles& roles, int s, const std::set<int>& others) {
  for (int n : body_neighbours(model, roles, s))
    if (others.count(n)) return true;
  return false;
}

// The face's outward normal averaged over a grid of its points (its middle's when the grid misses
// the trimmed face).
Vec3 mean_normal(const cad::Surface& face) {
  constexpr int kGrid = 5;
  const auto box = face.bounds();
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const cad::Vec2 uv(box[0].lo + box[0].length() * (i + 0.5) / kGrid, box[1].lo + box[1].length() * (j + 0.5) / kGrid);
      if (face.contains(uv)) sum += face.normal(uv);
    }
  if (!(sum.norm() > 0.0)) sum = face.normal(cad::Vec2(box[0].lo + 0.5 * box[0].length(), box[1].lo + 0.5 * box[1].length()));
  return sum.normalized();
}

// Whether face n goes on with the base face s: no sliver, and facing the same way (their mean normals
// within 45 degrees). A base's skins face across the stream and its tip along the span, at ~90
// degrees; its other half, or the next panel's base past a crank, downstream as it does.
bool continues_base(const cad::Model& model, int s, int n) {
  constexpr double kSameWay = 0.7071;  // cos 45 degrees
  return longest_curve(model, n) > kSliver * longest_curve(model, s) &&
         mean_normal(model.surface(s)).dot(mean_normal(model.surface(n))) > kSameWay;
}

// How nearly face n faces the way the base faces it borders do: the largest cosine between their
// mean normals.
double alignment_with_base(const cad::Model& model, const BodyRoles& roles, const std::vector<int>& base, int n) {
  const std::set<int> around = body_neighbours(model, roles, n);
  double best = -1.0;
  for (int s : base)
    if (around.count(s)) best = std::max(best, mean_normal(model.surface(s)).dot(mean_normal(model.surface(n))));
  return best;
}

}  // namespace

std::vector<int> trailing_edge_base(const cad::Model& model, const BodyRoles& roles, int root_face) {
  std::set<int> faces{root_face};
  std::vector<int> to_visit{root_face};
  while (!to_visit.empty()) {
    const int s = to_visit.back();
    to_visit.pop_back();
    for (int n : body_neighbours(model, roles, s))
      if (!faces.count(n) && continues_base(model, s, n)) faces.insert(n), to_visit.push_back(n);
  }
  return {faces.begin(), faces.end()};
}

int trailing_edge_continuation(const cad::Model& model, const BodyRoles& roles, const std::vector<int>& base,
                               int crack) {
  if (!base.empty()) {
    std::set<int> around;
    double span = 0.0;
    for (int s : base) {
      for (int n : body_neighbours(model, roles, s))
        if (!std::count(base.begin(), base.end(), n)) around.insert(n);
      span = std::max(span, longest_curve(model, s));
    }
    // Of several candidates (a tip of slivers leaves both a skin and a base's other half bordering
    // nothing else), the one facing most nearly as the base: where the trailing edge goes on.
    int next = -1;
    double next_alignment = -2.0;
    for (int n : around) {
      std::set<int> others = around;
      others.erase(n);
      if (borders_any(model, roles, n, others) || !(longest_curve(model, n) > kSliver * span)) continue;
      if (const double a = alignment_with_base(model, roles, base, n); a > next_alignment) next = n, next_alignment = a;
    }
    return next;
  }
  if (crack < 0) return -1;
  std::set<int> sides;
  for (const cad::SurfaceUse& u : model.surfaces_of_curve(crack)) sides.insert(u.surface);
  for (int v : model.curve_vertices(crack))
    for (int c : model.curves_of_vertex(v)) {
      const auto& uses = model.surfaces_of_curve(c);
      if (c == crack || uses.size() != 2 || uses[0].surface == uses[1].surface ||
          model.curve(c).length() <= kSliver * model.curve(crack).length())
        continue;
      bool next_panel = true;
      for (const cad::SurfaceUse& u : uses) next_panel = next_panel && is_body(roles, u.surface) && !sides.count(u.surface);
      if (next_panel) return c;
    }
  return -1;
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
      if (cosine < std::cos(kFlatCorner * h_type::kPi / 180.0)) {
        const auto ends = model.curve_vertices(out.curve);
        flat.insert(out.forward ? ends[0] : ends[1]);
      }
    }
  return flat;
}

}  // namespace detail

namespace h_type {

// The smallest share of wake.gap the block may keep above the wall layer downstream of its root.
constexpr double kLeastGapFraction = 0.5;

std::string direction_label(const WakeParams& w) {
  return "[" + number_label(w.direction[0]) + ", " + number_label(w.direction[1]) + ", " + number_label(w.direction[2]) + "]";
}

std::string widening_label(const WakeParams& w) {
  return w.widening_deg > 0.0 ? "wake.widening = " + number_label(w.widening_deg) + " with " : std::string();
}

bool element_valid(const mesh::Mesh& m, ho::Shape shape, const std::vector<NodeId>& v) {
  Eigen::MatrixX3d x(v.size(), 3);
  for (std::size_t k = 0; k < v.size(); ++k) x.row(k) = m.node(v[k]).transpose();
  return ho::certify_jacobian(shape, 1, ho::NodeSet::Equispaced, x).valid;
}

namespace {

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

TrailingEdge find_trailing_edge(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                                const WakeParams& wake, const Vec3& d) {
  const auto found = model.find_surface(wake.te_base);
  const bool blunt = found && std::count(roles.body_surfaces.begin(), roles.body_surfaces.end(), *found) > 0;
  TrailingEdge te;
  te.base = blunt ? *found : -1;
  if (blunt) te.faces = detail::trailing_edge_base(model, roles, te.base);
  te.crack = !blunt && wake.te_base == "auto" ? detail::sharp_trailing_edge(model, roles, d) : -1;
  if (!blunt && te.crack < 0)
    fail("wake.te_base = \"" + wake.te_base +
         "\": no such trailing-edge base among the body surfaces" +
         (wake.te_base == "auto" ? " and no sharp trailing edge (a curve between two body surfaces leaving the wall)"
                                 : "") +
         "; the H-type near field sweeps the wake from the trailing edge");
  if (const int next = detail::trailing_edge_continuation(model, roles, te.faces, te.crack); next >= 0)
    fail("the trailing edge goes on past " +
         (blunt ? "the base " + surfaces_label(model, te.faces) + " into " + surface_label(model, next) +
                      ", which does not face the way the base does (mean normals more than 45 degrees apart): the "
                      "H-type's wake block stands on base faces forming one strip from the root to the tip"
                : "curve " + std::to_string(te.crack) + " ('" + model.curve(te.crack).name() + "') into curve " +
                      std::to_string(next) + " ('" + model.curve(next).name() +
                      "') (several spanwise faces, a crank): the H-type's wake block stands on one sharp "
                      "trailing-edge curve from the root to the tip") +
         "; set nearfield.topology = \"C\"");
  for (int s : te.faces) {
    const std::set<int> flat = detail::flat_base_corners(model, s);
    te.flat.insert(flat.begin(), flat.end());
    const surface::SurfaceMesh& base_mesh = meshes.surfaces.at(s);
    if (base_mesh.quads.empty() || !base_mesh.triangles.empty())
      fail("the trailing-edge base " + surface_label(model, s) + " must be meshed with structured quads only");
  }
  return te;
}

// The surface meshes with the base faces' quads as triangle pairs (q0 q1 q2, q0 q2 q3), so the
// junction machinery sees one triangulated body; quad i of a face becomes its triangles 2i and
// 2i + 1. A quad at a flat corner is turned to start there, so its diagonal leaves the corner and
// halves its angle.
surface::SurfaceMeshes base_as_triangles(const surface::SurfaceMeshes& meshes, const std::vector<int>& faces,
                                         const std::set<int>& flat) {
  surface::SurfaceMeshes out = meshes;
  for (int face : faces) {
    surface::SurfaceMesh& m = out.surfaces.at(face);
    for (auto q : m.quads) {
      for (int k = 0; k < 4 && !flat.count(m.origin[q[0]].vertex); ++k) std::rotate(q.begin(), q.begin() + 1, q.end());
      m.triangles.push_back({q[0], q[1], q[2]});
      m.triangles.push_back({q[0], q[2], q[3]});
    }
    m.quads.clear();
  }
  return out;
}

// The C-type wing layer and junction with the base bare (lifted, no prisms) or the layer cracked
// open along the sharp edge; for PyFR the base's root corners with two halos each
// (JunctionShell::corners).
detail::JunctionShell junction_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes,
                                     const BodyRoles& roles, const ShellParams& params, const JunctionParams& junction,
                                     double wall_thickness, const TrailingEdge& te, bool for_pyfr) {
  return detail::build_junction_shell(model, te.base >= 0 ? base_as_triangles(meshes, te.faces, te.flat) : meshes, roles,
                                      params, junction, wall_thickness, {te.faces.begin(), te.faces.end()}, te.crack,
                                      for_pyfr);
}

// The footprint (wall feet) and its tops (strip tops' offsets, the halos) along the root loop, the
// fan's three legs in place of its root's one, a split corner's two (JunctionShell::corners).
void record_footprint(const detail::JunctionShell& js, const FanLegs& fan, NearField& field) {
  std::map<int, const detail::JunctionShell::Corner*> corner;
  for (const auto& c : js.corners) corner[c.index] = &c;
  for (std::size_t i = 0; i < js.chain.size(); ++i) {
    const bool at_fan = static_cast<int>(i) == js.fan.index;
    if (const auto it = corner.find(static_cast<int>(i)); it != corner.end()) {
      for (int side : {0, 1})
        field.footprint.push_back(it->second->foot[side]), field.footprint_top.push_back(it->second->top[side]);
      continue;
    }
    field.footprint.push_back(js.foot_id[i]);
    field.footprint_top.push_back(at_fan ? js.fan.top[0] : static_cast<NodeId>(js.chain[i]) + js.offset);
    if (at_fan)
      for (int leg : {1, 2}) field.footprint.push_back(fan.foot[leg]), field.footprint_top.push_back(fan.top[leg]);
  }
}

// The base's quads (body node ids, lifted) and their faces, rebuilt from the triangle pairs of
// base_as_triangles (each face's pairs consecutive); none for a sharp trailing edge.
std::vector<BaseQuad> base_quads(const detail::JunctionShell& js, const std::vector<int>& faces) {
  std::vector<BaseQuad> quads;
  std::vector<std::array<int, 3>> pair;
  for (std::size_t t = 0; t < js.body.triangles.size(); ++t) {
    const int face = js.body.triangle_surface[t];
    if (!std::count(faces.begin(), faces.end(), face)) continue;
    const auto& v = js.body.triangles[t];
    if (pair.empty()) {
      pair.push_back(v);
    } else {
      quads.push_back({{static_cast<NodeId>(pair[0][0]), static_cast<NodeId>(pair[0][1]),
                        static_cast<NodeId>(pair[0][2]), static_cast<NodeId>(v[2])},
                       face});
      pair.clear();
    }
  }
  return quads;
}

// The trailing-edge nodes: the base's, or the sharp trailing edge's inner ones.
std::vector<NodeId> trailing_edge_nodes(const detail::JunctionShell& js, const std::vector<BaseQuad>& base) {
  std::vector<NodeId> nodes;
  for (const auto& b : base) nodes.insert(nodes.end(), b.q.begin(), b.q.end());
  for (int v = 0; v < js.body.num_nodes(); ++v)
    if (js.crack[v]) nodes.push_back(static_cast<NodeId>(v));
  return nodes;
}

}  // namespace
}  // namespace h_type

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
      params::string("te_base", &WakeParams::te_base, "non-empty", "H: the squared-off trailing edge's surface on the root, by name or \"#id\" (the body faces continuing it to the tip, facing within 45 degrees of it, join it); \"auto\": the narrow body face at the root's downstream end, or a sharp trailing edge"),
  };
  return table;
}

// The method's steps (h_shell.hpp): the trailing edge, the C-type layer and junction around a bare
// base or a cracked sharp edge, the wake block swept from the cut row, a sharp edge's fan, and the
// skin handed to the far field, pre-cut where the split will cut it.
NearField build_h_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params, const JunctionParams& junction, double wall_thickness,
                        const WakeParams& wake, const cad::BBox& box, const LayerFractions& fractions) {
  using namespace h_type;  // the steps, h_shell_steps.hpp
  const Vec3 d = wake_direction(wake);
  const TrailingEdge te = find_trailing_edge(model, meshes, roles, wake, d);
  detail::JunctionShell js =
      junction_shell(model, meshes, roles, params, junction, wall_thickness, te, wake.translational_rear_interfaces);
  if (wake.translational_rear_interfaces) {
    const detail::TranslationalRims rims = detail::make_rear_interfaces_translational(js, wake.to_outlet ? &d : nullptr);
    open_root_corners(model, roles.wall_surface, params.thickness, wall_thickness, rims, js);
  }
  // Over a curved wall the normal turns under the block: the gap measured along it decides.
  if (!js.wall.curved && d.dot(js.wall.normal) < -1e-12)
    fail("wake.direction = " + direction_label(wake) + " points into the wall");
  NearField& field = js.field;
  const FanLegs fan = add_fan_middle_leg(model, roles.wall_surface, js);
  record_footprint(js, fan, field);

  const std::vector<BaseQuad> base = base_quads(js, te.faces);
  const CutRow cut = wake_cut_row(js, trailing_edge_nodes(js, base), wall_thickness, wake);
  const WakeSections sections = wake_sections(js, te, base, cut);
  const double tolerance = std::max(model.tolerance(), 1e-9 * model.bbox().diagonal());
  std::optional<Outlet> outlet;
  if (wake.to_outlet) outlet = find_outlet(field.mesh, sections.swept, wake, d, box, tolerance);
  WakeSweep sweep(field.mesh, wake, d, sections.swept, box,
                  outlet ? detail::wake_stations_to(wake, outlet->distance) : detail::wake_stations(wake),
                  outlet ? std::optional<double>(outlet->along) : std::nullopt);
  const auto outflow = add_wake_elements(field, sweep, sections.swept, wake, d, te.base);
  add_exposed_body_faces(field.mesh, sections.exposed_base, js.bare);
  describe_wake_block(js, sweep, sections.swept, wake, d, wall_thickness, field.wake);
  // A curved wall may rise under the block downstream (a fuselage widening): the gap must hold
  // along the whole block, not only at its root.
  if (!(field.wake.gap > kLeastGapFraction * wake.gap))
    fail("the wall rises under the wake block: it comes within " + number_label(field.wake.gap) +
         " of the wall layer's top (wake.gap = " + number_label(wake.gap) + " at the trailing edge); use a larger "
         "wake.gap, a shorter wake.length or a wake.direction that follows the wall");

  InterfaceNodes interface_node;
  auto fan_planes = fill_fan_wedge(field, js, fan, roles.wall_surface, fractions, interface_node);
  for (auto& plane : fill_corner_wedges(field, js, roles.wall_surface, fractions, interface_node))
    fan_planes.push_back(std::move(plane));
  cut_skin_at_split_interfaces(field, skin_faces(field, fan_planes, sections.exposed_base, js.bare), fractions,
                               interface_node);
  field.outlet = outlet_outline(field, outflow, fractions, interface_node);
  check_wake_faces_carry_pyramids(field, sweep, wake);
  return std::move(field);
}

}  // namespace semimesh::nearfield