#include "semimesh/nearfield/c_shell.hpp"

#include "semimesh/ho/validity.hpp"
#include "semimesh/nearfield/body_mesh.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/junction_geometry.hpp"
#include "semimesh/nearfield/node_normals.hpp"

#include "junction_shell.hpp"
#include "labels.hpp"
#include "shell_common.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

namespace semimesh::nearfield {
namespace {

using mesh::CadAttachment;
using mesh::NodeId;

void check_junction_params(const cad::Model& model, const BodyRoles& roles, const JunctionParams& j,
                           double wall_thickness) {
  auto fail = [](const std::string& what) { throw NearFieldError("near field: " + what); };
  if (const auto bad = params::violation(j, junction_keys(), "nearfield")) fail(*bad);
  if (!(j.min_angle_deg < j.max_angle_deg && j.max_angle_deg <= j.concave_below_deg))
    fail("junction angles must satisfy junction_min_angle (" + number_label(j.min_angle_deg) +
         ") < junction_max_angle (" + number_label(j.max_angle_deg) + ") <= concave_angle (" +
         number_label(j.concave_below_deg) + ")");
  if (!(wall_thickness > 0.0) || !std::isfinite(wall_thickness))
    fail("the wall layer's thickness must be a finite number > 0 for a C-type junction, got " +
         number_label(wall_thickness));
  if (roles.wall_surface < 0) fail("a C-type near field needs a wall surface");
}

// The root curves: every body-wall curve, each of which must be a concave corner (from the CAD,
// concave_wall_curves) of a supported angle. Returns curve -> its body surface.
// Where the wing leans away over the fluid (angle a > 90 degrees), the point at delta_wing from the
// wing's plane and delta_wall from the wall, (d_wing + d_wall cos a) / sin a out from the root, has
// its foot on the wing only if delta_wall >= -delta_wing cos a (below that the halo's nearest wing
// point is the root itself: the strip has no height), and lies in front of the root only if
// delta_wall < delta_wing / -cos a (above that the wall layer is thicker than the wing's shell can
// meet). Both bounds are tightest at the curve's largest angle.
std::map<int, int> root_curve_surfaces(const cad::Model& model, const BodyRoles& roles, const JunctionParams& j,
                                       double delta_wing, double delta_wall) {
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  std::map<int, int> surface_of;
  for (const WallCurve& w : concave_wall_curves(model, roles.body_surfaces, roles.wall_surface, j.concave_below_deg)) {
    const double worst = w.min_angle_deg < j.min_angle_deg ? w.min_angle_deg : w.max_angle_deg;
    if (w.min_angle_deg < j.min_angle_deg || w.max_angle_deg > j.max_angle_deg)
      throw NearFieldError("near field: " + curve_label(model, w.curve) + " between " +
                           surface_label(model, w.body_surface) + " and the wall meets the wall at " +
                           number_label(worst) + " degrees (seen from the fluid); the junction block supports " +
                           number_label(j.min_angle_deg) + " to " + number_label(j.max_angle_deg) + " degrees");
    const double cosine = std::cos(w.max_angle_deg * kDegree);
    const double needed = -delta_wing * cosine;
    if (cosine < 0.0 && !(delta_wall < delta_wing / -cosine))
      throw NearFieldError("near field: the wall layer (thickness " + number_label(delta_wall) +
                           ") is thicker than the wing's shell (thickness " + number_label(delta_wing) +
                           ") can meet along " + curve_label(model, w.curve) + ", which meets the wall at up to " +
                           number_label(w.max_angle_deg) +
                           " degrees: no point at both distances lies in front of the root; use a wall layer "
                           "thickness below " +
                           number_label(delta_wing / -cosine) + " (thickness / -cos of the angle)");
    if (delta_wall < needed)
      throw NearFieldError("near field: the wall layer (thickness " + number_label(delta_wall) +
                           ") is too thin for the wing's shell (thickness " + number_label(delta_wing) + ") along " +
                           curve_label(model, w.curve) + ", which meets the wall at up to " +
                           number_label(w.max_angle_deg) +
                           " degrees: the halo would sit over the root, leaving no root strip; use a wall layer "
                           "thickness of at least " +
                           number_label(needed) + " (thickness x -cos of the angle)");
    surface_of[w.curve] = w.body_surface;
  }
  for (const WallCurve& w : wall_curves(model, roles.body_surfaces, roles.wall_surface))
    if (!surface_of.count(w.curve))
      throw NearFieldError(
          "near field: " + curve_label(model, w.curve) + " between " + surface_label(model, w.body_surface) +
          " and the wall meets the wall at up to " + number_label(w.max_angle_deg) +
          " degrees (seen from the fluid): not a concave corner (below " + number_label(j.concave_below_deg) +
          " degrees); the junction block needs the whole root loop concave");
  return surface_of;
}

// The curve leaving a root vertex up the body: the one of its curves that does not bound the wall;
// -1 when none does (a vertex inside one body face, e.g. the leading edge of a wing whose skin is
// one face: the strip top is then on that face).
int spanwise_curve(const cad::Model& model, int vertex, int wall) {
  std::vector<int> found;
  for (int c : model.curves_of_vertex(vertex)) {
    const auto& uses = model.surfaces_of_curve(c);
    if (std::none_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& u) { return u.surface == wall; }))
      found.push_back(c);
  }
  if (found.empty()) return -1;
  if (found.size() != 1)
    throw NearFieldError("near field: the root vertex '" + model.vertex(vertex).name + "' (id " +
                         std::to_string(vertex) + ") has " + std::to_string(found.size()) +
                         " curves leaving the wall; the junction block needs at most one");
  return found.front();
}

struct JunctionNode {
  Vec3 root, halo, strip_top, wall_foot;
  CadAttachment strip_top_cad, wall_foot_cad;
};

using Frame = detail::WallFrame;

