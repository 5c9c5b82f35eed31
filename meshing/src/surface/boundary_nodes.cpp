#include "boundary_nodes.hpp"

#include "semimesh/surface/error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace semimesh::surface::detail {

namespace {

using Periods = std::array<std::optional<double>, 2>;

/// A boundary node before it joins the mesh: its point, where it comes from, its (u, v).
struct LoopNode {
  Vec3 point;
  NodeOrigin origin;
  Vec2 uv;
};

/// `uv` moved by whole periods to the image nearest `reference`.
Vec2 nearest_image(Vec2 uv, const Vec2& reference, const Periods& periods) {
  for (int d = 0; d < 2; ++d)
    if (periods[d]) uv[d] += std::round((reference[d] - uv[d]) / *periods[d]) * *periods[d];
  return uv;
}

/// Maps the curve uses of one face's loops into its parameter plane. A periodic face is cut
/// open along its seams: each use of a seam takes the image on whose left the face lies. A pole
/// (degenerate curve) becomes the segment between where its two neighbouring uses reach it.
class LoopMapper {
 public:
  LoopMapper(const cad::Model& model, int surface, const CurveMeshes& curves)
      : model_(model), surface_(surface), face_(model.surface(surface)), curves_(curves),
        max_distance_(std::max(100.0 * model.tolerance(), 1e-8 * model.bbox().diagonal())) {
    for (int d = 0; d < 2; ++d) periods_[d] = face_.period(d);
    for (const cad::Loop& loop : model.loops(surface))
      for (const cad::CurveUse& use : loop.uses)
        if (model.curve(use.curve).is_degenerate()) pole_vertices_.insert(model.curve_vertices(use.curve)[0]);
  }

  /// The nodes of a loop in walking order, each use's end left to the next use.
  std::vector<LoopNode> map(const cad::Loop& loop) const {
    const int n = static_cast<int>(loop.uses.size());
    std::vector<std::vector<LoopNode>> uses(n);  // [uses][nodes, end vertex included]
    for (int j = 0; j < n; ++j)
      if (!model_.curve(loop.uses[j].curve).is_degenerate()) uses[j] = map_use(loop.uses[j]);
    place_along_loop(loop, uses);
    std::vector<LoopNode> out;
    for (int j = 0; j < n; ++j) {
      if (uses[j].empty()) {  // a pole: its start is where the previous use reaches it
        const std::vector<LoopNode>& before = uses[(j + n - 1) % n];
        if (before.empty()) continue;
        LoopNode pole = before.back();
        pole.origin = NodeOrigin{loop.uses[j].curve, 0, model_.curve(loop.uses[j].curve).bounds().lo, pole.origin.vertex};
        out.push_back(pole);
        continue;
      }
      out.insert(out.end(), uses[j].begin(), uses[j].end() - 1);
    }
    return out;
  }

 private:
  cad::SurfaceProjection project(const Vec3& point, const NodeOrigin& origin, const Vec2* guess) const {
    const cad::SurfaceProjection proj = guess ? face_.project(point, *guess) : face_.project(point);
    if (proj.distance > max_distance_)
      throw SurfaceMeshError(cad::surface_label(model_, surface_) + ": node " + std::to_string(origin.index) + " of curve " +
                             std::to_string(origin.curve) + " ('" + model_.curve(origin.curve).name() + "') is " +
                             std::to_string(proj.distance) + " away from the surface (tolerance " +
                             std::to_string(max_distance_) +
                             "); the CAD topology or the surface projection is inconsistent");
    return proj;
  }

