#include "boundary_nodes.hpp"

#include "semimesh/surface/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace semimesh::surface::detail {

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
      throw SurfaceMeshError(cad::surface_label(model, surface) + ": node " + std::to_string(origin.index) + " of curve " +
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
        throw SurfaceMeshError(cad::surface_label(model, surface) + " uses " + cad::curve_label(model, use.curve) +
                               " twice (a periodic seam): seams are not supported by the surface mesher");
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
      throw SurfaceMeshError(cad::surface_label(model, surface) + ": a boundary loop has only " + std::to_string(chain.size()) +
                             " nodes; its curves need more segments");
    loops.push_back(std::move(chain));
  }
  if (loops.empty()) throw SurfaceMeshError(cad::surface_label(model, surface) + " has no boundary loop");
  return loops;
}

double parameter_grid_step(const cad::Surface& face, const SurfaceMesh& mesh) {
  const auto bounds = face.bounds();
  double extent = std::max(bounds[0].length(), bounds[1].length());
  if (!std::isfinite(extent) || !(extent > 0.0)) {
    Vec2 lo = mesh.uv.front(), hi = lo;
    for (const Vec2& uv : mesh.uv) {
      lo = lo.cwiseMin(uv);
      hi = hi.cwiseMax(uv);
    }
    extent = (hi - lo).maxCoeff();
  }
  if (!(extent > 0.0) || !std::isfinite(extent)) return 0.0;
  // The factor keeps round extents (1, 2, 0.5, ...) away from the power-of-two steps, where
  // extents differing by rounding noise would choose different grids.
  int exponent = 0;
  std::frexp(extent * (1.0 + 1e-6), &exponent);
  return std::ldexp(1.0, exponent - 32);
}

Vec2 snap_to_grid(const Vec2& uv, double step) {
  if (!(step > 0.0)) return uv;
  // Division and multiplication by a power of two are exact: only the rounding moves the point.
  return Vec2(std::round(uv.x() / step) * step, std::round(uv.y() / step) * step);
}

void canonicalise_boundary(double grid_step, SurfaceMesh& mesh, std::vector<std::vector<int>>& loops) {
  // Snapped copies decide; mesh.uv keeps the projections, which map exactly onto the curve points.
  std::vector<Vec2> snapped;  // [nodes]
  for (const Vec2& uv : mesh.uv) snapped.push_back(snap_to_grid(uv, grid_step));
  auto lower = [&](int a, int b) {
    return std::make_pair(snapped[a].x(), snapped[a].y()) < std::make_pair(snapped[b].x(), snapped[b].y());
  };
  for (std::size_t l = 0; l < loops.size(); ++l) {
    std::vector<int>& loop = loops[l];
    double twice_area = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec2 &p = snapped[loop[i]], &q = snapped[loop[(i + 1) % loop.size()]];
      twice_area += p.x() * q.y() - q.x() * p.y();
    }
    const bool outer = l == 0;  // the model lists the outer loop first
    if ((twice_area > 0.0) != outer) std::reverse(loop.begin(), loop.end());
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end(), lower), loop.end());
  }
  if (loops.size() > 2)
    std::sort(loops.begin() + 1, loops.end(), [&](const auto& a, const auto& b) { return lower(a.front(), b.front()); });

  std::vector<int> new_id(mesh.uv.size(), -1), order;  // [nodes] new id of each node; old ids in new order
  order.reserve(mesh.uv.size());
  auto visit = [&](int node) {
    if (new_id[node] >= 0) return;
    new_id[node] = static_cast<int>(order.size());
    order.push_back(node);
  };
  for (const auto& loop : loops)
    for (int node : loop) visit(node);
  for (int node = 0; node < static_cast<int>(mesh.uv.size()); ++node) visit(node);
  SurfaceMesh permuted;
  for (int node : order) {
    permuted.uv.push_back(mesh.uv[node]);
    permuted.points.push_back(mesh.points[node]);
    permuted.origin.push_back(mesh.origin[node]);
  }
  mesh.uv.swap(permuted.uv);
  mesh.points.swap(permuted.points);
  mesh.origin.swap(permuted.origin);
  for (auto& loop : loops)
    for (int& node : loop) node = new_id[node];
}

}  // namespace semimesh::surface::detail
