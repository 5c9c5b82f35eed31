#include "semimesh/nearfield/o_shell.hpp"

#include "semimesh/nearfield/body_mesh.hpp"
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/layer_checks.hpp"
#include "semimesh/nearfield/node_normals.hpp"

#include "labels.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <sstream>

namespace semimesh::nearfield {
namespace {

// Why a node's thickness was reduced (bits).
enum Reason : unsigned { kFold = 1, kProximity = 2 };

void check_params(const cad::Model& model, const BodyRoles& roles, const ShellParams& p) {
  auto fail = [](const std::string& what) { throw NearFieldError("near field: " + what); };
  if (const auto bad = params::violation(p, shell_keys(), "nearfield")) fail(*bad);
  if (roles.body_surfaces.empty()) fail("no body surfaces given");
  if (roles.wall_surface >= model.num_surfaces())
    fail("wall surface id " + std::to_string(roles.wall_surface) + " is not a surface of the model");
  if (std::count(roles.body_surfaces.begin(), roles.body_surfaces.end(), roles.wall_surface))
    fail("the wall " + surface_label(model, roles.wall_surface) + " is also listed as a body surface");
}

// Whether a body node on the open edge of the body lies on the wall: its curve, or a curve of its
// vertex, bounds the wall surface.
bool on_wall(const cad::Model& model, const mesh::CadAttachment& cad, int wall) {
  auto curve_on_wall = [&](int c) {
    for (const auto& use : model.surfaces_of_curve(c))
      if (use.surface == wall) return true;
    return false;
  };
  if (cad.kind == mesh::CadAttachment::Curve) return curve_on_wall(cad.entity);
  if (cad.kind == mesh::CadAttachment::Vertex)
    for (int c : model.curves_of_vertex(cad.entity))
      if (curve_on_wall(c)) return true;
  return false;
}

// thickness[i] <= thickness[j] + gradation |x_i - x_j| over mesh edges (Dijkstra from the thinnest).
void limit_gradation(const BodyMesh& body, const std::vector<std::vector<int>>& neighbours, double gradation,
                     std::vector<double>& thickness) {
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int i = 0; i < body.num_nodes(); ++i) queue.push({thickness[i], i});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > thickness[v]) continue;
    for (int w : neighbours[v]) {
      const double bound = d + gradation * (body.points[w] - body.points[v]).norm();
      if (bound < thickness[w]) thickness[w] = bound, queue.push({bound, w});
    }
  }
}

std::string reason_text(unsigned reasons) {
  std::string text;
  if (reasons & kFold) text += "neighbouring prisms would fold (concave curvature)";
  if (reasons & kProximity)
    text += std::string(text.empty() ? "" : "; ") + "the layer would come closer than half its thickness to another part of the body";
  return text.empty() ? "graded from a reduced neighbour" : text;
}

// One warning per connected region of nodes whose thickness was reduced, at its thinnest node.
std::vector<Warning> reduction_warnings(const cad::Model& model, const BodyMesh& body,
                                        const std::vector<std::vector<int>>& neighbours,
                                        const std::vector<double>& thickness, const std::vector<unsigned>& reasons,
                                        double requested) {
  std::vector<Warning> warnings;
  std::vector<char> seen(body.num_nodes(), 0);
  auto reduced = [&](int i) { return thickness[i] < requested * (1.0 - 1e-12); };
  for (int start = 0; start < body.num_nodes(); ++start) {
    if (seen[start] || !reduced(start)) continue;
    int thinnest = start, count = 0;
    unsigned why = 0;
    std::vector<int> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      ++count, why |= reasons[v];
      if (thickness[v] < thickness[thinnest]) thinnest = v;
      for (int w : neighbours[v])
        if (!seen[w] && reduced(w)) seen[w] = 1, stack.push_back(w);
    }
    std::ostringstream message;
    message << "near-field thickness reduced to " << thickness[thinnest] << " ("
            << std::lround(100.0 * thickness[thinnest] / requested) << "% of " << requested << ") on "
            << surface_label(model, body.node_surface[thinnest]) << " around " << point_label(body.points[thinnest])
            << " (" << count << " nodes): " << reason_text(why);
    warnings.push_back({message.str(), body.points[thinnest]});
  }
  return warnings;
}

