// The wing layer on the lifted body: the bare triangles left out, cracked open along a sharp
// trailing edge, pinned at the junction's halos, offset and meshed as prisms.
#include "semimesh/nearfield/error.hpp"
#include "semimesh/nearfield/node_normals.hpp"

#include "c_shell_steps.hpp"
#include "labels.hpp"

#include <algorithm>
#include <set>

namespace semimesh::nearfield::c_type {
namespace {

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
std::vector<char> bare_triangles(const cad::Model& model, const BodyMesh& body, const std::set<int>& bare_surfaces,
                                 int crack_curve, const CrackNodes& crack) {
  std::set<int> sides;
  if (crack_curve >= 0)
    for (const cad::SurfaceUse& u : model.surfaces_of_curve(crack_curve)) sides.insert(u.surface);
  std::vector<char> bare(body.triangles.size(), 0);
  for (std::size_t t = 0; t < body.triangles.size(); ++t) {
    bare[t] = bare_surfaces.count(body.triangle_surface[t]) > 0;
    if (sides.count(body.triangle_surface[t]))
      for (int v : body.triangles[t]) bare[t] |= crack.end[v];
  }
  return bare;
}

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

}  // namespace

WingLayer wing_layer(const cad::Model& model, const BodyMesh& body, const std::vector<int>& loop,
                     const std::set<int>& bare_surfaces, int crack_curve) {
  WingLayer w;
  w.crack = crack_nodes(model, body, crack_curve, loop);
  w.bare = bare_triangles(model, body, bare_surfaces, crack_curve, w.crack);
  w.cracked = crack_open(without_bare(body, w.bare), w.crack);
  w.neighbours = node_neighbours(w.cracked.layer);
  const int count = body.num_nodes();
  for (std::size_t k = 0; k < w.cracked.copy_of.size(); ++k) {
    w.neighbours[count + k].push_back(w.cracked.copy_of[k]);
    w.neighbours[w.cracked.copy_of[k]].push_back(count + static_cast<int>(k));
  }
  return w;
}

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
                         number_label(params.thickness) +
                         ") cannot meet the halo above the root strip (wall layer "
                         "thickness " +
                         number_label(delta_wall) + ") without folding at " + point_label(layer.points[fold.node]) +
                         " (" + fold.reason + "), even at min_thickness_fraction (" +
                         number_label(params.min_thickness_fraction) +
                         "); use a smaller thickness or wall layer thickness, or more segments along the root "
                         "(smaller sizing sizes)");
  }
}

void add_wing_layer(const BodyMesh& body, const WingLayer& w, const detail::LayerOffsets& offsets,
                    const std::set<int>& bare_surfaces, detail::JunctionShell& shell) {
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
    if (w.bare[t] && !bare_surfaces.count(body.triangle_surface[t])) shell.bare.push_back(body.triangles[t]);
  shell.offset = offset;
}

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

}  // namespace semimesh::nearfield::c_type