// Smallest ratio of a lifted triangle's area to its own before the lift (projected on its normal).
constexpr double kFlattest = 1e-6;

// Outward direction in the wall plane of a root segment a -> b whose wing triangle has normal n.
Vec3 segment_outward(const Vec3& a, const Vec3& b, const Vec3& n_tri, const Vec3& n_wall) {
  Vec3 m = (b - a).cross(n_wall).normalized();
  return m.dot(n_tri) >= 0.0 ? m : Vec3(-m);
}

bool hex_corners_valid(const std::array<Vec3, 8>& x) {
  Eigen::MatrixX3d nodes(8, 3);
  for (int i = 0; i < 8; ++i) nodes.row(i) = x[i].transpose();
  return ho::certify_jacobian(ho::Shape::Hexahedron, 1, ho::NodeSet::Equispaced, nodes).valid;
}

// The root loop: the body mesh's open edges, all on the wall, chained in their direction
// (counter-clockwise seen from the fluid); body node ids.
std::vector<int> root_loop(const cad::Model& model, const BodyMesh& body, const std::vector<std::pair<int, int>>& open,
                           int wall) {
  for (const auto& [a, b] : open)
    for (int v : {a, b})
      if (!detail::on_wall(model, body.cad[v], wall))
        throw NearFieldError("near field: the body mesh is open at " + point_label(body.points[v]) + " on " +
                             surface_label(model, body.node_surface[v]) + " away from the wall " +
                             surface_label(model, wall) + "; list every surface of the body");
  std::vector<int> loop;
  for (NodeId v : detail::footprint_loop(body, open, 0)) loop.push_back(static_cast<int>(v));
  if (loop.size() < 3)
    throw NearFieldError("near field: the body has no root loop on the wall " + surface_label(model, wall));
  return loop;
}

// The body without its bare triangles (same nodes): what the wing layer is built on.
BodyMesh without_bare(const BodyMesh& body, const std::vector<char>& bare) {
  BodyMesh layer = body;
  layer.triangles.clear();
  layer.triangle_surface.clear();
  for (std::size_t t = 0; t < body.triangles.size(); ++t)
    if (!bare[t]) {
      layer.triangles.push_back(body.triangles[t]);
      layer.triangle_surface.push_back(body.triangle_surface[t]);
    }
  return layer;
}

// A sharp trailing edge `curve`: its inner nodes (on the curve, the strip top on the root loop
// included: the junction gives it one halo per side) and its end node (the tip vertex).
struct CrackNodes {
  std::vector<char> inner, end;  // [body nodes]
};

CrackNodes crack_nodes(const cad::Model& model, const BodyMesh& body, int curve, const std::vector<int>& loop) {
  CrackNodes c{std::vector<char>(body.num_nodes(), 0), std::vector<char>(body.num_nodes(), 0)};
  if (curve < 0) return c;
  std::vector<char> on_loop(body.num_nodes(), 0);
  for (int r : loop) on_loop[r] = 1;
  const std::array<int, 2> ends = model.curve_vertices(curve);
  for (int v = 0; v < body.num_nodes(); ++v) {
    const CadAttachment& a = body.cad[v];
    if (a.kind == CadAttachment::Curve && a.entity == curve) c.inner[v] = 1;
    if (a.kind == CadAttachment::Vertex && (a.entity == ends[0] || a.entity == ends[1]) && !on_loop[v]) c.end[v] = 1;
  }
  return c;
}

// The triangles of the crack's two surfaces touching its tip end stay bare: around an end node with
// one offset the two sides' rear interfaces would close to a zero-angle wedge (they share the end's
// edge and its offset: no element fills that, no pyramid stands in it), so the crack ends where the
// layer does. The end's other triangles (the tip's) keep their prisms: a rounded tip's small faces
// there are curved, and a tet standing on one bare in the layer's pit folded when curved (the
// ONERA M6's tip slivers, 0.5 mm wide, at order 2 and 4).
std::vector<char> bare_triangles(const cad::Model& model, const BodyMesh& body, int bare_surface, int crack_curve,
                                 const CrackNodes& crack) {
  std::set<int> sides;
  if (crack_curve >= 0)
    for (const cad::SurfaceUse& u : model.surfaces_of_curve(crack_curve)) sides.insert(u.surface);
  std::vector<char> bare(body.triangles.size(), 0);
  for (std::size_t t = 0; t < body.triangles.size(); ++t) {
    bare[t] = body.triangle_surface[t] == bare_surface;
    if (sides.count(body.triangle_surface[t]))
      for (int v : body.triangles[t]) bare[t] |= crack.end[v];
  }
  return bare;
}

// The layer cracked open along the crack's inner nodes: each gets a copy (appended after the body's
// nodes) used by the triangles of the larger of its two surfaces, so each side has its own normal
// and offset there. copy_of[k]: the body node of layer node (body node count + k).
struct CrackedLayer {
  BodyMesh layer;
  std::vector<int> copy_of;
};

CrackedLayer crack_open(const BodyMesh& layer, const CrackNodes& crack) {
  CrackedLayer out{layer, {}};
  int second = -1;
  for (std::size_t t = 0; t < layer.triangles.size(); ++t)
    for (int v : layer.triangles[t])
      if (crack.inner[v]) second = std::max(second, layer.triangle_surface[t]);
  std::map<int, int> copy;
  for (std::size_t t = 0; t < layer.triangles.size(); ++t) {
    if (layer.triangle_surface[t] != second) continue;
    for (int& v : out.layer.triangles[t]) {
      if (!crack.inner[v]) continue;
      auto [it, fresh] = copy.emplace(v, out.layer.num_nodes());
      if (fresh) {
        out.layer.points.push_back(layer.points[v]);
        out.layer.cad.push_back(layer.cad[v]);
        out.layer.node_surface.push_back(second);
        out.copy_of.push_back(v);
      }
      v = it->second;
    }
  }
  return out;
}