  /// The nodes of a use from its start vertex to its end vertex, marching from the middle so
  /// that each projection starts next to its answer and (u, v) stays continuous across the box's
  /// sides of a periodic face. A node at a pole takes the free parameter that the use reaches it
  /// with (the limit along the curve), not the arbitrary one a projection of the pole gives.
  std::vector<LoopNode> map_use(const cad::CurveUse& use) const {
    const CurveMesh& cm = curves_.at(use.curve);
    const cad::Curve& curve = model_.curve(use.curve);
    const auto ends = model_.curve_vertices(use.curve);
    const int n = cm.segments();
    std::vector<LoopNode> nodes(n + 1);
    for (int k = 0; k <= n; ++k) {
      const int i = use.forward ? k : n - k;
      nodes[k].point = cm.points[i];
      nodes[k].origin = NodeOrigin{use.curve, i, cm.t[i], -1};
    }
    nodes.front().origin.vertex = use.forward ? ends[0] : ends[1];
    nodes.back().origin.vertex = use.forward ? ends[1] : ends[0];
    // The middle: a node when there is one, else the curve's mid-parameter point.
    const int mid = n / 2;
    const double t_seed = n >= 2 ? nodes[mid].origin.t : 0.5 * (cm.t.front() + cm.t.back());
    Vec2 seed = project(n >= 2 ? nodes[mid].point : curve.point(t_seed), nodes[mid].origin, nullptr).uv;
    if (model_.is_seam(surface_, use.curve)) seed = seam_image(seed, curve, t_seed, use.forward);
    if (n >= 2) nodes[mid].uv = seed;
    auto place = [&](int k, const Vec2& from) {
      if (pole_vertices_.count(nodes[k].origin.vertex)) {
        nodes[k].uv = pole_image(nodes[k], curve, cm, from);
        return;
      }
      nodes[k].uv = nearest_image(project(nodes[k].point, nodes[k].origin, &from).uv, from, periods_);
    };
    if (n >= 2) {
      for (int k = mid - 1; k >= 0; --k) place(k, nodes[k + 1].uv);
      for (int k = mid + 1; k <= n; ++k) place(k, nodes[k - 1].uv);
    } else {
      place(0, seed);
      place(1, seed);
    }
    return nodes;
  }

  /// Of the images of a seam point one period apart, the one with the face on the use's left
  /// (inside the parameter box a small step to the left).
  Vec2 seam_image(const Vec2& uv, const cad::Curve& curve, double t, bool forward) const {
    const cad::SurfaceDerivatives d = face_.derivatives(uv);
    Eigen::Matrix<double, 3, 2> jac;
    jac << d.du, d.dv;
    const Vec3 left3 = face_.normal(uv).cross((forward ? 1.0 : -1.0) * curve.tangent(t));
    Vec2 left = jac.colPivHouseholderQr().solve(left3);
    const auto box = face_.bounds();
    left = left.cwiseQuotient(Vec2(box[0].length(), box[1].length())).normalized() * 1e-3;
    Vec2 best = uv;
    double best_outside = std::numeric_limits<double>::max();
    for (int du = -1; du <= 1; ++du)
      for (int dv = -1; dv <= 1; ++dv) {
        if ((du != 0 && !periods_[0]) || (dv != 0 && !periods_[1])) continue;
        const Vec2 image = uv + Vec2(du * periods_[0].value_or(0.0), dv * periods_[1].value_or(0.0));
        double outside = 0.0;
        for (int k = 0; k < 2; ++k) {
          const double x = image[k] + left[k] * box[k].length();
          outside += std::max({0.0, box[k].lo - x, x - box[k].hi}) / box[k].length();
        }
        if (outside < best_outside - 1e-12) {
          best_outside = outside;
          best = image;
        }
      }
    return best;
  }

  /// (u, v) of a use's end node at a pole: the pinned parameter from the pole, the free one (the
  /// one along which the face's derivative vanishes there) from a point of the curve just before
  /// the pole, so the node sits where the use meets the pole segment.
  Vec2 pole_image(const LoopNode& node, const cad::Curve& curve, const CurveMesh& cm, const Vec2& from) const {
    const double t_pole = node.origin.t;
    const double inward = (node.origin.index == 0 ? 1.0 : -1.0) * 1e-6 * (cm.t.back() - cm.t.front());
    // Newton converges slowly next to the singular point: only the parameters are used here, the
    // node keeps its exact point (the pole vertex).
    const Vec2 near = nearest_image(face_.project(curve.point(t_pole + inward), from).uv, from, periods_);
    Vec2 uv = nearest_image(face_.project(node.point, near).uv, near, periods_);
    const cad::SurfaceDerivatives d = face_.derivatives(uv);
    const int free = d.du.norm() < d.dv.norm() ? 0 : 1;
    uv[free] = near[free];
    return uv;
  }

