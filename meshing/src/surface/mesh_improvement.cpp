#include "mesh_improvement.hpp"
#include "uv_triangle.hpp"

#include "semimesh/surface/mesh_quality.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace semimesh::surface::detail {
namespace {

constexpr int kMaxSwapPasses = 20;
// Interior edges shorter than this fraction of the size are merged when that helps the angles.
constexpr double kCollapseFraction = 0.6;
constexpr double kMinGain = 1e-6;  // in sine of the minimum angle: ignore changes in the noise
// Quality changes below this are rounding noise (e.g. two CAD backends agreeing to 1e-13): moves
// and collapses that keep the quality within it count as ties and are taken, so that noise does
// not decide them.
constexpr double kQualityNoise = 1e-10;
// Relative area below which a (u, v) triangle counts as flat (not valid).
constexpr double kMinRelativeArea = 1e-12;

bool positive_uv(const SurfaceMesh& m, int a, int b, int c) {
  const double scale = std::max({(m.uv[b] - m.uv[a]).squaredNorm(), (m.uv[c] - m.uv[b]).squaredNorm(),
                                 (m.uv[a] - m.uv[c]).squaredNorm()});
  return signed_area_uv(m, a, b, c) > kMinRelativeArea * scale;
}

// The sine of the smallest angle; negative when the triangle in space faces against the surface's
// du x dv at its (u, v) centroid (a fold, possible where the surface shrinks to a pole).
double quality(const cad::Surface& face, const SurfaceMesh& m, const std::array<int, 3>& t) {
  const double sine = min_angle_sine(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
  const cad::SurfaceDerivatives d = face.derivatives((m.uv[t[0]] + m.uv[t[1]] + m.uv[t[2]]) / 3.0);
  const Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
  return n.dot(d.du.cross(d.dv)) < 0.0 ? -1.0 - sine : sine;
}

// Whether an edge spans a third of a period or more of a periodic parameter: on a face cut open
// along its seam it would go the long way round (the refinement splits such edges).
bool wraps(const cad::Surface& face, const Vec2& a, const Vec2& b) {
  for (int d = 0; d < 2; ++d)
    if (const std::optional<double> period = face.period(d))
      if (std::abs(b[d] - a[d]) >= *period / 3.0) return true;
  return false;
}

}  // namespace

int swap_edges(const cad::Surface& face, SurfaceMesh& mesh) {
  auto& tris = mesh.triangles;
  int total = 0;
  for (int pass = 0; pass < kMaxSwapPasses; ++pass) {
    // edge -> the (one or two) triangles using it; -1 for none
    std::unordered_map<std::uint64_t, std::array<int, 2>> uses;
    uses.reserve(3 * tris.size());
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
      for (int i = 0; i < 3; ++i) {
        auto [it, fresh] = uses.try_emplace(edge_key(tris[t][i], tris[t][(i + 1) % 3]), std::array<int, 2>{t, -1});
        if (!fresh) it->second[1] = t;
      }
    std::vector<char> touched(tris.size(), 0);
    std::unordered_set<std::uint64_t> created;  // edges made by swaps of this pass
    int swaps = 0;
    for (const auto& [edge, pair] : uses) {
      const int ta = pair[0], tb = pair[1];
      if (tb < 0 || touched[ta] || touched[tb]) continue;  // boundary edge, or changed this pass
      const int a = static_cast<int>(edge >> 32), b = static_cast<int>(edge & 0xffffffffu);
      // Opposite nodes: the one of each triangle not on the edge.
      auto opposite = [&](int t) {
        for (int v : tris[t])
          if (v != a && v != b) return v;
        return -1;
      };
      const int c = opposite(ta), d = opposite(tb);
      if (c == d || uses.count(edge_key(c, d)) || created.count(edge_key(c, d))) continue;
      if (wraps(face, mesh.uv[c], mesh.uv[d])) continue;
      // Orient: in ta the edge runs p -> q with c after q (counter-clockwise).
      int p = a, q = b;
      for (int i = 0; i < 3; ++i)
        if (tris[ta][i] == b && tris[ta][(i + 1) % 3] == a) std::swap(p, q);
      const std::array<int, 3> n1{c, p, d}, n2{c, d, q};
      if (!positive_uv(mesh, n1[0], n1[1], n1[2]) || !positive_uv(mesh, n2[0], n2[1], n2[2])) continue;
      const double before = std::min(quality(face, mesh, tris[ta]), quality(face, mesh, tris[tb]));
      const double after = std::min(quality(face, mesh, n1), quality(face, mesh, n2));
      if (after <= before + kMinGain) continue;
      tris[ta] = n1;
      tris[tb] = n2;
      touched[ta] = touched[tb] = 1;
      created.insert(edge_key(c, d));
      ++swaps;
    }
    total += swaps;
    if (swaps == 0) break;
  }
  return total;
}

int collapse_short_edges(const cad::Surface& face, const SizeField& size, SurfaceMesh& mesh) {
  const int n = mesh.num_nodes();
  auto& tris = mesh.triangles;
  std::vector<std::vector<int>> ball(n);  // [nodes][incident triangles]
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
    for (int v : tris[t]) ball[v].push_back(t);
  std::vector<char> node_touched(n, 0), node_dead(n, 0), tri_dead(tris.size(), 0);
  std::vector<double> node_size(n, 0.0);  // [nodes] size field at interior nodes
  for (int v = 0; v < n; ++v)
    if (!mesh.origin[v].on_boundary()) node_size[v] = size(mesh.points[v]);
  auto neighbours = [&](int v) {
    std::vector<int> out;
    for (int t : ball[v])
      for (int w : tris[t])
        if (w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  int collapses = 0;
  for (int t0 = 0; t0 < static_cast<int>(tris.size()); ++t0) {
    if (tri_dead[t0]) continue;
    for (int i = 0; i < 3; ++i) {
      const int a = tris[t0][i], b = tris[t0][(i + 1) % 3];
      if (mesh.origin[a].on_boundary() || mesh.origin[b].on_boundary() || node_touched[a] || node_touched[b]) continue;
      if ((mesh.points[b] - mesh.points[a]).norm() >= kCollapseFraction * 0.5 * (node_size[a] + node_size[b])) continue;
      // Link condition: a and b share exactly the two nodes opposite the edge.
      const auto na = neighbours(a), nb = neighbours(b);
      std::vector<int> common;
      std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
      if (common.size() != 2) continue;

      const Vec2 new_uv = 0.5 * (mesh.uv[a] + mesh.uv[b]);
      const Vec3 new_point = face.point(new_uv);
      double before = 1.0, after = 1.0;
      bool ok = true;
      std::vector<int> kept;  // triangles that survive with b renamed a
      for (int v : {a, b})
        for (int t : ball[v]) {
          if (std::find(kept.begin(), kept.end(), t) != kept.end()) continue;
          before = std::min(before, quality(face, mesh, tris[t]));
          const bool has_a = std::count(tris[t].begin(), tris[t].end(), a) > 0;
          const bool has_b = std::count(tris[t].begin(), tris[t].end(), b) > 0;
          if (has_a && has_b) continue;
          kept.push_back(t);
        }
      const Vec2 uv_a = mesh.uv[a];
      const Vec3 point_a = mesh.points[a];
      mesh.uv[a] = new_uv;
      mesh.points[a] = new_point;
      for (int t : kept) {
        std::array<int, 3> renamed = tris[t];
        for (int& w : renamed)
          if (w == b) w = a;
        ok = ok && positive_uv(mesh, renamed[0], renamed[1], renamed[2]);
        after = std::min(after, quality(face, mesh, renamed));
      }
      if (!ok || after < before - kQualityNoise) {
        mesh.uv[a] = uv_a;
        mesh.points[a] = point_a;
        continue;
      }
      for (int t : ball[b]) {
        const bool has_a = std::count(tris[t].begin(), tris[t].end(), a) > 0;
        if (has_a) tri_dead[t] = 1;
        for (int& w : tris[t])
          if (w == b) w = a;
      }
      node_dead[b] = 1;
      node_touched[a] = node_touched[b] = 1;
      for (int w : na) node_touched[w] = 1;
      for (int w : nb) node_touched[w] = 1;
      ++collapses;
      break;
    }
  }
  if (collapses == 0) return 0;
  // Compact: drop dead triangles and nodes, renumbering the survivors in order (boundary nodes
  // come first and are never removed, so their ids stay).
  std::vector<int> new_id(n, -1);
  int next = 0;
  for (int v = 0; v < n; ++v)
    if (!node_dead[v]) {
      new_id[v] = next;
      mesh.uv[next] = mesh.uv[v];
      mesh.points[next] = mesh.points[v];
      mesh.origin[next] = mesh.origin[v];
      ++next;
    }
  mesh.uv.resize(next);
  mesh.points.resize(next);
  mesh.origin.resize(next);
  std::vector<std::array<int, 3>> kept_tris;
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (!tri_dead[t]) kept_tris.push_back({new_id[tris[t][0]], new_id[tris[t][1]], new_id[tris[t][2]]});
  tris.swap(kept_tris);
  return collapses;
}

int smooth_nodes(const cad::Surface& face, SurfaceMesh& mesh) {
  const int n = mesh.num_nodes();
  std::vector<std::vector<int>> ball(n);  // [nodes][incident triangles]
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int v : mesh.triangles[t]) ball[v].push_back(t);
  int moved = 0;
  for (int v = 0; v < n; ++v) {
    if (mesh.origin[v].on_boundary() || ball[v].empty()) continue;
    // Two targets: the mean of the apexes of equilateral triangles on the ball's outer edges
    // (favours good angles where sizes vary) and the mean of the neighbours (plain Laplacian).
    Vec3 ideal = Vec3::Zero(), mean = Vec3::Zero();
    for (int t : ball[v]) {
      const auto& tri = mesh.triangles[t];
      int k = 0;
      while (tri[k] != v) ++k;
      const Vec3 &a = mesh.points[tri[(k + 1) % 3]], &b = mesh.points[tri[(k + 2) % 3]];
      const Vec3 mid = 0.5 * (a + b), along = (b - a).normalized();
      Vec3 across = mesh.points[v] - mid;
      across -= across.dot(along) * along;
      ideal += mid + (std::sqrt(3.0) / 2.0) * (b - a).norm() * across.normalized();
      mean += a + b;
    }
    ideal /= static_cast<double>(ball[v].size());
    mean /= 2.0 * static_cast<double>(ball[v].size());
    // Gauss-Newton steps of the projection of each target onto the surface.
    const cad::SurfaceDerivatives d = face.derivatives(mesh.uv[v]);
    Eigen::Matrix<double, 3, 2> J;
    J << d.du, d.dv;
    const Eigen::Matrix2d JTJ = J.transpose() * J;
    if (!(std::abs(JTJ.determinant()) > 0.0)) continue;
    const auto solver = JTJ.ldlt();
    const std::array<Vec2, 2> steps{solver.solve(J.transpose() * (ideal - d.p)), solver.solve(J.transpose() * (mean - d.p))};

    double before = 1.0;
    for (int t : ball[v]) before = std::min(before, quality(face, mesh, mesh.triangles[t]));
    const Vec2 old_uv = mesh.uv[v];
    const Vec3 old_point = mesh.points[v];
    // Each full step, else half of it: accepted when the ball stays valid and its worst angle
    // does not get worse.
    bool accepted = false;
    for (int k = 0; k < 4 && !accepted; ++k) {
      mesh.uv[v] = old_uv + (k < 2 ? 1.0 : 0.5) * steps[k % 2];
      mesh.points[v] = face.point(mesh.uv[v]);
      bool ok = true;
      double after = 1.0;
      for (int t : ball[v]) {
        const auto& tri = mesh.triangles[t];
        ok = ok && positive_uv(mesh, tri[0], tri[1], tri[2]);
        after = std::min(after, quality(face, mesh, tri));
      }
      accepted = ok && after >= before - kQualityNoise;
    }
    if (accepted) {
      ++moved;
    } else {
      mesh.uv[v] = old_uv;
      mesh.points[v] = old_point;
    }
  }
  return moved;
}

}  // namespace semimesh::surface::detail