// The root curve a root node lies on (of its vertex: the first curve on the wall).
int root_curve_of(const cad::Model& model, const CadAttachment& root, int wall) {
  if (root.kind == CadAttachment::Curve) return root.entity;
  for (int c : model.curves_of_vertex(root.entity)) {
    const auto& uses = model.surfaces_of_curve(c);
    if (std::any_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& u) { return u.surface == wall; })) return c;
  }
  return -1;
}

// The wall foot L below halo j.halo of root j.root, `outward` the direction in the wall plane away
// from the body. Where the wing leans over the fluid, the halo's feet come close to the root: the
// hex would be a sliver there, folded by the curved root. Its wall strip keeps the width delta_wing
// (the wall layer's prisms lean to meet the halo) and its wing strip the height delta_wall.
void place_wall_foot(const cad::Model& model, int wall_surface, const Vec3& outward, const Frame& wall,
                     double delta_wing, double delta_wall, JunctionNode& j) {
  const double out = (j.halo - delta_wall * wall.normal_at(j.root) - j.root).dot(outward);
  const cad::Surface& face = model.surface(wall_surface);
  const Vec3 above_foot = j.root + std::max(out, delta_wing) * outward;
  const auto foot = wall.curved ? face.project(above_foot, wall.root_uv) : face.project(above_foot);
  j.wall_foot = foot.point;
  j.wall_foot_cad = {CadAttachment::Surface, wall_surface, foot.uv.x(), foot.uv.y()};
}

// Halo, strip top and wall foot of root node `i` of the loop; `outward` the direction in the wall
// plane away from the body (bisecting the two root segments' outward normals).
JunctionNode place_junction_node(const cad::Model& model, const BodyRoles& roles,
                                 const std::map<int, int>& root_surface, const BodyMesh& body, int r,
                                 const Vec3& outward, const Frame& wall, double delta_wing, double delta_wall) {
  JunctionNode j;
  j.root = body.points[r];
  j.halo = medial_halo(model, roles.body_surfaces, j.root, outward, wall.normal_at(j.root), delta_wing, delta_wall);
  place_wall_foot(model, roles.wall_surface, outward, wall, delta_wing, delta_wall, j);
  const CadAttachment& at = body.cad[r];
  // Where the halo's foot sinks below delta_wall: the point at that height straight up the wing
  // from the root (in the entity's parameters), so neighbouring strip tops keep the roots' order (a
  // foot projected onto the edge of its face, raised, could land on the next root's own).
  CadAttachment from_root;
  const int c = at.kind == CadAttachment::Vertex ? spanwise_curve(model, at.entity, roles.wall_surface) : -1;
  if (c >= 0) {
    const auto p = model.curve(c).project(j.halo);
    j.strip_top = p.point;
    j.strip_top_cad = {CadAttachment::Curve, c, p.t, 0.0};
    from_root = {CadAttachment::Curve, c, model.curve(c).project(j.root).t, 0.0};
  } else {
    const auto it = root_surface.find(root_curve_of(model, at, roles.wall_surface));
    if (it == root_surface.end())
      throw NearFieldError("near field: the root node at " + point_label(j.root) + " is not on a body-wall curve");
    const cad::Surface& face = model.surface(it->second);
    const auto p = face.project(j.halo, face.project(j.root).uv);
    if (!p.inside)
      throw NearFieldError("near field: the top of the root strip above " + point_label(j.root) + " falls off " +
                           surface_label(model, it->second) + " (wall layer thickness " + number_label(delta_wall) +
                           ", thickness " + number_label(delta_wing) + "); use a thinner wall layer or near field");
    j.strip_top = p.point;
    j.strip_top_cad = {CadAttachment::Surface, it->second, p.uv.x(), p.uv.y()};
    const cad::Vec2 root_uv = face.project(j.root).uv;
    from_root = {CadAttachment::Surface, it->second, root_uv.x(), root_uv.y()};
  }
  if (wall.height(j.strip_top) < delta_wall) {
    j.strip_top_cad = from_root;
    j.strip_top = detail::move_to_height(model, wall, j.root, j.strip_top_cad, delta_wall);
  }
  if (!(wall.height(j.strip_top) > 1e-3 * delta_wall))
    throw NearFieldError("near field: the root strip above " + point_label(j.root) + " on " +
                         surface_label(model, body.node_surface[r]) + " has no height");
  return j;
}