// The skin's edges on the wall, (a', b') as in their skin face, chained into one loop.
std::vector<mesh::NodeId> footprint_loop(const BodyMesh& body, const std::vector<std::pair<int, int>>& open,
                                         mesh::NodeId outer_offset) {
  if (open.empty()) return {};
  std::map<int, int> next;
  for (const auto& [a, b] : open)
    if (!next.emplace(a, b).second)
      throw NearFieldError("near field: the body's root passes twice through the node at " + point_label(body.points[a]) +
                           "; the wall footprint must be one simple loop");
  std::vector<mesh::NodeId> loop;
  int v = open.front().first;
  do {
    loop.push_back(static_cast<mesh::NodeId>(v) + outer_offset);
    const auto it = next.find(v);
    if (it == next.end() || loop.size() > open.size())
      throw NearFieldError("near field: the body's root edges near " + point_label(body.points[v]) +
                           " do not form a closed loop on the wall");
    v = it->second;
  } while (v != open.front().first);
  if (loop.size() != open.size())
    throw NearFieldError("near field: the body meets the wall in more than one loop (" + std::to_string(open.size()) +
                         " root edges, first loop " + std::to_string(loop.size()) + "); one wing per wall is supported");
  return loop;
}

}  // namespace

const params::Table<ShellParams>& shell_keys() {
  static const params::Table<ShellParams> table = {
      params::real("thickness", &ShellParams::thickness, "> 0", "shell thickness δ, model units"),
      params::integer("smoothing_passes", &ShellParams::normal_smoothing_passes, ">= 0",
                      "Laplacian smoothing passes of the node normals over the body mesh"),
      params::real("min_thickness_fraction", &ShellParams::min_thickness_fraction, "(0, 1]",
                   "local thickness reduction below this fraction of δ is an error"),
      params::real("reduction_factor", &ShellParams::reduction_factor, "(0, 1)",
                   "thickness multiplier per reduction round"),
      params::real("gradation", &ShellParams::gradation, "> 0",
                   "after a reduction, |δx − δy| <= gradation |x − y| between nodes x, y"),
  };
  return table;
}

