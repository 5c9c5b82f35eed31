// The junction block along the root: its cross-section at every root node (root, halo, strip top,
// wall foot; two at a sharp trailing edge's root) and its hexes.
#include "semimesh/ho/validity.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/junction_geometry.hpp"

#include "c_shell_steps.hpp"
#include "labels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace semimesh::nearfield::c_type {
namespace {

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

// The wall foot L below halo j.halo of root j.root, `outward` the direction in the wall plane away
// from the body. Where the wing leans over the fluid, the halo's feet come close to the root: the
// hex would be a sliver there, folded by the curved root. Its wall strip keeps the width delta_wing
// (the wall layer's prisms lean to meet the halo) and its wing strip the height delta_wall. Along
// the root the foot stays under the halo (a halo over a swept strip top stands downstream of the
// root: the wall layer's column there must not lean along the root either). At a sharp corner of
// the loop (`sides`: the two root segments' outward directions; a C-type's trailing edge) the foot
// must lie where both point, or one of the corner's hexes inverts: a halo over a strip top that a
// leaning wing carries sideways (a low wing on a fuselage, 45 degrees over its acute upper side:
// the foot as far to the side as it is downstream) would take it out; such a foot is put on the
// bisector, delta_wing out.
void place_wall_foot(const cad::Model& model, int wall_surface, const std::array<Vec3, 2>& sides,
                     const Vec3& outward, const Frame& wall, double delta_wing, double delta_wall, JunctionNode& j) {
  const Vec3 n = wall.normal_at(j.root);
  const Vec3 below = j.halo - delta_wall * n;
  const double out = (below - j.root).dot(outward);
  const cad::Surface& face = model.surface(wall_surface);
  Vec3 above_foot = below + std::max(0.0, delta_wing - out) * outward;
  const Vec3 offset = above_foot - j.root - (above_foot - j.root).dot(n) * n;
  if (!(offset.dot(sides[0]) > 0.0 && offset.dot(sides[1]) > 0.0)) above_foot = j.root + delta_wing * outward;
  const auto foot = wall.curved ? face.project(above_foot, wall.root_uv) : face.project(above_foot);
  j.wall_foot = foot.point;
  j.wall_foot_cad = {CadAttachment::Surface, wall_surface, foot.uv.x(), foot.uv.y()};
}

// A strip top raised from its root along the wing (in the wing's parameters, as the body mesh is
// lifted) stands where the wing's section is at that height: on a swept wing delta_wall tan(sweep)
// downstream of the root. The halo is then the medial point over the strip top, not over the root:
// over the root, the column strip top -> halo leaned along the root by that much, while the layer's
// columns in the row above stand along the wing's normals, and the prisms between them folded
// wherever that row lies closer than the lean (the ONERA M6 at coarse sizes, 30 degrees of sweep:
// a lean of 0.58 delta_wall against rows 0.2-0.4 delta_wall higher).
Vec3 halo_over_the_strip_top(const cad::Model& model, const std::vector<int>& body_surfaces, const Frame& wall,
                             const Vec3& strip_top, const Vec3& outward, double delta_wing, double delta_wall) {
  const Frame::Above above = wall.above(strip_top);
  const Vec3 under = strip_top - above.height * above.normal;
  return medial_halo(model, body_surfaces, under, outward, above.normal, delta_wing, delta_wall);
}

// The halo placed from its root, its foot on the wing moved to the strip top: the halo from the
// root moved along the wall as far (the column strip top -> halo keeps the wing's normal, not
// leaning along the root: see halo_over_the_strip_top); it stays where it is when the foot does.
Vec3 halo_moved_with_its_foot(const cad::Model& model, const std::vector<int>& body_surfaces, const Frame& wall,
                              const Vec3& root, const Vec3& foot, const Vec3& strip_top, const Vec3& outward,
                              double delta_wing, double delta_wall) {
  const Vec3 n = wall.normal_at(root), shift = strip_top - foot;
  return medial_halo(model, body_surfaces, root + shift - shift.dot(n) * n, outward, n, delta_wing, delta_wall);
}

// Halo, strip top and wall foot of root node `i` of the loop; `sides` the two root segments'
// outward normals in the wall plane (their bisector the direction away from the body). A sharp
// trailing edge's root (`fan`) keeps its halos over the root: keep_fan_halos_off_the_rear_interfaces
// places them against the rear interfaces standing on the strip top (over a strip top raised
// forward along a tapered wing's edge, the skins crossed near the fan: TetGen refused the far field).
JunctionNode place_junction_node(const cad::Model& model, const BodyRoles& roles,
                                 const std::map<int, int>& root_surface, const BodyMesh& body, int r,
                                 const std::array<Vec3, 2>& sides, const Frame& wall, double delta_wing,
                                 double delta_wall, bool fan) {
  const Vec3 outward = (sides[0] + sides[1]).normalized();
  JunctionNode j;
  j.root = body.points[r];
  j.halo = medial_halo(model, roles.body_surfaces, j.root, outward, wall.normal_at(j.root), delta_wing, delta_wall);
  const CadAttachment& at = body.cad[r];
  // Where the halo's foot sinks below delta_wall: the point at that height straight up the wing
  // from the root (in the entity's parameters), so neighbouring strip tops keep the roots' order (a
  // foot projected onto the edge of its face, raised, could land on the next root's own). Above
  // it, at the foot's height, straight up the wing from where the halo's shadow on the wall meets
  // the root's face: the foot itself on a straight wing, but on a swept one the foot stands nearly
  // straight over its root, delta_wall tan(sweep) upstream of the wing's section there, while its
  // neighbours below delta_wall and the lifted wing nodes move along the sections (robustness
  // sweep, H-type seed 77 run 10: two strip tops swapped places along the root and the lifted
  // triangle between them folded).
  CadAttachment from_root, from_shadow;  // from_shadow: on a face only (a curve is its own line up)
  Vec3 foot, shadow_on_face;
  const Vec3 shadow = j.halo - delta_wall * wall.normal_at(j.root);
  const int c = at.kind == CadAttachment::Vertex ? spanwise_curve(model, at.entity, roles.wall_surface) : -1;
  if (c >= 0) {
    const auto p = model.curve(c).project(j.halo);
    foot = p.point;
    j.strip_top_cad = {CadAttachment::Curve, c, p.t, 0.0};
    from_root = {CadAttachment::Curve, c, model.curve(c).project(j.root).t, 0.0};
  } else {
    const auto it = root_surface.find(root_curve_of(model, at, roles.wall_surface));
    if (it == root_surface.end())
      throw NearFieldError("near field: the root node at " + point_label(j.root) + " is not on a body-wall curve");
    const cad::Surface& face = model.surface(it->second);
    const cad::Vec2 root_uv = face.project(j.root).uv;
    const auto p = face.project(j.halo, root_uv);
    if (!p.inside)
      throw NearFieldError("near field: the top of the root strip above " + point_label(j.root) + " falls off " +
                           surface_label(model, it->second) + " (wall layer thickness " + number_label(delta_wall) +
                           ", thickness " + number_label(delta_wing) + "); use a thinner wall layer or near field");
    foot = p.point;
    j.strip_top_cad = {CadAttachment::Surface, it->second, p.uv.x(), p.uv.y()};
    from_root = {CadAttachment::Surface, it->second, root_uv.x(), root_uv.y()};
    const auto q = face.project(shadow, root_uv);
    shadow_on_face = q.point;
    from_shadow = {CadAttachment::Surface, it->second, q.uv.x(), q.uv.y()};
  }
  j.strip_top = foot;
  if (wall.height(foot) < delta_wall) {
    j.strip_top_cad = from_root;
    j.strip_top = detail::move_to_height(model, wall, j.root, j.strip_top_cad, delta_wall);
    if (!fan)
      j.halo = halo_over_the_strip_top(model, roles.body_surfaces, wall, j.strip_top, outward, delta_wing, delta_wall);
  } else if (c < 0) {
    j.strip_top_cad = from_shadow;
    j.strip_top = detail::move_to_height(model, wall, shadow_on_face, j.strip_top_cad, wall.height(foot));
    if (!fan)
      j.halo = halo_moved_with_its_foot(model, roles.body_surfaces, wall, j.root, foot, j.strip_top, outward,
                                        delta_wing, delta_wall);
  }
  if (!(wall.height(j.strip_top) > 1e-3 * delta_wall))
    throw NearFieldError("near field: the root strip above " + point_label(j.root) + " on " +
                         surface_label(model, body.node_surface[r]) + " has no height");
  place_wall_foot(model, roles.wall_surface, sides, outward, wall, delta_wing, delta_wall, j);
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

}  // namespace

RootSegments::RootSegments(const BodyMesh& body, const Frame& wall) : body_(body), wall_(wall) {
  triangle_of_edge_.reserve(3 * body.triangles.size());
  for (std::size_t t = 0; t < body.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      triangle_of_edge_.add(static_cast<std::uint32_t>(body.triangles[t][k]),
                            static_cast<std::uint32_t>(body.triangles[t][(k + 1) % 3]), t);
  triangle_of_edge_.sort();
}

int RootSegments::triangle(int a, int b) const {
  const auto t = triangle_of_edge_.find(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b));
  if (!t)
    throw std::out_of_range("RootSegments: no body triangle has the edge " + std::to_string(a) + " -> " +
                            std::to_string(b));
  return static_cast<int>(*t);
}

Vec3 RootSegments::outward(int a, int b) const {
  const auto& t = body_.triangles[triangle(a, b)];
  const Vec3 n_tri =
      (body_.points[t[1]] - body_.points[t[0]]).cross(body_.points[t[2]] - body_.points[t[0]]).normalized();
  return segment_outward(body_.points[a], body_.points[b], n_tri,
                         wall_.normal_at(0.5 * (body_.points[a] + body_.points[b])));
}

int root_curve_of(const cad::Model& model, const CadAttachment& root, int wall) {
  if (root.kind == CadAttachment::Curve) return root.entity;
  for (int c : model.curves_of_vertex(root.entity)) {
    const auto& uses = model.surfaces_of_curve(c);
    if (std::any_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& u) { return u.surface == wall; })) return c;
  }
  return -1;
}