// A sharp trailing edge's root (the crack curve's vertex on the wall): no side's halo upstream of
// that side's rear interface, the plane of the edge's tangent t at the strip top W and the side's
// normal there. A halo placed from the root in the wall plane, as elsewhere, lies upstream of that
// plane where the edge sweeps back (W stands downstream of the root): the lowest rear-interface
// quad twists from it to the next row's offset along the side's normal and lies flat over the fan's
// top (a NACA 0018 swept 34.5 degrees: a 24 degree wedge where no pyramid fitted; TetGen aborted).
// Such a halo is moved into the plane: delta_wing from the edge along the side's normal square to
// the edge, then along the edge to the wall layer's height; its wall foot below it (the wall
// layer's prisms stand straight there). Downstream of the plane (an edge leaning forward, the
// rear interface obtuse over the fan's top) a halo stays: moved up to the plane it would pass its
// neighbour's and fold the layer between them.
void keep_fan_halos_off_the_rear_interfaces(const cad::Model& model, int wall_surface, int crack_curve,
                                            const std::array<int, 2>& side_surface, const std::array<Vec3, 2>& outward,
                                            const Frame& wall, double delta_wing, double delta_wall,
                                            std::array<JunctionNode*, 2> j_side) {
  const Vec3 w = j_side[0]->strip_top;
  const Vec3 wall_normal = wall.normal_at(w);
  const cad::Curve& edge = model.curve(crack_curve);
  Vec3 t = edge.derivatives(edge.project(w).t).d1.normalized();
  if (t.dot(wall_normal) < 0.0) t = -t;
  const double rise = t.dot(wall_normal);  // of the edge per unit length along it
  constexpr double kLeast = 0.0871557;     // sin 5 degrees
  if (!(rise > kLeast))
    throw NearFieldError("near field: the sharp trailing edge " + curve_label(model, crack_curve) +
                         " leans within 5 degrees of the wall at its root " + point_label(j_side[0]->root) +
                         "; the junction cannot stand under it");
  std::array<Vec3, 2> across;  // each side's normal at W, square to the edge
  for (int side : {0, 1}) {
    const cad::Surface& face = model.surface(side_surface[side]);
    const Vec3 n = face.normal(face.project(w).uv);
    across[side] = (n - n.dot(t) * t).normalized();
  }
  const Vec3 downstream = across[0] + across[1];  // the bisector of the sides' normals leaves the edge
  for (int side : {0, 1}) {
    JunctionNode& j = *j_side[side];
    Vec3 behind = t.cross(across[side]);  // the rear interface's normal, downstream
    if (behind.dot(downstream) < 0.0) behind = -behind;
    if ((j.halo - w).dot(behind) >= 0.0) continue;
    const double along = (delta_wall - wall.height(w) - delta_wing * across[side].dot(wall_normal)) / rise;
    j.halo = w + delta_wing * across[side] + along * t;
    const Vec3 below = j.halo - delta_wall * wall_normal;
    const double out = (below - j.root).dot(outward[side]);  // the wall strip keeps the width delta_wing
    const Vec3 above_foot = below + std::max(0.0, delta_wing - out) * outward[side];
    const cad::Surface& face = model.surface(wall_surface);
    const auto foot = wall.curved ? face.project(above_foot, wall.root_uv) : face.project(above_foot);
    j.wall_foot = foot.point;
    j.wall_foot_cad = {CadAttachment::Surface, wall_surface, foot.uv.x(), foot.uv.y()};
  }
}

// The strip tops along a bare surface's root (the H-type's trailing-edge base) raised to one height,
// the highest of them. Nothing stands on that root row but the junction, whose W-H faces there face
// the far field and carry pyramids: on a swept, cambered base the two corners' strip tops (the
// halos projected onto the trailing-edge curves) differ in height by several times the base's
// thickness, which twists those quads until no pyramid apex is valid above them (a NACA 2412 swept
// 28.6 degrees: the short edge of the quad stood at 60 degrees to the long one).
void level_bare_strip_tops(const cad::Model& model, const Frame& wall, const BodyMesh& body,
                           const std::vector<int>& loop, int bare_surface,
                           const std::map<std::pair<int, int>, int>& triangle_of_edge, std::vector<JunctionNode>& nodes) {
  const int n = static_cast<int>(loop.size());
  auto on_bare = [&](int a, int b) { return body.triangle_surface[triangle_of_edge.at({a, b})] == bare_surface; };
  std::vector<int> base;
  double level = -1e300;
  for (int i = 0; i < n; ++i)
    if (on_bare(loop[(i + n - 1) % n], loop[i]) || on_bare(loop[i], loop[(i + 1) % n])) {
      base.push_back(i);
      level = std::max(level, wall.height(nodes[i].strip_top));
    }
  for (int i : base) {
    JunctionNode& j = nodes[i];
    j.strip_top = detail::move_to_height(model, wall, j.strip_top, j.strip_top_cad, level);
    if (!(std::abs(wall.height(j.strip_top) - level) <= 1e-6 * level))
      throw NearFieldError("near field: the root strip above " + point_label(j.root) + " on " +
                           surface_label(model, bare_surface) + " cannot reach the height " + number_label(level) +
                           " of its neighbours on that surface");
  }
}

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

// Lifts the body mesh off the wall so its root row lands on the strip tops (lift_node), fading out
// at the lowest CAD vertex of the body off the wall (the tip's corners on an ordinary wing; on a
// revolved tip the trailing edge's top, below the tip's crown: a node on the tip's faces must not
// be lifted past the end of the face below it); throws when the strip is too tall for the body or
// a triangle would fold. The lift also dies out below every surface that does not stand on the
// wall (lift_top). Returns the strip height and the body's top height.
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
    if (body.cad[v].kind == CadAttachment::Vertex && !on_root[v]) ceiling = std::min(ceiling, wall.height(body.points[v]));
  if (!(strip < 0.5 * ceiling))
    throw NearFieldError("near field: the root strip (height " + number_label(strip) +
                         ") for the wall layer thickness " + number_label(delta_wall) +
                         " takes more than half of the body's height " + number_label(ceiling) +
                         " above the wall (up to its lowest corner off the wall); use a thinner wall layer");
  const std::vector<Vec3> unlifted = body.points;
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

// The strip top next to body node `node` (the node itself, or one of a triangle it shares), -1 when
// it is away from the root strip.
int strip_top_next_to(const BodyMesh& layer, const std::map<int, int>& loop_index, int node) {
  if (loop_index.count(node)) return node;
  for (const auto& t : layer.triangles)
    if (std::count(t.begin(), t.end(), node))
      for (int v : t)
        if (loop_index.count(v)) return v;
  return -1;
}