  /// Moves whole uses by periods so that each starts where the previous one ends: seam uses are
  /// fixed by seam_image; the walk starts at the first seam use (or the first use). Across a pole
  /// nothing is aligned (the free parameter jumps along the pole segment).
  void place_along_loop(const cad::Loop& loop, std::vector<std::vector<LoopNode>>& uses) const {
    if (!periods_[0] && !periods_[1]) return;
    const int n = static_cast<int>(uses.size());
    int first = -1;
    for (int j = 0; j < n && first < 0; ++j)
      if (!uses[j].empty() && model_.is_seam(surface_, loop.uses[j].curve)) first = j;
    for (int j = 0; j < n && first < 0; ++j)
      if (!uses[j].empty()) first = j;
    if (first < 0) return;
    for (int step = 1; step < n; ++step) {
      const int j = (first + step) % n, before = (j + n - 1) % n;
      if (uses[j].empty() || uses[before].empty() || model_.is_seam(surface_, loop.uses[j].curve)) continue;
      const Vec2 shift = nearest_image(uses[j].front().uv, uses[before].back().uv, periods_) - uses[j].front().uv;
      for (LoopNode& node : uses[j]) node.uv += shift;
    }
    // The loop as a whole back into the parameter box.
    const auto box = face_.bounds();
    Vec2 lo = uses[first].front().uv;
    for (const auto& use : uses)
      for (const LoopNode& node : use) lo = lo.cwiseMin(node.uv);
    Vec2 shift = Vec2::Zero();
    for (int d = 0; d < 2; ++d)
      if (periods_[d]) shift[d] = std::ceil((box[d].lo - lo[d]) / *periods_[d] - 1e-9) * *periods_[d];
    for (auto& use : uses)
      for (LoopNode& node : use) node.uv += shift;
  }

  const cad::Model& model_;
  int surface_;
  const cad::Surface& face_;
  const CurveMeshes& curves_;
  double max_distance_;
  Periods periods_;
  std::set<int> pole_vertices_;
};

}  // namespace

std::vector<std::vector<int>> add_boundary_nodes(const cad::Model& model, int surface, const CurveMeshes& curves,
                                                 SurfaceMesh& mesh) {
  // A curve may be walked twice only as a seam (once each way).
  std::map<int, int> uses_of_curve;
  for (const cad::Loop& loop : model.loops(surface))
    for (const cad::CurveUse& use : loop.uses)
      if (++uses_of_curve[use.curve] == 2 && !model.is_seam(surface, use.curve))
        throw SurfaceMeshError(cad::surface_label(model, surface) + " uses " + cad::curve_label(model, use.curve) +
                               " twice in the same direction; only a seam (walked once each way) may be used twice");
  const LoopMapper mapper(model, surface, curves);
  const auto box = model.surface(surface).bounds();
  const double same_uv = 1e-9 * std::max(1.0, std::hypot(box[0].length(), box[1].length()));
  std::map<int, std::vector<int>> nodes_of_vertex;  // a vertex has one node per image in (u, v)
  std::vector<std::vector<int>> loops;
  for (const cad::Loop& loop : model.loops(surface)) {
    std::vector<int> chain;
    for (const LoopNode& node : mapper.map(loop)) {
      if (node.origin.vertex >= 0) {
        auto& known = nodes_of_vertex[node.origin.vertex];
        auto same = std::find_if(known.begin(), known.end(), [&](int k) { return (mesh.uv[k] - node.uv).norm() <= same_uv; });
        if (same != known.end()) {
          if (chain.empty() || chain.back() != *same) chain.push_back(*same);
          continue;
        }
        known.push_back(mesh.num_nodes());
      }
      mesh.uv.push_back(node.uv);
      mesh.points.push_back(node.point);
      mesh.origin.push_back(node.origin);
      chain.push_back(mesh.num_nodes() - 1);
    }
    if (chain.size() < 3)
      throw SurfaceMeshError(cad::surface_label(model, surface) + ": a boundary loop has only " + std::to_string(chain.size()) +
                             " nodes; its curves need more segments");
    loops.push_back(std::move(chain));
  }
  if (loops.empty()) throw SurfaceMeshError(cad::surface_label(model, surface) + " has no boundary loop");
  return loops;
}

void remove_pole_triangles(SurfaceMesh& mesh) {
  const auto same_vertex = [&](int a, int b) { return mesh.origin[a].vertex >= 0 && mesh.origin[a].vertex == mesh.origin[b].vertex; };
  mesh.triangles.erase(std::remove_if(mesh.triangles.begin(), mesh.triangles.end(),
                                      [&](const std::array<int, 3>& t) {
                                        return same_vertex(t[0], t[1]) || same_vertex(t[1], t[2]) || same_vertex(t[2], t[0]);
                                      }),
                       mesh.triangles.end());
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
