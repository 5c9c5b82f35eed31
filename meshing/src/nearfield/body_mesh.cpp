#include "semimesh/nearfield/body_mesh.hpp"

#include "semimesh/nearfield/error.hpp"
#include "labels.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

namespace semimesh::nearfield {

BodyMesh merge_body_meshes(const cad::Model& model, const surface::SurfaceMeshes& meshes,
                           const std::vector<int>& body_surfaces) {
  BodyMesh body;
  std::map<int, int> vertex_node;                   // CAD vertex -> body node
  std::map<std::pair<int, int>, int> curve_node;    // (curve, index) -> body node
  for (int s : body_surfaces) {
    if (s < 0 || s >= model.num_surfaces())
      throw NearFieldError("near field: body surface id " + std::to_string(s) + " is not a surface of the model (it has " +
                           std::to_string(model.num_surfaces()) + ")");
    if (s >= static_cast<int>(meshes.surfaces.size()) || meshes.surfaces[s].surface != s)
      throw NearFieldError("near field: body " + surface_label(model, s) + " has no surface mesh");
    const surface::SurfaceMesh& m = meshes.surfaces[s];
    if (!m.quads.empty())
      throw NearFieldError("near field: body " + surface_label(model, s) + " holds " + std::to_string(m.quads.size()) +
                           " quads; the O-type shell extrudes triangles (do not mesh body surfaces as structured strips)");
    if (m.triangles.empty()) throw NearFieldError("near field: body " + surface_label(model, s) + " has no triangles");

    std::vector<int> local_to_body(m.num_nodes());
    for (int i = 0; i < m.num_nodes(); ++i) {
      const surface::NodeOrigin& o = m.origin[i];
      int* slot = nullptr;
      mesh::CadAttachment cad;
      if (o.vertex >= 0) {
        slot = &vertex_node.emplace(o.vertex, -1).first->second;
        cad = {mesh::CadAttachment::Vertex, o.vertex, 0.0, 0.0};
      } else if (o.on_boundary()) {
        slot = &curve_node.emplace(std::make_pair(o.curve, o.index), -1).first->second;
        cad = {mesh::CadAttachment::Curve, o.curve, o.t, 0.0};
      } else {
        cad = {mesh::CadAttachment::Surface, s, m.uv[i].x(), m.uv[i].y()};
      }
      if (slot && *slot >= 0) {
        // Shared node: the surface mesher promises the very same point on both sides.
        if ((body.points[*slot] - m.points[i]).norm() > 1e3 * model.tolerance())
          throw NearFieldError("near field: " + surface_label(model, s) + " node at " + point_label(m.points[i]) +
                               " should be the shared curve node at " + point_label(body.points[*slot]) +
                               "; the surface meshes do not conform");
        local_to_body[i] = *slot;
        continue;
      }
      local_to_body[i] = body.num_nodes();
      if (slot) *slot = body.num_nodes();
      body.points.push_back(m.points[i]);
      body.cad.push_back(cad);
      body.node_surface.push_back(s);
    }
    for (const auto& t : m.triangles) {
      body.triangles.push_back({local_to_body[t[0]], local_to_body[t[1]], local_to_body[t[2]]});
      body.triangle_surface.push_back(s);
    }
  }
  return body;
}

std::vector<std::pair<int, int>> open_edges(const BodyMesh& body) {
  // Each directed use of an undirected edge (lo, hi): +1 for (lo, hi), -1 for (hi, lo). Sorted by
  // edge, every edge's uses lie side by side (in no particular order: none is needed).
  struct Use {
    int lo, hi, direction;
  };
  std::vector<Use> uses;
  uses.reserve(3 * body.triangles.size());
  for (const auto& t : body.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), a < b ? +1 : -1});
    }
  std::sort(uses.begin(), uses.end(),
            [](const Use& x, const Use& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); });
  std::vector<std::pair<int, int>> open;
  for (std::size_t first = 0, last = 0; first < uses.size(); first = last) {
    while (last < uses.size() && uses[last].lo == uses[first].lo && uses[last].hi == uses[first].hi) ++last;
    const std::size_t count = last - first;
    const Vec3 mid = 0.5 * (body.points[uses[first].lo] + body.points[uses[first].hi]);
    if (count > 2)
      throw NearFieldError("near field: the body mesh is not a surface at " + point_label(mid) + ": an edge has " +
                           std::to_string(count) + " triangles");
    if (count == 2 && uses[first].direction == uses[first + 1].direction)
      throw NearFieldError("near field: body triangles on both sides of the edge at " + point_label(mid) +
                           " are oriented inconsistently");
    if (count == 1)
      open.push_back(uses[first].direction > 0 ? std::make_pair(uses[first].lo, uses[first].hi)
                                               : std::make_pair(uses[first].hi, uses[first].lo));
  }
  return open;
}

std::vector<std::vector<int>> node_neighbours(const BodyMesh& body) {
  std::vector<std::vector<int>> nb(body.num_nodes());
  for (const auto& t : body.triangles)
    for (int i = 0; i < 3; ++i) {
      nb[t[i]].push_back(t[(i + 1) % 3]);
      nb[t[i]].push_back(t[(i + 2) % 3]);
    }
  for (auto& list : nb) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return nb;
}

}  // namespace semimesh::nearfield