// The wing layer's offsets at the strip tops are pinned at the halo: where the layer cannot be
// built next to them even at its thinnest, the root loop is too short (too few segments, too tight
// a turn) for the thickness and the wall layer's thickness: said so, naming the root curve.
detail::LayerOffsets offsets_meeting_the_halo(const cad::Model& model, const BodyMesh& layer,
                                              const std::vector<std::vector<int>>& neighbours,
                                              const std::vector<Vec3>& normals,
                                              const detail::OffsetConstraints& constraints, const ShellParams& params,
                                              const std::vector<int>& loop, const std::vector<CadAttachment>& root_cad,
                                              int wall, double delta_wall) {
  try {
    return detail::offset_body_nodes(model, layer, neighbours, normals, constraints, params);
  } catch (const detail::LayerFoldError& fold) {
    std::map<int, int> loop_index;
    for (std::size_t i = 0; i < loop.size(); ++i) loop_index[loop[i]] = static_cast<int>(i);
    const int top = strip_top_next_to(layer, loop_index, fold.node);
    if (top < 0) throw;
    const int curve = root_curve_of(model, root_cad[loop_index.at(top)], wall);
    throw NearFieldError("near field: the root loop is too short for the requested sizes along " +
                         (curve >= 0 ? curve_label(model, curve) : std::string("the root")) + " near " +
                         point_label(layer.points[top]) + ": the wing layer (thickness " +
                         number_label(params.thickness) + ") cannot meet the halo above the root strip (wall layer "
                         "thickness " + number_label(delta_wall) + ") without folding at " +
                         point_label(layer.points[fold.node]) + ", even at min_thickness_fraction (" +
                         number_label(params.min_thickness_fraction) +
                         "); use a smaller thickness or wall layer thickness, or more segments along the root "
                         "(smaller sizing sizes)");
  }
}


// The body's triangles by their directed edges, for the root segments a -> b along the loop: which
// triangle stands on each, its surface, and the segment's outward direction in the wall plane.
class RootSegments {
 public:
  RootSegments(const BodyMesh& body, const Frame& wall) : body_(body), wall_(wall) {
    for (std::size_t t = 0; t < body.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k)
        triangle_of_edge_[{body.triangles[t][k], body.triangles[t][(k + 1) % 3]}] = static_cast<int>(t);
  }

  Vec3 outward(int a, int b) const {
    const auto& t = body_.triangles[triangle_of_edge_.at({a, b})];
    const Vec3 n_tri =
        (body_.points[t[1]] - body_.points[t[0]]).cross(body_.points[t[2]] - body_.points[t[0]]).normalized();
    return segment_outward(body_.points[a], body_.points[b], n_tri,
                           wall_.normal_at(0.5 * (body_.points[a] + body_.points[b])));
  }
  int surface(int a, int b) const { return body_.triangle_surface[triangle_of_edge_.at({a, b})]; }
  const std::map<std::pair<int, int>, int>& triangle_of_edge() const { return triangle_of_edge_; }

 private:
  const BodyMesh& body_;
  const Frame& wall_;
  std::map<std::pair<int, int>, int> triangle_of_edge_;
};

// The crack's root node (a sharp trailing edge's vertex on the root loop): its index in the loop,
// -1 when there is none.
int fan_index(const cad::Model& model, const BodyMesh& body, const std::vector<int>& loop, int crack_curve) {
  int fan = -1;
  if (crack_curve < 0) return fan;
  const std::array<int, 2> ends = model.curve_vertices(crack_curve);
  for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
    const CadAttachment& a = body.cad[loop[i]];
    if (a.kind == CadAttachment::Vertex && (a.entity == ends[0] || a.entity == ends[1])) fan = i;
  }
  return fan;
}

// The junction's cross-section at every root node (root, halo, strip top, wall foot); at the fan
// node one per side, each over its own root segment's outward direction (side 0: the segment into
// it, side 1: the one out of it).
struct JunctionNodes {
  std::vector<JunctionNode> at;           ///< [loop]; the fan node's side 0
  int fan = -1;                           ///< loop index of the fan node, -1: none
  JunctionNode fan_side1;                 ///< the fan node's side 1
  std::array<int, 2> fan_surface{-1, -1};  ///< [sides] the surface of the fan node's root segment on each side
};

JunctionNodes place_junction_nodes(const cad::Model& model, const BodyRoles& roles, const std::map<int, int>& root_surface,
                                   const BodyMesh& body, const std::vector<int>& loop, const RootSegments& segments,
                                   int crack_curve, const Frame& wall, double delta_wing, double delta_wall) {
  const int n = static_cast<int>(loop.size());
  JunctionNodes j;
  j.at.resize(n);
  j.fan = fan_index(model, body, loop, crack_curve);
  for (int i = 0; i < n; ++i) {
    const int r = loop[i], prev = loop[(i + n - 1) % n], next = loop[(i + 1) % n];
    if (i == j.fan) {
      j.at[i] = place_junction_node(model, roles, root_surface, body, r, segments.outward(prev, r), wall, delta_wing,
                                    delta_wall);
      j.fan_side1 = place_junction_node(model, roles, root_surface, body, r, segments.outward(r, next), wall,
                                        delta_wing, delta_wall);
      continue;
    }
    j.at[i] = place_junction_node(model, roles, root_surface, body, r,
                                  (segments.outward(prev, r) + segments.outward(r, next)).normalized(), wall,
                                  delta_wing, delta_wall);
  }
  if (j.fan >= 0) {
    const int prev = loop[(j.fan + n - 1) % n], r = loop[j.fan], next = loop[(j.fan + 1) % n];
    j.fan_surface = {segments.surface(prev, r), segments.surface(r, next)};
    keep_fan_halos_off_the_rear_interfaces(model, roles.wall_surface, crack_curve, j.fan_surface,
                                           {segments.outward(prev, r), segments.outward(r, next)}, wall, delta_wing,
                                           delta_wall, {&j.at[j.fan], &j.fan_side1});
  }
  return j;
}

// The body the wing layer stands on: without the bare triangles (whose own nodes get no offset:
// pinned where they are), cracked open along the crack curve; the two sides of the crack count as
// neighbours, as they still crowd each other.
struct WingLayer {
  CrackNodes crack;
  std::vector<char> bare;                    ///< [body triangles]
  CrackedLayer cracked;
  std::vector<std::vector<int>> neighbours;  ///< [layer nodes]
};