JunctionNodes place_junction_nodes(const cad::Model& model, const BodyRoles& roles,
                                   const std::map<int, int>& root_surface, const BodyMesh& body,
                                   const std::vector<int>& loop, const RootSegments& segments, int crack_curve,
                                   const Frame& wall, double delta_wing, double delta_wall) {
  const int n = static_cast<int>(loop.size());
  JunctionNodes j;
  j.at.resize(n);
  j.fan = fan_index(model, body, loop, crack_curve);
  for (int i = 0; i < n; ++i) {
    const int r = loop[i], prev = loop[(i + n - 1) % n], next = loop[(i + 1) % n];
    const Vec3 before = segments.outward(prev, r), after = segments.outward(r, next);
    if (i == j.fan) {  // a side each
      j.at[i] = place_junction_node(model, roles, root_surface, body, r, {before, before}, wall, delta_wing,
                                    delta_wall, true);
      j.fan_side1 = place_junction_node(model, roles, root_surface, body, r, {after, after}, wall, delta_wing,
                                        delta_wall, true);
      continue;
    }
    j.at[i] = place_junction_node(model, roles, root_surface, body, r, {before, after}, wall, delta_wing, delta_wall,
                                  false);
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

void level_bare_strip_tops(const cad::Model& model, const Frame& wall, const BodyMesh& body,
                           const std::vector<int>& loop, const std::set<int>& bare_surfaces,
                           const RootSegments& segments, std::vector<JunctionNode>& nodes) {
  const int n = static_cast<int>(loop.size());
  auto on_bare = [&](int a, int b) { return bare_surfaces.count(body.triangle_surface[segments.triangle(a, b)]) > 0; };
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
                           surfaces_label(model, bare_surfaces) + " cannot reach the height " + number_label(level) +
                           " of its neighbours on the trailing-edge base");
  }
}

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

