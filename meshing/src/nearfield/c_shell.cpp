#include "semimesh/nearfield/c_shell.hpp"

#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/junction_geometry.hpp"

#include "c_shell_steps.hpp"
#include "labels.hpp"

#include <cmath>

namespace semimesh::nearfield {
namespace c_type {
namespace {

void check_junction_params(const BodyRoles& roles, const JunctionParams& j, double wall_thickness) {
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
    const bool too_sharp = w.min_angle_deg < j.min_angle_deg;
    if (too_sharp || w.max_angle_deg > j.max_angle_deg)
      throw NearFieldError("near field: " + curve_label(model, w.curve) + " between " +
                           surface_label(model, w.body_surface) + " and the wall meets the wall at " +
                           number_label(too_sharp ? w.min_angle_deg : w.max_angle_deg) + " degrees (seen from the fluid) at " +
                           point_label(too_sharp ? w.min_at : w.max_at) + "; the junction block supports " +
                           number_label(j.min_angle_deg) + " to " + number_label(j.max_angle_deg) +
                           " degrees (nearfield.junction_min_angle, nearfield.junction_max_angle)");
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

}  // namespace
}  // namespace c_type

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

// The method's steps (c_shell.hpp): the root loop and the junction's cross-section at each root
// node, the wing mesh lifted onto the strip tops, the wing layer's offsets meeting the halos there,
// then the mesh: the layer's prisms and the junction's hexes.
JunctionShell build_junction_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                                   const ShellParams& params, const JunctionParams& junction, double wall_thickness,
                                   const std::set<int>& bare_surfaces, int crack_curve, bool split_bare_corners) {
  using namespace c_type;  // the steps, c_shell_steps.hpp
  detail::check_shell_params(model, roles, params);
  check_junction_params(roles, junction, wall_thickness);
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
  if (!bare_surfaces.empty())
    level_bare_strip_tops(model, wall, body, loop, bare_surfaces, segments, j.at);
  std::vector<CadAttachment> root_cad;
  for (int r : loop) root_cad.push_back(body.cad[r]);
  const auto [strip, tip] = lift_onto_strip(model, wall, loop, j.at, delta_wall, body);

  // The wing layer on the lifted mesh, its offsets meeting the halos at the strip tops.
  const WingLayer layer = wing_layer(model, body, loop, bare_surfaces, crack_curve);
  const LayerStart start = pin_layer_at_the_halos(layer, body, loop, j, params);
  const detail::LayerOffsets offsets =
      offsets_meeting_the_halo(model, layer.cracked.layer, layer.neighbours, start.normals, start.constraints, params,
                               loop, root_cad, roles.wall_surface, delta_wall);

  JunctionShell shell;
  shell.field.warnings = offsets.warnings;
  shell.field.mesh.reserve(ho::Shape::Prism, body.triangles.size() + loop.size());
  add_wing_layer(body, layer, offsets, bare_surfaces, shell);
  add_junction_wall_nodes(loop, root_cad, j, shell);
  if (split_bare_corners && !bare_surfaces.empty()) split_bare_root_corners(loop, bare_surfaces, segments, shell);
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

}  // namespace detail

NearField build_c_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params, const JunctionParams& junction, double wall_thickness) {
  detail::JunctionShell shell =
      detail::build_junction_shell(model, meshes, roles, params, junction, wall_thickness, /*bare_surfaces=*/{},
                                   /*crack_curve=*/-1);
  NearField& field = shell.field;
  for (std::size_t i = 0; i < shell.chain.size(); ++i) {
    field.footprint.push_back(shell.foot_id[i]);
    field.footprint_top.push_back(static_cast<mesh::NodeId>(shell.chain[i]) + shell.offset);
  }
  return std::move(field);
}

}  // namespace semimesh::nearfield