WingLayer wing_layer(const cad::Model& model, const BodyMesh& body, const std::vector<int>& loop, int bare_surface,
                     int crack_curve) {
  WingLayer w;
  w.crack = crack_nodes(model, body, crack_curve, loop);
  w.bare = bare_triangles(model, body, bare_surface, crack_curve, w.crack);
  w.cracked = crack_open(without_bare(body, w.bare), w.crack);
  w.neighbours = node_neighbours(w.cracked.layer);
  const int count = body.num_nodes();
  for (std::size_t k = 0; k < w.cracked.copy_of.size(); ++k) {
    w.neighbours[count + k].push_back(w.cracked.copy_of[k]);
    w.neighbours[w.cracked.copy_of[k]].push_back(count + static_cast<int>(k));
  }
  return w;
}

// The fan node's layer node on each side: itself, or its copy on the side the crack gave copies.
std::array<int, 2> fan_layer_nodes(const WingLayer& w, const BodyMesh& body, const std::vector<int>& loop,
                                   const JunctionNodes& j) {
  const int count = body.num_nodes();
  const auto& copy_of = w.cracked.copy_of;
  const int copy = static_cast<int>(std::find(copy_of.begin(), copy_of.end(), loop[j.fan]) - copy_of.begin());
  if (copy == static_cast<int>(copy_of.size()) || j.fan_surface[0] == j.fan_surface[1])
    throw NearFieldError("near field: the sharp trailing edge's root at " + point_label(body.points[loop[j.fan]]) +
                         " does not part two body surfaces");
  const int copied_surface = w.cracked.layer.node_surface[count + copy];
  std::array<int, 2> fan_layer;
  for (int side : {0, 1}) fan_layer[side] = j.fan_surface[side] == copied_surface ? count + copy : loop[j.fan];
  return fan_layer;
}

// Where the layer's offsets start from and which stay: node normals ([layer nodes]); isolated nodes
// pinned where they are, the strip tops (and the fan node's two layer nodes) pinned at their halos,
// their normals towards them.
struct LayerStart {
  std::vector<Vec3> normals;
  detail::OffsetConstraints constraints;
  std::array<int, 2> fan_layer{-1, -1};  ///< the fan node's layer node on each side
};

LayerStart pin_layer_at_the_halos(const WingLayer& w, const BodyMesh& body, const std::vector<int>& loop,
                                  const JunctionNodes& j, const ShellParams& params) {
  const BodyMesh& layer = w.cracked.layer;
  const int layer_count = layer.num_nodes();
  LayerStart s;
  NormalOptions normal_options;
  normal_options.smoothing_passes = params.normal_smoothing_passes;
  s.normals = node_normals(layer, std::vector<Vec3>(layer_count, Vec3::Zero()), normal_options);
  s.constraints.pinned.assign(layer_count, 0);
  s.constraints.pinned_outer.assign(layer_count, Vec3::Zero());
  auto pin = [&](int node, const Vec3& outer, const Vec3& normal) {
    s.constraints.pinned[node] = 1, s.constraints.pinned_outer[node] = outer, s.normals[node] = normal;
  };
  for (int i = 0; i < layer_count; ++i)
    if (w.neighbours[i].empty()) pin(i, layer.points[i], Vec3::UnitX());
  for (std::size_t i = 0; i < loop.size(); ++i)
    pin(loop[i], j.at[i].halo, (j.at[i].halo - j.at[i].strip_top).normalized());
  if (j.fan >= 0) {
    s.fan_layer = fan_layer_nodes(w, body, loop, j);
    for (int side : {0, 1}) {
      const JunctionNode& halo = side == 0 ? j.at[j.fan] : j.fan_side1;
      pin(s.fan_layer[side], halo.halo, (halo.halo - j.at[j.fan].strip_top).normalized());
    }
  }
  return s;
}

// The wing layer's prisms (region wing_layer): body node i is mesh node i, layer node i's offset
// mesh node i + offset; each prism's body face a wing boundary face, its outer face skin. The
// bare triangles off the bare surface are listed (the crack's ends).
void add_wing_layer(const BodyMesh& body, const WingLayer& w, const detail::LayerOffsets& offsets, int bare_surface,
                    detail::JunctionShell& shell) {
  NearField& field = shell.field;
  mesh::Mesh& m = field.mesh;
  const BodyMesh& layer = w.cracked.layer;
  const int count = body.num_nodes(), layer_count = layer.num_nodes();
  const int layer_region = m.region_index("wing_layer");
  for (int i = 0; i < count; ++i) m.add_node(body.points[i], body.cad[i]);
  const auto offset = static_cast<NodeId>(count);
  for (int i = 0; i < layer_count; ++i) m.add_node(offsets.outer[i]);
  auto id = [](int v) { return static_cast<NodeId>(v); };
  shell.layer_body.resize(layer_count);
  for (int i = 0; i < layer_count; ++i) shell.layer_body[i] = id(i < count ? i : w.cracked.copy_of[i - count]);
  for (std::size_t t = 0; t < layer.triangles.size(); ++t) {
    const auto& l = layer.triangles[t];
    const std::array<NodeId, 3> v{shell.layer_body[l[0]], shell.layer_body[l[1]], shell.layer_body[l[2]]};
    m.add_element(ho::Shape::Prism, {v[0], v[1], v[2], id(l[0]) + offset, id(l[1]) + offset, id(l[2]) + offset},
                  layer_region);
    field.stacks.push_back({field.element_surface.size(), {LayerDirection{2, LayerFamily::Wing}}});
    field.element_surface.push_back(layer.triangle_surface[t]);
    m.add_boundary_face("wing", ho::Shape::Triangle, {v[0], v[2], v[1]});
    field.skin.push_back({{id(l[0]) + offset, id(l[1]) + offset, id(l[2]) + offset, mesh::kNoNode}, 3});
  }
  for (std::size_t t = 0; t < body.triangles.size(); ++t)
    if (w.bare[t] && body.triangle_surface[t] != bare_surface) shell.bare.push_back(body.triangles[t]);
  shell.offset = offset;
}