NearField build_o_shell(const cad::Model& model, const surface::SurfaceMeshes& meshes, const BodyRoles& roles,
                        const ShellParams& params) {
  check_params(model, roles, params);
  const BodyMesh body = merge_body_meshes(model, meshes, roles.body_surfaces);
  const int count = body.num_nodes();
  const auto open = open_edges(body);
  const auto neighbours = node_neighbours(body);

  // Root nodes: on the body's open edges, which must all lie on the wall.
  std::vector<char> root(count, 0);
  std::vector<Vec3> plane_normal(count, Vec3::Zero());
  std::vector<cad::Vec2> wall_uv(count, cad::Vec2::Zero());  // [nodes] root nodes: (u, v) on the wall
  for (const auto& [a, b] : open)
    for (int v : {a, b}) {
      if (root[v]) continue;
      if (roles.wall_surface < 0 || !on_wall(model, body.cad[v], roles.wall_surface))
        throw NearFieldError("near field: the body mesh is open at " + point_label(body.points[v]) + " on " +
                             surface_label(model, body.node_surface[v]) +
                             (roles.wall_surface < 0 ? " and no wall surface is given"
                                                     : " away from the wall " + surface_label(model, roles.wall_surface)) +
                             "; list every surface of the body");
      const cad::Surface& wall = model.surface(roles.wall_surface);
      root[v] = 1;
      wall_uv[v] = wall.project(body.points[v]).uv;
      plane_normal[v] = wall.normal(wall_uv[v]);
    }

  NormalOptions normal_options;
  normal_options.smoothing_passes = params.normal_smoothing_passes;
  const std::vector<Vec3> normals = node_normals(body, plane_normal, normal_options);

  std::vector<double> thickness(count, params.thickness);
  std::vector<unsigned> reasons(count, 0);
  std::vector<Vec3> outer(count);
  std::vector<cad::Vec2> outer_wall_uv = wall_uv;  // [nodes] root nodes: (u, v) of the offset on the wall
  auto place_outer = [&] {
    for (int i = 0; i < count; ++i) {
      outer[i] = body.points[i] + thickness[i] * normals[i];
      if (root[i]) {
        const auto projection = model.surface(roles.wall_surface).project(outer[i], wall_uv[i]);
        outer[i] = projection.point, outer_wall_uv[i] = projection.uv;
      }
    }
  };
  const double thinnest_allowed = params.min_thickness_fraction * params.thickness;
  const int max_rounds = 1000;
  for (int round = 0;; ++round) {
    place_outer();
    std::vector<unsigned> bad(count, 0);
    for (const auto& t : body.triangles) {
      const std::array<Vec3, 6> x{body.points[t[0]], body.points[t[1]], body.points[t[2]],
                                  outer[t[0]],       outer[t[1]],       outer[t[2]]};
      if (!prism_is_sound(x))
        for (int v : t) bad[v] |= kFold;
    }
    const auto crowded = crowded_nodes(body, neighbours, outer, thickness);
    for (int i = 0; i < count; ++i) bad[i] |= crowded[i] ? kProximity : 0u;
    if (std::none_of(bad.begin(), bad.end(), [](unsigned b) { return b != 0; })) break;
    for (int i = 0; i < count; ++i) {
      if (!bad[i]) continue;
      reasons[i] |= bad[i];
      if (thickness[i] <= thinnest_allowed * (1.0 + 1e-12) || round == max_rounds)
        throw NearFieldError("near field: cannot build the prism layer on " + surface_label(model, body.node_surface[i]) +
                             " at " + point_label(body.points[i]) + ": " + reason_text(bad[i]) +
                             " even at min_thickness_fraction (" + number_label(params.min_thickness_fraction) +
                             ") x thickness (" + number_label(params.thickness) +
                             "); use a smaller 'thickness' or a finer surface mesh there");
      thickness[i] = std::max(thickness[i] * params.reduction_factor, thinnest_allowed);
    }
    limit_gradation(body, neighbours, params.gradation, thickness);
  }

  NearField field;
  field.warnings = reduction_warnings(model, body, neighbours, thickness, reasons, params.thickness);
  mesh::Mesh& m = field.mesh;
  m.reserve(ho::Shape::Prism, body.triangles.size());
  const int layer_region = m.region_index("wing_layer");
  for (int i = 0; i < count; ++i) m.add_node(body.points[i], body.cad[i]);
  const auto offset = static_cast<mesh::NodeId>(count);
  for (int i = 0; i < count; ++i) {
    mesh::CadAttachment cad;
    if (root[i]) cad = {mesh::CadAttachment::Surface, roles.wall_surface, outer_wall_uv[i].x(), outer_wall_uv[i].y()};
    m.add_node(outer[i], cad);
  }
  auto id = [](int v) { return static_cast<mesh::NodeId>(v); };
  for (std::size_t t = 0; t < body.triangles.size(); ++t) {
    const auto& v = body.triangles[t];
    m.add_element(ho::Shape::Prism, {id(v[0]), id(v[1]), id(v[2]), id(v[0]) + offset, id(v[1]) + offset, id(v[2]) + offset},
                  layer_region);
    field.element_surface.push_back(body.triangle_surface[t]);
    m.add_boundary_face("wing", ho::Shape::Triangle, {id(v[0]), id(v[2]), id(v[1])});
    field.skin.push_back({{id(v[0]) + offset, id(v[1]) + offset, id(v[2]) + offset, mesh::kNoNode}, 3});
  }
  for (const auto& [a, b] : open)
    m.add_boundary_face("wall", ho::Shape::Quadrilateral, {id(a), id(b), id(b) + offset, id(a) + offset});
  field.footprint = footprint_loop(body, open, offset);

  field.thickness_min = params.thickness;
  field.thickness_max = 0.0;
  for (int i = 0; i < count; ++i) {
    const double used = (outer[i] - body.points[i]).norm();
    field.thickness_min = std::min(field.thickness_min, used);
    field.thickness_max = std::max(field.thickness_max, used);
  }
  return field;
}

}  // namespace semimesh::nearfield