void split_bare_root_corners(const std::vector<int>& loop, const std::set<int>& bare_surfaces,
                             const RootSegments& segments, detail::JunctionShell& shell) {
  mesh::Mesh& m = shell.field.mesh;
  const int n = static_cast<int>(loop.size());
  for (int i = 0; i < n; ++i) {
    const std::array<bool, 2> on_bare{bare_surfaces.count(segments.surface(loop[(i + n - 1) % n], loop[i])) > 0,
                                      bare_surfaces.count(segments.surface(loop[i], loop[(i + 1) % n])) > 0};
    if (on_bare[0] == on_bare[1]) continue;
    detail::JunctionShell::Corner c;
    c.index = i;
    c.bare = on_bare[0] ? 0 : 1;
    const NodeId foot = shell.foot_id[i], halo = static_cast<NodeId>(loop[i]) + shell.offset;
    c.foot[1 - c.bare] = foot, c.top[1 - c.bare] = halo;
    c.foot[c.bare] = m.add_node(m.node(foot), m.cad_attachment(foot));
    c.top[c.bare] = m.add_node(m.node(halo));
    shell.corners.push_back(c);
  }
}

void add_junction_hexes(const cad::Model& model, const BodyMesh& body, const std::vector<int>& loop,
                        const JunctionNodes& j, const std::array<int, 2>& fan_layer, double delta_wing,
                        double delta_wall, detail::JunctionShell& shell) {
  NearField& field = shell.field;
  mesh::Mesh& m = field.mesh;
  const int n = static_cast<int>(loop.size()), fan = j.fan;
  const int junction_region = m.region_index("junction");
  auto id = [](int v) { return static_cast<NodeId>(v); };
  auto side_of = [&](int i, int other) { return other == (i + n - 1) % n ? 0 : 1; };
  std::map<int, const detail::JunctionShell::Corner*> corner;
  for (const auto& c : shell.corners) corner[c.index] = &c;
  auto foot = [&](int i, int other) {
    if (corner.count(i)) return corner.at(i)->foot[side_of(i, other)];
    return i == fan ? shell.fan.foot[side_of(i, other)] : shell.foot_id[i];
  };
  auto top = [&](int i, int other) {
    if (corner.count(i)) return corner.at(i)->top[side_of(i, other)];
    return id(i == fan ? fan_layer[side_of(i, other)] : loop[i]) + shell.offset;
  };
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

}  // namespace semimesh::nearfield::c_type