// The junction's wall nodes: the root R and the wall foot L of every root node, and the fan node's
// second foot (side 1).
void add_junction_wall_nodes(const std::vector<int>& loop, const std::vector<CadAttachment>& root_cad,
                             const JunctionNodes& j, detail::JunctionShell& shell) {
  mesh::Mesh& m = shell.field.mesh;
  const std::size_t n = loop.size();
  shell.root_id.resize(n), shell.foot_id.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    shell.root_id[i] = m.add_node(j.at[i].root, root_cad[i]);
    shell.foot_id[i] = m.add_node(j.at[i].wall_foot, j.at[i].wall_foot_cad);
  }
  if (j.fan >= 0) shell.fan.foot = {shell.foot_id[j.fan], m.add_node(j.fan_side1.wall_foot, j.fan_side1.wall_foot_cad)};
}

// Junction hexes R_a R_b W_b W_a L_a L_b H_b H_a on every root segment (region junction, stacks
// of both families); a -> b along the loop or against it, whichever gives a positive volume. At
// the fan node each segment takes its own side's foot and halo.
void add_junction_hexes(const cad::Model& model, const BodyMesh& body, const std::vector<int>& loop,
                        const JunctionNodes& j, const std::array<int, 2>& fan_layer, double delta_wing,
                        double delta_wall, detail::JunctionShell& shell) {
  NearField& field = shell.field;
  mesh::Mesh& m = field.mesh;
  const int n = static_cast<int>(loop.size()), fan = j.fan;
  const int junction_region = m.region_index("junction");
  auto id = [](int v) { return static_cast<NodeId>(v); };
  auto side_of = [&](int other) { return other == (fan + n - 1) % n ? 0 : 1; };
  auto foot = [&](int i, int other) { return i == fan ? shell.fan.foot[side_of(other)] : shell.foot_id[i]; };
  auto top = [&](int i, int other) { return id(i == fan ? fan_layer[side_of(other)] : loop[i]) + shell.offset; };
  auto hex_of = [&](int a, int b) {
    return std::array<NodeId, 8>{shell.root_id[a], shell.root_id[b], id(loop[b]), id(loop[a]),
                                 foot(a, b),       foot(b, a),       top(b, a),   top(a, b)};
  };
  auto corners = [&](const std::array<NodeId, 8>& h) {
    std::array<Vec3, 8> x;
    for (int k = 0; k < 8; ++k) x[k] = m.node(h[k]);
    return x;
  };
  const bool along = hex_corners_valid(corners(hex_of(0, 1)));
  for (int i = 0; i < n; ++i) {
    const int a = along ? i : (i + 1) % n, b = along ? (i + 1) % n : i;
    const std::array<NodeId, 8> h = hex_of(a, b);
    if (!hex_corners_valid(corners(h)))
      throw NearFieldError("near field: the junction hex on the root segment " + point_label(j.at[a].root) + " - " +
                           point_label(j.at[b].root) + " on " + surface_label(model, body.node_surface[loop[a]]) +
                           " would be inverted: the root loop turns too sharply there for thickness " +
                           number_label(delta_wing) + " and wall layer thickness " + number_label(delta_wall) +
                           "; use thinner layers or a finer root mesh");
    m.add_element(ho::Shape::Hexahedron, std::vector<NodeId>(h.begin(), h.end()), junction_region);
    field.stacks.push_back(
        {field.element_surface.size(), {LayerDirection{2, LayerFamily::Wing}, LayerDirection{1, LayerFamily::Wall}}});
    field.element_surface.push_back(body.node_surface[loop[a]]);
    m.add_boundary_face("wing", ho::Shape::Quadrilateral, {h[0], h[3], h[2], h[1]});
    m.add_boundary_face("wall", ho::Shape::Quadrilateral, {h[0], h[1], h[5], h[4]});
    ++field.junction_hexes;
  }
}

// The layer's thinnest and thickest offset after reduction, over the nodes that have neighbours
// (the bare surface's own nodes get no offset).
void record_thickness_range(const detail::LayerOffsets& offsets, const std::vector<std::vector<int>>& neighbours,
                            double thickness, NearField& field) {
  field.thickness_min = thickness;
  field.thickness_max = 0.0;
  for (std::size_t i = 0; i < neighbours.size(); ++i) {
    if (neighbours[i].empty()) continue;
    field.thickness_min = std::min(field.thickness_min, offsets.thickness[i]);
    field.thickness_max = std::max(field.thickness_max, offsets.thickness[i]);
  }
}

}  // namespace

const params::Table<JunctionParams>& junction_keys() {
  static const params::Table<JunctionParams> table = {
      params::real("concave_angle", &JunctionParams::concave_below_deg, "(0, 180]",
                   "C: a body-wall curve whose dihedral angle seen from the fluid stays below this (degrees) is a "
                   "concave corner"),
      params::real("junction_min_angle", &JunctionParams::min_angle_deg, "(0, 180)",
                   "C: smallest supported dihedral angle of a root curve, degrees"),
      params::real("junction_max_angle", &JunctionParams::max_angle_deg, "(0, 180]",
                   "C: largest supported dihedral angle of a root curve, degrees"),
  };
  return table;
}

