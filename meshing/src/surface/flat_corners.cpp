#include "flat_corners.hpp"
#include "uv_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace semimesh::surface::detail {
namespace {

// Whether the boundary of `surface` is smooth at CAD vertex v: the (exactly two) curve ends of the
// surface's loops that meet there leave v in nearly opposite directions.
bool smooth_vertex(const cad::Model& model, int surface, int v) {
  std::vector<Vec3> outgoing;
  for (int c : model.curves_of_vertex(v)) {
    const auto& uses = model.surfaces_of_curve(c);
    if (std::none_of(uses.begin(), uses.end(), [&](const cad::SurfaceUse& u) { return u.surface == surface; })) continue;
    const cad::Curve& curve = model.curve(c);
    const auto ends = model.curve_vertices(c);
    if (ends[0] == v) outgoing.push_back(curve.derivatives(curve.bounds().lo).d1.normalized());
    if (ends[1] == v) outgoing.push_back(-curve.derivatives(curve.bounds().hi).d1.normalized());
  }
  if (outgoing.size() != 2) return false;
  return outgoing[0].dot(outgoing[1]) < std::cos(kSmoothCornerDeg * M_PI / 180.0);
}

}  // namespace

int fix_flat_corners(const cad::Model& model, int surface, SurfaceMesh& mesh) {
  auto& tris = mesh.triangles;
  std::map<std::uint64_t, std::vector<int>> uses;  // edge -> triangles
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
    for (int i = 0; i < 3; ++i) uses[edge_key(tris[t][i], tris[t][(i + 1) % 3])].push_back(t);
  auto on_boundary = [&](int a, int b) { return uses[edge_key(a, b)].size() == 1; };
  auto smooth = [&](int n) {
    const NodeOrigin& o = mesh.origin[n];
    return o.on_boundary() && (o.vertex < 0 || smooth_vertex(model, surface, o.vertex));
  };

  int fixed = 0;
  const int original = static_cast<int>(tris.size());
  for (int t = 0; t < original; ++t)
    for (int i = 0; i < 3; ++i) {
      const int n = tris[t][i], p = tris[t][(i + 1) % 3], q = tris[t][(i + 2) % 3];
      if (!on_boundary(n, p) || !on_boundary(q, n) || on_boundary(p, q) || !smooth(n)) continue;
      // The neighbour across the opposite edge p -> q runs q -> p -> r.
      auto& across = uses[edge_key(p, q)];
      const int s = across[0] == t ? across[1] : across[0];
      int r = -1;
      for (int v : tris[s])
        if (v != p && v != q) r = v;
      // A swap to a boundary node r would make the edge n-r join two nodes of one curve, which
      // curving reads as lying on that curve: only swap to an interior node.
      const bool swap = !mesh.origin[r].on_boundary() && signed_area_uv(mesh, n, p, r) > 0.0 &&
                        signed_area_uv(mesh, n, r, q) > 0.0;
      if (swap) {
        tris[t] = {n, p, r};
        tris[s] = {n, r, q};
        uses.erase(edge_key(p, q));
        uses[edge_key(n, r)] = {t, s};
        auto& pr = uses[edge_key(p, r)];
        std::replace(pr.begin(), pr.end(), s, t);
        auto& nq = uses[edge_key(n, q)];
        std::replace(nq.begin(), nq.end(), t, s);
      } else {
        const int m = mesh.num_nodes();
        const Vec2 uv = 0.5 * (mesh.uv[p] + mesh.uv[q]);
        mesh.uv.push_back(uv);
        mesh.points.push_back(model.surface(surface).point(uv));
        mesh.origin.push_back(NodeOrigin{});
        tris[t] = {n, p, m};
        tris[s] = {q, m, r};
        tris.push_back({n, m, q});
        tris.push_back({m, p, r});
        const int u = static_cast<int>(tris.size()) - 2, w = u + 1;
        uses.erase(edge_key(p, q));
        uses[edge_key(n, m)] = {t, u};
        uses[edge_key(p, m)] = {t, w};
        uses[edge_key(q, m)] = {u, s};
        uses[edge_key(r, m)] = {s, w};
        auto& nq = uses[edge_key(n, q)];
        std::replace(nq.begin(), nq.end(), t, u);
        auto& pr = uses[edge_key(p, r)];
        std::replace(pr.begin(), pr.end(), s, w);
      }
      ++fixed;
      break;
    }
  return fixed;
}

}  // namespace semimesh::surface::detail
