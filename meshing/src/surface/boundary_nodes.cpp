#include "boundary_nodes.hpp"

#include "semimesh/surface/error.hpp"

#include <map>
#include <set>
#include <string>

namespace semimesh::surface::detail {

std::string surface_label(const cad::Model& model, int surface) {
  return "surface " + std::to_string(surface) + " ('" + model.surface(surface).name() + "')";
}

std::vector<std::vector<int>> add_boundary_nodes(const cad::Model& model, int surface, const CurveMeshes& curves,
                                                 SurfaceMesh& mesh) {
  const cad::Surface& face = model.surface(surface);
  // Curve nodes lie on the surface up to the model's tolerance and the projection's accuracy.
  const double max_distance = std::max(100.0 * model.tolerance(), 1e-8 * model.bbox().diagonal());
  std::map<int, int> node_of_vertex;
  std::set<int> used_curves;
  std::vector<std::vector<int>> loops;

  auto add_node = [&](const Vec3& point, const NodeOrigin& origin, const Vec2* guess) {
    const cad::SurfaceProjection proj = guess ? face.project(point, *guess) : face.project(point);
    if (proj.distance > max_distance)
      throw SurfaceMeshError(surface_label(model, surface) + ": node " + std::to_string(origin.index) + " of curve " +
                             std::to_string(origin.curve) + " ('" + model.curve(origin.curve).name() +
                             "') is " + std::to_string(proj.distance) + " away from the surface (tolerance " +
                             std::to_string(max_distance) + "); the CAD topology or the surface projection is inconsistent");
    mesh.uv.push_back(proj.uv);
    mesh.points.push_back(point);
    mesh.origin.push_back(origin);
    return mesh.num_nodes() - 1;
  };

  for (const cad::Loop& loop : model.loops(surface)) {
    std::vector<int> chain;
    for (const cad::CurveUse& use : loop.uses) {
      if (!used_curves.insert(use.curve).second)
        throw SurfaceMeshError(surface_label(model, surface) + " uses curve " + std::to_string(use.curve) + " ('" +
                               model.curve(use.curve).name() +
                               "') twice (a periodic seam): seams are not supported by the surface mesher");
      const CurveMesh& cm = curves.at(use.curve);
      const auto ends = model.curve_vertices(use.curve);
      const int n = cm.segments();
      // Walk the use from its start vertex; its end vertex is the next use's start.
      for (int k = 0; k < n; ++k) {
        const int i = use.forward ? k : n - k;
        NodeOrigin origin{use.curve, i, cm.t[i], -1};
        if (k == 0) {
          origin.vertex = use.forward ? ends[0] : ends[1];
          auto found = node_of_vertex.find(origin.vertex);
          if (found != node_of_vertex.end()) {
            chain.push_back(found->second);
            continue;
          }
        }
        const Vec2* guess = chain.empty() ? nullptr : &mesh.uv[chain.back()];
        const int node = add_node(cm.points[i], origin, guess);
        if (k == 0) node_of_vertex[origin.vertex] = node;
        chain.push_back(node);
      }
    }
    if (chain.size() < 3)
      throw SurfaceMeshError(surface_label(model, surface) + ": a boundary loop has only " + std::to_string(chain.size()) +
                             " nodes; its curves need more segments");
    loops.push_back(std::move(chain));
  }
  if (loops.empty()) throw SurfaceMeshError(surface_label(model, surface) + " has no boundary loop");
  return loops;
}

}  // namespace semimesh::surface::detail