namespace detail {

// The method's steps (c_shell.hpp): the root loop and the junction's cross-section at each root
// node, the wing mesh lifted onto the strip tops, the wing layer's offsets meeting the halos there,
// then the mesh: the layer's prisms and the junction's hexes.
JunctionShell build_junction_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                                   const ShellParams& params, const JunctionParams& junction, double wall_thickness,
                                   int bare_surface, int crack_curve) {
  detail::check_shell_params(model, roles, params);
  check_junction_params(model, roles, junction, wall_thickness);
  const std::map<int, int> root_surface = root_curve_surfaces(model, roles, junction, params.thickness, wall_thickness);
  const double delta_wing = params.thickness, delta_wall = wall_thickness;
  BodyMesh body = merge_body_meshes(model, meshes, roles.body_surfaces);

  // Junction geometry per root node, then the wing mesh lifted onto the strip tops.
  const std::vector<int> loop = root_loop(model, body, open_edges(body), roles.wall_surface);
  std::vector<Vec3> root_points;
  for (int r : loop) root_points.push_back(body.points[r]);
  const Frame wall = wall_frame(model, roles.wall_surface, root_points);
  const RootSegments segments(body, wall);
  JunctionNodes j = place_junction_nodes(model, roles, root_surface, body, loop, segments, crack_curve, wall,
                                         delta_wing, delta_wall);
  if (bare_surface >= 0) level_bare_strip_tops(model, wall, body, loop, bare_surface, segments.triangle_of_edge(), j.at);
  std::vector<CadAttachment> root_cad;
  for (int r : loop) root_cad.push_back(body.cad[r]);
  const auto [strip, tip] = lift_onto_strip(model, wall, loop, j.at, delta_wall, body);

  // The wing layer on the lifted mesh, its offsets meeting the halos at the strip tops.
  const WingLayer layer = wing_layer(model, body, loop, bare_surface, crack_curve);
  const LayerStart start = pin_layer_at_the_halos(layer, body, loop, j, params);
  const detail::LayerOffsets offsets =
      offsets_meeting_the_halo(model, layer.cracked.layer, layer.neighbours, start.normals, start.constraints, params,
                               loop, root_cad, roles.wall_surface, delta_wall);

  JunctionShell shell;
  shell.field.warnings = offsets.warnings;
  shell.field.mesh.reserve(ho::Shape::Prism, body.triangles.size() + loop.size());
  add_wing_layer(body, layer, offsets, bare_surface, shell);
  add_junction_wall_nodes(loop, root_cad, j, shell);
  add_junction_hexes(model, body, loop, j, start.fan_layer, delta_wing, delta_wall, shell);
  record_thickness_range(offsets, layer.neighbours, params.thickness, shell.field);
  shell.body = std::move(body);
  shell.layer = layer.cracked.layer;
  shell.crack = layer.crack.inner;
  shell.chain = loop;
  if (j.fan >= 0) {
    shell.fan.index = j.fan;
    shell.fan.top = {static_cast<NodeId>(start.fan_layer[0]) + shell.offset,
                     static_cast<NodeId>(start.fan_layer[1]) + shell.offset};
  }
  shell.wall = wall;
  shell.strip = strip;
  shell.tip = tip;
  return shell;
}

WallFrame wall_frame(const cad::Model& model, int wall_surface, const std::vector<Vec3>& root_points) {
  const cad::Surface& face = model.surface(wall_surface);
  if (face.is_planar()) {  // taken at the middle of its parameter box
    const cad::Vec2 mid(0.5 * (face.bounds()[0].lo + face.bounds()[0].hi), 0.5 * (face.bounds()[1].lo + face.bounds()[1].hi));
    return {face.normal(mid), face.point(mid)};
  }
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& x : root_points) centroid += x;
  // From a root point's parameters: the centroid lies in the root's hole, off the trimmed face.
  const cad::Vec2 start = face.project(root_points.front()).uv;
  const cad::SurfaceProjection foot = face.project(centroid / static_cast<double>(root_points.size()), start);
  return {face.normal(foot.uv), foot.point, &face, foot.uv};
}

Vec3 move_to_height(const cad::Model& model, const WallFrame& wall, const Vec3& x, CadAttachment& cad, double target) {
  // Newton on the height along its gradient in the entity's parameters: on a lofted wing the
  // chordwise parameter stays (the height grows with the spanwise one), so a node near a swept
  // leading edge keeps its place along the section. A move in space projected back (vertical or
  // steepest ascent on the surface) drifts to the closest point, onto the edge itself.
  Vec3 p = x;
  for (int iteration = 0; iteration < 12; ++iteration) {
    const double missing = target - wall.height(p);
    if (cad.kind == CadAttachment::Surface) {
      const cad::Surface& face = model.surface(cad.entity);
      const cad::SurfaceDerivatives d = face.derivatives(cad::Vec2(cad.u, cad.v));
      const Vec3 normal = wall.normal_at(p);
      const cad::Vec2 gradient(d.du.dot(normal), d.dv.dot(normal));
      if (!(gradient.squaredNorm() > 0.0)) break;
      const auto bounds = face.bounds();
      const cad::Vec2 uv(std::clamp(cad.u + missing * gradient.x() / gradient.squaredNorm(), bounds[0].lo, bounds[0].hi),
                         std::clamp(cad.v + missing * gradient.y() / gradient.squaredNorm(), bounds[1].lo, bounds[1].hi));
      cad.u = uv.x(), cad.v = uv.y();
      p = face.point(uv);
    } else {
      const cad::Curve& curve = model.curve(cad.entity);
      const double slope = curve.derivatives(cad.u).d1.dot(wall.normal_at(p));
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

NearField build_c_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params, const JunctionParams& junction, double wall_thickness) {
  detail::JunctionShell shell =
      detail::build_junction_shell(model, meshes, roles, params, junction, wall_thickness, /*bare_surface=*/-1,
                                   /*crack_curve=*/-1);
  NearField& field = shell.field;
  for (std::size_t i = 0; i < shell.chain.size(); ++i) {
    field.footprint.push_back(shell.foot_id[i]);
    field.footprint_top.push_back(static_cast<mesh::NodeId>(shell.chain[i]) + shell.offset);
  }
  return std::move(field);
}

}  // namespace semimesh::nearfield
